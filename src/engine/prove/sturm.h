// Sturm's theorem (Sturm, 1829; Basu, Pollack and Roy, "Algorithms in Real Algebraic
// Geometry", Ch. 2), shared by the sign prover's argument about one symbol
// (sign_arguments.h) and the search for where an inequality fails (real_roots.cpp): a
// square-free polynomial in one symbol with rational coefficients has, in (a, b], as many
// distinct real roots as its Sturm sequence loses sign changes from a to b (zeros skipped).
#pragma once

#include "engine/expr/domain.h"

#include <ginac/ginac.h>

#include <optional>
#include <vector>

namespace impact::engine {

/// The closure of a domain: its ends, each a rational or none (infinite), whether the
/// domain holds it, and the ends as the domain writes them (Pi/2). An end of π is the
/// rational within 10^-20 beyond it (below a lower end, above an upper one), counted in:
/// the closure holds the domain, and a sign shown on it holds on the domain.
struct closed_interval {
    std::optional<GiNaC::numeric> lower, upper;
    bool lower_in = false, upper_in = false;
    std::optional<GiNaC::ex> lower_shown, upper_shown;
};
closed_interval closure_of(const domain& d);

/// -1, 0 or 1: the sign of a rational number.
int sign_of(const GiNaC::ex& value);

/// Whether `p` is a polynomial in `s` with rational coefficients.
bool rational_polynomial_in(const GiNaC::ex& p, const GiNaC::ex& s);

/// The Sturm sequence of a square-free polynomial q in s: q, q', then each the negated
/// remainder of the two before it, down to a constant.
std::vector<GiNaC::ex> sturm_sequence(const GiNaC::ex& q, const GiNaC::ex& s);

/// The sign changes of the sequence at x, zeros skipped; or at +infinity (−infinity) when
/// x is none and `above` is true (false): there, the signs of the leading coefficients.
int sign_changes(const std::vector<GiNaC::ex>& sequence, const GiNaC::ex& s, const std::optional<GiNaC::numeric>& x,
                 bool above);

} // namespace impact::engine
