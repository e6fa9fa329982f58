// LaTeX emitter: GiNaC expressions → LaTeX math, derivations → LaTeX fragments.
//
// `print_tex` is a GiNaC print context of Impact's own: symbols are written with the
// LaTeX names their derivation file gives, quotients as \frac, square roots as \sqrt,
// operands in `term_order` so that the text is the same on every run.
#pragma once

#include "engine/order.h"
#include "engine/derive.h"

#include <ginac/ginac.h>

#include <string>

namespace impact::emit {

using engine::term_order;

class print_tex : public GiNaC::print_context {
    GINAC_DECLARE_PRINT_CONTEXT(print_tex, GiNaC::print_context)
public:
    print_tex(std::ostream& os, const term_order& order);
    const term_order* order = nullptr;
};

/// An expression as LaTeX math (without the surrounding `$`).
std::string latex(const GiNaC::ex& e, const term_order& order);

/// A check's claim as LaTeX math: `\lim_{v_\perp \to \infty} \cos\theta = 0`, `\Delta E_K \leq 0`.
std::string claim_math(const engine::check_result& c, const term_order& order);

/// Plain text escaped for LaTeX.
std::string latex_text(const std::string& text);

/// The LaTeX fragment of one derivation: givens, steps, results, checks.
std::string latex_fragment(const engine::derivation& d);

/// The file name of a derivation's fragment (`<id>.tex`).
std::string latex_fragment_name(const engine::derivation& d);

} // namespace impact::emit
