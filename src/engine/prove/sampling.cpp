// Claims tested at points of the domains, never proofs: an identity or an inequality
// sampled at 40 digits where no proof is found (a failing point evaluated again exactly);
// the signs an expression is believed to take (a refutation of a sign, or of "= 0"); and a
// counterexample among simple values a reader can check by hand.
#include "engine/prove/prove_internal.h"

#include <fmt/format.h>

#include <cln/real.h>
#include <cln/rational.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

namespace impact::engine {
namespace {

constexpr std::size_t sample_points = 200;
constexpr int sample_digits = 40;

// The exact rational value of a double, so that sampled points carry no rounding.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

// A value over twelve decades, 10^-6 to 10^6 (either sign on the real line), for a domain
// without ends; an interval's as `draw` draws it. The ordinary draws stay within [-10, 10]
// and [1/20, 20], where a claim false only near 0 or far out (1 + e^6 >= 2 e^3 sqrt(1 + 1/x),
// false for 0 < x < 1/100) always holds.
double draw_wide(const domain& range, uniform_stream& stream)
{
    if (range.what == domain::kind::interval)
        return draw(range, stream);
    const double u = stream.next();
    const double magnitude = std::pow(10.0, -6 + 12 * stream.next());
    return range.what == domain::kind::real && u < 0.5 ? -magnitude : magnitude;
}

} // namespace

// Evaluates both sides at points of the declared domains where the conditions `where`
// hold, and tests `holds` on them. Returns `failed` at the first point where it does not
// hold, or where a side is undefined or not real: the claim is said to hold there, so the
// point refutes it, and is never skipped. Else `sampled`.
verdict sample(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const GiNaC::ex& residual, const symbol_table& symbols,
               const std::function<bool(const GiNaC::numeric&, const GiNaC::numeric&)>& holds,
               const std::string& claim, const std::vector<condition>& where)
{
    GiNaC::lst free;
    for (const quantity& q : symbols.all()) {
        bool in_condition = false;
        for (const condition& c : where)
            in_condition = in_condition || c.expr.has(q.symbol);
        if ((lhs - rhs).has(q.symbol) || in_condition)
            free.append(q.symbol);
    }

    const auto saved_digits = GiNaC::Digits;
    GiNaC::Digits = sample_digits;
    uniform_stream stream(0x1a2b3c4d5e6f7081ULL);
    std::size_t tested = 0;
    verdict v;
    v.residual = residual;
    // Each side evaluated at the point: numbers are substituted as 40-digit floats, so
    // that a large expression is not first evaluated in exact rationals whose digits
    // grow with every product (the cost of a sampled check, ten times over); a point
    // where the claim fails is evaluated again exactly before it is believed. False where
    // a side is not a real number there (or a pole).
    auto evaluated = [&](const GiNaC::exmap& point, GiNaC::numeric& a, GiNaC::numeric& b) {
        try {
            const GiNaC::ex x = GiNaC::evalf(lhs.subs(point, GiNaC::subs_options::no_pattern));
            const GiNaC::ex y = GiNaC::evalf(rhs.subs(point, GiNaC::subs_options::no_pattern));
            if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::is_a<GiNaC::numeric>(y) ||
                !GiNaC::ex_to<GiNaC::numeric>(x).is_real() || !GiNaC::ex_to<GiNaC::numeric>(y).is_real())
                return false;
            a = GiNaC::ex_to<GiNaC::numeric>(x);
            b = GiNaC::ex_to<GiNaC::numeric>(y);
            return true;
        } catch (const std::exception&) {
            return false;
        }
    };
    const auto refuted = [&](const GiNaC::exmap& point, const std::string& what) {
        std::vector<std::string> values;
        for (const GiNaC::ex& s : free)
            values.push_back(fmt::format("{} = {:.6g}", symbols.text(s),
                                         GiNaC::ex_to<GiNaC::numeric>(point.at(s)).to_double()));
        GiNaC::Digits = saved_digits;
        v.what = verdict::status::failed;
        v.samples = tested + 1;
        v.method = fmt::format("{} at a sampled point{}: {}", what,
                               where.empty() ? "" : fmt::format(" where {} hold", to_string(where)),
                               fmt::join(values, ", "));
        return v;
    };
    for (std::size_t attempt = 0; tested < sample_points && attempt < 50 * sample_points; ++attempt) {
        GiNaC::exmap point, rounded;
        // The last quarter of the points over twelve decades (draw_wide).
        const bool wide = tested >= sample_points * 3 / 4;
        for (const GiNaC::ex& s : free) {
            point[s] = exact(wide ? draw_wide(*symbols.domain_of(s), stream) : draw(*symbols.domain_of(s), stream));
            rounded[s] = point[s].evalf();
        }
        if (!where.empty() && !hold_at(where, point))
            continue;   // outside what the claim is said of
        GiNaC::numeric a, b;
        if (!evaluated(rounded, a, b)) {
            // Not a real number: again exactly, at twice the digits, before it is believed.
            GiNaC::Digits = 2 * sample_digits;
            const bool real = evaluated(point, a, b);
            GiNaC::Digits = sample_digits;
            if (!real)
                return refuted(point, "a side is undefined or not real");
        }
        if (!holds(a, b)) {
            if (!evaluated(point, a, b))
                return refuted(point, "a side is undefined or not real");
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
    }
    GiNaC::Digits = saved_digits;
    v.what = tested > 0 ? verdict::status::sampled : verdict::status::failed;
    v.samples = tested;
    v.method = tested > 0 ? fmt::format("not proven symbolically; holds at {} sampled points ({} digits)", tested,
                                        sample_digits)
                          : "no sampled point could be evaluated";
    return v;
}

// Within 1e-30 of each other, relative to the larger (or to 1): in GiNaC's numbers, not
// doubles, whose range ends at 1e308 (exp(exp(3)^2)^2 = 2*exp(2*exp(3)^2), both sides
// near 1e350, was sampled: an infinite scale let any two values through).
bool nearly_equal(const GiNaC::numeric& a, const GiNaC::numeric& b)
{
    const GiNaC::numeric scale = std::max({GiNaC::numeric(1), GiNaC::abs(a), GiNaC::abs(b)});
    return GiNaC::abs(a - b) <= scale / GiNaC::numeric(10).power(30);
}

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
        if (!given.where.empty() && !hold_at(given.where, point))
            continue;   // outside what the claim is said of
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

std::vector<GiNaC::numeric> simple_values(const domain& range)
{
    std::vector<GiNaC::numeric> candidates;
    if (range.what == domain::kind::interval) {
        // An end of π (Pi/2) as the double on its inside, exactly: the simplest rational near
        // that double may lie beyond π/2.
        const auto end = [](const GiNaC::ex& exact, double inside) {
            return exact.has(GiNaC::Pi) ? GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(inside))))
                                        : GiNaC::numeric(cln::rationalize(cln::cl_DF(inside)));
        };
        const GiNaC::numeric a = end(range.exact_lower(), range.lower);
        const GiNaC::numeric b = end(range.exact_upper(), range.upper);
        // 0 and +-1 too where they lie inside ((-1, 2]: exp(z^2) > 1 fails at 0 alone).
        candidates = {b, a, (a + b) / 2, (3 * a + b) / 4, (a + 3 * b) / 4, 0, 1, -1};
    } else {
        candidates = {1, 2, GiNaC::numeric(1, 2), 0, -1, 3, -2};
    }
    std::vector<GiNaC::numeric> inside;
    for (const GiNaC::numeric& x : candidates)
        if (range.contains(GiNaC::ex(x)) && std::find(inside.begin(), inside.end(), x) == inside.end())
            inside.push_back(x);
    return inside;
}

