// Limits, which GiNaC does not provide.
//
// A limit s → a is established, in this order, by
//   substitution, where the expression is continuous at a (its denominator there is
//     proven non-zero from the domains, radicals of squares taken out by sign);
//   the leading term of GiNaC's series in (s − a) otherwise;
// and s → ∞ by substituting s = 1/t and taking t → 0⁺ the same way, after pulling
// the powers of t out of square roots (t > 0). The method is reported with the value.
#pragma once

#include "engine/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace impact::engine {

struct limit_result {
    GiNaC::ex value;        ///< the limit, or ±1 for ±∞ when `infinite`
    bool infinite = false;  ///< true when the expression grows without bound
    std::string method;     ///< how it was established, in words
};

/// The limit of `e` as `symbol` → `point`; `to_infinity` for s → +∞. Nothing when
/// no method applies.
std::optional<limit_result> limit(const GiNaC::ex& e, const GiNaC::ex& symbol, const GiNaC::ex& point,
                                  bool to_infinity, const assumptions& given);

} // namespace impact::engine
