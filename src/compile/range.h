// The inputs' range within which a program's arithmetic stays in the normal range.
//
// A batch loop tests each pair's inputs (every magnitude not 0 within [2^-k, 2^k]) instead
// of every value its arithmetic computes: k is derived here from the program by propagating
// bounds on the exponents of its values, operation by operation.
#pragma once

#include "compile/program.h"

#include <vector>

namespace impact::compile {

/// A binary floating-point format, as std::numeric_limits describes it: `digits` bits of
/// mantissa, the least normal number 2^(min_exponent - 1), the largest below 2^max_exponent.
struct float_format {
    int digits = 53;
    int min_exponent = -1021;
    int max_exponent = 1024;
};

/// The largest k (at most the format's largest exponent) such that, whenever every input of
/// `p` is 0 or of magnitude within [2^-k, 2^k], every value v of p with `needed[v]` is 0 or
/// finite and at most 2^(max_exponent - 1), and every one of those that can underflow
/// (`can_underflow`) is 0 or at least the least normal number: -1 if none does (k = 0 fails,
/// or p calls a function it has no bounds for). It is then not 0 either where its operands
/// are not (a product, quotient or fused multiply-add of values not 0 is not 0 unless it underflowed).
///
/// Bounds, for values not 0 (0 is always allowed: a product with a factor 0 is 0): 2^lo <=
/// |v| <= 2^hi, and v a multiple of 2^q (a floating-point number of at least 2^lo is a
/// multiple of its ulp, 2^(lo - digits + 1)). A product adds them (q included: rounded, a
/// multiple of 2^q stays one, its ulp being coarser); a sum, difference or fused multiply-add
/// is exactly a multiple of its terms' finest q, and so, rounded or not 0, at least 2^q, and
/// at most 2^(larger hi + 1); a quotient subtracts the bounds crosswise, a square root halves
/// them; atan2(y, x) is within [min(lo_y - hi_x - 2, -1), 2] (|atan(r)| >= r/2 for r <= 1,
/// π/4 beyond, a bit for rounding); rounding, monotonic, keeps a value at or beyond a power
/// of 2 it bounds. The compensated arithmetic's corrections are bounded alike.
int input_exponent_bound(const program& p, const std::vector<bool>& needed, float_format format);

} // namespace impact::compile
