#include "engine/prove/prove.h"

#include "engine/algebra/polynomial.h"

#include <fmt/format.h>

#include <cln/real.h>
#include <cln/rational.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace impact::engine {
namespace {

constexpr std::size_t sample_points = 200;
constexpr int sample_digits = 40;

// `e` with its abbreviations replaced by their definitions, and those in the definitions
// in turn; an expression with none (or a derivation without any) is not walked again.
GiNaC::ex spelled_out(const GiNaC::ex& e, const GiNaC::exmap& abbreviations)
{
    if (abbreviations.empty())
        return e;
    const GiNaC::ex once = e.subs(abbreviations);
    return once.is_equal(e) ? once : once.subs(abbreviations);
}

// False when `e` is certainly not identically zero: its exact value at one point of
// rationals is a non-zero number. True otherwise (zero there, or not a number there: a
// radical of rationals, a pole), when only normal() can tell. A cheap test before
// normal() on large expressions that are mostly not equal.
bool may_vanish(const GiNaC::ex& e)
{
    GiNaC::exmap point;
    long k = 0;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !point.count(*it)) {
            ++k;
            point[*it] = GiNaC::numeric(2 * k + 3, k + 7);  // distinct, positive, below 1 after 4
        }
    try {
        const GiNaC::ex value = e.subs(point, GiNaC::subs_options::no_pattern);
        return !(GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_rational() &&
                 !value.is_zero());
    } catch (const std::exception&) {
        return true;
    }
}

// The exact rational value of a double, so that sampled points carry no rounding.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

// Evaluates `lhs - rhs` at points of the declared domains. Returns the failing
// residual's value as a verdict, or a `sampled` verdict when every point agrees.
// Evaluates both sides at points of the declared domains and tests `holds` on them.
// Returns `failed` at the first point where it does not hold, else `sampled`.
verdict sample(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::ex& residual, const symbol_table& symbols,
               const std::function<bool(const GiNaC::numeric&, const GiNaC::numeric&)>& holds,
               const std::string& claim)
{
    GiNaC::lst free;
    for (const quantity& q : symbols.all())
        if ((lhs - rhs).has(q.symbol))
            free.append(q.symbol);

    const auto saved_digits = GiNaC::Digits;
    GiNaC::Digits = sample_digits;
    uniform_stream stream(0x1a2b3c4d5e6f7081ULL);
    std::size_t tested = 0;
    verdict v;
    v.residual = residual;
    // Each side evaluated at the point: numbers are substituted as 40-digit floats, so
    // that a large expression is not first evaluated in exact rationals whose digits
    // grow with every product (the cost of a sampled check, ten times over); a point
    // where the claim fails is evaluated again exactly before it is believed.
    auto evaluated = [&](const GiNaC::exmap& point, GiNaC::numeric& a, GiNaC::numeric& b) {
        const GiNaC::ex x = GiNaC::evalf(lhs.subs(point, GiNaC::subs_options::no_pattern));
        const GiNaC::ex y = GiNaC::evalf(rhs.subs(point, GiNaC::subs_options::no_pattern));
        if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::is_a<GiNaC::numeric>(y) ||
            !GiNaC::ex_to<GiNaC::numeric>(x).is_real() || !GiNaC::ex_to<GiNaC::numeric>(y).is_real())
            return false;
        a = GiNaC::ex_to<GiNaC::numeric>(x);
        b = GiNaC::ex_to<GiNaC::numeric>(y);
        return true;
    };
    for (std::size_t attempt = 0; tested < sample_points && attempt < 4 * sample_points; ++attempt) {
        GiNaC::exmap point, rounded;
        for (const GiNaC::ex& s : free) {
            point[s] = exact(draw(*symbols.domain_of(s), stream));
            rounded[s] = point[s].evalf();
        }
        try {
            GiNaC::numeric a, b;
            if (!evaluated(rounded, a, b))
                continue;
            if (!holds(a, b)) {
                if (!evaluated(point, a, b))
                    continue;
                if (!holds(a, b)) {
                    GiNaC::Digits = saved_digits;
                    v.what = verdict::status::failed;
                    v.samples = tested + 1;
                    v.method = fmt::format("does not hold at a sampled point: {} {} vs {:.6g}", a.to_double(), claim,
                                           b.to_double());
                    return v;
                }
            }
            ++tested;
        } catch (const std::exception&) {
            continue; // a pole of either side: draw another point
        }
    }
    GiNaC::Digits = saved_digits;
    v.what = tested > 0 ? verdict::status::sampled : verdict::status::failed;
    v.samples = tested;
    v.method = tested > 0 ? fmt::format("not proven symbolically; holds at {} sampled points ({} digits)", tested,
                                        sample_digits)
                          : "no sampled point could be evaluated";
    return v;
}

