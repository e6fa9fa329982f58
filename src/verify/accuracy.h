// Measuring the accuracy of floating-point kernels against CLN.
//
// A kernel's output is compared with the exact (rational) or high-precision value of
// the symbolic result at the same inputs, the inputs taken exactly as the binary
// floating-point numbers the kernel saw. Errors are counted in units in the last place
// (ulps) of a stated scale, e.g. the largest velocity in a collision.
#pragma once

#include <ginac/ginac.h>

#include <limits>

namespace impact::verify {

/// The exact rational value of a binary floating-point number.
GiNaC::numeric exact(long double value);

/// `e` at `point`: exact when it is rational there, otherwise to `digits` decimal digits.
GiNaC::numeric evaluate(const GiNaC::ex& e, const GiNaC::exmap& point, int digits = 50);

/// One ulp at `scale` for a type with `mantissa_bits` (53 for double): 2^(⌊log2|scale|⌋ + 1 − p).
GiNaC::numeric ulp(const GiNaC::numeric& scale, int mantissa_bits);

/// |computed − exact| in ulps of `scale`.
double ulps(const GiNaC::numeric& computed, const GiNaC::numeric& exact_value, const GiNaC::numeric& scale,
            int mantissa_bits);

template <class Real>
double ulps(Real computed, const GiNaC::numeric& exact_value, const GiNaC::numeric& scale)
{
    return ulps(exact(static_cast<long double>(computed)), exact_value, scale, std::numeric_limits<Real>::digits);
}

} // namespace impact::verify
