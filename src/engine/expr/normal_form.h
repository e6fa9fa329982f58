// Rational functions with square roots, written one way whatever order GiNaC gives
// their terms.
//
// GiNaC orders the terms of sums by hash values seeded with addresses, which change with
// the build (CMakeLists.txt, impact_ginac). normal() follows that order in what it leaves
// unexpanded, which powers of a radicand it keeps and where it puts a sign; with square
// roots it is not even idempotent (sqrt(S) and S^(3/2) become two unrelated symbols, so
// that S sqrt(S) - S^(3/2) is left as it stands). A value that is printed, or whose form
// decides which argument a proof takes, is brought to the one form here first.
#pragma once

#include "engine/expr/order.h"

#include <ginac/ginac.h>

#include <utility>

namespace impact::engine {

/// True when `e` contains a power with a non-integer exponent.
bool has_radical(const GiNaC::ex& e);

/// e's numerator and denominator in a form GiNaC's order of terms does not choose: each
/// square root a symbol t with t^2 = its radicand (expanded) while normal() works, its
/// powers past the first reduced, common factors cancelled, and the sign put where
/// `order` writes the denominator's first term positive.
std::pair<GiNaC::ex, GiNaC::ex> unique_numer_denom(const GiNaC::ex& e, const term_order& order);

/// normal(e) written one way (unique_numer_denom, as one quotient). Use it for a value
/// that is printed.
GiNaC::ex normal_written_once(const GiNaC::ex& e, const term_order& order);

} // namespace impact::engine
