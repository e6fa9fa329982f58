// Identities of sin, cos, tan, their hyperbolic kin, exp and log, decided (internal to
// engine/prove; prove_equal calls it before sampling).
//
// The decision: the angles that occur (the arguments of sin, cos and tan) are written as
// rational combinations of a Q-basis of base angles, a multiple of Pi apart (sin(Pi/2 - phi)
// = cos(phi)); every sin, cos and tan is expanded through the sine s_i and cosine c_i of the
// base angles by the addition theorems (tan as sin/cos, its condition cos != 0 attached by
// definedness.h); the numerator of the difference of the sides is reduced modulo the ideal
// of the s_i^2 + c_i^2 - 1, c_i^2 replaced by 1 - s_i^2 until every c_i has degree at most
// one. That remainder is unique (the leading terms c_i^2 are coprime: a Groebner basis),
// so the identity holds wherever both sides are defined exactly when it is zero. exp,
// sinh, cosh and tanh are written as powers of exp of a basis of exponents (exp(k log p) =
// p^k) and decided as rational functions. Before that, a logarithm of a product is split
// into the logarithms of its factors proven > 0 (from the domains and the conditions the
// claim is said to hold under), and asin(sin(t)), acos(cos(t)) and atan(tan(t)) are t
// where the range of t proves t within the principal range. A difference that does not
// reduce to zero is not proven: the caller samples it.
#pragma once

#include "engine/prove/prove.h"

#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

/// One base angle, and its sine and cosine: symbols of their own (`sin(theta/2)`) where
/// GiNaC keeps them as functions, else their algebraic values (sin(acos(u)) = sqrt(1 - u^2)).
struct base_angle {
    GiNaC::ex angle;
    GiNaC::ex sine, cosine;
    bool symbols = false;   ///< sine and cosine are symbols, bound by sine^2 + cosine^2 = 1
};

/// `e` with sin, cos and tan of every angle written through the sines and cosines of a
/// basis of base angles, and that basis (in the order of their texts); none when `e` has
/// none, or an angle is not a rational combination of its parts (or needs a multiple
/// beyond 32 of a base angle).
struct through_bases {
    GiNaC::ex value;
    std::vector<base_angle> bases;
};
std::optional<through_bases> through_base_angles(const GiNaC::ex& e, const assumptions& given);

/// A polynomial reduced modulo sine^2 + cosine^2 = 1 for each base angle with symbols:
/// each cosine of degree at most one.
GiNaC::ex reduced_modulo_circle(const GiNaC::ex& polynomial, const std::vector<base_angle>& bases);

/// `lhs = rhs` decided by the method above under `given` (the domains, narrowed by the
/// conditions attached to the claim): proven, with the method in words, or none.
std::optional<verdict> decide_transcendental(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const assumptions& given);

} // namespace impact::engine
