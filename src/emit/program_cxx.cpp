#include "emit/program_cxx.h"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace impact::emit {

using compile::instruction;
using compile::opcode;
using compile::program;

namespace {

std::string literal(const GiNaC::numeric& n)
{
    std::ostringstream out;
    if (n.is_integer())
        out << "Real(" << n << ')';
    else
        out << "Real(" << n.numer() << ") / Real(" << n.denom() << ')';
    return out.str();
}

// Whether value v of p is tested for underflow; and the operands whose product or quotient
// it is (a constant is not 0, and is left out), which are not 0 where v fell to 0.
bool tested(const program& p, const std::vector<bool>& watched, std::size_t v)
{
    return v < watched.size() && watched[v] && compile::can_underflow(p.code[v]);
}

std::vector<int> multiplied(const program& p, const instruction& in)
{
    std::vector<int> of;
    if (in.op == opcode::mul || in.op == opcode::fma)
        of = {in.a, in.b};
    else if (in.op == opcode::div || (in.op == opcode::call && in.function == "atan2"))  // atan2(y, x) = 0 where y = 0
        of = {in.a};
    of.erase(std::remove_if(of.begin(), of.end(), [&](int o) { return p.code[o].op == opcode::constant; }), of.end());
    if (of.size() == 2 && of[0] == of[1])  // a square
        of.pop_back();
    return of;
}

// Whether value o may be 0 where nothing underflowed: an input, a sum or a difference may,
// and so may a product with a factor that may be 0, a quotient whose dividend may, a root
// or a function of one (a product or quotient of values not 0 is not 0 unless it
// underflowed). A product of an input that is 0 (a sphere at rest) with anything is 0, and
// so is what divides it: were it not exempt, every such pair of a batch would count as an
// underflow and be computed again by the scalar kernel. Only operands of `multiplied` are
// asked about, each of which the scalar kernel's own test (underflow_test) requires to be
// non-zero: an exemption here never lets the loop write what the scalar kernel refuses.
bool may_be_zero(const program& p, int o)
{
    const instruction& in = p.code[static_cast<std::size_t>(o)];
    switch (in.op) {
    case opcode::constant: return in.value.is_zero();
    case opcode::neg:
    case opcode::sqrt: return may_be_zero(p, in.a);
    case opcode::mul: return may_be_zero(p, in.a) || may_be_zero(p, in.b);
    case opcode::div: return may_be_zero(p, in.a);
    case opcode::call:
        return in.function == "atan2" || in.function == "abs" ? may_be_zero(p, in.a) : true;
    default: return true;   // input, add, sub, fma, select
    }
}

// The test that value v (written text[v]) fell below the normal range, as cxx_code says.
std::string underflow_test(const program& p, std::size_t v, const std::vector<std::string>& text)
{
    const instruction& in = p.code[v];
    std::vector<std::string> nonzero;
    for (int o : multiplied(p, in))
        nonzero.push_back(text[o] + " != Real(0)");
    if (in.op == opcode::fma && !nonzero.empty())  // a sum may cancel to 0 exactly: 0 only where 0 is added
        nonzero = {fmt::format("({} != Real(0) || ({} == Real(0) && {}))", text[v], text[in.c], fmt::join(nonzero, " && "))};
    else if (nonzero.empty())  // a function's value, a product of constants
        nonzero.push_back(text[v] + " != Real(0)");
    return fmt::format("(std::fabs({}) < std::numeric_limits<Real>::min() && {})", text[v], fmt::join(nonzero, " && "));
}

} // namespace

