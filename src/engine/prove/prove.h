// Proving that two expressions are equal.
//
// An identity is `proven` only when the difference of its sides normalises to zero
// with GiNaC (a rational-function identity, exact for every value where both sides are
// defined). When normalisation leaves something GiNaC cannot decide, the identity is
// tested at sampled points of the declared domains with 40-digit arithmetic (a point
// where it fails evaluated again exactly) and
// reported as `sampled (N points)`, never as proven; if any point disagrees it is
// `failed` with the residual.
#pragma once

#include "engine/prove/definedness.h"
#include "engine/prove/sign.h"
#include "engine/expr/symbols.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace impact::engine {

struct verdict {
    enum class status { proven, sampled, failed };
    status what = status::failed;
    /// How a `proven` verdict was reached, for a reader (`method` says it with the
    /// expressions): what the errata's agreeing rows say.
    enum class basis {
        none,             ///< not proven, or proven some other way (case by case: see the check's parts)
        zero_difference,  ///< the difference of the sides normalises to zero
        signs,            ///< the sign of each factor of the difference follows from the domains
        identity,         ///< the difference is a side of an identity proven before it
        constant_factor,  ///< two equations whose differences of sides differ by a constant factor
        same_difference,  ///< two equations with the same difference of sides
        angles,           ///< two angles in [0, pi] whose cosines are proven equal
        counterexample,   ///< a claim said not to hold, refuted at a point of the domains
        decided,          ///< sin, cos, tan, their hyperbolic kin, exp and log: angles and exponents
                          ///< over a basis, reduced modulo sin^2 + cos^2 = 1 (transcendental.h)
    };
    basis how = basis::none;
    std::size_t samples = 0;     ///< points tested when not proven symbolically
    /// The normalised difference of the sides: zero when proven by it, or, proven by signs
    /// or through an identity, the difference whose factors' signs decide it.
    GiNaC::ex residual;
    std::string method;          ///< how the verdict was reached, in words
    finding typeset;             ///< the same with its mathematics, when a printer can typeset it
    std::vector<sign_step> proof; ///< for inequalities: the sign of each factor
    /// Where the claim is defined (engine/prove/definedness.h): the conditions it is said
    /// to hold under, not proven from the domains (`proven, where x != y`), and those the
    /// domains and assumptions prove (a divisor M + m, a radicand 1 - eps^2).
    std::vector<condition> where;
    std::vector<condition> defined;

    bool holds() const { return what != status::failed; }
};

/// `proven`, `sampled (N points)` or `failed`; `, where x != y` after the first two when
/// the verdict rests on attached conditions.
std::string to_string(const verdict& v);

/// What `prove_equal` does with an identity it cannot prove: test it at sampled points
/// (`sampled` or `failed`), or give up at once (`failed`, with the residual) for a caller
/// that needs a proof and would take nothing less (sampling a long radical expression at
/// 40 digits takes seconds).
enum class when_unproven { sample, give_up };

/// Decides whether `lhs == rhs` for all values of the symbols' domains; `run` keeps what
/// the proof works out for the proofs after it.
/// Sampled, it is tested where the conditions `where` hold (definedness.h).
/// A claim of sin, cos, tan, their hyperbolic kin, exp or log is decided under `under`
/// (a check's narrowed domains, with the conditions `where`) when given, else under the
/// declared domains narrowed by `where`.
verdict prove_equal(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const symbol_table& symbols, proof_cache& run,
                    when_unproven otherwise = when_unproven::sample, const std::vector<condition>& where = {},
                    const assumptions* under = nullptr);

/// Whether `lhs == rhs` wherever both are defined, seen as written: the difference's numerator
/// over the product of its denominators expands to zero, each radical a variable as it is
/// written. No normal(), no sampling, and no more than that: false says only that this did
/// not show it (prove_equal tries further).
bool equal_as_written(const GiNaC::ex& lhs, const GiNaC::ex& rhs);

/// Decides `lhs op rhs` for an inequality: proven from the signs of the factors of
/// the difference under `given` (prove_sign), else sampled, else failed.
verdict prove_inequality(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const symbol_table& symbols,
                         const assumptions& given);

/// Whether `e` is found < 0 at one point and > 0 at another, drawn from the domains of
/// `given` (at most `points` of them; each value's sign the same at 40 and at 80 digits):
/// then no sign proof under `given` can find it of one sign, nor >= 0, nor <= 0, and a
/// caller that needs one need not search (seconds, on the long polynomials of a rough
/// contact in space). A refutation, never a proof; false where a symbol has no domain.
bool takes_both_signs(const GiNaC::ex& e, const assumptions& given, std::size_t points = 16);

/// Whether `e` is found non-zero at one of `points` points drawn as takes_both_signs draws
/// them (40 and 80 digits agreeing): then `e` is not identically zero. A refutation of
/// "e = 0" (a proof that it is not), never a proof that it is; false where a symbol has no
/// domain.
bool nonzero_somewhere(const GiNaC::ex& e, const assumptions& given, std::size_t points = 8);

/// A point of the domains where a claim fails, and both sides' values there.
struct counterexample {
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> point;  ///< each free symbol and its value, in declaration order
    GiNaC::ex lhs, rhs;                                  ///< the sides there, exactly (radicals kept)
    bool exact = false;  ///< decided exactly: both sides rationals, or equal sides (radicals too) of a strict claim
};

/// A counterexample to `lhs op rhs` among simple values of the domains of `given` (their
/// ends, 0, 1, 2, 1/2, -1, ...), where every abbreviation that shares a symbol with it lies
/// in its own domain too (s_n > 0: the spheres approach), the first found: tried first with each symbol at its first
/// simple value, then at others drawn in a fixed order; then, for an inequality, one symbol
/// at a time at the points its real roots pick out (a thin interval, a single point where a
/// strict claim fails: real_roots.cpp), the others at simple values. A failure is believed
/// when both sides are rationals or a strict claim's sides are equal (decided exactly) or,
/// with radicals, when 50 and 80 digits agree and the sides differ far beyond the rounding.
/// None when no such point is found, or when a symbol has no domain.
std::optional<counterexample> find_counterexample(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                  const symbol_table& symbols, const assumptions& given,
                                                  std::size_t points = 400);

/// Decides `lhs op rhs` from the signs of the factors of the difference alone: proven,
/// or none (nothing sampled).
std::optional<verdict> prove_inequality_by_signs(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                 const symbol_table& symbols, const assumptions& given);

/// An equality the derivation has proven (a check, or a result's display form), its
/// sides with the derived quantities substituted and nothing expanded.
struct proven_identity {
    std::string name;
    GiNaC::ex lhs;
    GiNaC::ex rhs;
};

/// Decides `lhs op rhs` through an identity proven before it, as a textbook argues "by
/// (n), the difference is ..., each of whose terms is ...": when the claim's difference
/// (rhs − lhs for <=, lhs − rhs for >=) is ± one side of an identity, the sign of ± its
/// other side, as written, is proven instead. None when no identity matches, or the
/// sign of the matching side is not proven.
std::optional<verdict> prove_inequality_through(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                                const std::vector<proven_identity>& identities,
                                                const symbol_table& symbols, const assumptions& given);

/// Decides whether two equations are equivalent: their differences lhs − rhs are equal
/// up to a non-zero constant factor.
verdict prove_equivalent(const GiNaC::ex& equation, const GiNaC::ex& other, const symbol_table& symbols,
                         proof_cache& run);

} // namespace impact::engine
