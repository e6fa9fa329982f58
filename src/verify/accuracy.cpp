#include "verify/accuracy.h"

#include <cln/float.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <cmath>
#include <stdexcept>

namespace impact::verify {

GiNaC::numeric exact(long double value)
{
    if (!std::isfinite(value))
        throw std::domain_error("a non-finite number has no exact value");
    // Split into an integer mantissa and a power of two, both exact.
    // |fraction| is in [1/2, 1) and has at most 64 significant bits, so |fraction| * 2^64
    // is an integer below 2^64.
    int exponent = 0;
    const long double fraction = std::frexp(std::fabs(value), &exponent);
    const auto mantissa = static_cast<unsigned long>(std::ldexp(fraction, 64));
    const GiNaC::numeric result = GiNaC::numeric(mantissa) * GiNaC::numeric(2).power(exponent - 64);
    return value < 0 ? -result : result;
}

GiNaC::numeric evaluate(const GiNaC::ex& e, const GiNaC::exmap& point, int digits)
{
    GiNaC::ex value = e.subs(point);
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_rational()) {
        const auto saved = GiNaC::Digits;
        GiNaC::Digits = digits;
        value = GiNaC::evalf(value);
        GiNaC::Digits = saved;
    }
    if (!GiNaC::is_a<GiNaC::numeric>(value))
        throw std::domain_error("the expression does not evaluate to a number at the point");
    return GiNaC::ex_to<GiNaC::numeric>(value);
}

GiNaC::numeric ulp(const GiNaC::numeric& scale, int mantissa_bits)
{
    const GiNaC::numeric magnitude = GiNaC::abs(scale);
    if (magnitude.is_zero())
        return 0;
    // ⌊log2 |scale|⌋ from the double approximation, corrected exactly.
    int power = static_cast<int>(std::floor(std::log2(magnitude.to_double())));
    while (GiNaC::numeric(2).power(power) > magnitude)
        --power;
    while (GiNaC::numeric(2).power(power + 1) <= magnitude)
        ++power;
    return GiNaC::numeric(2).power(power + 1 - mantissa_bits);
}

double ulps(const GiNaC::numeric& computed, const GiNaC::numeric& exact_value, const GiNaC::numeric& scale,
            int mantissa_bits)
{
    const GiNaC::numeric gap = GiNaC::abs(computed - exact_value);
    if (gap.is_zero())
        return 0;
    const GiNaC::numeric unit = ulp(scale, mantissa_bits);
    if (unit.is_zero())
        return std::numeric_limits<double>::infinity();
    return (gap / unit).to_double();
}

} // namespace impact::verify
