// The C library functions a program calls (compile/functions.h), correctly rounded to
// float, double and long double by CLN, so that the interpreter (compile::run) gives the
// same values on every machine (compile/program.h, correctly_rounded).
#include "compile/program.h"

#include "compile/functions.h"

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

// std::`function`(a, b) (for an odd function, a >= 0: the caller gives a's sign back) to 60
// digits, as a rational (exactly where it is rational: pow to an integer power); nullopt for
// infinities and NaN (which the kernels' guards refuse before they compute) and where the
// function has no finite value (compile/functions.h, exact_value), left to the C library.
template <class Real>
std::optional<cln::cl_RA> value_of(const std::string& function, Real a, Real b)
{
    if (!std::isfinite(a) || !std::isfinite(b))
        return std::nullopt;
    if (const std::optional<cln::cl_R> v = exact_value(function, exactly(a), exactly(b), 60))
        return cln::rational(*v);
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
    if (function == "sin")
        return std::sin(a);
    if (function == "cos")
        return std::cos(a);
    if (function == "tan")
        return std::tan(a);
    if (function == "asin")
        return std::asin(a);
    if (function == "acos")
        return std::acos(a);
    if (function == "atan")
        return std::atan(a);
    if (function == "atan2")
        return std::atan2(a, b);
    if (function == "exp")
        return std::exp(a);
    if (function == "expm1")
        return std::expm1(a);
    if (function == "log")
        return std::log(a);
    if (function == "log1p")
        return std::log1p(a);
    if (function == "sinh")
        return std::sinh(a);
    if (function == "cosh")
        return std::cosh(a);
    if (function == "tanh")
        return std::tanh(a);
    if (function == "pow")
        return std::pow(a, b);
    throw std::invalid_argument("no interpreter for std::" + function);
}

template <class Real>
Real rounded_call(const std::string& function, Real a, Real b)
{
    // An odd function is computed for |a|, a's sign (of a zero too) given back; a zero's
    // sign is kept by the others that are 0 there (expm1, log1p).
    const bool odd = is_odd_function(function);
    if (a == 0 && (function == "expm1" || function == "log1p"))
        return a;
    if (const std::optional<cln::cl_RA> exact = value_of(function, odd ? std::fabs(a) : a, b))
        if (const std::optional<Real> value = nearest<Real>(*exact))
            return odd && std::signbit(a) ? -*value : *value;   // f(-x) = -f(x), f(-0) = -0
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

// π to 60 digits, rounded once more to the type (no second rounding: π is not within
// 2^-199 of a tie of any of them).
template <class Real>
Real nearest_pi()
{
    static const Real value = *nearest<Real>(cln::rational(cln::pi(cln::float_format(60))));
    return value;
}

template <>
float rounded_pi<float>()
{
    return nearest_pi<float>();
}

template <>
double rounded_pi<double>()
{
    return nearest_pi<double>();
}

template <>
long double rounded_pi<long double>()
{
    return nearest_pi<long double>();
}

} // namespace impact::compile