// e = numerator / denominator, the denominator kept as a product of powers of its
// factors so that a sum takes the least common multiple of its terms' denominators
// (factor by factor) and no gcd is ever computed: gcds are the costly part of normal().
// Radicals and functions are kept whole, as normal() keeps them.
struct over_denominator {
    GiNaC::ex numerator;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> denominator;
};

over_denominator over_common_denominator(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
        if (!n.is_rational() || n.is_integer())
            return {e, {}};
        return {n.numer(), {{n.denom(), 1}}};
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        over_denominator r{1, {}};
        for (std::size_t i = 0; i < e.nops(); ++i) {
            over_denominator f = over_common_denominator(e.op(i));
            r.numerator *= f.numerator;
            for (const auto& [base, k] : f.denominator)
                r.denominator[base] += k;
        }
        return r;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::integer)) {
        const int k = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_int();
        over_denominator base = over_common_denominator(e.op(0));
        if (k >= 0) {
            for (auto& [b, j] : base.denominator)
                j *= k;
            return {GiNaC::pow(base.numerator, k), base.denominator};
        }
        // (n / d)^-k = d^k / n^k
        GiNaC::ex top = 1;
        for (const auto& [b, j] : base.denominator)
            top *= GiNaC::pow(b, -k * j);
        return {top, {{base.numerator, -k}}};
    }
    if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::rational) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).denom() == 2 && !e.op(1).is_equal(GiNaC::numeric(1, 2))) {
        // x^(p/2) = x^((p-1)/2) sqrt(x): the root kept whole, the rest an integer power,
        // so that x^(-3/2) meets sqrt(x)/x^2.
        const GiNaC::numeric p = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).numer();
        over_denominator whole = over_common_denominator(GiNaC::pow(e.op(0), (p - 1) / 2));
        whole.numerator *= GiNaC::sqrt(e.op(0));
        return whole;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        std::vector<over_denominator> terms;
        std::map<GiNaC::ex, int, GiNaC::ex_is_less> lcm;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            terms.push_back(over_common_denominator(e.op(i)));
            for (const auto& [base, k] : terms.back().denominator)
                lcm[base] = std::max(lcm[base], k);
        }
        GiNaC::ex top = 0;
        for (const over_denominator& t : terms) {
            GiNaC::ex scaled = t.numerator;
            for (const auto& [base, k] : lcm) {
                const auto own = t.denominator.find(base);
                const int missing = k - (own == t.denominator.end() ? 0 : own->second);
                if (missing > 0)
                    scaled *= GiNaC::pow(base, missing);
            }
            top += scaled;
        }
        return {top, lcm};
    }
    return {e, {}};
}

// cos of acos(u), atan(u) or atan2(y, x), as an algebraic expression.
std::optional<GiNaC::ex> cosine_of(const GiNaC::ex& angle)
{
    if (!GiNaC::is_a<GiNaC::function>(angle))
        return std::nullopt;
    const std::string name = GiNaC::ex_to<GiNaC::function>(angle).get_name();
    if (name == "acos")
        return angle.op(0);
    if (name == "atan")
        return 1 / GiNaC::sqrt(1 + GiNaC::pow(angle.op(0), 2));
    if (name == "atan2")
        return angle.op(1) / GiNaC::sqrt(GiNaC::pow(angle.op(0), 2) + GiNaC::pow(angle.op(1), 2));
    return std::nullopt;
}

