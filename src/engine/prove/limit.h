// Limits, which GiNaC does not provide.
//
// A limit s → a is established, in this order, by
//   substitution, where the expression is continuous at a (its denominator there is
//     proven non-zero from the domains, radicals of squares taken out by sign);
//   the leading term of GiNaC's series in (s − a) otherwise;
// and s → ∞ by substituting s = 1/t and taking t → 0⁺ the same way, after pulling
// the powers of t out of square roots (t > 0). The method is reported with the value.
#pragma once

#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace impact::engine {

/// How a limit s → a (or s → ∞) was established, as data a printer can set.
struct limit_method {
    enum class kind { substitution, series };
    kind how = kind::substitution;
    GiNaC::ex symbol;            ///< s, or t for s → ∞ (s = 1/t, t → 0⁺)
    GiNaC::ex point;             ///< a, or 0 for s → ∞
    GiNaC::ex denominator;       ///< substitution: the denominator at the point ...
    sign_set denominator_sign;   ///< ... proven non-zero
    GiNaC::ex coefficient;       ///< series: the leading term coefficient*(s - a)^order
    int order = 0;
    bool at_infinity = false;    ///< s → ∞, by s = 1/t
    GiNaC::ex inverted;          ///< s of s = 1/t
    std::optional<GiNaC::ex> leading_in_inverse;   ///< the leading term in 1/s, when found
    std::string words;           ///< all of it in words (for a printer that sets no more)
};

struct limit_result {
    GiNaC::ex value;        ///< the limit, or ±1 for ±∞ when `infinite`
    bool infinite = false;  ///< true when the expression grows without bound
    limit_method how;
    std::string method;     ///< `how` in words (`how.words`), for derivations.json and the terminal
};

/// The limit of `e` as `symbol` → `point`; `to_infinity` for s → +∞. Nothing when
/// no method applies.
std::optional<limit_result> limit(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                  bool to_infinity, const assumptions& given);

/// The limit of `e` as `symbol` → +∞ when it is finite, its value alone, or nothing: what
/// a fixed sphere's kernel needs, without the work `limit` does to say more (the sign of
/// an infinite limit proven, the leading term in 1/s for the reader).
std::optional<GiNaC::ex> finite_limit_at_infinity(const GiNaC::ex& e, const GiNaC::ex& symbol,
                                                  const assumptions& given);

} // namespace impact::engine
