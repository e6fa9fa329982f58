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
    bool summed = false;  // reached by sums from an input not tested (range_cut): not bounded
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

// How propagate takes a value: as the program computes it, as tested (0 or within
// [2^-k, 2^k], whatever computes it), or as an input not tested (range_cut).
enum class role : char { computed, tested, untested };

// The bounds of every value of p for inputs within [2^-k, 2^k] (or 0), or, with `roles`,
// for the values tested within it; false where p calls a function without bounds, or
// multiplies, divides, roots, calls or selects by a value reached from an untested input.
bool propagate(const program& p, long k, long digits, std::vector<exponents>& e, const std::vector<role>& roles = {})
{
    e.assign(p.code.size(), exponents{});
    const exponents zero{0, 0, 0, true};
    for (std::size_t i = 0; i < p.code.size(); ++i) {
        const instruction& in = p.code[i];
        exponents& r = e[i];
        const role as = roles.empty() ? role::computed : roles[i];
        if (as == role::tested || (as == role::computed && in.op == opcode::input)) {
            r = rounded(-k, k, digits);
            continue;
        }
        if (as == role::untested) {
            r.summed = true;
            continue;
        }
        const exponents a = in.a >= 0 ? e[in.a] : exponents{}, b = in.b >= 0 ? e[in.b] : exponents{},
                        c = in.c >= 0 ? e[in.c] : exponents{};
        if (a.summed || b.summed || c.summed) {
            // Only sums carry such a value, unbounded, to an output, which is tested.
            if (in.op != opcode::add && in.op != opcode::sub && in.op != opcode::neg)
                return false;
            r.summed = true;
            continue;
        }
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

bool within(const program& p, const std::vector<bool>& needed, long k, const float_format& f,
            const std::vector<role>& roles = {})
{
    std::vector<exponents> e;
    if (!propagate(p, k, f.digits, e, roles))
        return false;
    for (std::size_t v = 0; v < p.code.size(); ++v) {
        if (v >= needed.size() || !needed[v] || e[v].zero || e[v].summed)
            continue;
        if (e[v].hi > f.max_exponent - 1)
            return false;
        if (can_underflow(p.code[v]) && e[v].lo < f.min_exponent - 1)
            return false;
    }
    return true;
}

// The largest k for which `holds` (the bounds widen with k), by bisection; -1 if none.
template <class Holds>
int largest_k(const float_format& format, Holds holds)
{
    long good = -1, bad = format.max_exponent;
    while (bad - good > 1) {
        const long k = (good + bad) / 2;
        (holds(k) ? good : bad) = k;
    }
    return static_cast<int>(good);
}

bool additive(const instruction& in) { return in.op == opcode::add || in.op == opcode::sub || in.op == opcode::neg; }

} // namespace

int input_exponent_bound(const program& p, const std::vector<bool>& needed, float_format format)
{
    return largest_k(format, [&](long k) { return within(p, needed, k, format); });
}

range_cut cut_for_range(const program& p, const std::vector<bool>& needed)
{
    const std::size_t n = p.code.size();
    const auto is_needed = [&](std::size_t v) { return v < needed.size() && needed[v]; };
    std::vector<std::vector<int>> users(n);
    for (std::size_t i = 0; i < n; ++i)
        if (is_needed(i))
            for (int o : operands(p.code[i]))
                users[static_cast<std::size_t>(o)].push_back(static_cast<int>(i));
    std::vector<bool> output(n, false);
    for (int o : p.outputs)
        output[static_cast<std::size_t>(o)] = true;
    // Values that reach the outputs by sums alone (later values first: a user comes after).
    std::vector<bool> by_sums(n, false);
    for (std::size_t v = n; v-- > 0;) {
        if (!is_needed(v))
            continue;
        bool sums = output[v] || !users[v].empty();
        for (int u : users[v])
            sums = sums && additive(p.code[u]) && by_sums[u];
        by_sums[v] = sums;
    }
    const auto is_input = [&](int v) { return v >= 0 && p.code[v].op == opcode::input; };
    // A sum or difference of two inputs.
    const auto pairs = [&](int u) {
        const instruction& in = p.code[u];
        return (in.op == opcode::add || in.op == opcode::sub) && is_input(in.a) && is_input(in.b) && in.a != in.b;
    };
    std::vector<role> roles(n, role::computed);
    std::size_t inputs = 0;
    for (std::size_t v = 0; v < n; ++v) {
        if (!is_needed(v) || p.code[v].op != opcode::input)
            continue;
        ++inputs;
        // Finite where a tested sum or difference with another input is: at least one.
        bool untested = std::any_of(users[v].begin(), users[v].end(), pairs);
        for (int u : users[v])
            untested = untested && (pairs(u) || (additive(p.code[u]) && by_sums[u]));
        roles[v] = untested ? role::untested : role::tested;
    }
    range_cut cut;
    for (std::size_t v = 0; v < n; ++v) {
        if (!is_needed(v))
            continue;
        const instruction& in = p.code[v];
        if (roles[v] == role::tested || (pairs(static_cast<int>(v)) && (roles[in.a] == role::untested || roles[in.b] == role::untested))) {
            roles[v] = role::tested;
            cut.tested.push_back(static_cast<int>(v));
        }
    }
    // The outputs reached from an untested input (through sums only).
    std::vector<bool> summed(n, false);
    for (std::size_t v = 0; v < n; ++v) {
        if (!is_needed(v))
            continue;
        if (roles[v] == role::untested)
            summed[v] = true;
        else if (roles[v] == role::computed)
            for (int o : operands(p.code[v]))
                summed[v] = summed[v] || summed[static_cast<std::size_t>(o)];
    }
    for (std::size_t o = 0; o < p.outputs.size(); ++o)
        if (summed[static_cast<std::size_t>(p.outputs[o])])
            cut.summed.push_back(static_cast<int>(o));
    if (2 * cut.tested.size() + cut.summed.size() >= 2 * inputs) {  // no cheaper than the inputs
        cut = {};
        for (std::size_t v = 0; v < n; ++v)
            if (is_needed(v) && p.code[v].op == opcode::input)
                cut.tested.push_back(static_cast<int>(v));
    }
    return cut;
}

namespace {

// The roles of p's values under `cut`: its tested values, the other inputs untested.
std::vector<role> cut_roles(const program& p, const std::vector<bool>& needed, const range_cut& cut)
{
    std::vector<role> roles(p.code.size(), role::computed);
    for (std::size_t v = 0; v < p.code.size(); ++v)  // (an input p's outputs do not need bounds none of them)
        if (p.code[v].op == opcode::input && v < needed.size() && needed[v])
            roles[v] = role::untested;
    for (int v : cut.tested)
        roles[static_cast<std::size_t>(v)] = role::tested;
    return roles;
}

} // namespace

int cut_exponent_bound(const program& p, const std::vector<bool>& needed, const range_cut& cut, float_format format)
{
    const std::vector<role> roles = cut_roles(p, needed, cut);
    return largest_k(format, [&](long k) { return within(p, needed, k, format, roles); });
}

bool cut_bounds_within(const program& p, const std::vector<bool>& needed, const range_cut& cut, long k, float_format format, const std::vector<int>& values,
                       long lo, long hi)
{
    std::vector<exponents> e;
    if (!propagate(p, k, format.digits, e, cut_roles(p, needed, cut)))
        return false;
    return std::all_of(values.begin(), values.end(), [&](int v) {
        const exponents& b = e.at(static_cast<std::size_t>(v));
        return !b.summed && (b.zero || (b.lo >= lo && b.hi <= hi));
    });
}

} // namespace impact::compile
