#include "engine/prove/sign.h"

#include "engine/expr/infix.h"
#include "engine/algebra/polynomial.h"
#include "engine/prove/sign_arguments.h"

#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sstream>

namespace impact::engine {
namespace {

// The exact rational value of a bound written in a derivation file.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

sign_set times(const sign_set& a, const sign_set& b)
{
    sign_set r;
    r.zero = a.zero || b.zero;
    r.positive = (a.positive && b.positive) || (a.negative && b.negative);
    r.negative = (a.positive && b.negative) || (a.negative && b.positive);
    return r;
}

sign_set plus(const sign_set& a, const sign_set& b)
{
    sign_set r;
    r.positive = a.positive || b.positive;
    r.negative = a.negative || b.negative;
    r.zero = (a.zero && b.zero) || (a.positive && b.negative) || (a.negative && b.positive);
    return r;
}

// 1/x: the same signs, never zero (a denominator is non-zero wherever it is defined).
sign_set reciprocal(const sign_set& a)
{
    return {a.negative, false, a.positive};
}

sign_set of_domain(const domain& d)
{
    switch (d.what) {
    case domain::kind::real: return sign_set::any();
    case domain::kind::positive: return {false, false, true};
    case domain::kind::nonnegative: return {false, true, true};
    case domain::kind::interval: break;
    }
    sign_set r;
    r.negative = d.lower < 0;
    r.positive = d.upper > 0;
    r.zero = (d.lower < 0 || (d.lower == 0 && !d.lower_open)) && (d.upper > 0 || (d.upper == 0 && !d.upper_open));
    return r;
}

// factor_polynomial, with the run's factors where the assumptions come with a run. A
// polynomial too long to factor has the abbreviations of declared sign that divide it
// taken out first (s_n^2 from the hundreds of terms a bound on sliding leaves), and what
// is left factored: exact division by a short polynomial costs little.
GiNaC::ex factored_in(const GiNaC::ex& e, const assumptions& given)
{
    const GiNaC::ex f = given.run ? factor_polynomial(e, *given.run) : factor_polynomial(e);
    if (!f.is_equal(e) || given.assumed.empty() || has_radical(e) || !e.info(GiNaC::info_flags::rational_polynomial))
        return f;
    GiNaC::ex rest = GiNaC::expand(e);
    if (!GiNaC::is_a<GiNaC::add>(rest))
        return f;
    GiNaC::ex taken = 1;
    for (const assumptions::assumed_sign& a : given.assumed) {
        if (!GiNaC::is_a<GiNaC::add>(a.definition) || !a.definition.info(GiNaC::info_flags::rational_polynomial))
            continue;
        GiNaC::ex quotient;
        while (GiNaC::is_a<GiNaC::add>(rest) && GiNaC::divide(rest, a.definition, quotient)) {
            rest = GiNaC::expand(quotient);
            taken *= a.definition;
        }
    }
    if (taken.is_equal(1))
        return f;
    return taken * factored_in(rest, given);
}

} // namespace

std::optional<std::pair<GiNaC::numeric, const assumptions::assumed_sign*>> assumed_multiple(const GiNaC::ex& e,
                                                                                           const assumptions& given)
{
    if (given.assumed.empty())
        return std::nullopt;
    if (GiNaC::is_a<GiNaC::power>(e)) {   // a root: d = sqrt(r.r), declared positive
        for (const assumptions::assumed_sign& a : given.assumed)
            if (GiNaC::is_a<GiNaC::power>(a.definition) && a.definition.op(1).is_equal(e.op(1)) &&
                GiNaC::expand(e.op(0)).is_equal(a.definition.op(0)))
                return std::make_pair(GiNaC::numeric(1), &a);
        return std::nullopt;
    }
    const GiNaC::ex terms = GiNaC::expand(e);
    if (!GiNaC::is_a<GiNaC::add>(terms))
        return std::nullopt;
    for (const assumptions::assumed_sign& a : given.assumed) {
        if (!GiNaC::is_a<GiNaC::add>(a.definition) || a.definition.nops() != terms.nops())
            continue;
        // c from the first term and the definition's term of the same symbols.
        for (std::size_t i = 0; i < a.definition.nops(); ++i) {
            const GiNaC::ex ratio = terms.op(0) / a.definition.op(i);
            if (!GiNaC::is_a<GiNaC::numeric>(ratio) || !GiNaC::ex_to<GiNaC::numeric>(ratio).is_real())
                continue;
            if (GiNaC::expand(terms - ratio * a.definition).is_zero())
                return std::make_pair(GiNaC::ex_to<GiNaC::numeric>(ratio), &a);
            break;
        }
    }
    return std::nullopt;
}

namespace {

class sign_prover {
public:
    explicit sign_prover(const assumptions& given) : given_(given), domains_(given.domains) {}

