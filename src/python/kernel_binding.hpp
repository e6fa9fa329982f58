// Impact's kernels called on NumPy arrays: what the generated binding sources (emit/python.h)
// describe each kernel with, and the calls they are made through (docs/python.md).
//
// A kernel is described by its parameters and outputs, each a scalar or a vector of N
// components, and two runners, for float and double, that run it over `columns`: one array
// of values per component. The call turns its arguments into such columns: NumPy's rules of
// broadcasting over the leading axes (a vector's components on its last), float32 when every
// array among the arguments is float32 and float64 otherwise, a column taken as it is where it
// is contiguous already and copied once where it is not (the batch loop's layout, one
// contiguous array per component, is taken without a copy). The loop runs with the GIL
// released. Each output is one array of `count` values per component, returned as an array
// of the broadcast shape (with the components last); a kernel with a status returns its
// outputs and `status` as a named tuple, one returning a scalar that scalar's array.
#pragma once

#include "impact/common.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// Declared only: the generated sources that describe kernels do not parse pybind11's headers
// (five seconds a translation unit), only module.cpp and kernel_binding.cpp do.
namespace pybind11 {
class module_;
}

namespace impact::python {

/// A parameter of a kernel: its name and components (0: a scalar).
struct parameter {
    std::string name;
    std::size_t components = 0;
};

/// An output of a kernel: its name (the C++ result's member), components (0: a scalar), and
/// the parameter it is written over in the batch loop (named after it), or -1.
struct output {
    std::string name;
    std::size_t components = 0;
    int written_over = -1;
};

/// The arrays a runner runs a kernel over: input component j's value for pair i is
/// in[j][i * step[j]] (a step of 0 for one value shared by every pair, 1 otherwise), output
/// component j's is out[j][i]; `status` holds `count` statuses. In a batch call every step
/// is 1, and the runner copies each input written over into its output first.
struct columns {
    std::size_t count = 0;
    std::vector<const void*> in;
    std::vector<std::size_t> step;
    std::vector<void*> out;
    impact::status* status = nullptr;
};

/// A batch runner's copy of an input written over into its output's column, before the loop;
/// none where the caller passed that input's own array as the output (`out=`, in place).
template <class Real>
inline void copy_over(const void* in, Real* out, std::size_t count) noexcept
{
    const Real* const from = static_cast<const Real*>(in);
    if (from != out)
        std::copy_n(from, count, out);
}

/// Whether some input of the columns is one value shared by every pair (a step of 0): the
/// scalar loops index the others without a multiplication.
inline bool strided(const columns& c) noexcept
{
    for (std::size_t s : c.step)
        if (s != 1)
            return true;
    return false;
}

// A runner, of a scalar loop or of a batch loop, is compiled twice where GCC can choose between
// clones when the module loads (x86-64 on Linux): for the baseline and for x86-64-v3 (AVX2 and
// FMA), with the kernel inlined into each (`flatten`; the runners are compiled under the
// kernels' own options, IMPACT_PRECISE_BEGIN, without which GCC inlines none of the kernels'
// functions), so that its std::fma are one instruction, not a call to libm's emulation, and a
// batch loop a vector loop, where the processor has FMA. The results are the same: an FMA
// rounds once either way, and the kernels are compiled without contraction (-ffp-contract=off).
// The batch loops so compiled ran 4.2 times as fast (3D collide's 4 million pairs, 282 ms to
// 67.5 ms; docs/python.md); the module from nothing took 164 s of CPU against 96 s.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define IMPACT_PYTHON_LOOP __attribute__((target_clones("arch=x86-64-v3", "default"), flatten))
#else
#define IMPACT_PYTHON_LOOP
#endif

/// Runs a kernel over the columns in one floating-point type, its fast form if `fast`.
using runner = void (*)(const columns& c, bool fast) noexcept;

/// A kernel as the generated bindings describe it.
struct kernel_entry {
    std::string name;
    std::size_t dimension = 0;  ///< the components of its vectors; 0 without vectors
    std::vector<parameter> parameters;
    std::vector<output> outputs;
    bool status = false;          ///< whether its result carries a status
    bool returns_scalar = false;  ///< whether it returns its one output (NaN where refused)
    bool batch = false;           ///< whether the runner calls the batch loop
    std::string doc;
    runner run_float = nullptr;
    runner run_double = nullptr;
};

/// The kernels of the module, each added by its derivation file's binding; kernels of one
/// name in several dimensions (collide in 2D and 3D) become one Python function, which takes
/// the dimension from the shape of its first vector argument.
class registry {
public:
    void add(kernel_entry entry);
    /// Defines one function of the module for each name added, in the order first added.
    void define(pybind11::module_& m) const;

private:
    std::vector<kernel_entry> entries_;
};

/// `impact._impact.status_names`: each status's name and value, in the order of the values.
void define_statuses(pybind11::module_& m, const std::vector<std::pair<std::string, impact::status>>& statuses);

} // namespace impact::python
