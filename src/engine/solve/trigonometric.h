// Equations in one unknown u that hold it only in sin, cos or tan of one expression x =
// a u + b linear in it (a and b numbers, or rational multiples of π): c₁ f(x) + c₀ = 0,
// so f(x) = w = −c₀/c₁ (eliminate.h calls it where the equation is not polynomial in u).
//
// The roots are the families of the inverse function's principal value:
//   sin x = w:  x = asin w + 2πk  and  x = π − asin w + 2πk,   asin w ∈ [−π/2, π/2];
//   cos x = w:  x = acos w + 2πk  and  x = −acos w + 2πk,      acos w ∈ [0, π];
//   tan x = w:  x = atan w + πk,                               atan w ∈ (−π/2, π/2);
// with the range of w narrowed by what its sign and 1 ∓ w are proven to be (w > 0 gives
// asin w ∈ (0, π/2]; the inverse functions are increasing, acos decreasing). On a bounded
// domain of u, every k whose root can meet the domain is taken, and each root carries the
// interval its value lies in, exactly, against which solve.cpp keeps or rejects it. On an
// unbounded domain the roots are infinitely many: an error that says so, unless |w| ≤ 1
// is proven false (no real root). w within [−1, 1] is the existence condition of sin and
// cos: proven from the domains, or stated (the root's asin w is defined only there, and
// the derivation states it as the value's condition).
#pragma once

#include "engine/prove/sign.h"

#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

/// An equation c₁ f(a u + b) + c₀ = 0 in u alone.
struct trigonometric_equation {
    GiNaC::ex function;   ///< f(a u + b) as it occurs, e.g. sin(2*phi)
    std::string name;     ///< sin, cos or tan
    GiNaC::ex a, b;       ///< the argument a u + b
    GiNaC::ex value;      ///< w = −c₀/c₁
};

/// The equation `p` (a numerator, = 0) in the form above, when it is one: u occurs only
/// in one sin, cos or tan, whose argument is linear in u with coefficients free of it, and
/// p is of degree one in that function.
std::optional<trigonometric_equation> trigonometric_form(const GiNaC::ex& p, const GiNaC::ex& u);

/// A root of a trigonometric equation: u's value, and the interval that value lies in
/// (exact ends, from the range of the inverse function), with why, in words.
struct trigonometric_root {
    GiNaC::ex unknown, value;
    GiNaC::ex low, high;
    bool low_open = false, high_open = false;
    std::string why;        ///< e.g. "asin(D*g/s^2) in (0, Pi/2] since D*g/s^2 > 0"
    std::string existence;  ///< w within [-1, 1]: proven, or stated
};

/// Every root of `eq` whose interval meets the closure of u's bounded domain `range`, a
/// double root once; none when |w| ≤ 1 is proven false (`no_root` then says why). Throws
/// `unsolvable` (eliminate.h) when u's domain is unbounded and roots exist, or when a
/// and b are not numbers (nor multiples of π), so that the roots in the domain cannot be
/// told.
std::vector<trigonometric_root> trigonometric_roots(const trigonometric_equation& eq, const GiNaC::ex& u,
                                                    const domain& range, const assumptions& given,
                                                    std::string& no_root);

/// Where a root's interval lies against its unknown's domain: inside, outside (no
/// point in common) or neither (the sign proofs of solve.cpp decide then).
enum class interval_placement { inside, outside, across };
interval_placement place_interval(const trigonometric_root& root, const domain& range);

/// The interval as text, e.g. "(0, Pi/4]".
std::string interval_text(const GiNaC::ex& low, bool low_open, const GiNaC::ex& high, bool high_open,
                          const assumptions& given);

/// `e` with each sin, cos and tan of an argument y + mπ/2 (m an integer, 0 too) written as
/// the function of y it equals, y's sign taken out: sin(π − y) = sin y, cos(y + π/2) =
/// −sin y, tan(y + π) = tan y, cos(−y) = cos y.
/// A root π − asin w put back into sin x = w gives sin(asin w) = w so.
GiNaC::ex quarter_turns_reduced(const GiNaC::ex& e);

} // namespace impact::engine