    std::string text(const GiNaC::ex& e) const { return given_.text(e); }

    // The sign of e and why, in a few words.
    std::pair<sign_set, sign_reason> sign(const GiNaC::ex& e, int depth = 0) const
    {
        auto& signs = given_.known->signs;
        const auto known = signs.find(e);
        if (known != signs.end())
            return known->second;
        if (given_.effort) {
            if (*given_.effort == 0)
                return {sign_set::any(), "not worked out within the effort of a try"};
            --*given_.effort;
        }
        auto decided = decide(e, depth);
        if (given_.effort && *given_.effort == 0)
            return decided;   // perhaps cut short: not remembered
        if (signs.size() >= 4096)  // bounded, as the factor cache
            signs.clear();
        signs.emplace(e, decided);
        return decided;
    }

private:
    std::pair<sign_set, sign_reason> decide(const GiNaC::ex& e, int depth) const
    {
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (!n.is_real())
                return {sign_set::any(), "not a real number"};
            return {sign_set::exactly(n.is_zero() ? 0 : n.is_positive() ? 1 : -1), "a number"};
        }
        // Pi and GiNaC's other constants: positive ones say so.
        if (GiNaC::is_a<GiNaC::constant>(e) && e.info(GiNaC::info_flags::positive))
            return {sign_set::exactly(1), "a positive constant"};
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            const auto found = domains_.find(e);
            if (found == domains_.end())
                return {sign_set::any(), "no declared domain"};
            sign_reason why(fmt::format("{} in {}", text(e), found->second.to_string()));
            why.declared = e;
            why.domain = found->second.to_string();
            return {of_domain(found->second), why};
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            sign_set r = sign_set::exactly(1);
            for (std::size_t i = 0; i < e.nops(); ++i)
                r = times(r, sign(e.op(i), depth).first);
            return {r, "a product of factors of known sign"};
        }
        if (GiNaC::is_a<GiNaC::power>(e)) {
            if (auto assumed = assumed_sign(e))
                return *assumed;
            return power_sign(e, depth);
        }
        if (GiNaC::is_a<GiNaC::add>(e))
            return sum_sign(e, depth);
        if (GiNaC::is_a<GiNaC::function>(e)) {
            const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
            if (name == "abs")
                return {{false, true, true}, "an absolute value"};
            if (name == "acos")
                return {{false, true, true}, "an arccosine, in [0, pi]"};
        }
        return {sign_set::any(), "not determined"};
    }

    std::pair<sign_set, sign_reason> power_sign(const GiNaC::ex& e, int depth) const
    {
        const GiNaC::ex base = e.op(0);
        const GiNaC::ex exponent = e.op(1);
        if (!GiNaC::is_a<GiNaC::numeric>(exponent))
            return {sign_set::any(), "a power with a symbolic exponent"};
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        const sign_set b = sign(base, depth).first;
        sign_set r;
        sign_reason why;
        if (n.is_even()) {
            r = {false, b.zero, b.negative || b.positive};
            why = "an even power";
        } else if (n.is_integer()) {
            r = b;
            why = "an odd power";
        } else if (n.is_rational() && n.denom().is_even()) {
            // A real root: x^(p/2q) >= 0.
            r = {false, b.zero, b.positive || b.negative};
            why = "a square root";
        } else {
            return {sign_set::any(), "a fractional power"};
        }
        if (n.is_negative())
            r = reciprocal(r);
        return {r, why};
    }

