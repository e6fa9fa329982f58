// Candidate forms without the cancellations of the transcendental functions.
//
// 1 − cos θ computed as written loses every digit of a small angle's (cos θ rounds to 1),
// and so do exp(x) − 1 and log(1 + x) near x = 0, and acos(1 − y) of a small y. Each has a form that keeps them, equal to
// it by an identity: a kernel's output has it among its candidates (verify/choice.h), and the
// reference it is measured against is computed from it (verify/measure.h).
#pragma once

#include <ginac/ginac.h>

namespace impact::verify {

/// `e` with every sum and logarithm below written without its cancellation, by the
/// identities (c any factor, the same in both terms):
///   c − c cos x = 2c sin²(x/2),    c + c cos x = 2c cos²(x/2),
///   c cosh x − c = 2c sinh²(x/2),  c exp x − c = c expm1(x),
///   log(1 + y) = log1p(y),         log(a/b) = log1p((a − b)/b),
///   acos(1 − y) = 2 asin(√(y/2)),  acos(−1 + y) = π − 2 asin(√(y/2)).
/// `e` itself where none applies.
GiNaC::ex without_cancellation(const GiNaC::ex& e);

} // namespace impact::verify
