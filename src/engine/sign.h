// Proving the sign of an expression from the declared domains.
//
// An inequality such as ΔE ≤ 0 is proven, never sampled, when the sign of the
// expression follows from the signs of its parts: the expression is normalised and
// factored, and each factor's sign is derived from the domains (a positive mass, an
// interval ε ∈ [0, 1], a square, a square root, a sum of terms of one sign, a linear
// function of one bounded symbol at the ends of its interval, or A − B with A, B ≥ 0
// through A² − B²). The derivation of each factor's sign is kept as the proof text.
#pragma once

#include "engine/order.h"
#include "engine/symbols.h"

#include <ginac/ginac.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace impact::engine {

/// The signs an expression can take: a subset of {negative, zero, positive}.
struct sign_set {
    bool negative = true;
    bool zero = true;
    bool positive = true;

    static sign_set any() { return {}; }
    static sign_set exactly(int sign);
    bool is_known() const { return !(negative && positive); }
    std::string describe() const;   ///< "> 0", ">= 0", "= 0", "<= 0", "< 0" or "of unknown sign"
};

/// Domains by GiNaC symbol; a check may narrow the declared ones (e.g. ε ∈ [0, 1)).
using domain_map = std::map<GiNaC::ex, domain, GiNaC::ex_is_less>;

/// What a proof may assume: the domains, and the order in which its text is written.
struct assumptions {
    domain_map domains;
    term_order order;
    std::string text(const GiNaC::ex& e) const;

    /// What is already worked out under these domains: signs with their reasons, and
    /// radicals simplified. Domains narrowed (a check's `assuming`) need one of their own.
    struct worked_out {
        std::map<GiNaC::ex, std::pair<sign_set, std::string>, GiNaC::ex_is_less> signs;
        std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> radicals;
    };
    std::shared_ptr<worked_out> known = std::make_shared<worked_out>();
};

/// The declared domains of a derivation's symbols.
assumptions declared_assumptions(const symbol_table& symbols);

struct sign_proof {
    sign_set sign;
    std::vector<std::string> steps;   ///< one line per factor: "1 + eps > 0 (eps in [0, 1])"
};

/// The sign of `e` as far as it follows from `domains`.
sign_proof prove_sign(const GiNaC::ex& e, const assumptions& given);

/// True when `e` contains a power with a non-integer exponent.
bool has_radical(const GiNaC::ex& e);

/// GiNaC's factor() for an expression without radicals; one with radicals is returned
/// as it is (factoring under a root may pull out -1 and leave I behind).
GiNaC::ex factor_polynomial(const GiNaC::ex& e);

/// `sqrt(x^2 y)` → `x sqrt(y)` wherever the sign of x is proven: radicals of squares
/// taken out under the domains.
GiNaC::ex simplify_radicals(const GiNaC::ex& e, const assumptions& given);

} // namespace impact::engine
