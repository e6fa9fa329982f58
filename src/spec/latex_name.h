// How a symbol the derivation file gives no `latex` is typeset: made from its name by the
// conventions physicists write names in, so that a file nobody here wrote typesets
// properly without a `latex` for every symbol.
#pragma once

#include <string>

namespace impact::spec {

/// The LaTeX of a name: the part before the first `_` is the symbol, the parts after it its
/// subscripts, separated by commas (`a_10` → a_{10}, `r_x_1` → r_{x,1}); digits that end a
/// name without `_` are a subscript (`v1` → v_{1}); a trailing `_after` primes it
/// (`v_M_after` → v'_{M}); a Greek letter's name is the letter (`theta_1` → \theta_{1},
/// `eps` → \epsilon), `perp` and `par` are ⊥ and ∥; a word of several letters is set upright
/// as a subscript (`t_top` → t_{\mathrm{top}}) and in italics as a symbol (`vel` → \mathit{vel}).
std::string latex_of_name(const std::string& name);

} // namespace impact::spec
