// A straight-line program printed as C++: the body of a generated kernel.
//
// Each operation of the program (src/compile/program.h) is printed as the operation the
// interpreter measured, with the parentheses that keep the program's tree, so that what
// is emitted is exactly what was measured.
#pragma once

#include "compile/program.h"

#include <string>
#include <vector>

namespace impact::emit {

/// The body of a kernel: one `const Real tN = ...;` line per instruction that is not an
/// input (inputs are referred to by `names`), and the C++ expression of each output.
/// With `kept_if` (an int64 flag), every divisor d that is not a constant is written
/// `detail::blend(kept_if, d, Real(1))` and every square root's argument x
/// `detail::blend(kept_if, x, Real(0))`: a batch loop computes every lane, and one whose
/// results it discards neither divides by zero nor takes a root of a negative number.
/// Selects are blends too (no branch a compiler could divide in).
/// Every divisor that is not a constant is named, so that a kernel can test their range
/// before dividing (compile::grouped_divisors): those computed without a division
/// (`divisors`) by the first `divisors_known` statements, before any division; those that
/// need one (`late_divisors`, written `detail::blend(kept_if_late, d, Real(1))` with
/// `kept_if`) by the first `late_divisors_known`, before any division by one of them; no
/// division is made before its group is known unless `divides_early`.
/// With `watched` (a flag per value of p), every watched value that can fall below the
/// normal range (compile::can_underflow) is named, with its operands, and `underflows`
/// holds for each the test that it did: a non-zero value below
/// std::numeric_limits<Real>::min(), or a product (of a fused multiply-add, one added to
/// 0) or quotient that is 0 though what it multiplies or divides is not (for atan2(y, x),
/// 0 though y is not). A batch loop, whose exact test would cost as much as its arithmetic,
/// tests its inputs' range instead (compile::input_exponent_bound), or, for a format where
/// no range can be derived, the least magnitude of `watched_values` (a value 0 because an
/// operand that may be 0 is, counted as min), and leaves a pair outside, or where that is
/// below the normal range, or 0, to the scalar kernel.
struct cxx_code {
    std::vector<std::string> statements;
    std::vector<int> statement_values;   ///< the value each statement computes
    std::vector<std::string> outputs;
    std::vector<std::string> divisors;
    std::vector<int> divisor_values;       ///< the value of p each of `divisors` is
    std::size_t divisors_known = 0;
    std::vector<std::string> late_divisors;
    std::vector<int> late_divisor_values;  ///< the value of p each of `late_divisors` is
    std::size_t late_divisors_known = 0;
    bool divides_early = false;
    std::vector<std::string> underflows;
    std::vector<std::string> watched_values;  ///< the values `underflows` tests (named), but inputs
    /// For each of `watched_values`, its operands that may be 0 (an input, a sum, a difference),
    /// making it 0 as it should be; none for a fused multiply-add (a 0 goes to the scalar kernel).
    std::vector<std::vector<std::string>> watched_zero_if;
    /// With `watched`, the arguments of its functions (named): a function can hide an
    /// overflow (atan2 of an infinity is finite), so a kernel tests them as it tests its results.
    std::vector<std::string> arguments;
};
/// With `in_batch_loop`, a call of a C library function other than fabs is written
/// `detail::scalar_<name>(...)` (common.hpp), the scalar function never made a vector one.
cxx_code program_cxx(const compile::program& p, const std::vector<std::string>& names, const std::string& kept_if = {},
                     const std::vector<bool>& watched = {}, bool in_batch_loop = false);

} // namespace impact::emit
