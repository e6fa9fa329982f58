// Arguments for a claim that holds under a condition (a case of a quantity defined by
// cases, engine/cases/cases.h): absolute values taken out where the domains decide their sign,
// the symbols under |.| whose sign a proof must split on, and the claim divided by the
// condition.
#pragma once

#include "engine/prove/prove.h"
#include "engine/prove/sign.h"

#include <ginac/ginac.h>

#include <optional>
#include <vector>

namespace impact::engine {

/// `e` with |x y| = |x| |y|, and |x| = x or -x wherever the sign of x is proven.
GiNaC::ex without_abs(const GiNaC::ex& e, const assumptions& given);

/// Adds to `found` the real symbols of unknown sign whose absolute value `e` takes.
void symbols_under_abs(const GiNaC::ex& e, const assumptions& given, std::vector<GiNaC::ex>& found);

/// The claim G >= 0 (> 0 when `strict`) from the condition C >= 0 (> 0 when
/// `condition_strict`): G's numerator divided by C's in a symbol x that C is linear in, a
/// term at a time, G = q C + r with q and r proven non-negative. None when no such division
/// is found.
std::optional<verdict> divided_by_condition(const GiNaC::ex& g, bool strict, const GiNaC::ex& condition,
                                            bool condition_strict, const assumptions& given);

} // namespace impact::engine
