// Straight-line programs: the arithmetic a kernel performs, operation by operation.
//
// A kernel's outputs are compiled into one program of single operations (add, mul,
// div, sqrt, fma, ...), each common subexpression computed once, in the fixed order of
// `term_order`. The same program is printed as C++ (the kernel's body, emit/program_cxx.h)
// and run by an interpreter in float, double or long double (to measure its accuracy
// against CLN): what is measured is exactly what is emitted, operation for operation.
#pragma once

#include "engine/expr/order.h"

#include <ginac/ginac.h>

#include <cmath>
#include <stdexcept>
#include <limits>
#include <string>
#include <vector>

namespace impact::compile {

/// `select`: b where a > 0, c otherwise (a quantity defined by cases), both computed.
enum class opcode { input, constant, add, sub, mul, div, neg, sqrt, fma, call, select };

struct instruction {
    opcode op = opcode::constant;
    int a = -1, b = -1, c = -1;   ///< operands: indices of earlier instructions
    int input = -1;               ///< for `input`: the index among the program's inputs
    GiNaC::numeric value;         ///< for `constant`: an exact rational (π's within 10^-80 of it)
    bool pi = false;              ///< for `constant`: π, rounded to the type (`rounded_pi`)
    std::string function;         ///< for `call`: sin, atan2, pow, ... (compile/functions.h)
    /// A correction of compensated arithmetic (the low part of a value: a rounding error,
    /// a remainder, what carries them), not a value of the arithmetic itself: its
    /// magnitude is naturally near the rounding error of another, even below the normal
    /// range, where that costs nothing (a kernel's underflow test leaves it alone).
    bool correction = false;
};

struct program {
    std::vector<GiNaC::ex> inputs;      ///< the input symbols, in parameter order
    std::vector<instruction> code;      ///< instruction i computes value i
    std::vector<int> outputs;           ///< the value of each output
};

struct compile_options {
    bool fma = false;          ///< fuse a*b + c into std::fma(a, b, c)
    bool compensated = false;  ///< evaluate in double-double (error-free transformations)
    bool compensated_lets = false;  ///< only the `let` values in double-double
};

/// Values a program computes once, where first needed: symbol = expression in the inputs.
using let_values = std::vector<std::pair<GiNaC::ex, GiNaC::ex>>;

/// Compiles `outputs` (expressions in `inputs`) into one program.
program compile_program(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                const engine::term_order& order, compile_options options = {}, const let_values& lets = {});

/// The same, with options chosen output by output.
program compile_program(const std::vector<std::pair<GiNaC::ex, compile_options>>& outputs,
                const std::vector<GiNaC::ex>& inputs, const engine::term_order& order,
                const let_values& lets = {});

/// The number of operations of each kind, e.g. to show that one division is used.
std::size_t count(const program& p, opcode op);

/// What a program costs, counted (the same in every run, unlike a timing): its operations
/// (every instruction that computes, a fused multiply-add one), and among them its
/// divisions and square roots, the slowest.
struct cost {
    std::size_t operations = 0;
    std::size_t divisions = 0;
    std::size_t square_roots = 0;
};

/// `p`'s cost.
cost cost_of(const program& p);

/// Whether `a` is cheaper than `b`: fewer square roots, then fewer divisions, then fewer
/// operations (a division or a square root takes several times an addition's time, and
/// vectorised, blocks the unit that does them).
bool cheaper(const cost& a, const cost& b);

/// The values the outputs [first, last) of `p` need, directly or through others.
std::vector<bool> needed_by(const program& p, std::size_t first, std::size_t last);

/// The most values live at once when p runs in its order: a value its outputs need, from
/// where it is computed (an input from where it is first read) to its last use.
std::size_t most_live(const program& p);

/// The same program (the same operations on the same operands, the same outputs), its
/// instructions in an order that keeps fewer values live at once: every step continues
/// the oldest unfinished work (the ready instruction whose oldest operand was computed or
/// first read earliest), and reads an input not yet read only when nothing else is
/// ready, for the first such instruction of the original order. A division by an early
/// divisor, or a square root, waits until every early divisor that does not need it is
/// computed, and a division by a late divisor until every divisor that does not need it is
/// (`grouped_divisors`, `cxx_code::divisors_known`); where the divisions need each other's
/// divisors, so that no order allows that, the program is returned as it is.
program ordered_for_registers(const program& p);

/// Whether `in` is an input or a constant (nothing computed).
bool is_leaf(const instruction& in);

/// The values an instruction reads (at most three), iterable without allocating.
struct operand_list {
    int value[3] = {-1, -1, -1};
    int count = 0;
    const int* begin() const { return value; }
    const int* end() const { return value + count; }
};

/// The values `in` reads.
operand_list operands(const instruction& in);

/// Whether `in`'s result can fall below the normal range where its operands are within it,
/// losing precision: a product, quotient, fused multiply-add or function that is not a
/// correction (sums and differences of floating-point numbers are exact when they are that small).
bool can_underflow(const instruction& in);

/// Whether `in` divides by a value that is not a constant (one a kernel names and tests).
bool divides(const program& p, const instruction& in);

/// The values `p` divides by that are not constants, each once, in the order of their divisions.
std::vector<int> divisors(const program& p);

/// A kernel's divisors in the two groups it tests: `early`, those computed without a
/// division (tested before its first division), and `late`, those that need one (a
/// compensated |g_t| built on |n|, whose square root is corrected by a division), tested
/// once all are computed, before the first division by any of them. Each in the order of
/// their divisions.
struct divisor_groups {
    std::vector<int> early;
    std::vector<int> late;

