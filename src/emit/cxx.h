// C++ emitter: kernel plans → header-only C++17 kernels.
//
// Each derivation with kernels gets a header named after the function it defines
// (`impact/collide_line.hpp`; `impact/collide_2d.hpp` and `collide_3d.hpp` for the overloads
// of `collide` on arrays of 2 and 3 components; `impact/<id>.hpp` when it defines several
// kernels), whose banner names the derivation file and the paper's equation;
// `impact/common.hpp` holds what
// kernels share (the status enum, the result and batch structures of array kernels
// emitted in several dimensions), and `impact/impact.hpp` includes everything. The
// arithmetic is the kernel plan's program, printed statement by statement
// (compile/program.h, printed by emit/program_cxx.h), so the code is exactly what was measured.
#pragma once

#include "verify/choice.h"
#include "engine/derivation/derivation.h"
#include "engine/library/library.h"
#include "engine/expr/infix.h"

#include <map>
#include <string>
#include <vector>

namespace impact::emit {

using engine::term_order;
using verify::kernel_plan;

/// The header of one derivation's kernels; `plans` are those kernels' plans, in order, each
/// followed by the plans of its fixed spheres' kernels (`engine::kernel::limits`).
std::string kernel_header(const engine::derivation& d, const std::vector<const kernel_plan*>& plans);

/// The file name of a derivation's kernel header: its kernel's name, with `_<N>d` when the
/// kernel takes arrays of N components; the derivation's id when it has several kernels.
std::string kernel_header_name(const engine::derivation& d);

/// `impact/common.hpp`: the status enum and the structures array kernels share; its banner
/// names `folder`, the derivation files' (engine::source_folder).
std::string common_header(const std::vector<const kernel_plan*>& plans, const std::string& folder);

/// The umbrella header `impact/impact.hpp` including every kernel header.
std::string umbrella_header(const std::vector<const engine::derivation*>& with_kernels);

/// Every kernel header (`kernels/impact/<name>.hpp`, common.hpp, impact.hpp) for `lib`,
/// whose kernels' plans are `plans`, in the library's order.
std::map<std::string, std::string> kernel_files(const engine::library& lib,
                                                const std::vector<verify::kernel_plan>& plans);

} // namespace impact::emit