// acos lies in [0, pi]; atan2(y, x) does when y >= 0; atan(u) does when u >= 0.
bool within_zero_and_pi(const GiNaC::ex& angle, const assumptions& given)
{
    const std::string name = GiNaC::ex_to<GiNaC::function>(angle).get_name();
    if (name == "acos")
        return true;
    return !prove_sign(angle.op(0), given).sign.negative;
}

bool nearly_equal(const GiNaC::numeric& a, const GiNaC::numeric& b);

// Two angles in [0, pi], where cos is one-to-one, are equal when their cosines are.
std::optional<verdict> prove_equal_angles(const GiNaC::ex& a, const GiNaC::ex& b, const symbol_table& symbols,
                                          const assumptions& given)
{
    const auto ca = cosine_of(a), cb = cosine_of(b);
    if (!ca || !cb || !within_zero_and_pi(a, given) || !within_zero_and_pi(b, given))
        return std::nullopt;
    verdict v = prove_equal(*ca, *cb, symbols, *given.run);
    if (v.what != verdict::status::proven)
        return std::nullopt;
    v.method = "both angles lie in [0, pi], where cos is one-to-one, and their cosines are proven equal";
    v.how = verdict::basis::angles;
    return v;
}

bool nearly_equal(const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    const double scale = std::max({1.0, std::abs(a.to_double()), std::abs(b.to_double())});
    return GiNaC::abs(a - b).to_double() <= 1e-30 * scale;
}

} // namespace

namespace {

// The signs `e` is believed to take at up to `points` points drawn from the domains of
// `given` (bit 0: negative, bit 1: positive), drawing until both are seen, or until one is
// when `one_is_enough`; 0 where a symbol has no domain. A sign is believed where 40 and 80
// digits agree on it and on the value to a half: a value that is 0 (an identity) comes out
// as noise of either sign.
unsigned believed_signs(const GiNaC::ex& e, const assumptions& given, std::size_t points, bool one_is_enough)
{
    std::vector<std::pair<GiNaC::ex, const domain*>> free;
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) &&
            std::none_of(free.begin(), free.end(), [&](const auto& f) { return f.first.is_equal(*it); })) {
            const auto d = given.domains.find(*it);
            if (d == given.domains.end())
                return 0;
            free.emplace_back(*it, &d->second);
        }
    std::sort(free.begin(), free.end(), [&](const auto& a, const auto& b) { return given.order.before(a.first, b.first); });
    const auto saved_digits = GiNaC::Digits;
    uniform_stream stream(0x5e1f2a3b4c5d6e7fULL);
    unsigned seen = 0;
    for (std::size_t n = 0; n < points && seen != 3u && !(one_is_enough && seen != 0); ++n) {
        GiNaC::exmap point;
        for (const auto& [symbol, range] : free)
            point[symbol] = exact(draw(*range, stream));
        try {
            const GiNaC::ex at = e.subs(point, GiNaC::subs_options::no_pattern);
            int sign[2] = {0, 0};
            GiNaC::numeric value[2];
            for (int k = 0; k < 2; ++k) {
                GiNaC::Digits = k == 0 ? 40 : 80;
                const GiNaC::ex x = GiNaC::evalf(at);
                if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real())
                    break;
                value[k] = GiNaC::ex_to<GiNaC::numeric>(x);
                sign[k] = value[k].is_zero() ? 0 : value[k].is_positive() ? 1 : -1;
            }
            if (sign[0] != 0 && sign[0] == sign[1] && GiNaC::abs(value[0] - value[1]) < GiNaC::abs(value[1]) / 2)
                seen |= sign[0] < 0 ? 1u : 2u;
        } catch (const std::exception&) {
            // a pole: another point
        }
    }
    GiNaC::Digits = saved_digits;
    return seen;
}

} // namespace

bool takes_both_signs(const GiNaC::ex& e, const assumptions& given, std::size_t points)
{
    return believed_signs(e, given, points, false) == 3u;
}

bool nonzero_somewhere(const GiNaC::ex& e, const assumptions& given, std::size_t points)
{
    return believed_signs(e, given, points, true) != 0;
}