cxx_code program_cxx(const program& p, const std::vector<std::string>& names, const std::string& kept_if,
                     const std::vector<bool>& watched, bool in_batch_loop)
{
    // A value used more than once gets a name; one used once is written in place, with
    // the parentheses that keep the program's tree (C++ evaluates a - b + c as (a - b) + c,
    // so every operation is the one the interpreter measured).
    std::vector<int> uses(p.code.size(), 0);
    for (const instruction& in : p.code)
        for (int operand : operands(in))
            ++uses[operand];
    for (int o : p.outputs)
        ++uses[o];
    // Divisors that are not constants are named, so that a kernel can test them.
    const std::vector<int> divided_by = divisors(p);
    for (int d : divided_by)
        uses[d] += 2;
    // Values tested for underflow are named, and so are the operands their tests read.
    for (std::size_t v = 0; v < p.code.size(); ++v)
        if (tested(p, watched, v)) {
            uses[v] += 2;
            for (int o : multiplied(p, p.code[v]))
                uses[o] += 2;
            if (p.code[v].op == opcode::fma)
                uses[p.code[v].c] += 2;
            if (p.code[v].op == opcode::call)
                for (int o : operands(p.code[v]))
                    uses[o] += 2;
        }
    const compile::divisor_groups groups = compile::grouped_divisors(p);
    const int last_divisor = groups.last_early(), last_late_divisor = groups.last_late();

    constexpr int sum = 1, product = 2, unary = 3, atom = 4;
    std::vector<std::string> text(p.code.size());
    std::vector<int> precedence(p.code.size(), atom);
    auto operand = [&](int v, int needed) {
        return precedence[v] >= needed ? text[v] : "(" + text[v] + ")";
    };
    cxx_code code;
    int next_name = 0;
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        const instruction& in = p.code[i];
        std::string expression;
        int own = atom;
        switch (in.op) {
        case opcode::input: expression = names.at(in.input); break;
        case opcode::constant:
            expression = in.pi ? "detail::pi<Real>()" : literal(in.value);
            own = in.pi || in.value.is_integer() ? atom : product;
            break;
        case opcode::add: expression = operand(in.a, sum) + " + " + operand(in.b, product); own = sum; break;
        case opcode::sub: expression = operand(in.a, sum) + " - " + operand(in.b, product); own = sum; break;
        case opcode::mul: expression = operand(in.a, product) + " * " + operand(in.b, unary); own = product; break;
        case opcode::div:
            expression = operand(in.a, product) + " / " +
                         (kept_if.empty() || !divides(p, in)
                              ? operand(in.b, unary)
                              : "detail::blend(" + kept_if + (groups.is_late(in.b) ? "_late" : "") + ", " + text[in.b] +
                                    ", Real(1))");
            own = product;
            break;
        case opcode::neg: expression = "-" + operand(in.a, unary); own = unary; break;
        case opcode::sqrt:
            // A root an early divisor needs (or is) is taken before `kept_if` is known (from
            // those divisors): a discarded pair's NaN there makes its divisors fail their
            // test, and no more. A root after them (one a late divisor needs among them) is
            // taken of 0 where the pair is discarded.
            expression = "std::sqrt(" +
                         (kept_if.empty() || static_cast<int>(i) <= last_divisor
                              ? text[in.a]
                              : "detail::blend(" + kept_if + ", " + text[in.a] + ", Real(0))") +
                         ")";
            break;
        case opcode::fma: expression = "std::fma(" + text[in.a] + ", " + text[in.b] + ", " + text[in.c] + ")"; break;
        // Both values computed, one chosen: no branch (a conditional move, a blend in vectors).
        // In a batch loop (`kept_if`), a blend of the bits: GCC made a select of divisors a
        // division in each branch, which a loop without AVX-512 cannot vectorise.
        case opcode::select:
            expression = kept_if.empty()
                             ? "(" + text[in.a] + " > Real(0) ? " + text[in.b] + " : " + text[in.c] + ")"
                             : "detail::blend(" + text[in.a] + " > Real(0), " + text[in.b] + ", " + text[in.c] + ")";
            break;
        case opcode::call:
            // |x| as std::fabs: std::abs(double) is a wrapper of <cmath>, compiled with the
            // caller's flags, which GCC does not inline into the kernels' precise code. In a
            // batch loop, any other function through detail::scalar_<name>, never inlined: the
            // scalar C library function, never a vector one (common.hpp says why).
            expression = (in.function == "abs" ? std::string("std::fabs")
                          : !in_batch_loop     ? "std::" + in.function
                                               : "detail::scalar_" + in.function) +
                         "(" + text[in.a] + (in.b >= 0 ? ", " + text[in.b] : "") + ")";
            break;
        }
        const bool named = uses[i] > 1 && !is_leaf(in);
        if (!named) {
            text[i] = expression;
            precedence[i] = own;
            continue;
        }
        const std::string name = fmt::format("t{}", next_name++);
        code.statements.push_back(fmt::format("const Real {} = {};", name, expression));
        code.statement_values.push_back(static_cast<int>(i));
        text[i] = name;
        precedence[i] = atom;
    }
    for (int o : p.outputs)
        code.outputs.push_back(text[o]);
    for (std::size_t v = 0; v < p.code.size(); ++v) {
        if (!tested(p, watched, v))
            continue;
        code.underflows.push_back(underflow_test(p, v, text));
        code.watched_values.push_back(text[v]);
        std::vector<std::string> zero_if;  // operands that may be 0, making the value 0 as it should be
        if (p.code[v].op != opcode::fma)
            for (int o : multiplied(p, p.code[v]))
                if (may_be_zero(p, o))
                    zero_if.push_back(text[o]);
        code.watched_zero_if.push_back(std::move(zero_if));
        if (p.code[v].op == opcode::call)
            for (int o : operands(p.code[v]))
                if (p.code[o].op != opcode::constant)
                    code.arguments.push_back(text[o]);
    }
    for (int d : groups.early) {
        code.divisors.push_back(text[d]);
        code.divisor_values.push_back(d);
    }
    for (int d : groups.late) {
        code.late_divisors.push_back(text[d]);
        code.late_divisor_values.push_back(d);
    }
    code.divides_early = compile::divides_early(p);
    const auto known_after = [&](int last) {
        std::size_t s = 0;
        while (s < code.statements.size() && code.statement_values[s] <= last)
            ++s;
        return s;
    };
    code.divisors_known = known_after(last_divisor);
    code.late_divisors_known = known_after(last_late_divisor);
    return code;
}

} // namespace impact::emit