    // A constant multiple c of an abbreviation declared with a domain: the domain's sign,
    // times c's.
    std::optional<std::pair<sign_set, sign_reason>> assumed_sign(const GiNaC::ex& e) const
    {
        const auto multiple = assumed_multiple(e, given_);
        if (!multiple)
            return std::nullopt;
        const auto& [c, a] = *multiple;
        const sign_set of = of_domain(a->range);
        const sign_set s = c.is_positive() ? of : sign_set{of.positive, of.zero, of.negative};
        sign_reason why(fmt::format("{} with {} assumed {}", text(c * a->symbol), text(a->symbol),
                                    a->range.to_string()));
        why.typeset.math(c * a->symbol).say(", with ");
        if (a->range.what == domain::kind::positive && !a->range.infinity_included)
            why.typeset.states(a->symbol, relation::greater, 0).say(" assumed");
        else
            why.typeset.math(a->symbol).say(" assumed " + a->range.to_string());
        return std::make_pair(s, why);
    }

    std::pair<sign_set, sign_reason> sum_sign(const GiNaC::ex& e, int depth) const
    {
        sign_set r = sign_set::exactly(0);
        std::vector<sign_set> terms;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            terms.push_back(sign(e.op(i), depth).first);
            r = plus(r, terms.back());
        }
        if (r.is_known())
            return {r, "a sum of terms of one sign"};
        if (auto assumed = assumed_sign(e))
            return *assumed;

        if (auto linear = linear_in_bounded_symbol(e))
            return *linear;
        if (auto affine = affine_in_bounded_symbol(e, depth))
            return *affine;
        if (auto argued = argued_sign(e, depth))
            return *argued;
        const bool radical = has_radical(e);

