// What a block of pairs that the batch's sure block leaves costs: collide_batch in 2D, in
// cache (4 096 pairs), accurate and fast, on ordinary approaching pairs, and on the same
// pairs with a fixed sphere (a mass +infinity), a velocity of 1e-13 (below the accurate
// loop's input range in double) or a pair separating (its velocities swapped) in one pair of
// every block of 8, or of one block in 16. The sure block resolves a block with a separating
// pair itself; one with a fixed sphere or a velocity out of range it leaves, to the loop and
// the scalar kernel, and after a block it leaves it is not tried on the next 1, 2, 4 ... 16.
//
// A benchmark, never a test: each iteration makes one pass of every case, side by side, the
// velocities reset before each pass (untimed), and reports nanoseconds a pair and each case
// against the ordinary pairs of the same form.

#include "machine.hpp"
#include "impact/impact.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t pairs = 4096;

enum class trouble {
    none,
    fixed_every_block,
    fixed_one_block_in_16,
    tiny_every_block,
    tiny_one_block_in_16,
    separating_every_block,
    separating_one_block_in_16
};
constexpr std::array<trouble, 7> cases = {trouble::none,
                                          trouble::fixed_every_block,
                                          trouble::fixed_one_block_in_16,
                                          trouble::tiny_every_block,
                                          trouble::tiny_one_block_in_16,
                                          trouble::separating_every_block,
                                          trouble::separating_one_block_in_16};
constexpr const char* case_names[] = {"ordinary",
                                      "fixed sphere, every block",
                                      "fixed sphere, 1 block in 16",
                                      "velocity 1e-13, every block",
                                      "velocity 1e-13, 1 block in 16",
                                      "separating, every block",
                                      "separating, 1 block in 16"};

struct batch {
    std::vector<double> M, m, eps;
    std::array<std::vector<double>, 2> C_M, C_m, v_M, v_m, v_M0, v_m0;
    std::vector<impact::status> status;

    explicit batch(trouble t)
        : M(pairs), m(pairs), eps(pairs, 0.5), status(pairs)
    {
        for (auto* a : {&C_M, &C_m, &v_M, &v_m, &v_M0, &v_m0})
            for (auto& axis : *a)
                axis.resize(pairs);
        for (std::size_t i = 0; i < pairs; ++i) {
            M[i] = 1.5 + 0.125 * static_cast<double>(i % 5);
            m[i] = 0.75 + 0.25 * static_cast<double>(i % 3);
            C_M[0][i] = -1;
            C_M[1][i] = 0.25 + 0.01 * static_cast<double>(i % 7);
            C_m[0][i] = 1;
            C_m[1][i] = -0.5;
            v_M0[0][i] = 2;  // towards m
            v_M0[1][i] = 0.5;
            v_m0[0][i] = -1;
            v_m0[1][i] = 0.125;
            const bool every = i % 8 == 3, sparse = i % 128 == 3;
            if ((t == trouble::fixed_every_block && every) || (t == trouble::fixed_one_block_in_16 && sparse))
                M[i] = std::numeric_limits<double>::infinity();
            if ((t == trouble::tiny_every_block && every) || (t == trouble::tiny_one_block_in_16 && sparse))
                v_M0[1][i] = 1e-13;
            if ((t == trouble::separating_every_block && every) || (t == trouble::separating_one_block_in_16 && sparse))
                for (std::size_t k = 0; k < 2; ++k)
                    std::swap(v_M0[k][i], v_m0[k][i]);
        }
    }
    impact::collide_batch_data<double, 2> reset()
    {
        v_M = v_M0;
        v_m = v_m0;
        impact::collide_batch_data<double, 2> d{};
        d.count = pairs;
        d.M = M.data();
        d.m = m.data();
        d.eps = eps.data();
        for (std::size_t k = 0; k < 2; ++k) {
            d.C_M[k] = C_M[k].data();
            d.C_m[k] = C_m[k].data();
            d.v_M[k] = v_M[k].data();
            d.v_m[k] = v_m[k].data();
        }
        d.status = status.data();
        return d;
    }
};

template <bool fast>
void blocks_left(benchmark::State& state)
{
    std::vector<batch> batches;
    for (trouble t : cases)
        batches.emplace_back(t);
    std::array<double, cases.size()> seconds{};
    for (auto _ : state) {
        double pass = 0;
        for (std::size_t c = 0; c < cases.size(); ++c) {
            const impact::collide_batch_data<double, 2> d = batches[c].reset();
            const auto start = std::chrono::steady_clock::now();
            if constexpr (fast)
                impact::collide_batch(d, impact::fast);
            else
                impact::collide_batch(d);
            benchmark::ClobberMemory();
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            seconds[c] += elapsed;
            pass += elapsed;
        }
        state.SetIterationTime(pass);
    }
    const double passes = static_cast<double>(state.iterations());
    for (std::size_t c = 0; c < cases.size(); ++c) {
        state.counters[std::string(case_names[c]) + " ns"] = seconds[c] / passes / pairs * 1e9;
        state.counters[std::string(case_names[c]) + " / ordinary"] = seconds[c] / seconds[0];
    }
}

} // namespace

BENCHMARK(blocks_left<false>)->Name("accurate")->UseManualTime()->Repetitions(7)->ReportAggregatesOnly(true);
BENCHMARK(blocks_left<true>)->Name("fast")->UseManualTime()->Repetitions(7)->ReportAggregatesOnly(true);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    std::printf("\ncollide_batch in 2D, %zu pairs in cache; medians of 7 (the `_median` rows). Compiled for %s.\n", pairs,
                impact::benchmarks::isa().c_str());
    return 0;
}
