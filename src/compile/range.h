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

/// What a batch loop's sure block tests in place of every input (docs/design-kernels.md, "How
/// the batch loops were shaped"): `tested`, values each 0 or of magnitude within
/// [2^-k, 2^k]. An input that p only adds, subtracts or negates, and at least once subtracts
/// from or adds to another input
/// (C_M - C_m, v_M - v_m), is not tested itself: that sum or difference is, and it is finite
/// only where both inputs are. Every other input is tested. Every product, quotient, fused
/// multiply-add, root and function of p then reads values bounded from the tested ones, as
/// input_exponent_bound bounds them from the inputs; the values an untested input reaches by
/// sums alone are not bounded, and the outputs among them (`summed`, a velocity plus its
/// change) are tested as the loop tests every result: out of range where not finite (an
/// infinity or NaN stays one through sums, so nothing before them needs a test).
struct range_cut {
    std::vector<int> tested;  ///< values of p, in p's order
    std::vector<int> summed;  ///< indices into p.outputs
};

/// The cut of p's values that `needed` keeps, or every input read (and no output) where the
/// cut would test as many values (a summed output counted as half a value).
range_cut cut_for_range(const program& p, const std::vector<bool>& needed);

/// input_exponent_bound for the values of `cut`: the largest k such that, whenever every
/// tested value is 0 or of magnitude within [2^-k, 2^k], every needed value that can
/// underflow is 0 or normal and every needed value not reached from an untested input is
/// finite; -1 if none (or if p multiplies, divides, roots or calls a value an untested
/// input reaches).
int cut_exponent_bound(const program& p, const std::vector<bool>& needed, const range_cut& cut, float_format format);

/// Whether, whenever every value of `cut` is 0 or of magnitude within [2^-k, 2^k], each of
/// `values` is 0 or of magnitude within [2^lo, 2^hi], bounded as cut_exponent_bound bounds
/// them (false for a value reached from an untested input, which has no bound).
bool cut_bounds_within(const program& p, const std::vector<bool>& needed, const range_cut& cut, long k, float_format format, const std::vector<int>& values,
                       long lo, long hi);

} // namespace impact::compile