        // A sum without a radical that factors (one that came here as a factor of a product
        // with a radical, which is not factored whole: sqrt(k) (a^2 - 2 a b + b^2)): the
        // signs of its factors.
        if (!radical && depth < 3) {
            const GiNaC::ex f = factored(e);
            if (!f.is_equal(e) && (GiNaC::is_a<GiNaC::mul>(f) || GiNaC::is_a<GiNaC::power>(f))) {
                const auto [s, why] = sign(f, depth + 1);
                if (s.is_known()) {
                    sign_reason reason(fmt::format("factored, {} {} ({})", text(f), s.describe(), why.words));
                    reason.typeset.say("factored, ").math(f).say(s.negative ? (s.zero ? ", which is not positive"
                                                                                      : ", which is negative")
                                                                            : (s.zero ? ", which is not negative"
                                                                                      : ", which is positive"));
                    return {s, reason};
                }
            }
        }
        // A - B with A, B >= 0 has the sign of A^2 - B^2, which has no radical where A - B
        // had one. The terms with radicals form one side and the rest the other (each
        // factored to find its sign), or else the terms are grouped by their own signs.
        // Without a radical it gains nothing: the sum is factored (above, or before it came
        // here), and A^2 - B^2 factors back into A - B and A + B, the question asked again.
        // Expanding and factoring it was most of the time of the sign proofs of rough
        // spheres with Coulomb's cases (factor() on 33 to 39 terms, 0.15 to 0.25 s each,
        // seventy times).
        if (depth < 3 && radical) {
            GiNaC::ex a = 0, b = 0;
            GiNaC::ex radicals = 0, rest = 0;
            for (std::size_t i = 0; i < e.nops(); ++i)
                (has_radical(e.op(i)) ? radicals : rest) += e.op(i);
            const sign_set of_radicals = sign(factored(radicals), depth + 1).first;
            const sign_set of_rest = sign(factored(rest), depth + 1).first;
            if (!radicals.is_zero() && !rest.is_zero() && !of_radicals.negative && !of_rest.positive) {
                a = radicals;
                b = -rest;
            } else if (!radicals.is_zero() && !rest.is_zero() && !of_radicals.positive && !of_rest.negative) {
                a = rest;
                b = -radicals;
            } else {
                for (std::size_t i = 0; i < e.nops(); ++i) {
                    if (!terms[i].negative) {
                        a += e.op(i);
                    } else if (!terms[i].positive) {
                        b -= e.op(i);
                    } else {
                        a = b = 0;   // a term of unknown sign: no A - B
                        break;
                    }
                }
            }
            const GiNaC::ex difference =
                a.is_zero() && b.is_zero() ? GiNaC::ex(0) : GiNaC::normal(GiNaC::expand(a * a - b * b));
            const auto [squares, why] =
                difference.is_zero() ? std::make_pair(sign_set::any(), sign_reason()) : sign(factored(difference), depth + 1);
            if (squares.is_known()) {
                sign_set s;
                s.positive = squares.positive;
                s.negative = squares.negative;
                s.zero = squares.zero;
                sign_reason reason(fmt::format("A - B with A, B >= 0 and A^2 - B^2 = {} {}",
                                               text(factored(difference)), squares.describe()));
                reason.typeset.say("a difference of non-negative terms whose squares differ by ")
                    .math(factored(difference))
                    .say(squares.negative ? ", which is negative"
                         : squares.zero   ? ", which is not negative"
                                          : ", which is positive");
                return {s, reason};
            }
        }
        return {r, "a sum of terms of unknown sign"};
    }

    // An argument about one symbol (sign_arguments.h): Sturm's theorem for a
    // polynomial in one symbol alone, else monotonicity in a symbol bounded below.
    std::optional<std::pair<sign_set, sign_reason>> argued_sign(const GiNaC::ex& e, int depth) const
    {
        if (depth > 6)
            return std::nullopt;
        const auto write = [this](const GiNaC::ex& x) { return text(x); };
        std::vector<std::pair<GiNaC::ex, const domain*>> in;
        for (const auto& [s, d] : by_name())
            if (e.has(s))
                in.emplace_back(s, d);
        if (in.size() == 1)
            if (auto sturm = sturm_sign(e, in.front().first, *in.front().second, write))
                return sturm;
        // Trying every symbol, and again for each slope, grows as the symbols' count to the
        // depth: kept to short polynomials in a few symbols (in ten, it ran for half an hour).
        if (depth > 2 || in.size() > 4 || (GiNaC::is_a<GiNaC::add>(e) && e.nops() > 24))
            return std::nullopt;
        for (const auto& [s, d] : in) {
            auto monotone = monotone_sign(
                e, s, *d, [&](const GiNaC::ex& x) { return sign(factored(x), depth + 1); }, write);
            if (monotone)
                return monotone;
        }
        return std::nullopt;
    }

    // A polynomial of degree one in a symbol s with an interval domain, or in s^2 (no odd
    // power of s), whatever its other symbols: for each value of those it is an affine
    // function of s (of s^2) and lies between its values at the ends of the range of s
    // (of s^2: [0, max(lower^2, upper^2)] when the interval holds 0), so the signs at
    // those ends settle its sign (1 - b^2 >= 0 on [-1, 1]: 1 at b = 0 and 0 at b = 1).
    std::optional<std::pair<sign_set, sign_reason>> affine_in_bounded_symbol(const GiNaC::ex& e, int depth) const
    {
        if (depth > 6)
            return std::nullopt;
        std::optional<GiNaC::ex> expanded;   // once, for the first symbol that may do
        for (const auto& [s, range] : by_name()) {
            const domain& d = *range;
            if (d.what != domain::kind::interval || !e.has(s) || !e.is_polynomial(s))
                continue;
            if (!expanded)
                expanded = GiNaC::expand(e);
            const GiNaC::ex& p = *expanded;
            const int degree = p.degree(s);
            const bool squared = degree == 2 && p.coeff(s, 1).is_zero();
            if (degree != 1 && !squared)
                continue;
            const GiNaC::numeric low = exact(d.lower), high = exact(d.upper);
            std::vector<GiNaC::numeric> ends = {low, high};
            if (squared && !low.is_positive() && !high.is_negative())
                ends = {0, GiNaC::abs(low) > GiNaC::abs(high) ? low : high};
            sign_set r{false, false, false};
            std::vector<std::string> at;
            finding typeset;
            typeset.say(squared ? "affine in " : "linear in ").math(squared ? GiNaC::pow(s, 2) : s);
            typeset.say(", so between its values at the ends of the domain of ").math(s).say(": ");
            bool known = true;
            for (const GiNaC::numeric& end : ends) {
                const GiNaC::ex value = factored(p.subs(s == end));
                const auto [sign_at, why] = sign(value, depth + 1);
                known = known && sign_at.is_known();
                if (!known || (r.negative && sign_at.positive) || (r.positive && sign_at.negative)) {
                    known = false;   // the other end is not worked out: this symbol settles nothing
                    break;
                }
                r.negative = r.negative || sign_at.negative;
                r.positive = r.positive || sign_at.positive;
                r.zero = r.zero || sign_at.zero;
                at.push_back(fmt::format("{} {} at {} = {}", text(value), sign_at.describe(), text(s), text(end)));
                if (&end != &ends.front())
                    typeset.say(" and ");
                typeset.math(value).say(sign_at.negative ? (sign_at.zero ? " is not positive" : " is negative")
                                                         : (sign_at.zero ? " is not negative" : " is positive"));
                typeset.say(" at ").math(s == end);
            }
            if (!known || (r.negative && r.positive))
                continue;
            sign_reason reason(fmt::format("{}, {} in {}, between its values at the ends: {}",
                                           squared ? "affine in " + text(GiNaC::pow(s, 2)) : "linear in " + text(s),
                                           text(s), d.to_string(), fmt::format("{}", fmt::join(at, " and "))));
            reason.typeset = typeset;
            return std::make_pair(r, reason);
        }
        return std::nullopt;
    }

    // A polynomial of degree one in a single symbol with an interval domain takes its
    // extremes at the ends of the interval.
    std::optional<std::pair<sign_set, sign_reason>> linear_in_bounded_symbol(const GiNaC::ex& e) const
    {
        GiNaC::ex only;
        int count = 0;
        for (const auto& [symbol, range] : domains_) {
            if (e.has(symbol)) {
                only = symbol;
                ++count;
            }
        }
        if (count != 1)
            return std::nullopt;
        const domain& d = domains_.at(only);
        if (d.what != domain::kind::interval || !e.is_polynomial(only) || e.degree(only) != 1)
            return std::nullopt;
        // The values fill the interval between the values at the two ends; an end that
        // the domain excludes is approached but not attained.
        const GiNaC::ex low = e.subs(only == exact(d.lower));
        const GiNaC::ex high = e.subs(only == exact(d.upper));
        if (!GiNaC::is_a<GiNaC::numeric>(low) || !GiNaC::is_a<GiNaC::numeric>(high))
            return std::nullopt;
        const double lo = GiNaC::ex_to<GiNaC::numeric>(low).to_double();
        const double hi = GiNaC::ex_to<GiNaC::numeric>(high).to_double();
        const double least = std::min(lo, hi), most = std::max(lo, hi);
        const bool least_open = lo <= hi ? d.lower_open : d.upper_open;
        const bool most_open = lo <= hi ? d.upper_open : d.lower_open;
        sign_set r;
        r.negative = least < 0;
        r.positive = most > 0;
        r.zero = (least < 0 && most > 0) || (least == 0 && !least_open) || (most == 0 && !most_open);
        sign_reason reason(fmt::format("linear in {} in {}: {} and {} at the ends", text(only), d.to_string(),
                                       text(low), text(high)));
        reason.typeset.say("linear in ").math(only).say(", ").math(low).say(" and ").math(high).say(
            " at the ends of its domain");
        return std::make_pair(r, reason);
    }

    // The symbols with a domain, in the order of their names (GiNaC's order of symbols
    // differs between runs, and the argument a proof takes must not).
    std::vector<std::pair<GiNaC::ex, const domain*>> by_name() const
    {
        std::vector<std::pair<GiNaC::ex, const domain*>> all;
        for (const auto& [s, d] : domains_)
            all.emplace_back(s, &d);
        std::sort(all.begin(), all.end(), [this](const auto& a, const auto& b) { return text(a.first) < text(b.first); });
        return all;
    }

    GiNaC::ex factored(const GiNaC::ex& e) const
    {
        const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
        return factored_in(nd.op(0), given_) / factored_in(nd.op(1), given_);
    }

    const assumptions& given_;
    const domain_map& domains_;
};

} // namespace

