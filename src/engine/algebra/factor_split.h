// A polynomial factored by Gauss's lemma as far as it decides, GiNaC's factor() asked only
// of what is left.
//
// The emitters factor each coefficient of a value collected in every quantity it holds
// (emit/latex_textbook.cpp), thousands of polynomials of 2 to 40 terms in up to twenty
// symbols; factor() took 15 to 200 ms for each of those of 12 to 25 terms, 7 of the 10 s
// the LaTeX of the whole project took. Most of them are of degree one in some symbol
// x, a x + b: a symbol dividing every term is a factor; with those out, gcd(a, b) is the
// part of the polynomial free of x, and what it leaves, a x + b over it, is irreducible (a
// factor would have to divide both a and b). One gcd() splits off an irreducible factor,
// and the gcd, in fewer symbols, is split again the same way.
#pragma once

#include <ginac/ginac.h>

namespace impact::engine {

/// `p` factored: equal to `p`, a product of a rational number, symbols and powers of them,
/// and sums with integer coefficients of gcd 1, each irreducible over the rationals (or,
/// where factor() runs out of time in factor_reproducibly, as it is). The same factors as
/// factor_reproducibly(p, options) finds, up to their signs, the rational number and how
/// far a factor is collected. A polynomial with coefficients not all rational, or an
/// expression that is not a polynomial, is passed to factor_reproducibly whole.
GiNaC::ex factor_split(const GiNaC::ex& p, unsigned options = 0);

} // namespace impact::engine
