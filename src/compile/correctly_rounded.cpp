// The C library functions a program calls (acos, atan, atan2, pow), correctly rounded to
// float, double and long double by CLN, so that the interpreter (compile::run) gives the
// same values on every machine (compile/program.h, correctly_rounded).
#include "compile/program.h"

#include <cln/cln.h>

#include <algorithm>
#include <limits>
#include <optional>

namespace impact::compile {

namespace {

// `x` (finite) exactly, as a rational: its fraction in [1/2, 1) is the sum of at most three
// doubles, each the nearest to what the ones before left (for 24, 53, 64 or 113 bits).
template <class Real>
cln::cl_RA exactly(Real x)
{
    int exponent = 0;
    Real fraction = std::frexp(x, &exponent);
    cln::cl_RA sum = 0;
    while (fraction != 0) {
        const double part = static_cast<double>(fraction);
        sum = sum + cln::rational(cln::cl_DF(part));
        fraction -= static_cast<Real>(part);
    }
    return sum * cln::expt(cln::cl_RA(2), exponent);
}

// std::`function`(a, b) for a >= 0 (atan, atan2: odd in a; the caller gives a's sign back):
// exactly where it is rational (pow to an integer power), else to 60 digits, as a rational;
// nullopt for infinities and NaN (which the kernels' guards refuse before they compute),
// atan2(0, 0), arguments outside the function's domain and pow of 0, left to the C library.
template <class Real>
std::optional<cln::cl_RA> value_of(const std::string& function, Real a, Real b)
{
    if (!std::isfinite(a) || !std::isfinite(b))
        return std::nullopt;
    const cln::float_format_t digits = cln::float_format(60);
    const auto rational = [&](const cln::cl_R& v) { return cln::rational(cln::cl_float(v, digits)); };
    const cln::cl_RA x = exactly(a), y = exactly(b);
    if (function == "atan")
        return rational(cln::atan(cln::cl_float(x, digits)));
    if (function == "atan2" && !(a == 0 && b == 0))
        return rational(cln::atan(cln::cl_float(y, digits), cln::cl_float(x, digits)));  // the point (b, a)
    if (function == "acos" && a >= -1 && a <= 1)
        return rational(cln::realpart(cln::acos(cln::cl_float(x, digits))));
    if (function == "pow" && a != 0) {
        if (cln::denominator(y) == 1 && cln::abs(y) <= 4096)  // exactly: a tie is then rounded to even
            return cln::expt(x, cln::numerator(y));
        if (a > 0)
            return rational(cln::exp(cln::cl_float(y, digits) * cln::ln(cln::cl_float(x, digits))));
    }
    return std::nullopt;
}

// `q` rounded to the nearest `Real`, ties to even, subnormals included (a negative one that
// rounds to zero is -0); nullopt when it overflows.
template <class Real>
std::optional<Real> nearest(const cln::cl_RA& q)
{
    using limits = std::numeric_limits<Real>;
    if (cln::zerop(q))
        return Real(0);
    const cln::cl_RA size = cln::abs(q);
    // 2^(exponent - 1) <= |q| < 2^exponent.
    long exponent = static_cast<long>(cln::integer_length(cln::numerator(size))) -
                    static_cast<long>(cln::integer_length(cln::denominator(size)));
    if (size >= cln::expt(cln::cl_RA(2), exponent))
        ++exponent;
    if (exponent > limits::max_exponent)
        return std::nullopt;
    const long shift = limits::digits - std::max<long>(exponent, limits::min_exponent);
    const cln::cl_I magnitude = cln::round1(size * cln::expt(cln::cl_RA(2), shift));
    Real value = 0;  // its 32-bit pieces, high first: each partial sum fits the type's digits
    for (long piece = (cln::integer_length(magnitude) + 31) / 32 - 1; piece >= 0; --piece)
        value = value * Real(4294967296.0) +
                static_cast<Real>(cln::cl_I_to_ulong(cln::ldb(magnitude, cln::cl_byte(32, 32 * piece))));
    value = std::ldexp(value, static_cast<int>(-shift));
    return cln::minusp(q) ? -value : value;
}

template <class Real>
Real library_call(const std::string& function, Real a, Real b)
{
    if (function == "acos")
        return std::acos(a);
    if (function == "atan")
        return std::atan(a);
    if (function == "atan2")
        return std::atan2(a, b);
    if (function == "pow")
        return std::pow(a, b);
    throw std::invalid_argument("no interpreter for std::" + function);
}

template <class Real>
Real rounded_call(const std::string& function, Real a, Real b)
{
    // atan and atan2 are odd in a: computed for |a|, a's sign (of a zero too) given back.
    const bool odd = function == "atan" || function == "atan2";
    if (const std::optional<cln::cl_RA> exact = value_of(function, odd ? std::fabs(a) : a, b))
        if (const std::optional<Real> value = nearest<Real>(*exact))
            return odd ? std::copysign(*value, a) : *value;
    return library_call(function, a, b);
}

} // namespace

// From 60 digits (about 199 bits) to the type's 24, 53, 64 or 113: a second rounding only
// within 2^-199 of the value's size from a tie (none for pow to an integer power, exact).
float correctly_rounded(const std::string& function, float a, float b)
{
    return rounded_call(function, a, b);
}

double correctly_rounded(const std::string& function, double a, double b)
{
    return rounded_call(function, a, b);
}

long double correctly_rounded(const std::string& function, long double a, long double b)
{
    return rounded_call(function, a, b);
}

} // namespace impact::compile
