// Infix printing of GiNaC expressions in a deterministic order.
//
// `print_infix` is a GiNaC print context of Impact's own: print functions registered
// for numbers, symbols, sums, products and powers write operands in `term_order`
// (never GiNaC's run-dependent order) with the fewest parentheses the precedences
// need. Its `infix_style` decides the spelling; `print_ginac_syntax` (text GiNaC's parser
// reads back, used in derivations.json and messages) derives from it.
#pragma once

#include "engine/expr/order.h"

#include <ginac/ginac.h>

#include <string>

namespace impact::engine {

/// How an infix printer spells operators, numbers and functions.
struct infix_style {
    const char* times;
    const char* plus;
    const char* minus;
    const char* divide;
    const char* functions;    ///< prefix of function names, e.g. "std::"
    bool typed_numbers;       ///< numbers as `Real(2)` rather than `2`
    bool powers_as_products;  ///< x^2 as `x * x`, x^(1/2) as sqrt, others as pow(x, e)
};

class print_infix : public GiNaC::print_context {
    GINAC_DECLARE_PRINT_CONTEXT(print_infix, GiNaC::print_context)
public:
    print_infix(std::ostream& os, const term_order& order, infix_style style);
    const term_order* order = nullptr;
    infix_style style{};
};

/// GiNaC's syntax (`(M*v_M+m*v_m)/(M+m)`), operands in a fixed order.
class print_ginac_syntax : public print_infix {
    GINAC_DECLARE_PRINT_CONTEXT(print_ginac_syntax, print_infix)
public:
    print_ginac_syntax(std::ostream& os, const term_order& order);
};

/// Prints `e` with an infix context (of either kind).
void print_expression(const GiNaC::ex& e, const print_infix& c);

/// An expression in GiNaC's syntax, deterministic from run to run.
std::string ginac_syntax(const GiNaC::ex& e, const term_order& order);

} // namespace impact::engine
