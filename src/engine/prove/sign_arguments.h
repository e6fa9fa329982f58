// Signs settled by an argument about one symbol, where the signs of the parts do not
// settle them (sign.h tries these last).
//
// Sturm's theorem (Sturm, 1829; Basu, Pollack and Roy, "Algorithms in Real Algebraic
// Geometry", Ch. 2): a square-free polynomial q in one symbol s with rational coefficients
// has, on an interval (a, b) whose ends are not roots, as many distinct real roots as its
// Sturm sequence q, q', −rem(q, q'), ... loses sign changes between a and b. A polynomial whose factors of odd multiplicity have
// no root inside the interval keeps one sign there, read at one inner point; a root at an
// included end, or of a factor of even multiplicity, adds zero.
//
// Monotonicity: a polynomial in s (whatever its other symbols) whose derivative in s has a
// proven sign on s's interval lies between its values at the ends, so the sign of the
// value at one end settles it (x³ + x − 1 on [1, 2]: 3x² + 1 > 0 and 1 > 0 at x = 1).
#pragma once

#include "engine/prove/sign.h"

#include <functional>
#include <optional>
#include <string>
#include <utility>

namespace impact::engine {

/// A sign and why: what the sign prover works with.
using reasoned_sign = std::pair<sign_set, sign_reason>;

/// The sign of `p`, a polynomial in `s` alone with rational coefficients, on the domain
/// `range` of `s`, by Sturm's theorem; nullopt when `p` is not such a polynomial or
/// changes sign on the domain. `text` writes an expression.
std::optional<reasoned_sign> sturm_sign(const GiNaC::ex& p, const GiNaC::ex& s, const domain& range,
                                        const std::function<std::string(const GiNaC::ex&)>& text);

/// The sign of `e`, a polynomial of degree two or more in `s` (its other symbols free),
/// on the domain `range` of `s` (which must have a finite lower end), from the sign of its
/// derivative in `s` and of its values at the ends, each found by `sign`; nullopt when
/// they do not settle it.
std::optional<reasoned_sign> monotone_sign(const GiNaC::ex& e, const GiNaC::ex& s, const domain& range,
                                           const std::function<reasoned_sign(const GiNaC::ex&)>& sign,
                                           const std::function<std::string(const GiNaC::ex&)>& text);

} // namespace impact::engine
