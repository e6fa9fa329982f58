#include "engine/prove/limit.h"

#include "engine/algebra/polynomial.h"
#include "engine/expr/normal_form.h"

#include <fmt/format.h>

namespace impact::engine {
namespace {

// By substitution, when the denominator at the point is proven non-zero.
std::optional<limit_result> by_substitution(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                            const assumptions& given)
{
    GiNaC::ex at, denominator;
    try {
        // Written once, its denominator with it: normal() alone leaves S sqrt(S) - S^(3/2)
        // and (w S)/S as they stand in one order of GiNaC's terms and cancels them in another,
        // and numer_denom() would give the denominator the sign that order chooses.
        const auto [numer, denom] =
            unique_numer_denom(simplify_radicals(GiNaC::normal(e).subs(symbol == point), given), given.order);
        at = numer / denom;
        denominator = denom;
    } catch (const std::exception&) {
        return std::nullopt;
    }
    const sign_proof nonzero = prove_sign(denominator, given);
    if (nonzero.sign.zero || at.has(symbol))
        return std::nullopt;
    limit_result r;
    r.value = at;
    r.how.how = limit_method::kind::substitution;
    r.how.symbol = symbol;
    r.how.point = point;
    r.how.denominator = denominator;
    r.how.denominator_sign = nonzero.sign;
    r.method = fmt::format("by substitution: continuous there, its denominator {} being {}", given.text(denominator),
                           nonzero.sign.describe());
    return r;
}

// The leading term of the series in (symbol - point).
// `finite_only`: an infinite limit is given up at once, its sign not proven.
std::optional<limit_result> by_series(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                      const assumptions& given, bool finite_only)
{
    try {
        const GiNaC::ex s = GiNaC::series(simplify_radicals(e, given), symbol == point, 3);
        const GiNaC::pseries& p = GiNaC::ex_to<GiNaC::pseries>(s);
        {
            const int order = p.ldegree(symbol);
            const GiNaC::ex coefficient = normal_written_once(p.coeff(symbol, order), given.order);
            limit_result r;
            if (order > 0) {
                r.value = 0;
            } else if (order == 0) {
                r.value = coefficient;
            } else {
                if (finite_only)
                    return std::nullopt;
                const sign_proof sign = prove_sign(coefficient, given);
                if (!sign.sign.is_known() || sign.sign.zero)
                    return std::nullopt;
                r.value = sign.sign.positive ? 1 : -1;
                r.infinite = true;
            }
            r.how.how = limit_method::kind::series;
            r.how.symbol = symbol;
            r.how.point = point;
            r.how.coefficient = coefficient;
            r.how.order = order;
            r.method = fmt::format("leading term of the series in {} - {}: {}*({} - {})^{}", given.text(symbol),
                                   given.text(point), given.text(coefficient), given.text(symbol), given.text(point),
                                   order);
            return r;
        }
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

} // namespace

namespace {

// `finite_only`: a value and no more, none when infinite (see finite_limit_at_infinity).
std::optional<limit_result> find_limit(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                       bool to_infinity, const assumptions& given, bool finite_only = false)
{
    if (!to_infinity) {
        if (auto r = by_substitution(e, symbol, point, given))
            return r;
        return by_series(e, symbol, point, given, finite_only);
    }
    // s → ∞: s = 1/t with t → 0⁺, a t of this limit's own: a t shared by every limit
    // would be newer than the symbols of the first derivation and older than those of
    // the next, so that GiNaC's order of terms would depend on what ran before.
    const GiNaC::possymbol t("t");
    assumptions with_t = given;
    with_t.domains[t] = domain{domain::kind::positive};
    // Zero wherever it is defined (a law that holds at every mass, which a fixed sphere's check
    // claims in the limit): its numerator over the product of its denominators, radicals as
    // variables, expands to zero, and so would normal()'s of the expression in t. That normal()
    // took most of a rough contact's limit in space (2 s for one case's 150 000 characters).
    const bool zero = expand_numerator(e) == expansion::zero;
    const GiNaC::ex in_t = zero ? GiNaC::ex(0) : simplify_radicals(GiNaC::normal(e.subs(symbol == 1 / t)), with_t);
    std::optional<limit_result> r = by_substitution(in_t, t, 0, with_t);
    if (!r)
        r = by_series(in_t, t, 0, with_t, finite_only);
    if (!r || finite_only)
        return r;
    r->how.at_infinity = true;
    r->how.inverted = symbol;
    // Report the leading term in 1/s, which is what a reader checks by eye. A limit found by
    // substitution that is not zero is that term (order 0 in 1/s): the series, which for a
    // case's value of many symbols takes seconds, is taken only for a limit of 0 or one the
    // series found.
    std::optional<GiNaC::ex> leading;
    if (r->how.how == limit_method::kind::substitution && !r->value.is_zero()) {
        leading = r->value;
    } else if (r->value.is_zero() && expand_numerator(in_t) == expansion::zero) {
        // Zero wherever it is defined: its series to order 3 is O(t^3), whose coefficient
        // of t^3 is 0, found without the series (seconds for a rough contact's case).
        leading = GiNaC::ex(0);
    } else {
        try {
            const GiNaC::ex s = GiNaC::series(in_t, t == 0, 3);
            const GiNaC::pseries& p = GiNaC::ex_to<GiNaC::pseries>(s);
            const int order = p.ldegree(t);
            leading = normal_written_once(p.coeff(t, order) * GiNaC::pow(symbol, -order), given.order);
        } catch (const std::exception&) {
        }
    }
    if (leading) {
        r->how.leading_in_inverse = *leading;
        r->method = fmt::format("substituting {} = 1/t and letting t -> 0+: the leading term in 1/{} is {}",
                                given.text(symbol), given.text(symbol), given.text(*leading));
    } else {
        r->method = fmt::format("substituting {} = 1/t and letting t -> 0+, {}", given.text(symbol), r->method);
    }
    return r;
}

} // namespace

std::optional<limit_result> limit(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                  bool to_infinity, const assumptions& given)
{
    std::optional<limit_result> r = find_limit(e, symbol, point, to_infinity, given);
    if (r)
        r->how.words = r->method;
    return r;
}

std::optional<GiNaC::ex> finite_limit_at_infinity(const GiNaC::ex& e, const GiNaC::ex& symbol, const assumptions& given)
{
    const std::optional<limit_result> r = find_limit(e, symbol, 0, true, given, true);
    if (!r || r->infinite)
        return std::nullopt;
    return r->value;
}

} // namespace impact::engine