assumptions with_effort(const assumptions& given, std::size_t signs)
{
    assumptions trial = given;
    trial.effort = std::make_shared<std::size_t>(signs);
    return trial;
}

namespace {

// factor() cannot be interrupted: on the rough-sphere energy it ran for minutes at 120
// terms in some runs (GiNaC's order of terms differs between runs), and polynomials of 29
// to 38 terms in ten symbols took 2 to 10 s each (the energy of rough spheres claimed to
// fall with no identity for it checked first, which the fuzzer found: a minute in all,
// against half a second now). A longer polynomial is left as it is, its sign settled by
// another argument (prove_inequality_through) or sampled. Nothing in derivations/ or in
// the draft of rough spheres in space factors a longer one to be proven.
constexpr std::size_t most_terms_factored = 28;

bool worth_factoring(const GiNaC::ex& e)
{
    if (has_radical(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e))
        return false;
    const GiNaC::ex expanded = GiNaC::expand(e);
    return !GiNaC::is_a<GiNaC::add>(expanded) || expanded.nops() <= most_terms_factored;
}

// factor()'s result with each factor a flat sum: factor() may leave a factor partly
// collected (t*(a^2 + b^2) + 2*a*v for t*a^2 + t*b^2 + 2*a*v), one way or the other
// depending on GiNaC's order of terms, which changes from run to run.
GiNaC::ex flattened(const GiNaC::ex& f)
{
    if (GiNaC::is_a<GiNaC::add>(f))
        return GiNaC::expand(f);
    if (GiNaC::is_a<GiNaC::mul>(f) || (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::integer))) {
        struct each : GiNaC::map_function {
            GiNaC::ex operator()(const GiNaC::ex& part) override { return flattened(part); }
        } flatten;
        return f.map(flatten);
    }
    return f;
}

} // namespace

