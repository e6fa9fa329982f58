// The order of a straight-line program's operations for registers: how many values it
// holds at once, and an order that holds fewer (declared in compile/program.h).
#include "compile/program.h"

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

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
    // square root: that need no square root, so that two roots never wait for each other);
    // a division by an early divisor, or a root, only the early ones (compile::grouped_divisors:
    // a late divisor needs divisions by early ones, which must not wait for it).
    const divisor_groups groups = grouped_divisors(p);
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
        const bool by_late = !root && groups.is_late(p.code[d].b);
        for (int divisor : by_late ? divided_by : groups.early)
            if (!needs_d[divisor] && !(root && needs_a_root[divisor]))
                waits[d].push_back(divisor);
    }

    // The scheduler: a value is ready when its operands and what it waits for are done. Of
    // the ready ones, the first (in the original order) of those that read no input not yet
    // read and whose oldest operand is oldest, or else the first of those that read one.
    // A ready value's key changes only when an input it reads is first read.
    constexpr double never = std::numeric_limits<double>::infinity();
    std::vector<bool> done(n, false);
    std::vector<double> since(n, never);  // when a value was computed, or an input first read
    std::vector<int> order;               // the leaves first, as they were
    std::vector<int> pending(n, 0);       // operands and waits not yet done
    std::vector<std::vector<int>> unblocks(n), readers(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (is_leaf(p.code[i])) {
            done[i] = true;
            order.push_back(static_cast<int>(i));
            continue;
        }
        for (int operand : operands(p.code[i])) {
            if (p.code[operand].op == opcode::input)
                readers[operand].push_back(static_cast<int>(i));
            if (!is_leaf(p.code[operand])) {
                ++pending[i];
                unblocks[operand].push_back(static_cast<int>(i));
            }
        }
        for (int w : waits[i]) {
            if (is_leaf(p.code[w]))
                continue;
            ++pending[i];
            unblocks[w].push_back(static_cast<int>(i));
        }
    }
    using key = std::tuple<bool, double, int>;  // reads a new input, oldest operand, index
    const auto key_of = [&](int i) {
        bool reads = false;
        double oldest = never;
        for (int operand : operands(p.code[i])) {
            if (p.code[operand].op == opcode::input && since[operand] == never)
                reads = true;
            else if (p.code[operand].op != opcode::constant)
                oldest = std::min(oldest, since[operand]);
        }
        return reads ? key{true, 0.0, i} : key{false, oldest, i};
    };
    std::set<key> ready;
    std::vector<key> key_now(n);
    std::vector<bool> is_ready(n, false);
    const auto make_ready = [&](int i) {
        key_now[i] = key_of(i);
        ready.insert(key_now[i]);
        is_ready[i] = true;
    };
    for (std::size_t i = 0; i < n; ++i)
        if (!done[i] && pending[i] == 0)
            make_ready(static_cast<int>(i));
    for (double step = 0; order.size() < n; ++step) {
        if (ready.empty())
            return p;  // divisions whose quotients make each other's divisors: no such order
        const int best = std::get<2>(*ready.begin());
        ready.erase(ready.begin());
        is_ready[best] = false;
        for (int operand : operands(p.code[best]))
            if (p.code[operand].op == opcode::input && since[operand] == never) {
                since[operand] = step - 0.5;  // read just before the value is computed
                for (int reader : readers[operand])
                    if (is_ready[reader]) {
                        ready.erase(key_now[reader]);
                        make_ready(reader);
                    }
            }
        since[best] = step;
        done[best] = true;
        order.push_back(best);
        for (int next : unblocks[best])
            if (--pending[next] == 0)
                make_ready(next);
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
