// C++ emitter: GiNaC expressions → C++17 source, and derivations → kernel headers.
//
// The printer is a GiNaC print context of Impact's own (`print_cxx`): it writes
// `std::sqrt` rather than `pow(x,1.0/2.0)`, small integer powers as products,
// numbers as literals of the kernel's floating-point type `Real`, and qualifies
// functions with `std::`.
#pragma once

#include "engine/infix.h"
#include "engine/derive.h"

#include <ginac/ginac.h>

#include <string>

namespace impact::emit {

using engine::print_infix;
using engine::term_order;

/// The C++ print context: `std::` functions, `Real(2)` literals, x * x for x^2.
class print_cxx : public print_infix {
    GINAC_DECLARE_PRINT_CONTEXT(print_cxx, print_infix)
public:
    print_cxx(std::ostream& os, const term_order& order);
};

/// An expression as C++ source, its numbers of type `Real`.
std::string cxx(const GiNaC::ex& e, const term_order& order);

/// The header-only kernel file for one derivation (`output/kernels/impact/<id>.hpp`).
std::string kernel_header(const engine::derivation& d);

/// The file name of a derivation's kernel header.
std::string kernel_header_name(const engine::derivation& d);

/// The umbrella header `impact/impact.hpp` including every kernel header.
std::string umbrella_header(const std::vector<const engine::derivation*>& with_kernels);

} // namespace impact::emit