// factor() on a polynomial; an expression with radicals is left as it is, since
// factoring under a root may pull out -1 and leave I behind.
GiNaC::ex factor_polynomial(const GiNaC::ex& e)
{
    return worth_factoring(e) ? flattened(factor_reproducibly(e)) : e;
}

GiNaC::ex factor_polynomial(const GiNaC::ex& e, proof_cache& run)
{
    if (has_radical(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e))
        return e;
    // factor() is the engine's most expensive call and meets the same polynomials again
    // and again (in sign proofs, in radicals, in each step's simplification).
    auto& factored = run.factored;
    const auto known = factored.find(e);
    if (known != factored.end())
        return known->second;
    const bool worth = worth_factoring(e);
    const GiNaC::ex f = worth ? flattened(factor_reproducibly(e)) : e;
    if (factored.size() >= 4096)  // bounded: a long run (the fuzzer) meets ever new polynomials
        factored.clear();
    factored.emplace(e, f);
    // Its factors are irreducible: asked again (a sign proof asks of each factor), each is
    // its own factorization, not another call of factor().
    if (worth && !f.is_equal(e)) {
        const auto irreducible = [&factored](const GiNaC::ex& part) {
            const GiNaC::ex base = GiNaC::is_a<GiNaC::power>(part) ? part.op(0) : part;
            if (GiNaC::is_a<GiNaC::add>(base))
                factored.emplace(base, base);
        };
        if (GiNaC::is_a<GiNaC::mul>(f))
            for (const GiNaC::ex& part : f)
                irreducible(part);
        else
            irreducible(f);
    }
    return f;
}

bool proof_cache::empty() const
{
    return factored.empty() && declared->signs.empty() && declared->radicals.empty();
}

sign_set sign_set::exactly(int sign)
{
    return {sign < 0, sign == 0, sign > 0};
}

