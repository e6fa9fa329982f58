// Speed of the rough-sphere kernel beside the smooth one, side by side in one run: a
// benchmark, never a test. Each iteration makes one pass of each loop over the same 4 096
// approaching pairs (in cache), in 2D and in 3D, in an order that turns from one iteration to the
// next, velocities and spins reset untimed before each pass: `collide` (Eq. 9, smooth),
// `collide_rough` (Walton's model, half the pairs sticking and half sliding), each scalar
// and batch. It prints pairs per second and the ratio rough / smooth, with the instruction
// set the loops were compiled for and the processor they ran on.

#include "impact/impact.hpp"
#include "machine.hpp"

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t pairs = 4096;

// The spins' arrays: one in 2D (about the axis out of the plane), three in 3D.
template <std::size_t N>
constexpr std::size_t spin_axes = N == 2 ? 1 : 3;

template <std::size_t N>
struct pair_data {
    std::vector<double> M, m, R_M, R_m, q_M, q_m, eps, beta, mu;
    std::array<std::vector<double>, N> C_M, C_m, v_M, v_m;
    std::array<std::vector<double>, spin_axes<N>> w_M, w_m;
};

template <std::size_t N>
pair_data<N> drawn()
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1, 1), positive(0.5, 2), fraction(0, 1);
    pair_data<N> p;
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
        for (std::size_t a = 0; a < spin_axes<N>; ++a) {
            p.w_M[a].push_back(unit(random));
            p.w_m[a].push_back(unit(random));
        }
        // A direction from M's centre to m's: on the unit circle, or on the unit sphere.
        const double angle = 6.283185307179586 * fraction(random);
        const double z = N == 2 ? 0 : unit(random), across = std::sqrt(1 - z * z);
        const double n[3] = {across * std::cos(angle), across * std::sin(angle), z};
        for (std::size_t a = 0; a < N; ++a) {
            p.C_M[a].push_back(0);
            p.C_m[a].push_back(n[a]);
            // M moves towards m, m stands: every pair approaches.
            p.v_M[a].push_back(n[a] + 0.3 * unit(random));
            p.v_m[a].push_back(0);
        }
    }
    return p;
}

template <std::size_t N>
std::array<double, N> at(const std::array<std::vector<double>, N>& v, std::size_t i)
{
    std::array<double, N> x;
    for (std::size_t a = 0; a < N; ++a)
        x[a] = v[a][i];
    return x;
}

// A spin as collide_rough takes it: a number in 2D, a 3-vector in 3D.
template <std::size_t N>
auto spin(const std::array<std::vector<double>, spin_axes<N>>& w, std::size_t i)
{
    if constexpr (N == 2)
        return w[0][i];
    else
        return at<3>(w, i);
}

// A batch's arrays that collide and collide_rough share: masses, eps, centres, velocities, status.
template <class Data, std::size_t N>
Data shared_arrays(pair_data<N>& p, std::vector<impact::status>& status)
{
    Data d{};
    d.count = pairs;
    d.M = p.M.data();
    d.m = p.m.data();
    d.eps = p.eps.data();
    for (std::size_t a = 0; a < N; ++a) {
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

template <std::size_t N>
void side_by_side(benchmark::State& state)
{
    const pair_data<N> start = drawn<N>();
    pair_data<N> p = start;
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
                    const auto r = impact::collide(p.M[i], p.m[i], at<N>(p.C_M, i), at<N>(p.C_m, i), at<N>(p.v_M, i),
                                                   at<N>(p.v_m, i), p.eps[i]);
                    sink += r.v_M[0];
                }
                break;
            case rough_scalar:
                for (std::size_t i = 0; i < pairs; ++i) {
                    const auto r = impact::collide_rough(p.M[i], p.m[i], p.R_M[i], p.R_m[i], p.q_M[i], p.q_m[i],
                                                         at<N>(p.C_M, i), at<N>(p.C_m, i), at<N>(p.v_M, i),
                                                         at<N>(p.v_m, i), spin<N>(p.w_M, i), spin<N>(p.w_m, i),
                                                         p.eps[i], p.beta[i], p.mu[i]);
                    if constexpr (N == 2)
                        sink += r.v_M[0] + r.w_M;
                    else
                        sink += r.v_M[0] + r.w_M[0];
                }
                break;
            case smooth_batch: {
                auto d = shared_arrays<impact::collide_batch_data<double, N>>(p, status);
                impact::collide_batch(d);
                break;
            }
            case rough_batch: {
                auto d = shared_arrays<impact::collide_rough_batch_data<double, N>>(p, status);
                d.R_M = p.R_M.data();
                d.R_m = p.R_m.data();
                d.q_M = p.q_M.data();
                d.q_m = p.q_m.data();
                d.beta = p.beta.data();
                d.mu = p.mu.data();
                if constexpr (N == 2) {
                    d.w_M = p.w_M[0].data();
                    d.w_m = p.w_m[0].data();
                } else {
                    for (std::size_t a = 0; a < 3; ++a) {
                        d.w_M[a] = p.w_M[a].data();
                        d.w_m[a] = p.w_m[a].data();
                    }
                }
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

BENCHMARK_TEMPLATE(side_by_side, 2)->Name("side_by_side_2d")->UseManualTime()->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_TEMPLATE(side_by_side, 3)->Name("side_by_side_3d")->UseManualTime()->Repetitions(5)->ReportAggregatesOnly(true);

int main(int argc, char** argv)
{
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    std::printf("M/s: million pairs per second, in cache (%zu pairs, in 2D and in 3D); rough/smooth: the rough kernel's speed "
                "as a share of the smooth one's. Compiled for %s.\n",
                pairs, impact::benchmarks::isa().c_str());
    return 0;
}
