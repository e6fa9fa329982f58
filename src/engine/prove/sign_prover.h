// The prover of signs behind prove_sign (sign.cpp) and simplify_radicals (radicals.cpp),
// declared for the files that define it: sign_prover.cpp (the sign of a number, a symbol, a
// product, a power, from the declared domains) and sign_of_sums.cpp (the sign of a sum, by
// the arguments sign.h lists). The arithmetic of sign sets and the factoring under the
// assumptions are shared with them. Internal to engine/prove.
#pragma once

#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impact::engine {

/// The signs of a product of factors of signs `a` and `b`.
sign_set times(const sign_set& a, const sign_set& b);
/// The signs of a sum of terms of signs `a` and `b`.
sign_set plus(const sign_set& a, const sign_set& b);
/// The signs of 1/x for x of signs `a`.
sign_set reciprocal(const sign_set& a);

/// factor_polynomial under `given` (sign_prover.cpp).
GiNaC::ex factored_in(const GiNaC::ex& e, const assumptions& given);

class sign_prover {
public:
    explicit sign_prover(const assumptions& given) : given_(given), domains_(given.domains) {}

    std::string text(const GiNaC::ex& e) const { return given_.text(e); }

    // The sign of e and why, in a few words.
    std::pair<sign_set, sign_reason> sign(const GiNaC::ex& e, int depth = 0) const;

private:
    // sign_prover.cpp
    std::pair<sign_set, sign_reason> decide(const GiNaC::ex& e, int depth) const;
    std::pair<sign_set, sign_reason> power_sign(const GiNaC::ex& e, int depth) const;
    std::optional<std::pair<sign_set, sign_reason>> assumed_sign(const GiNaC::ex& e) const;
    std::vector<std::pair<GiNaC::ex, const domain*>> by_name() const;
    GiNaC::ex factored(const GiNaC::ex& e) const;

    // sign_of_functions.cpp
    std::optional<std::pair<sign_set, sign_reason>> function_sign(const GiNaC::ex& e, int depth) const;
    std::optional<std::pair<sign_set, sign_reason>> constant_sign(const GiNaC::ex& e) const;
    // `trig_only`: only for a sum with sin or cos in it (tried before the arguments that would
    // settle for less).
    std::optional<std::pair<sign_set, sign_reason>> bounded_functions_sign(const GiNaC::ex& e, int depth,
                                                                           bool trig_only = false) const;

    // sign_of_sums.cpp
    std::pair<sign_set, sign_reason> sum_sign(const GiNaC::ex& e, int depth) const;
    std::optional<std::pair<sign_set, sign_reason>> argued_sign(const GiNaC::ex& e, int depth) const;
    std::optional<std::pair<sign_set, sign_reason>> affine_in_bounded_symbol(const GiNaC::ex& e, int depth) const;
    std::optional<std::pair<sign_set, sign_reason>> linear_in_bounded_symbol(const GiNaC::ex& e) const;

    const assumptions& given_;
    const domain_map& domains_;
};

} // namespace impact::engine
