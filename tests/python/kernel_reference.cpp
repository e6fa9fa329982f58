// The C++ kernels called pair by pair, for tests/python/test_kernels.py to compare the Python
// module's results with, bit for bit: a few kernels, each through its scalar kernel (the
// module calls the batch loop where one exists, and that one's scalar loop otherwise).
//
//     kernel_reference <kernel> <float|double> <accurate|fast> <count> <inputs> <outputs>
//
// <inputs> holds each input component's `count` values in turn (native byte order), the
// components in the order of the kernel's parameters; <outputs> receives each output
// component's values in turn, then the statuses as 64-bit integers when the kernel has them.
#include "impact/impact.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

template <class Real>
using pair_kernel = std::int64_t (*)(const Real* x, Real* y, bool fast);

template <class Real>
std::int64_t collide_line(const Real* x, Real* y, bool fast)
{
    const auto r = fast ? impact::collide_line<Real>(x[0], x[1], x[2], x[3], x[4], impact::fast)
                        : impact::collide_line<Real>(x[0], x[1], x[2], x[3], x[4]);
    y[0] = r.v_M;
    y[1] = r.v_m;
    y[2] = r.J;
    return static_cast<std::int64_t>(r.status);
}

template <class Real>
std::int64_t energy_loss(const Real* x, Real* y, bool fast)
{
    y[0] = fast ? impact::energy_loss<Real>(x[0], x[1], x[2], x[3], x[4], impact::fast)
                : impact::energy_loss<Real>(x[0], x[1], x[2], x[3], x[4]);
    return 0;
}

template <class Real>
std::int64_t collide_3d(const Real* x, Real* y, bool fast)
{
    using v3 = std::array<Real, 3>;
    const v3 C_M{x[2], x[3], x[4]}, C_m{x[5], x[6], x[7]}, v_M{x[8], x[9], x[10]}, v_m{x[11], x[12], x[13]};
    const auto r = fast ? impact::collide<Real>(x[0], x[1], C_M, C_m, v_M, v_m, x[14], impact::fast)
                        : impact::collide<Real>(x[0], x[1], C_M, C_m, v_M, v_m, x[14]);
    for (int i = 0; i < 3; ++i) {
        y[i] = r.v_M[i];
        y[3 + i] = r.v_m[i];
    }
    return static_cast<std::int64_t>(r.status);
}

template <class Real>
std::int64_t collide_rough_2d(const Real* x, Real* y, bool fast)
{
    using v2 = std::array<Real, 2>;
    const v2 C_M{x[6], x[7]}, C_m{x[8], x[9]}, v_M{x[10], x[11]}, v_m{x[12], x[13]};
    const auto r = fast ? impact::collide_rough<Real>(x[0], x[1], x[2], x[3], x[4], x[5], C_M, C_m, v_M, v_m, x[14],
                                                      x[15], x[16], x[17], x[18], impact::fast)
                        : impact::collide_rough<Real>(x[0], x[1], x[2], x[3], x[4], x[5], C_M, C_m, v_M, v_m, x[14],
                                                      x[15], x[16], x[17], x[18]);
    y[0] = r.v_M[0];
    y[1] = r.v_M[1];
    y[2] = r.v_m[0];
    y[3] = r.v_m[1];
    y[4] = r.w_M;
    y[5] = r.w_m;
    return static_cast<std::int64_t>(r.status);
}

template <class Real>
int run(pair_kernel<Real> kernel, std::size_t inputs, std::size_t outputs, bool status, bool fast, std::size_t count,
        const char* in_path, const char* out_path)
{
    std::vector<Real> in(inputs * count), out(outputs * count);
    std::vector<std::int64_t> statuses(count);
    std::ifstream in_file(in_path, std::ios::binary);
    if (!in_file.read(reinterpret_cast<char*>(in.data()), static_cast<std::streamsize>(in.size() * sizeof(Real)))) {
        std::fprintf(stderr, "kernel_reference: %s holds fewer than %zu values\n", in_path, in.size());
        return 2;
    }
    std::vector<Real> x(inputs), y(outputs);
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t j = 0; j < inputs; ++j)
            x[j] = in[j * count + i];
        statuses[i] = kernel(x.data(), y.data(), fast);
        for (std::size_t j = 0; j < outputs; ++j)
            out[j * count + i] = y[j];
    }
    std::ofstream out_file(out_path, std::ios::binary);
    out_file.write(reinterpret_cast<const char*>(out.data()), static_cast<std::streamsize>(out.size() * sizeof(Real)));
    if (status)
        out_file.write(reinterpret_cast<const char*>(statuses.data()),
                       static_cast<std::streamsize>(statuses.size() * sizeof(std::int64_t)));
    return out_file ? 0 : 2;
}

template <class Real>
int run_named(const std::string& kernel, bool fast, std::size_t count, const char* in, const char* out)
{
    if (kernel == "collide_line")
        return run<Real>(collide_line<Real>, 5, 3, true, fast, count, in, out);
    if (kernel == "energy_loss")
        return run<Real>(energy_loss<Real>, 5, 1, false, fast, count, in, out);
    if (kernel == "collide_3d")
        return run<Real>(collide_3d<Real>, 15, 6, true, fast, count, in, out);
    if (kernel == "collide_rough_2d")
        return run<Real>(collide_rough_2d<Real>, 19, 6, true, fast, count, in, out);
    std::fprintf(stderr, "kernel_reference: no kernel %s\n", kernel.c_str());
    return 2;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 7) {
        std::fprintf(stderr, "usage: kernel_reference <kernel> <float|double> <accurate|fast> <count> <inputs> <outputs>\n");
        return 2;
    }
    const std::string type = argv[2];
    const bool fast = std::string(argv[3]) == "fast";
    const std::size_t count = std::strtoull(argv[4], nullptr, 10);
    if (type == "float")
        return run_named<float>(argv[1], fast, count, argv[5], argv[6]);
    return run_named<double>(argv[1], fast, count, argv[5], argv[6]);
}
