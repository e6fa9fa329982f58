// Python emitter: the sources of the module `impact._impact`, the generated kernels bound for
// NumPy arrays with pybind11 (docs/python.md).
//
// Each derivation file gets one translation unit, `python/<file name without .toml>.cpp`
// (empty for a file without kernels, so that the build knows the sources from the folder of
// derivation files alone and compiles them side by side), which describes its kernels to
// src/python/kernel_binding.hpp: their parameters and outputs by name and shape, whether they
// have a status and a batch loop, and a loop calling the scalar kernel, or the batch kernel,
// for float and double, in the accurate and the fast form. `python/module.cpp` calls them all
// and names the statuses of `impact::status`. Everything is printed from the kernels as the
// engine describes them (engine::kernel), as the C++ headers are: a new kernel gets its
// binding when the sources are generated again.
#pragma once

#include "engine/library/library.h"

#include <map>
#include <string>

namespace impact::emit {

/// The binding sources for `lib`'s kernels, by path (`python/module.cpp`,
/// `python/<file name>.cpp` for every derivation file), in the library's order.
std::map<std::string, std::string> python_binding_files(const engine::library& lib);

/// The name of the function that binds the kernels of a derivation file, from its path:
/// `bind_eq08_inelastic_line` (every character but a letter, a digit or _ written as _).
std::string python_binder_name(const std::string& file);

} // namespace impact::emit
