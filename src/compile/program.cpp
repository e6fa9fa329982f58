// What a straight-line program computes and costs, read from its instructions
// (compile/program.h): its operations counted, its operands, its divisors and their groups,
// the values its outputs need. Programs are compiled in compiler.cpp, and the C library
// calls they make are rounded as the interpreter runs them in correctly_rounded.cpp.
#include "compile/program.h"

#include <algorithm>

namespace impact::compile {

std::size_t count(const program& p, opcode op)
{
    std::size_t n = 0;
    for (const instruction& in : p.code)
        n += in.op == op ? 1 : 0;
    return n;
}

cost cost_of(const program& p)
{
    cost c;
    for (const instruction& in : p.code) {
        c.operations += is_leaf(in) ? 0 : 1;
        c.divisions += in.op == opcode::div ? 1 : 0;
        c.square_roots += in.op == opcode::sqrt ? 1 : 0;
    }
    return c;
}

bool cheaper(const cost& a, const cost& b)
{
    if (a.square_roots != b.square_roots)
        return a.square_roots < b.square_roots;
    if (a.divisions != b.divisions)
        return a.divisions < b.divisions;
    return a.operations < b.operations;
}

bool is_leaf(const instruction& in)
{
    return in.op == opcode::input || in.op == opcode::constant;
}

operand_list operands(const instruction& in)
{
    operand_list of;
    for (int operand : {in.a, in.b, in.c})
        if (operand >= 0)
            of.value[of.count++] = operand;
    return of;
}

bool can_underflow(const instruction& in)
{
    return !in.correction && (in.op == opcode::mul || in.op == opcode::div || in.op == opcode::fma || in.op == opcode::call);
}

// A division by a value that is not a constant: one whose divisor a kernel names and tests.
bool divides(const program& p, const instruction& in)
{
    return in.op == opcode::div && p.code[in.b].op != opcode::constant;
}

divisor_groups grouped_divisors(const program& p)
{
    std::vector<bool> needs_division(p.code.size(), false);
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        needs_division[i] = divides(p, p.code[i]);
        for (int operand : operands(p.code[i]))
            needs_division[i] = needs_division[i] || needs_division[operand];
    }
    divisor_groups groups;
    for (int d : divisors(p))
        (needs_division[static_cast<std::size_t>(d)] ? groups.late : groups.early).push_back(d);
    return groups;
}

namespace {

int last_of(const std::vector<int>& values)
{
    return values.empty() ? -1 : *std::max_element(values.begin(), values.end());
}

} // namespace

bool divisor_groups::is_late(int value) const
{
    return std::find(late.begin(), late.end(), value) != late.end();
}

int divisor_groups::last_early() const
{
    return last_of(early);
}

int divisor_groups::last_late() const
{
    return last_of(late);
}

bool divides_early(const program& p)
{
    const divisor_groups groups = grouped_divisors(p);
    const int last_early = groups.last_early(), last_late = groups.last_late();
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        if (!divides(p, p.code[i]))
            continue;
        const int at = static_cast<int>(i);
        if (at < last_early || (groups.is_late(p.code[i].b) && at < last_late))
            return true;
    }
    return false;
}

std::vector<int> divisors(const program& p)
{
    std::vector<int> found;
    for (const instruction& in : p.code)
        if (divides(p, in) && std::find(found.begin(), found.end(), in.b) == found.end())
            found.push_back(in.b);
    return found;
}

std::vector<bool> needed_by(const program& p, std::size_t first, std::size_t last)
{
    std::vector<bool> needed(p.code.size(), false);
    for (std::size_t o = first; o < last; ++o)
        needed[p.outputs[o]] = true;
    for (std::size_t i = p.code.size(); i-- > 0;)
        if (needed[i])
            for (int operand : operands(p.code[i]))
                needed[operand] = true;
    return needed;
}

} // namespace impact::compile
