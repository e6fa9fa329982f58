// How the LaTeX printer (latex.cpp) sees sums and products, shared with the line breaker
// (latex_lines.cpp), which breaks a displayed equation where the printer would write a
// term or a factor. Internal to emit.
#pragma once

#include "emit/latex.h"

#include <ginac/ginac.h>

#include <climits>
#include <string>
#include <utility>
#include <vector>

namespace impact::emit::detail {

using power_term = engine::term_order::power_term;

// Precedence levels: an operand printed at `level` is parenthesised when its own level
// is lower (a sum inside a product, a product or a negative number as a power's base).
constexpr unsigned sum_level = 10;
constexpr unsigned product_level = 20;
constexpr unsigned atom_level = 30;

/// Registers print_tex's print functions with GiNaC (once).
void register_print_functions();

/// `e` printed in the context of `c` at precedence `level`.
std::string render(const GiNaC::ex& e, const print_tex& c, unsigned level);

/// A product as ± [leading fraction] numerator / denominator, each factor placed where
/// the written product has it (numbers first, then `term_order`, when not written).
struct placed {
    power_term factor;
    int index = INT_MAX;     ///< the position in the written product
    std::string key;         ///< term_order's key, for what the text does not place
};

struct product_parts {
    bool negated = false;
    GiNaC::numeric leading = 1;   ///< ½ of `1/2*m*v^2`, typeset before the rest
    std::vector<placed> numerator;
    std::vector<placed> denominator;
};

/// A product split into the parts it is printed as.
product_parts split(const GiNaC::ex& product, const print_tex& c);

/// Prints the parts of a product into `c`.
void print_parts(const product_parts& f, const print_tex& c, unsigned level);

/// Each term of a sum with the sign it is written with: "-" for the first term when
/// negative, "+ " or "- " before the others.
std::vector<std::pair<std::string, GiNaC::ex>> signed_terms(const GiNaC::ex& sum, const print_tex& c);

} // namespace impact::emit::detail
