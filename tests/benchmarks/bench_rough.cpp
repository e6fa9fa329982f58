// Speed of the rough-sphere kernel beside the smooth one, side by side in one run: a
// benchmark, never a test. Each iteration makes one pass of each loop over the same 4 096
// approaching pairs in 2D (in cache), in an order that turns from one iteration to the
// next, velocities and spins reset untimed before each pass: `collide` (Eq. 9, smooth),
// `collide_rough` (Walton's model, half the pairs sticking and half sliding), each scalar
// and batch. It prints pairs per second and the ratio rough / smooth, with the instruction
// set the loops were compiled for and the processor they ran on.

#include "impact/impact.hpp"
#include "machine.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t pairs = 4096;

struct pair_data {
    std::vector<double> M, m, R_M, R_m, q_M, q_m, eps, beta, mu, w_M, w_m;
    std::array<std::vector<double>, 2> C_M, C_m, v_M, v_m;
};

pair_data drawn()
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 2), fraction(0, 1);
    pair_data p;
    for (std::size_t i = 0; i < pairs; ++i) {
        p.M.push_back(positive(random));
        p.m.push_back(positive(random));
        p.R_M.push_back(positive(random));
        p.R_m.push_back(positive(random));
        p.q_M.push_back(0.4);
        p.q_m.push_back(2.0 / 3);
        p.eps.push_back(fraction(random));
        p.beta.push_back(unit(random));
        p.mu.push_back(i % 2 ? 0.05 : 5.0);  // sliding, sticking
        p.w_M.push_back(unit(random));
        p.w_m.push_back(unit(random));
        const double angle = 6.283185307179586 * fraction(random);
        for (std::size_t a = 0; a < 2; ++a) {
            p.C_M[a].push_back(0);
            p.C_m[a].push_back(a == 0 ? std::cos(angle) : std::sin(angle));
            // M moves towards m, m stands: every pair approaches.
            p.v_M[a].push_back((a == 0 ? std::cos(angle) : std::sin(angle)) + 0.3 * unit(random));
            p.v_m[a].push_back(0);
        }
    }
    return p;
}

// A batch's arrays that collide and collide_rough share: masses, eps, centres, velocities, status.
template <class Data>
Data shared_arrays(pair_data& p, std::vector<impact::status>& status)
{
    Data d{};
    d.count = pairs;
    d.M = p.M.data();
    d.m = p.m.data();
    d.eps = p.eps.data();
    for (std::size_t a = 0; a < 2; ++a) {
        d.C_M[a] = p.C_M[a].data();
        d.C_m[a] = p.C_m[a].data();
        d.v_M[a] = p.v_M[a].data();
        d.v_m[a] = p.v_m[a].data();
    }
    d.status = status.data();
    return d;
}

enum loop { smooth_scalar, rough_scalar, smooth_batch, rough_batch, loops };
const char* const names[] = {"collide", "collide_rough", "collide_batch", "collide_rough_batch"};

void side_by_side(benchmark::State& state)
{
    const pair_data start = drawn();
    pair_data p = start;
    std::array<double, loops> seconds{};
    std::vector<impact::status> status(pairs);
    double sink = 0;
    std::size_t turn = 0;
    for (auto _ : state) {
        double iteration = 0;
        for (std::size_t k = 0; k < loops; ++k) {
            const loop which = static_cast<loop>((k + turn) % loops);
            p.v_M = start.v_M;
            p.v_m = start.v_m;
            p.w_M = start.w_M;
            p.w_m = start.w_m;
            const auto began = std::chrono::steady_clock::now();
            switch (which) {
            case smooth_scalar:
                for (std::size_t i = 0; i < pairs; ++i) {
                    using v2 = std::array<double, 2>;
                    const auto r = impact::collide(p.M[i], p.m[i], v2{p.C_M[0][i], p.C_M[1][i]},
                                                   v2{p.C_m[0][i], p.C_m[1][i]}, v2{p.v_M[0][i], p.v_M[1][i]},
                                                   v2{p.v_m[0][i], p.v_m[1][i]}, p.eps[i]);
                    sink += r.v_M[0];
                }
                break;
            case rough_scalar:
                for (std::size_t i = 0; i < pairs; ++i) {
                    const auto r = impact::collide_rough(
                        p.M[i], p.m[i], p.R_M[i], p.R_m[i], p.q_M[i], p.q_m[i], {p.C_M[0][i], p.C_M[1][i]},
                        {p.C_m[0][i], p.C_m[1][i]}, {p.v_M[0][i], p.v_M[1][i]}, {p.v_m[0][i], p.v_m[1][i]}, p.w_M[i],
                        p.w_m[i], p.eps[i], p.beta[i], p.mu[i]);
                    sink += r.v_M[0] + r.w_M;
                }
                break;
            case smooth_batch: {
                auto d = shared_arrays<impact::collide_batch_data<double, 2>>(p, status);
                impact::collide_batch(d);
                break;
            }
            case rough_batch: {
                auto d = shared_arrays<impact::collide_rough_batch_data<double, 2>>(p, status);
                d.R_M = p.R_M.data();
                d.R_m = p.R_m.data();
                d.q_M = p.q_M.data();
                d.q_m = p.q_m.data();
                d.beta = p.beta.data();
                d.mu = p.mu.data();
                d.w_M = p.w_M.data();
                d.w_m = p.w_m.data();
                impact::collide_rough_batch(d);
                break;
            }
            default: break;
            }
            benchmark::ClobberMemory();
            const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
            seconds[which] += took;
            iteration += took;
        }
        ++turn;
        state.SetIterationTime(iteration);
    }
    benchmark::DoNotOptimize(sink);
    for (std::size_t k = 0; k < loops; ++k)
        state.counters[names[k]] = static_cast<double>(pairs) * static_cast<double>(state.iterations()) / seconds[k] / 1e6;
    state.counters["rough/smooth scalar"] = seconds[smooth_scalar] / seconds[rough_scalar];
    state.counters["rough/smooth batch"] = seconds[smooth_batch] / seconds[rough_batch];
}

} // namespace

BENCHMARK(side_by_side)->UseManualTime()->Repetitions(5)->ReportAggregatesOnly(true);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    std::printf("M/s: million pairs per second, in cache (%zu pairs, 2D); rough/smooth: the rough kernel's speed "
                "as a share of the smooth one's. Compiled for %s.\n",
                pairs, impact::benchmarks::isa().c_str());
    return 0;
}