namespace {

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

    const bool strict = op == relation::less || op == relation::greater;
    const auto saved_digits = GiNaC::Digits;
    // The claim at a point of the free symbols: a counterexample where it fails.
    const auto tried_at = [&](const GiNaC::exmap& at) -> std::optional<counterexample> {
        counterexample x;
        for (const auto& entry : free)
            x.point.emplace_back(entry.first, at.at(entry.first));
        try {
            if (!in_domains(at) || (!given.where.empty() && !hold_at(given.where, at)))
                return std::nullopt;
            x.lhs = GiNaC::normal(a.subs(at, GiNaC::subs_options::no_pattern));
            x.rhs = GiNaC::normal(b.subs(at, GiNaC::subs_options::no_pattern));
            if (GiNaC::is_a<GiNaC::numeric>(x.lhs) && GiNaC::is_a<GiNaC::numeric>(x.rhs) &&
                GiNaC::ex_to<GiNaC::numeric>(x.lhs).is_rational() && GiNaC::ex_to<GiNaC::numeric>(x.rhs).is_rational()) {
                x.exact = true;
                if (fails(GiNaC::ex_to<GiNaC::numeric>(x.lhs), op, GiNaC::ex_to<GiNaC::numeric>(x.rhs), 0))
                    return x;
                return std::nullopt;
            }
            // Equal sides, radicals and all (at a root of the difference): a strict claim
            // fails, decided exactly.
            if (strict && GiNaC::normal(GiNaC::expand(x.lhs - x.rhs)).is_zero()) {
                x.exact = true;
                return x;
            }
            // Radicals: believed when 50 and 80 digits agree and the failure is far beyond
            // their rounding.
            bool believed = true;
            for (const int digits : {50, 80}) {
                GiNaC::Digits = digits;
                const GiNaC::ex le = GiNaC::evalf(x.lhs), re = GiNaC::evalf(x.rhs);
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
            if (believed)
                return x;
        } catch (const std::exception&) {
            GiNaC::Digits = saved_digits;   // a pole: another point
        }
        return std::nullopt;
    };
    uniform_stream stream(0x6c0e7e1a5b3d2f19ULL);
    std::optional<counterexample> found;
    for (std::size_t n = 0; n < points && !found; ++n) {
        GiNaC::exmap at;
        for (const auto& [symbol, values] : free) {
            const std::size_t k =
                n == 0 ? 0 : std::min(values.size() - 1, static_cast<std::size_t>(stream.next() * values.size()));
            at[symbol] = values[k];
        }
        found = tried_at(at);
    }
    // Then one symbol at a time, the others at their first, second and third simple values:
    // the points where its real roots say the difference may change sign (real_roots.cpp).
    if (op != relation::equal)
        for (std::size_t s = 0; s < free.size() && !found; ++s)
            for (std::size_t k = 0; k < (free.size() > 1 ? 3u : 1u) && !found; ++k) {
                const GiNaC::ex& symbol = free[s].first;
                GiNaC::exmap at;
                for (std::size_t t = 0; t < free.size(); ++t)
                    if (t != s)
                        at[free[t].first] = free[t].second[std::min(k, free[t].second.size() - 1)];
                std::vector<GiNaC::ex> values;
                try {
                    values = points_beside_roots((a - b).subs(at, GiNaC::subs_options::no_pattern), symbol,
                                                 given.domains.at(symbol));
                } catch (const std::exception&) {
                    continue;   // a pole at these values
                }
                for (std::size_t v = 0; v < values.size() && !found; ++v) {
                    at[symbol] = values[v];
                    found = tried_at(at);
                }
            }
    GiNaC::Digits = saved_digits;
    return found;
}

} // namespace impact::engine
