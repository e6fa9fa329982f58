// A derivation as text for the terminal (`impact derive`): its givens, each step with what
// it yields and its checks, the results, every check with its verdict, and the paper's
// printed forms compared. Expressions in GiNaC's syntax, as a derivation file writes them.
#pragma once

#include "engine/derivation/derivation.h"

#include <string>

namespace impact::emit {

/// The text `impact derive` prints for `d`.
std::string terminal_text(const engine::derivation& d);

} // namespace impact::emit
