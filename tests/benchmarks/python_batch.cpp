// The C++ side of tests/benchmarks/python_kernels.py (target benchmark_python): collide_batch in
// 3D, double, on `count` pairs in collide_batch_arrays, the best of `runs` runs, each on the
// velocities afresh (their copy not timed). Prints the best time in seconds and the statuses'
// checksum, so that the loop is not optimised away. Flags: the module's (-O3, -ffp-contract=off),
// and the loop compiled as the module's runners are (IMPACT_PYTHON_LOOP: for x86-64-v3 too, chosen
// when the program loads).
#include "impact/collide_3d.hpp"
#include "python/kernel_binding.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

IMPACT_PRECISE_BEGIN

IMPACT_PYTHON_LOOP void run(const impact::collide_batch_data<double, 3>& data) noexcept
{
    impact::collide_batch(data);
}

IMPACT_PRECISE_END

} // namespace

int main(int argc, char** argv)
{
    const std::size_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 4'000'000;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
    impact::collide_batch_arrays<double, 3> a(count);
    std::mt19937_64 random(1);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> mass(0.5, 2.0), eps(0.0, 1.0);
    std::vector<double> v(6 * count);
    for (std::size_t i = 0; i < count; ++i) {
        a.M()[i] = mass(random);
        a.m()[i] = mass(random);
        a.eps()[i] = eps(random);
        for (std::size_t k = 0; k < 3; ++k) {
            a.C_M(k)[i] = normal(random);
            a.C_m(k)[i] = normal(random);
        }
    }
    for (double& x : v)
        x = normal(random);
    double best = 1e300;
    long checksum = 0;
    for (int r = 0; r < runs; ++r) {
        for (std::size_t k = 0; k < 3; ++k) {
            std::copy_n(v.data() + k * count, count, a.v_M(k));
            std::copy_n(v.data() + (3 + k) * count, count, a.v_m(k));
        }
        const auto start = std::chrono::steady_clock::now();
        run(a.data());
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
        for (std::size_t i = 0; i < count; ++i)
            checksum += static_cast<long>(a.status()[i]);
    }
    std::printf("%.6f %ld\n", best, checksum);
}