namespace {

// The simple values of a domain a reader can check by hand, in the order they are tried:
// its ends and middle for an interval, else 1, 2, 1/2, 3 (and 0, -1, -2 where they lie in it).
std::vector<GiNaC::numeric> simple_values(const domain& range)
{
    std::vector<GiNaC::numeric> candidates;
    if (range.what == domain::kind::interval) {
        const GiNaC::numeric a(cln::rationalize(cln::cl_DF(range.lower)));
        const GiNaC::numeric b(cln::rationalize(cln::cl_DF(range.upper)));
        candidates = {b, a, (a + b) / 2, (3 * a + b) / 4, (a + 3 * b) / 4};
    } else {
        candidates = {1, 2, GiNaC::numeric(1, 2), 0, -1, 3, -2};
    }
    std::vector<GiNaC::numeric> inside;
    for (const GiNaC::numeric& x : candidates)
        if (range.contains(x.to_double()) && std::find(inside.begin(), inside.end(), x) == inside.end())
            inside.push_back(x);
    return inside;
}

// Whether `a op b` fails for the two numbers, by more than `margin` (0: exactly).
bool fails(const GiNaC::numeric& a, relation op, const GiNaC::numeric& b, const GiNaC::numeric& margin)
{
    const bool exactly = margin.is_zero();
    switch (op) {
    case relation::equal: return GiNaC::abs(a - b) > margin;
    case relation::less_equal: return a - b > margin;
    case relation::less: return exactly ? a >= b : a - b > margin;
    case relation::greater_equal: return b - a > margin;
    case relation::greater: return exactly ? a <= b : b - a > margin;
    }
    return false;
}

} // namespace

