// Proving that two expressions are equal (prove_equal, prove_equivalent): over a common
// denominator without gcds, else by normal(), else two angles in [0, pi] by their cosines,
// else sampled (sampling.cpp); and a verdict in words.
#include "engine/prove/prove_internal.h"

#include "engine/prove/transcendental.h"

#include "engine/algebra/polynomial.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>

namespace impact::engine {

// `e` with its abbreviations replaced by their definitions, and those in the definitions
// in turn; an expression with none (or a derivation without any) is not walked again.
GiNaC::ex spelled_out(const GiNaC::ex& e, const GiNaC::exmap& abbreviations)
{
    if (abbreviations.empty())
        return e;
    // Symbols replaced, no pattern matched: the same result, without GiNaC's matching.
    const GiNaC::ex once = e.subs(abbreviations, GiNaC::subs_options::no_pattern);
    return once.is_equal(e) ? once : once.subs(abbreviations, GiNaC::subs_options::no_pattern);
}

namespace {

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
    v.typeset = {};
    return v;
}

} // namespace

std::string to_string(const verdict& v)
{
    const std::string where = v.where.empty() ? "" : ", where " + to_string(v.where);
    switch (v.what) {
    case verdict::status::proven: return "proven" + where;
    case verdict::status::sampled: return fmt::format("sampled ({} points){}", v.samples, where);
    case verdict::status::failed: break;
    }
    return "failed";
}

bool equal_as_written(const GiNaC::ex& lhs, const GiNaC::ex& rhs)
{
    return expand_numerator(lhs - rhs) == expansion::zero;
}

verdict prove_equal(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const symbol_table& symbols, proof_cache& run,
                    when_unproven otherwise, const std::vector<condition>& where, const assumptions* under)
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
    // sin, cos, tan, their hyperbolic kin, exp and log: decided (transcendental.h), under
    // the conditions the claim is said to hold under (log(p*q) splits where p, q > 0).
    if (auto decided = decide_transcendental(a, b, under ? *under : impact::engine::where(given, where)))
        return *decided;
    if (auto angles = prove_equal_angles(a, b, symbols, given))
        return *angles;
    if (otherwise == when_unproven::give_up) {
        verdict v;
        v.what = verdict::status::failed;
        v.residual = residual;
        v.method = "difference not proven zero (not sampled)";
        return v;
    }
    return sample(a, b, residual, symbols, nearly_equal, "=", where);
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
        v.typeset = {};
    }
    return v;
}

} // namespace impact::engine
