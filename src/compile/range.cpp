#include "compile/range.h"

#include <algorithm>
#include <cmath>

namespace impact::compile {

namespace {

// Bounds of a value not 0: 2^lo <= |v| <= 2^hi, and v a multiple of 2^quantum (every
// floating-point number of magnitude at least 2^lo is a multiple of 2^(lo - digits + 1));
// `zero` where the value is always 0.
struct exponents {
    long lo = 0, hi = 0, quantum = 0;
    bool zero = false;
};

long floor_half(long e) { return e >= 0 ? e / 2 : -((-e + 1) / 2); }
long ceil_half(long e) { return e >= 0 ? (e + 1) / 2 : -((-e) / 2); }

// A value within [2^lo, 2^hi], rounded to `digits`: its quantum is its ulp's at least.
exponents rounded(long lo, long hi, long digits) { return {lo, hi, lo - digits + 1}; }

// An exact result that is a multiple of 2^quantum, at most 2^hi: rounded, it is still a
// multiple of 2^quantum (a result that is not exact is a multiple of its ulp, coarser),
// and not 0, at least 2^quantum; and being a floating-point number of magnitude at least
// 2^lo, a multiple of its ulp.
exponents on_grid(long quantum, long lo, long hi, long digits)
{
    lo = std::max(lo, quantum);
    return {lo, hi, std::max(quantum, lo - digits + 1)};
}

// The bounds of every value of p for inputs within [2^-k, 2^k] (or 0); false where p
// calls a function without bounds.
bool propagate(const program& p, long k, long digits, std::vector<exponents>& e)
{
    e.assign(p.code.size(), exponents{});
    const exponents zero{0, 0, 0, true};
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        const instruction& in = p.code[i];
        exponents& r = e[i];
        const exponents a = in.a >= 0 ? e[in.a] : exponents{}, b = in.b >= 0 ? e[in.b] : exponents{},
                        c = in.c >= 0 ? e[in.c] : exponents{};
        switch (in.op) {
        case opcode::input: r = rounded(-k, k, digits); break;
        case opcode::constant: {
            if (in.value.is_zero()) {
                r = zero;
                break;
            }
            // The constant's magnitude, rounded to the type: a bit of room either side.
            const long exponent = static_cast<long>(std::floor(std::log2(std::fabs(in.value.to_double()))));
            r = rounded(exponent - 1, exponent + 2, digits);
            break;
        }
        case opcode::neg: r = a; break;
        case opcode::select:
            if (b.zero || c.zero)
                r = b.zero ? c : b;
            else
                r = {std::min(b.lo, c.lo), std::max(b.hi, c.hi), std::min(b.quantum, c.quantum)};
            break;
        case opcode::add:
        case opcode::sub:
            if (a.zero || b.zero)
                r = a.zero ? b : a;
            else  // exactly, a multiple of the finer quantum
                r = on_grid(std::min(a.quantum, b.quantum), std::min(a.quantum, b.quantum), std::max(a.hi, b.hi) + 1, digits);
            break;
        case opcode::mul:
            r = a.zero || b.zero ? zero : on_grid(a.quantum + b.quantum, a.lo + b.lo, a.hi + b.hi, digits);
            break;
        case opcode::div: r = a.zero ? zero : rounded(a.lo - b.hi, a.hi - b.lo, digits); break;
        case opcode::sqrt: r = a.zero ? zero : rounded(floor_half(a.lo), ceil_half(a.hi), digits); break;
        case opcode::fma:
            if (a.zero || b.zero)
                r = c;
            else if (c.zero)
                r = on_grid(a.quantum + b.quantum, a.lo + b.lo, a.hi + b.hi, digits);
            else  // exactly a b + c, a multiple of the finer quantum
                r = on_grid(std::min(a.quantum + b.quantum, c.quantum), std::min(a.quantum + b.quantum, c.quantum),
                            std::max(a.hi + b.hi, c.hi) + 1, digits);
            break;
        case opcode::call:
            if (in.function == "atan2")
                r = rounded(a.zero ? -1 : std::min(a.lo - b.hi - 2, -1L), 2, digits);
            else if (in.function == "abs")
                r = a;
            else
                return false;
            break;
        }
    }
    return true;
}

bool within(const program& p, const std::vector<bool>& needed, long k, const float_format& f)
{
    std::vector<exponents> e;
    if (!propagate(p, k, f.digits, e))
        return false;
    for (std::size_t v = 0; v < p.code.size(); ++v) {
        if (v >= needed.size() || !needed[v] || e[v].zero)
            continue;
        if (e[v].hi > f.max_exponent - 1)
            return false;
        if (can_underflow(p.code[v]) && e[v].lo < f.min_exponent - 1)
            return false;
    }
    return true;
}

} // namespace

int input_exponent_bound(const program& p, const std::vector<bool>& needed, float_format format)
{
    // The bounds widen with k: the largest k that holds, by bisection.
    long good = -1, bad = format.max_exponent;
    while (bad - good > 1) {
        const long k = (good + bad) / 2;
        (within(p, needed, k, format) ? good : bad) = k;
    }
    return static_cast<int>(good);
}

} // namespace impact::compile