std::optional<counterexample> find_counterexample(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                  const symbol_table& symbols, const assumptions& given,
                                                  std::size_t points)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const GiNaC::ex a = spelled_out(lhs, abbreviations), b = spelled_out(rhs, abbreviations);
    // The claim's symbols, and those of each abbreviation that shares one with them, in
    // turn: the abbreviation must take a value of its own domain at the point (s_n > 0, the
    // spheres approach; or as `assuming` narrows it), or the point is none of the domains'.
    std::vector<GiNaC::ex> names;
    const auto add_symbols = [&](const GiNaC::ex& e) {
        bool added = false;
        for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) &&
                std::none_of(names.begin(), names.end(), [&](const GiNaC::ex& n) { return n.is_equal(*it); })) {
                names.push_back(*it);
                added = true;
            }
        return added;
    };
    // Both sides' symbols, also those their difference cancels (u + du - g t against u - g t):
    // each side must come to a number at the point.
    add_symbols(a);
    add_symbols(b);
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> constrained;   // an abbreviation and its definition in the inputs
    std::set<GiNaC::ex, GiNaC::ex_is_less> taken;
    for (bool more = true; more;) {
        more = false;
        for (const auto& [symbol, definition] : abbreviations) {
            if (taken.count(symbol))
                continue;
            const GiNaC::ex spelled = spelled_out(definition, abbreviations);
            if (std::none_of(names.begin(), names.end(), [&](const GiNaC::ex& n) { return spelled.has(n); }))
                continue;
            taken.insert(symbol);
            constrained.emplace_back(symbol, spelled);
            add_symbols(spelled);
            more = true;
        }
    }
    std::sort(constrained.begin(), constrained.end(),
              [&](const auto& x, const auto& y) { return given.order.before(x.first, y.first); });
    std::vector<std::pair<GiNaC::ex, std::vector<GiNaC::numeric>>> free;
    for (const GiNaC::ex& name : names) {
        if (abbreviations.count(name))
            continue;   // spelled out
        const auto d = given.domains.find(name);
        if (d == given.domains.end())
            return std::nullopt;
        std::vector<GiNaC::numeric> values = simple_values(d->second);
        if (values.empty())
            return std::nullopt;
        free.emplace_back(name, std::move(values));
    }
    // Whether each abbreviation lies in its domain at the point (none: a pole, or complex).
    const auto in_domains = [&](const GiNaC::exmap& at) {
        for (const auto& [symbol, spelled] : constrained) {
            // Its domain: as `assuming` narrows it, else as declared.
            const domain* range = nullptr;
            if (const auto d = given.domains.find(symbol); d != given.domains.end())
                range = &d->second;
            for (const assumptions::assumed_sign& a : given.assumed)
                if (!range && a.symbol.is_equal(symbol))
                    range = &a.range;
            const GiNaC::ex value = GiNaC::evalf(GiNaC::normal(spelled.subs(at, GiNaC::subs_options::no_pattern)));
            if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
                return false;
            if (range && !range->contains(GiNaC::ex_to<GiNaC::numeric>(value).to_double()))
                return false;
        }
        return true;
    };
    std::sort(free.begin(), free.end(), [&](const auto& x, const auto& y) { return given.order.before(x.first, y.first); });

    const auto saved_digits = GiNaC::Digits;
    uniform_stream stream(0x6c0e7e1a5b3d2f19ULL);
    std::optional<counterexample> found;
    for (std::size_t n = 0; n < points && !found; ++n) {
        GiNaC::exmap at;
        counterexample x;
        for (const auto& [symbol, values] : free) {
            const std::size_t k =
                n == 0 ? 0 : std::min(values.size() - 1, static_cast<std::size_t>(stream.next() * values.size()));
            at[symbol] = values[k];
            x.point.emplace_back(symbol, values[k]);
        }
        try {
            if (!in_domains(at))
                continue;
            const GiNaC::ex l = GiNaC::normal(a.subs(at, GiNaC::subs_options::no_pattern));
            const GiNaC::ex r = GiNaC::normal(b.subs(at, GiNaC::subs_options::no_pattern));
            if (GiNaC::is_a<GiNaC::numeric>(l) && GiNaC::is_a<GiNaC::numeric>(r) &&
                GiNaC::ex_to<GiNaC::numeric>(l).is_rational() && GiNaC::ex_to<GiNaC::numeric>(r).is_rational()) {
                if (fails(GiNaC::ex_to<GiNaC::numeric>(l), op, GiNaC::ex_to<GiNaC::numeric>(r), 0)) {
                    x.lhs = l;
                    x.rhs = r;
                    x.exact = true;
                    found = std::move(x);
                }
                continue;
            }
            // Radicals: believed when 50 and 80 digits agree and the failure is far beyond
            // their rounding.
            bool believed = true;
            for (const int digits : {50, 80}) {
                GiNaC::Digits = digits;
                const GiNaC::ex le = GiNaC::evalf(l), re = GiNaC::evalf(r);
                if (!GiNaC::is_a<GiNaC::numeric>(le) || !GiNaC::is_a<GiNaC::numeric>(re) ||
                    !GiNaC::ex_to<GiNaC::numeric>(le).is_real() || !GiNaC::ex_to<GiNaC::numeric>(re).is_real()) {
                    believed = false;
                    break;
                }
                const GiNaC::numeric u = GiNaC::ex_to<GiNaC::numeric>(le), v = GiNaC::ex_to<GiNaC::numeric>(re);
                const GiNaC::numeric margin = GiNaC::numeric(1, 1000000000) * (1 + GiNaC::abs(u) + GiNaC::abs(v));
                believed = believed && fails(u, op, v, margin);
            }
            GiNaC::Digits = saved_digits;
            if (believed) {
                x.lhs = l;
                x.rhs = r;
                found = std::move(x);
            }
        } catch (const std::exception&) {
            GiNaC::Digits = saved_digits;   // a pole: another point
        }
    }
    GiNaC::Digits = saved_digits;
    return found;
}

std::string to_string(const verdict& v)
{
    switch (v.what) {
    case verdict::status::proven: return "proven";
    case verdict::status::sampled: return fmt::format("sampled ({} points)", v.samples);
    case verdict::status::failed: break;
    }
    return "failed";
}

