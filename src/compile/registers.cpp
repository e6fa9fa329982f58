// The order of a straight-line program's operations for registers: how many values it
// holds at once, and an order that holds fewer (declared in compile/program.h).
#include "compile/program.h"

#include <algorithm>
#include <limits>

namespace impact::compile {

std::size_t most_live(const program& p)
{
    const std::size_t n = p.code.size();
    const std::vector<bool> needed = needed_by(p, 0, p.outputs.size());
    std::vector<std::size_t> first(n, n), last(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!needed[i])
            continue;
        if (!is_leaf(p.code[i]))
            first[i] = std::min(first[i], i);
        for (int operand : operands(p.code[i]))
            if (p.code[operand].op != opcode::constant) {
                first[operand] = std::min(first[operand], i);
                last[operand] = std::max(last[operand], i);
            }
    }
    for (int o : p.outputs)
        last[o] = n;
    std::vector<int> change(n + 1, 0);  // values becoming live, less those dying, at each step
    for (std::size_t v = 0; v < n; ++v)
        if (first[v] < last[v]) {
            ++change[first[v]];
            --change[last[v]];
        }
    std::size_t most = 0;
    long live = 0;
    for (std::size_t i = 0; i < n; ++i) {
        live += change[i];
        most = std::max(most, static_cast<std::size_t>(live));
    }
    return most;
}

program ordered_for_registers(const program& p)
{
    const std::size_t n = p.code.size();
    // What each division or square root waits for: the divisors that do not need it (a
    // square root: that need no square root, so that two roots never wait for each other).
    const std::vector<int> divided_by = divisors(p);
    std::vector<bool> needs_a_root(n, false);
    for (std::size_t i = 0; i < n; ++i) {
        needs_a_root[i] = p.code[i].op == opcode::sqrt;
        for (int operand : operands(p.code[i]))
            needs_a_root[i] = needs_a_root[i] || needs_a_root[operand];
    }
    std::vector<std::vector<int>> waits(n);
    for (std::size_t d = 0; d < n; ++d) {
        const bool root = p.code[d].op == opcode::sqrt;
        if (!divides(p, p.code[d]) && !root)
            continue;
        std::vector<bool> needs_d(n, false);
        needs_d[d] = true;
        for (std::size_t i = d + 1; i < n; ++i)
            for (int operand : operands(p.code[i]))
                needs_d[i] = needs_d[i] || needs_d[operand];
        for (int divisor : divided_by)
            if (!needs_d[divisor] && !(root && needs_a_root[divisor]))
                waits[d].push_back(divisor);
    }

    constexpr double never = std::numeric_limits<double>::infinity();
    std::vector<bool> done(n, false);
    std::vector<double> since(n, never);  // when a value was computed, or an input first read
    std::vector<int> order;               // the leaves first, as they were
    for (std::size_t i = 0; i < n; ++i)
        if (is_leaf(p.code[i])) {
            done[i] = true;
            order.push_back(static_cast<int>(i));
        }
    for (double step = 0; order.size() < n; ++step) {
        int best = -1;
        bool best_reads = true;  // reads an input not yet read
        double best_since = never;
        for (std::size_t i = 0; i < n; ++i) {
            if (done[i])
                continue;
            bool ready = true, reads = false;
            double oldest = never;
            for (int operand : operands(p.code[i])) {
                ready = ready && done[operand];
                if (p.code[operand].op == opcode::input && since[operand] == never)
                    reads = true;
                else if (p.code[operand].op != opcode::constant)
                    oldest = std::min(oldest, since[operand]);
            }
            for (int w : waits[i])
                ready = ready && done[w];
            if (ready && (best < 0 || (best_reads && !reads) || (!best_reads && !reads && oldest < best_since))) {
                best = static_cast<int>(i);
                best_reads = reads;
                best_since = oldest;
            }
        }
        if (best < 0)
            return p;  // divisions whose quotients make each other's divisors: no such order
        for (int operand : operands(p.code[best]))
            if (p.code[operand].op == opcode::input && since[operand] == never)
                since[operand] = step - 0.5;  // read just before the value is computed
        since[best] = step;
        done[best] = true;
        order.push_back(best);
    }

    std::vector<int> renumbered(n);
    for (std::size_t i = 0; i < n; ++i)
        renumbered[order[i]] = static_cast<int>(i);
    program q;
    q.inputs = p.inputs;
    for (int i : order) {
        instruction in = p.code[i];
        for (int* operand : {&in.a, &in.b, &in.c})
            if (*operand >= 0)
                *operand = renumbered[*operand];
        q.code.push_back(std::move(in));
    }
    for (int o : p.outputs)
        q.outputs.push_back(renumbered[o]);
    return q;
}

} // namespace impact::compile
