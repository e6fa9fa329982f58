// A derivation's `[[kernel]]` described for the stages after the engine: its inputs
// (scalars and arrays), its outputs with every candidate form proven equal to the
// derived value, its `let` values, guards and error scales, all written in the kernel's
// inputs only.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/prove/sign.h"

namespace impact::engine {

/// The kernel `source` of the derivation `d` (whose results and paper comparisons are
/// already derived); `resolve` writes a derived quantity as its value. Throws
/// `impact::error` at the place in the file of an input listed twice, an output depending
/// on a symbol that is not an input, a form not proven equal to its output, a guard or
/// error scale that is not understood.
kernel build_kernel(const spec::kernel& source, const derivation& d, const resolver& resolve, proof_cache& run);

} // namespace impact::engine