verdict prove_equal(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const symbol_table& symbols, proof_cache& run,
                    when_unproven otherwise)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const assumptions given = declared_assumptions(symbols, run);
    // Radicals in one canonical form first: normal() cannot see that sqrt(1/x) = 1/sqrt(x).
    const GiNaC::ex a = simplify_radicals(spelled_out(lhs, abbreviations), given);
    const GiNaC::ex b = simplify_radicals(spelled_out(rhs, abbreviations), given);
    // Fast path: over the product of all denominators (no gcd), the numerator expands
    // to zero exactly when the difference is zero as a rational function. It is expanded
    // as a polynomial first (engine/algebra/polynomial.h); GiNaC is asked only when radicals or
    // functions in it might still cancel. A radical written two ways stands there as two
    // variables, and as one once every radicand is expanded (the conditions of a rough
    // contact's cases at shifted or exchanged inputs, whose normal() below takes minutes).
    expansion numerator = expand_numerator(a - b);
    if (numerator == expansion::undecided)
        numerator = expand_numerator(expanded_radicands(a) - expanded_radicands(b));
    if (numerator == expansion::zero ||
        (numerator == expansion::undecided && GiNaC::expand(over_common_denominator(a - b).numerator).is_zero())) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = 0;
        v.method = "difference normalises to zero";
        v.how = verdict::basis::zero_difference;
        return v;
    }
    // normal() brings the difference over one denominator; its numerator may still hold
    // unexpanded products that cancel, so it is expanded once more before giving up.
    GiNaC::ex residual = GiNaC::normal(a - b);
    if (!residual.is_zero()) {
        const GiNaC::ex nd = residual.numer_denom();
        const GiNaC::ex top = GiNaC::expand(nd.op(0));
        residual = top.is_zero() ? GiNaC::ex(0) : GiNaC::normal(top / nd.op(1));
    }
    if (residual.is_zero()) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = residual;
        v.method = "difference normalises to zero";
        v.how = verdict::basis::zero_difference;
        return v;
    }
    // A rational function with no radicals or functions left is decided by normal():
    // a non-zero residual is a counterexample, no sampling needed.
    bool rational = true;
    for (GiNaC::const_preorder_iterator it = residual.preorder_begin(); it != residual.preorder_end(); ++it) {
        if (GiNaC::is_a<GiNaC::function>(*it) ||
            (GiNaC::is_a<GiNaC::power>(*it) && !it->op(1).info(GiNaC::info_flags::integer)))
            rational = false;
    }
    if (rational) {
        verdict v;
        v.what = verdict::status::failed;
        v.residual = residual;
        v.method = "difference normalises to a non-zero rational function";
        return v;
    }
    if (auto angles = prove_equal_angles(a, b, symbols, given))
        return *angles;
    if (otherwise == when_unproven::give_up) {
        verdict v;
        v.what = verdict::status::failed;
        v.residual = residual;
        v.method = "difference not proven zero (not sampled)";
        return v;
    }
    return sample(a, b, residual, symbols, nearly_equal, "=");
}

std::optional<verdict> prove_inequality_by_signs(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                 const symbol_table& symbols, const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    const GiNaC::ex a = spelled_out(lhs, abbreviations), b = spelled_out(rhs, abbreviations);
    const GiNaC::ex difference = upper ? b - a : a - b;
    const sign_proof proof = prove_sign(difference, given);
    if (proof.sign.negative || (strict && proof.sign.zero))
        return std::nullopt;
    verdict v;
    v.residual = GiNaC::normal(difference);
    v.proof = proof.steps;
    v.what = verdict::status::proven;
    v.method = fmt::format("the sign of each factor of {} follows from the domains", given.text(v.residual));
    v.how = verdict::basis::signs;
    return v;
}

