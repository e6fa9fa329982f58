// The range of a batch loop's inputs within which its arithmetic stays in the normal
// range (compile::input_exponent_bound), printed per floating-point format.
#include "emit/cxx_parts.h"

#include <fmt/format.h>

namespace impact::emit::cxx_detail {

// `f` of `terms` as a balanced tree: f(f(a, b), f(c, d)), ...
std::string balanced(const std::string& f, std::vector<std::string> terms)
{
    while (terms.size() > 1) {
        std::vector<std::string> pairs;
        for (std::size_t t = 0; t < terms.size(); t += 2)
            pairs.push_back(t + 1 < terms.size() ? fmt::format("{}({}, {})", f, terms[t], terms[t + 1]) : terms[t]);
        terms = std::move(pairs);
    }
    return terms.front();
}

// The exponent k of the batch loop's input range, per floating-point format, derived from
// the program of its outputs (compile::input_exponent_bound).
std::vector<int> print_input_k(std::string& out, const std::string& loop, const kernel_plan& plan)
{
    compile::program arithmetic = plan.code;
    arithmetic.outputs.erase(arithmetic.outputs.begin(), arithmetic.outputs.begin() + static_cast<long>(plan.guard_values));
    const std::vector<bool> needed = compile::needed_by(arithmetic, 0, arithmetic.outputs.size());
    std::vector<int> ks;
    for (const compile::float_format& f : batch_formats)
        ks.push_back(compile::input_exponent_bound(arithmetic, needed, f));
    out += fmt::format(
        "// The range of {0}'s inputs within which its arithmetic stays in the normal range: where\n"
        "// every input is 0 or of magnitude within [2^-k, 2^k], every value it computes is 0 or\n"
        "// normal, and a product, quotient or fused multiply-add of values not 0 is not 0, so that\n"
        "// the scalar kernel's underflow test holds; the loop tests the inputs only. k is derived\n"
        "// by Impact from the program, operation by operation, bounding each value not 0 by powers\n"
        "// of 2, 2^lo <= |v| <= 2^hi, and by the power of 2 it is a multiple of, 2^q (a number of\n"
        "// at least 2^lo is a multiple of its ulp, 2^(lo - digits + 1)): a product adds them; a sum,\n"
        "// difference or fused multiply-add is exactly a multiple of its terms' finest q, and so,\n"
        "// rounded or not 0, at least 2^q, and at most 2^(larger hi + 1); a quotient subtracts the\n"
        "// bounds crosswise, a square root halves them, atan2(y, x) lies within\n"
        "// [min(lo(y) - hi(x) - 2, -1), 2]. For 24, 53, 64 and 113 mantissa digits (float, double, x87's and IEEE's\n"
        "// quadruple long double): k = {1}; where it is -1, the loop tests the least magnitude of the values.\n"
        "template <class Real>\nconstexpr int {0}_k = input_k<Real>({1});\n\n",
        loop, fmt::join(ks, ", "));
    return ks;
}

// The least magnitude of the values the scalar kernel tests for underflow, a balanced tree
// of minima, for a format without an input range: a value 0 because an operand that may be
// 0 is (centres level in an axis) counts as min, without a comparison (detail::zero_as_min):
// with a comparison and a blend per value, GCC no longer takes minima in one instruction.
std::string least_magnitude(const cxx_code& code)
{
    std::vector<std::string> terms;
    for (std::size_t v = 0; v < code.watched_values.size(); ++v) {
        std::string term = fmt::format("std::fabs({})", code.watched_values[v]);
        for (const std::string& operand : code.watched_zero_if[v])
            term = fmt::format("detail::most({}, detail::zero_as_min({}))", term, operand);
        terms.push_back(term);
    }
    return balanced("detail::least", terms);
}

} // namespace impact::emit::cxx_detail
