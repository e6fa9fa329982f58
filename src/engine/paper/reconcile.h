// The smallest change that reconciles a printed equation with the derived one.
//
// When the paper prints something other than what Impact derives, the reader wants to
// know the misprint, not only that there is one. Impact tries every single edit of
// the printed form — the sign of the whole or of one term, one symbol written for
// another (a swapped M and m, a missing prime), two symbols swapped throughout, the
// primes missing from one side of an equation, the squares of the symbols of one
// dimension missing, a factor of 2, the reciprocal — and reports each edit after which
// the printed form is proven equal to (or, for an equation, equivalent to) the derived
// one; when no single edit does, each pair of edits that does (Appendix A's first line:
// the squares, and M for m), a pair that makes the same form as another said once. Each
// change found mends the form alone: after the first, each is said as an alternative
// ("or ...").
// Candidates are screened at exact rational points and confirmed with normal(); the list
// is sorted, so the report is the same on every run.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/expr/finding.h"
#include "engine/prove/sign.h"
#include "engine/expr/symbols.h"
#include "engine/expr/written_form.h"

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace impact::engine {

/// Single edits of `printed` (an expression) that make it equal to `derived`.
std::vector<finding> reconcile_expression(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                              const symbol_table& symbols, const resolver& resolve,
                                              proof_cache& run);

/// Single edits of the equation `printed` (a relational) that make it equivalent to
/// `derived` (equal up to a non-zero constant factor between lhs − rhs of the two).
std::vector<finding> reconcile_equation(const GiNaC::ex& printed, const GiNaC::ex& derived,
                                            const symbol_table& symbols, const resolver& resolve,
                                            proof_cache& run);

/// Where a printed member of a line differs from another member of the same line that
/// agrees (Eq. 14's first line: v'_1 v'_2 / (|v'_1| |v'_2|), then the same with the values
/// put in): the factors of both, as written, matched in order (a run of the printed
/// member's factors for each factor of the other's, numerator with numerator), and the one
/// run that differs named, when exactly one does and putting the other's factor in its
/// place reconciles the printed form with `derived`. This settles which of several edits
/// of equal size is the misprint: the second (1/2 - eps/2) v_1 of Eq. 14's numerator,
/// where v'_2 belongs, not the (1/2 + eps/2) v_1 of its denominator.
std::optional<finding> locate_by_member(const written_form::node& printed, const written_form::node& other,
                                        const GiNaC::ex& derived, const symbol_table& symbols,
                                        const resolver& resolve, proof_cache& run);

} // namespace impact::engine
