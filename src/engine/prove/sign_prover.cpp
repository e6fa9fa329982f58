// The sign of an expression from the declared domains, for all but sums (sign_of_sums.cpp):
// a number, a positive constant, a symbol by its domain, a product by its factors, a power
// by its base and exponent, a multiple of an abbreviation declared with a domain. What is
// worked out is remembered under the assumptions (bounded), and the effort of a try counted.
#include "engine/prove/sign_prover.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace impact::engine {

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

namespace {

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

} // namespace

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

// The sign of e and why, in a few words.
std::pair<sign_set, sign_reason> sign_prover::sign(const GiNaC::ex& e, int depth) const
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

std::pair<sign_set, sign_reason> sign_prover::decide(const GiNaC::ex& e, int depth) const
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
        if (name == "exp")
            return {{false, false, true}, "an exponential"};
        if (name == "cosh")
            return {{false, false, true}, "a hyperbolic cosine, >= 1"};
        if (auto known = function_sign(e, depth))
            return *known;
    }
    return {sign_set::any(), "not determined"};
}

std::pair<sign_set, sign_reason> sign_prover::power_sign(const GiNaC::ex& e, int depth) const
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
    } else if (n.is_rational()) {
        // GiNaC's principal root x^(p/q), q odd, is real only where x >= 0 (the condition
        // that it is defined, engine/prove/definedness.h), and there it is >= 0.
        r = {false, b.zero, b.positive || b.negative};
        why = "a real root";
    } else {
        return {sign_set::any(), "a fractional power"};
    }
    if (n.is_negative())
        r = reciprocal(r);
    return {r, why};
}

// A constant multiple c of an abbreviation declared with a domain: the domain's sign,
// times c's.
std::optional<std::pair<sign_set, sign_reason>> sign_prover::assumed_sign(const GiNaC::ex& e) const
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

// The symbols with a domain, in the order of their names (GiNaC's order of symbols
// differs between runs, and the argument a proof takes must not).
std::vector<std::pair<GiNaC::ex, const domain*>> sign_prover::by_name() const
{
    std::vector<std::pair<GiNaC::ex, const domain*>> all;
    for (const auto& [s, d] : domains_)
        all.emplace_back(s, &d);
    std::sort(all.begin(), all.end(), [this](const auto& a, const auto& b) { return text(a.first) < text(b.first); });
    return all;
}

GiNaC::ex sign_prover::factored(const GiNaC::ex& e) const
{
    const GiNaC::ex nd = GiNaC::normal(e).numer_denom();
    return factored_in(nd.op(0), given_) / factored_in(nd.op(1), given_);
}

} // namespace impact::engine