verdict prove_inequality(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const symbol_table& symbols,
                         const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const GiNaC::ex a = spelled_out(lhs, abbreviations);
    const GiNaC::ex b = spelled_out(rhs, abbreviations);
    // lhs <= rhs  <=>  rhs - lhs >= 0; strict relations need > 0.
    const bool upper = op == relation::less_equal || op == relation::less;
    const GiNaC::ex difference = upper ? b - a : a - b;
    if (auto proven = prove_inequality_by_signs(lhs, op, rhs, symbols, given))
        return *proven;
    const sign_proof proof = prove_sign(difference, given);   // worked out: the steps it got to
    verdict v;
    v.residual = GiNaC::normal(difference);
    auto holds = [&](const GiNaC::numeric& x, const GiNaC::numeric& y) {
        switch (op) {
        case relation::less_equal: return x <= y;
        case relation::less: return x < y;
        case relation::greater_equal: return x >= y;
        case relation::greater: return x > y;
        case relation::equal: break;
        }
        return nearly_equal(x, y);
    };
    verdict sampled = sample(a, b, v.residual, symbols, holds, to_string(op));
    sampled.proof = proof.steps;
    return sampled;
}

namespace {

// `given` with each abbreviation of `e` an atom of the sign its definition is proven to
// have (m_t > 0 for a tangential mass): a sum of terms in m_t, g_n and g_t keeps its few
// terms instead of being spelled out over a common denominator.
assumptions with_abbreviations_as_atoms(const GiNaC::ex& e, const GiNaC::exmap& abbreviations,
                                        const assumptions& given)
{
    assumptions atoms = given;
    atoms.known = std::make_shared<worked_out>();
    for (const auto& [symbol, definition] : abbreviations) {
        if (!e.has(symbol) || atoms.domains.count(symbol))
            continue;
        const sign_set s = prove_sign(spelled_out(definition, abbreviations), given).sign;
        domain range;
        if (s.is_positive())
            range.what = domain::kind::positive;
        else if (s.is_nonnegative())
            range.what = domain::kind::nonnegative;
        atoms.domains[symbol] = range;
    }
    return atoms;
}

} // namespace

std::optional<verdict> prove_inequality_through(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                const std::vector<proven_identity>& identities,
                                                const symbol_table& symbols, const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    const GiNaC::ex difference = spelled_out(upper ? rhs - lhs : lhs - rhs, abbreviations);
    for (const proven_identity& identity : identities) {
        const GiNaC::ex sides[2] = {identity.lhs, identity.rhs};
        for (int side = 0; side < 2; ++side) {
            for (const int s : {1, -1}) {
                const GiNaC::ex same = spelled_out(s * sides[side], abbreviations);
                if (!may_vanish(difference - same) || !GiNaC::normal(difference - same).is_zero())
                    continue;
                const GiNaC::ex other = s * sides[1 - side];
                const auto settled = [strict](const sign_proof& p) {
                    return strict ? p.sign.is_positive() : p.sign.is_nonnegative();
                };
                sign_proof proof = prove_sign(other, with_abbreviations_as_atoms(other, abbreviations, given));
                if (!settled(proof))
                    proof = prove_sign(spelled_out(other, abbreviations), given);
                if (!settled(proof))
                    continue;
                verdict v;
                v.what = verdict::status::proven;
                v.residual = 0;
                v.proof = proof.steps;
                v.method = fmt::format("by {} the difference of the sides is {}, and the sign of each factor of "
                                       "that follows from the domains",
                                       identity.name, given.text(other));
                v.how = verdict::basis::identity;
                return v;
            }
        }
    }
    return std::nullopt;
}

verdict prove_equivalent(const GiNaC::ex& equation, const GiNaC::ex& other, const symbol_table& symbols,
                         proof_cache& run)
{
    const GiNaC::ex d1 = equation.lhs() - equation.rhs();
    const GiNaC::ex d2 = other.lhs() - other.rhs();
    const GiNaC::ex ratio = GiNaC::normal(d1 / d2);
    if (GiNaC::is_a<GiNaC::numeric>(ratio) && !ratio.is_zero()) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = 0;
        v.method = "the two equations differ by a constant factor";
        v.how = verdict::basis::constant_factor;
        return v;
    }
    verdict v = prove_equal(d1, d2, symbols, run);
    if (v.what == verdict::status::proven) {
        v.method = "the two equations have the same difference of sides";
        v.how = verdict::basis::same_difference;
    }
    return v;
}

} // namespace impact::engine