std::string sign_set::describe() const
{
    if (!negative && !zero && positive)
        return "> 0";
    if (!negative && zero && positive)
        return ">= 0";
    if (!negative && zero && !positive)
        return "= 0";
    if (negative && zero && !positive)
        return "<= 0";
    if (negative && !zero && !positive)
        return "< 0";
    if (!negative && !zero && !positive)
        return "undefined";
    return "of unknown sign";
}

std::string assumptions::text(const GiNaC::ex& e) const
{
    return ginac_syntax(e, order);
}

assumptions declared_assumptions(const symbol_table& symbols, proof_cache& run)
{
    // Under the declared domains the sign of an expression never changes, and GiNaC's
    // symbols are never reused (each has its own serial number), so what is worked out
    // serves every derivation of the run. Narrowed domains (a check's `assuming`) need
    // their own.
    assumptions given{{}, declaration_order(symbols), run.declared, &run};
    for (const quantity& q : symbols.all()) {
        if (!q.definition) {
            given.domains[q.symbol] = q.range;
            continue;
        }
        if (q.range.what == domain::kind::real)
            continue;
        // The definition in the inputs (an abbreviation may be written with others),
        // expanded; a root's radicand expanded under it, as assumed_multiple compares it.
        const GiNaC::ex inputs = symbols.in_inputs(*q.definition);
        given.assumed.push_back({q.symbol,
                                 GiNaC::is_a<GiNaC::power>(inputs) ? GiNaC::pow(GiNaC::expand(inputs.op(0)), inputs.op(1))
                                                                   : GiNaC::expand(inputs),
                                 q.range});
    }
    return given;
}

sign_proof prove_sign(const GiNaC::ex& e, const assumptions& given)
{
    const sign_prover prover(given);
    sign_proof proof;
    // The factored form, factor by factor: the proof a reader can follow.
    const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
    std::vector<std::pair<GiNaC::ex, bool>> factors;  // factor, in the denominator
    for (int part = 0; part < 2; ++part) {
        const GiNaC::ex f = factored_in(nd.op(part), given);
        if (GiNaC::is_a<GiNaC::mul>(f)) {
            for (std::size_t i = 0; i < f.nops(); ++i)
                factors.emplace_back(f.op(i), part == 1);
        } else if (!(part == 1 && f.is_equal(1))) {
            factors.emplace_back(f, part == 1);
        }
    }
    // Listed in print order, numerator first: the proof reads the same on every run.
    std::sort(factors.begin(), factors.end(), [&](const auto& a, const auto& b) {
        if (a.second != b.second)
            return b.second;
        return given.order.before(a.first, b.first);
    });
    proof.sign = sign_set::exactly(1);
    for (const auto& [factor, below] : factors) {
        const auto [s, why] = prover.sign(factor);
        const sign_set used = below ? reciprocal(s) : s;
        proof.sign = times(proof.sign, used);
        proof.steps.push_back({below ? 1 / factor : factor, used, why,
                               below ? fmt::format("1/({}) {} ({})", given.text(factor), used.describe(), why.words)
                                     : fmt::format("{} {} ({})", given.text(factor), used.describe(), why.words)});
    }
    if (!proof.sign.is_known()) {
        // The whole expression may still have a provable sign where its factors do not.
        const auto [s, why] = prover.sign(e);
        if (s.is_known()) {
            proof.sign = s;
            proof.steps = {{e, s, why, fmt::format("{} {} ({})", given.text(e), s.describe(), why.words)}};
        }
    }
    return proof;
}

