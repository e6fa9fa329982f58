// ∂f/∂x in a derivation file: `diff(f, x)`.
//
// A claim about how a result changes with an input ("the steepness being determined by
// incident perpendicular velocity", Sec. III C after Eq. 14) is about the derivative of the
// result's value, not of its name: diff(theta, eps) is 0 while theta is a symbol. So a diff
// is read and kept as written, a GiNaC function that never evaluates itself, and taken
// where the engine puts the derived quantities in (derive.cpp's resolve), innermost first.
// Its variable is an input: a declared quantity that no step derives and no abbreviation
// stands for (the engine refuses others at their place in the file).
#pragma once

#include <ginac/ginac.h>

namespace impact::engine {

/// diff(f, x), held as written.
GiNaC::ex derivative(const GiNaC::ex& f, const GiNaC::ex& x);

/// Whether `e` is a held diff(f, x), and whether it holds one.
bool is_derivative(const GiNaC::ex& e);
bool has_derivative(const GiNaC::ex& e);

/// Every diff(f, x) in `e` taken, innermost first. Throws std::invalid_argument when an x
/// is not a symbol (a derived quantity's value put in for it).
GiNaC::ex derivatives_taken(const GiNaC::ex& e);

} // namespace impact::engine
