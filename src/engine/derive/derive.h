// Running a derivation: given equations → steps → checked results.
//
// The engine trusts no step. A solution is substituted back into the equations it
// solves; a quotient of equations records the divisor it assumes non-zero; a
// rearranged equation is proven equivalent to its source; a display form is proven
// equal to the derived result; every check of the file is proven or reported with its
// residual. The paper's printed forms are compared with the derived results, but a
// disagreement there is a finding about the paper, not a failure of the derivation.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/prove/prove.h"
#include "spec/derivation.h"

namespace impact::engine {

/// Runs one derivation. Bad input throws `impact::error`; a failed check does not throw
/// but is recorded (see `derivation::all_hold`). What its proofs work out is kept in
/// `run`, for the derivations run after it with the same cache.
derivation derive(const spec::derivation& source, const derived_by_id& done, proof_cache& run);
/// Runs one derivation with a cache of its own, gone when it returns.
derivation derive(const spec::derivation& source, const derived_by_id& done);

} // namespace impact::engine
