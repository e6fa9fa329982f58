// Solving a step's equations for its unknowns.
//
// A linear system is solved by GiNaC's lsolve. Any other is brought to polynomials in
// the unknowns (the numerators of lhs − rhs) and solved by elimination (eliminate.h): an
// unknown held linearly is substituted (splitting the system where its coefficient holds
// other unknowns), an equation left in one unknown is solved through its factors of
// degree one or two, and two equations that share an unknown give way to their
// resultant; each root is a branch of its own. Every solution found
// is substituted back into the equations and proven, then kept or rejected: by the
// declared domain of an unknown (the sign of the value proven against it: a positive V
// rejects V = −√(2gh)), or by a condition the step states (`reject`, proven to hold for
// the solution). Exactly one solution must be kept; several are an error listing them.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/prove/sign.h"

#include <functional>

namespace impact::engine {

/// A derived value in its simplest form: numerator and denominator factored, radicals
/// of squares taken out by sign, radicals of quotients split (see simplify_radicals).
GiNaC::ex simplified(const GiNaC::ex& e, const assumptions& given);

/// `simplified` without the radicands of nested radicals expanded.
GiNaC::ex simplified_as_normalised(const GiNaC::ex& e, const assumptions& given);

/// What a `solve` step needs of the derivation it is part of.
struct solve_context {
    const symbol_table& symbols;
    proof_cache& run;
    resolver resolve;                                                  ///< derived quantities by value
    std::function<const equation&(const spec::text&)> equation_at;     ///< an equation by name, or error
    const GiNaC::exmap& derived;                                       ///< the values derived so far
};

/// Carries out the `solve` step `st`: fills `r` (its description, the values kept, every
/// solution with its fate, and the checks of each substituted back) and returns the
/// kept value of each unknown. Throws `impact::error` at the step when the system is
/// underdetermined, inconsistent, not solvable by the means above, or left with no
/// solution or with several.
GiNaC::exmap solve_equations(const spec::step& st, const solve_context& context, step_result& r);

} // namespace impact::engine