    bool is_late(int value) const;
    int last_early() const;  ///< the last computed, or -1 for none
    int last_late() const;
};
divisor_groups grouped_divisors(const program& p);

/// Whether `p` divides before it has computed the values it divides by, as a kernel with
/// guards tests them (`divisor_groups`): a division before the last early divisor, or a
/// division by a late divisor before the last late one.
bool divides_early(const program& p);

/// A C library function a program calls (compile/functions.h; `b` is atan2's x and pow's
/// exponent) correctly rounded to the type, computed by CLN to 60 digits (pow to an integer
/// power exactly): an interpreted program gives the same values on every machine, while the C
/// library's own result differs between libraries and CPUs in its last bit (x87's `fpatan`,
/// which glibc's long double atan2 uses, on Intel and AMD). Signed zeros are kept (atan2(-0, -1)
/// is -pi, sin(-0) and expm1(-0) are -0). Infinities and NaN, which a kernel's guards refuse
/// before it computes, atan2(0, 0), pow of 0 and arguments outside a function's domain are left
/// to the C library. `abs` is exact and never passes here.
float correctly_rounded(const std::string& function, float a, float b);
double correctly_rounded(const std::string& function, double a, double b);
long double correctly_rounded(const std::string& function, long double a, long double b);

/// π rounded to the nearest float, double or long double (by CLN): a program's constant π,
/// as a kernel's `detail::pi<Real>()` gives it (emit/cxx_common.cpp).
template <class Real>
Real rounded_pi();
template <>
float rounded_pi<float>();
template <>
double rounded_pi<double>();
template <>
long double rounded_pi<long double>();

/// Every value of `p` run in the floating-point type `Real`, exactly as the printed C++
/// computes it (`run` keeps the outputs), its C library calls correctly rounded
/// (`correctly_rounded`).
template <class Real>
std::vector<Real> run_values(const program& p, const std::vector<Real>& inputs)
{
    std::vector<Real> v(p.code.size());
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        const instruction& in = p.code[i];
        switch (in.op) {
        case opcode::input: v[i] = inputs[in.input]; break;
        case opcode::constant:
            v[i] = in.pi ? rounded_pi<Real>()
                 : in.value.is_integer() ? static_cast<Real>(in.value.to_double())
                                         : static_cast<Real>(in.value.numer().to_double()) /
                                               static_cast<Real>(in.value.denom().to_double());
            break;
        case opcode::add: v[i] = v[in.a] + v[in.b]; break;
        case opcode::sub: v[i] = v[in.a] - v[in.b]; break;
        case opcode::mul: v[i] = v[in.a] * v[in.b]; break;
        case opcode::div: v[i] = v[in.a] / v[in.b]; break;
        case opcode::neg: v[i] = -v[in.a]; break;
        case opcode::sqrt: v[i] = std::sqrt(v[in.a]); break;
        case opcode::fma: v[i] = std::fma(v[in.a], v[in.b], v[in.c]); break;
        case opcode::select: v[i] = v[in.a] > Real(0) ? v[in.b] : v[in.c]; break;
        case opcode::call:
            if (in.function == "abs")
                v[i] = std::abs(v[in.a]);
            else
                v[i] = correctly_rounded(in.function, v[in.a], in.b >= 0 ? v[in.b] : Real(0));
            break;
        }
    }
    return v;
}

/// Runs `p` in the floating-point type `Real` as the printed C++ does, operation for operation,
/// its C library calls correctly rounded (`correctly_rounded`).
template <class Real>
std::vector<Real> run(const program& p, const std::vector<Real>& inputs)
{
    const std::vector<Real> v = run_values(p, inputs);
    std::vector<Real> out;
    for (int o : p.outputs)
        out.push_back(v[o]);
    return out;
}

/// Whether a kernel emitted from `p` refuses the inputs whose values (`run_values`) are `v`
/// as out of range: a divisor below `smallest_divisor` (the least normal number over the
/// type's epsilon, common.hpp's `detail::smallest_divisor`) or infinite, as its emitted
/// test decides (`divisors` lists them).
template <class Real>
bool divisor_out_of_range(const std::vector<int>& divisors, const std::vector<Real>& v)
{
    constexpr Real smallest = std::numeric_limits<Real>::min() / std::numeric_limits<Real>::epsilon();
    for (int d : divisors) {
        const Real x = std::fabs(v[static_cast<std::size_t>(d)]);
        if (!(x >= smallest) || !(x <= std::numeric_limits<Real>::max()))
            return true;
    }
    return false;
}

} // namespace impact::compile
