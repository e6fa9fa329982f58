// Every solution of polynomial equations, by elimination (solve.h calls it for a system
// that is not linear).
//
// The equations are the numerators of lhs − rhs. At each stage, in this order:
//  1. an unknown u that an equation holds linearly with a coefficient free of the
//     unknowns is u = −c₀/c₁, substituted into the others;
//  2. an equation left in one unknown is solved: of degree two by the quadratic formula;
//     of a higher degree through its factors over the rationals (GiNaC's factor), each of
//     degree one or two, or a quadratic in u² (u = ±√w); a factor beyond these is an error
//     naming its degree; one that holds u only in sin, cos or tan of a u + b, by the
//     inverse function, each root in u's domain (trigonometric.h);
//  3. an unknown u that an equation holds linearly with a coefficient c₁ holding other
//     unknowns splits the system in two: u = −c₀/c₁ where c₁ ≠ 0, and c₁ = 0 = c₀;
//  4. two equations p, q that share an unknown u: q is replaced by their resultant in u
//     (Sylvester's), free of u, which vanishes wherever both do (Cox, Little, O'Shea,
//     "Ideals, Varieties, and Algorithms", Ch. 3 §6).
// Each root is a branch of its own. A branch whose equations reduce to a non-zero constant
// has no solution; a quadratic whose discriminant is proven negative has no real root.
// Stages 3 and 4 can find more than the solutions (a root of the resultant that is no
// common root, a value of u = −c₀/c₁ that makes c₁ vanish): their branches are marked, so
// that each is substituted into the equations and dropped when it does not satisfy them.
#pragma once

#include "engine/prove/sign.h"
#include "engine/solve/trigonometric.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace impact::engine {

/// Why a system could not be solved, said at the step by the caller.
struct unsolvable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// lhs − rhs (or an expression) as a polynomial: the numerator of its normal form, expanded.
GiNaC::ex polynomial_of(const GiNaC::ex& e);

/// √d up to its sign, squares taken out of the root factor by factor (√((a − b)² c) →
/// (a − b)√c), and a positive number as far as it is a square (√8 = 2√2).
GiNaC::ex root_up_to_sign(const GiNaC::ex& d, proof_cache& run);

/// A candidate solution: a value for each unknown, and whether it must be checked in
/// the equations before it is believed (stages 3 and 4).
struct candidate {
    GiNaC::exmap values;
    bool unverified = false;
};

class eliminator {
public:
    eliminator(const symbol_table& symbols, const assumptions& given) : symbols_(symbols), given_(given) {}

    std::vector<candidate> found;
    std::size_t dead_ends = 0;         ///< branches found inconsistent
    std::vector<std::string> complex;  ///< quadratics (and sin, cos = w) without real roots, in words
    /// The roots of trigonometric equations (trigonometric.h), each with the interval its
    /// value lies in: solve.cpp keeps or rejects them by it.
    std::vector<trigonometric_root> trigonometric;

    /// Solves `equations` for `unknowns`; throws `unsolvable` when it cannot.
    void run(const std::vector<GiNaC::ex>& equations, const std::vector<GiNaC::ex>& unknowns)
    {
        branch(equations, unknowns, {}, false, 0);
    }

private:
    void branch(const std::vector<GiNaC::ex>& equations, const std::vector<GiNaC::ex>& unknowns,
                const GiNaC::exmap& values, bool unverified, int depth);
    // Stage 2: the roots of p, an equation in u alone; false when its degree is not 2
    // and `any_degree` is not set.
    bool solve_in_one(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                      const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values, bool unverified,
                      int depth, bool any_degree);
    // Each root of a u² + b u + c = 0 (a, b, c free of u), or of a w² + b w + c with w = u²
    // when `squared`.
    void quadratic(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                   const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values, bool unverified, int depth,
                   const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c, bool squared);
    // Stage 2 for an equation in u alone that is not polynomial in it: sin, cos or tan of
    // an expression linear in u equal to a value (trigonometric.h); false when it is not.
    bool solve_trigonometric(const std::vector<GiNaC::ex>& left, const GiNaC::ex& p, const GiNaC::ex& u,
                             const std::vector<GiNaC::ex>& unknowns, const GiNaC::exmap& values, bool unverified,
                             int depth);
    void eliminate(const std::vector<GiNaC::ex>& left, const GiNaC::ex& used, const std::vector<GiNaC::ex>& unknowns,
                   const GiNaC::ex& u, const GiNaC::ex& value, const GiNaC::exmap& values, bool unverified,
                   int depth);
    std::string names(const std::vector<GiNaC::ex>& unknowns) const;

    const symbol_table& symbols_;
    const assumptions& given_;
};

/// Whether `residual`, an expression of the declared symbols, is zero: true when it is
/// shown so (normal form, or the numerator expanded with radicals as variables), false
/// when exact evaluation at a point of the domains gives a non-zero real number, true
/// when neither settles it (the solution is then kept, and its check substituted back
/// says what holds).
bool may_vanish(const GiNaC::ex& residual, const assumptions& given);

} // namespace impact::engine