namespace {

// simplify_radicals, for an expression with radicals.
GiNaC::ex take_out_radicals(const GiNaC::ex& e, const assumptions& given)
{
    struct inner : GiNaC::map_function {
        const assumptions& given;
        explicit inner(const assumptions& g) : given(g) {}
        GiNaC::ex operator()(const GiNaC::ex& part) override { return simplify_radicals(part, given); }
    } recurse(given);
    const GiNaC::ex mapped = e.map(recurse);
    if (!GiNaC::is_a<GiNaC::power>(mapped) || !GiNaC::is_a<GiNaC::numeric>(mapped.op(1)))
        return mapped;
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(mapped.op(1));
    if (n != GiNaC::numeric(1, 2) && n != GiNaC::numeric(-1, 2))
        return mapped;
    // sqrt(f^2 g) = |f| sqrt(g), and |f| = ±f where the sign of f is proven.
    const sign_prover prover(given);
    const GiNaC::ex nd = GiNaC::normal(mapped.op(0)).numer_denom();
    GiNaC::exvector parts;
    for (int part = 0; part < 2; ++part) {
        const GiNaC::ex f = factored_in(nd.op(part), given);
        const int direction = part == 0 ? 1 : -1;
        if (GiNaC::is_a<GiNaC::mul>(f)) {
            for (const GiNaC::ex& g : f)
                parts.push_back(GiNaC::pow(g, direction));
        } else {
            parts.push_back(GiNaC::pow(f, direction));
        }
    }
    // A negative number among the factors is paired with a sum, whose sign it takes:
    // sqrt(-1/(t^2 - 4)) is sqrt(1/(4 - t^2)), never I*sqrt(1/(t^2 - 4)).
    GiNaC::numeric number = 1;
    for (GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::numeric>(f)) {
            number *= GiNaC::ex_to<GiNaC::numeric>(f);
            f = 1;
        }
    }
    if (number.is_negative()) {
        for (GiNaC::ex& f : parts) {
            const bool odd_sum = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::add>(f.op(0)) &&
                                 f.op(1).info(GiNaC::info_flags::odd);
            if (odd_sum || GiNaC::is_a<GiNaC::add>(f)) {
                f = odd_sum ? GiNaC::pow(term_order::negated_sum(f.op(0)), f.op(1)) : term_order::negated_sum(f);
                number = -number;
                break;
            }
        }
    }
    parts.push_back(number);
    GiNaC::ex outside = 1, inside = 1;
    for (const GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::even)) {
            const sign_set s = prover.sign(f.op(0)).first;
            if (!s.negative) {
                outside *= GiNaC::pow(f.op(0), f.op(1) / 2);
                continue;
            }
            if (!s.positive) {
                outside *= GiNaC::pow(-f.op(0), f.op(1) / 2);
                continue;
            }
        }
        inside *= f;
    }
    // sqrt(N/D) = sqrt(N)/sqrt(D) where D > 0: one form for every radical of a quotient,
    // whichever GiNaC's normal() happened to return.
    const GiNaC::ex inside_nd = GiNaC::normal(inside).numer_denom();
    GiNaC::ex root = GiNaC::sqrt(inside);
    if (!inside_nd.op(1).is_equal(1)) {
        const sign_set below = prover.sign(factored_in(inside_nd.op(1), given)).first;
        if (!below.negative && !below.zero)
            root = GiNaC::sqrt(inside_nd.op(0)) / GiNaC::sqrt(inside_nd.op(1));
        else if (outside.is_equal(1))
            return mapped;
    } else if (outside.is_equal(1)) {
        return mapped;
    }
    return n.is_positive() ? outside * root : 1 / (outside * root);
}

} // namespace

GiNaC::ex simplify_radicals(const GiNaC::ex& e, const assumptions& given)
{
    if (!has_radical(e))
        return e;
    // The same radicals meet again in every proof of a derivation: kept, bounded as the
    // sign cache.
    auto& radicals = given.known->radicals;
    const auto known = radicals.find(e);
    if (known != radicals.end())
        return known->second;
    const GiNaC::ex simplified = take_out_radicals(e, given);
    if (radicals.size() >= 4096)
        radicals.clear();
    radicals.emplace(e, simplified);
    return simplified;
}

GiNaC::ex expanded_radicands(const GiNaC::ex& e)
{
    struct expand_under : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& part) override
        {
            if (GiNaC::is_a<GiNaC::power>(part) && !part.op(1).info(GiNaC::info_flags::integer))
                return GiNaC::pow(GiNaC::expand((*this)(part.op(0))), part.op(1));
            return part.map(*this);
        }
    } expand;
    return expand(e);
}

} // namespace impact::engine
