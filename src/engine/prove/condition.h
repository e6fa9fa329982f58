// A condition for an expression to be defined in the reals (definedness.h finds them):
// what a claim rests on, and what a proof or a sample may assume (sign.h's assumptions).
#pragma once

#include <ginac/ginac.h>

#include <string>

namespace impact::engine {

/// One condition for an expression to be defined in the reals: `expr` != 0, > 0 or >= 0.
struct condition {
    enum class kind { nonzero, positive, nonnegative };
    GiNaC::ex expr;
    kind need = kind::nonzero;
    std::string text;      ///< as the terminal writes it, e.g. "x != y", "p > 0", "1 >= u^2"
    std::string because;   ///< what needs it: "a divisor", "a radicand", "the argument of log", ...
};

} // namespace impact::engine
