// The C library functions a kernel calls, and their values computed by CLN.
//
// A kernel computes with +, -, *, /, sqrt and the functions listed here, each printed as
// std::<name> (emit/program_cxx.h). Their values to any number of digits, computed by CLN,
// are what the accuracy of a kernel is measured against (verify/measure.h) and what the
// interpreter rounds to each type (correctly_rounded, compile/program.h). CLN itself has
// sin, cos, exp, ln, atan (of a point too), sinh and cosh; the others are built from them
// without cancellation: tan = sin/cos, tanh = sinh/cosh, asin x = atan2(x, √((1−x)(1+x))),
// acos x = atan2(√((1−x)(1+x)), x) with (1−x)(1+x) exact, log1p x = ln(1+x) and
// expm1 x = exp(x) − 1 with 1+x exact, pow(a, b) = exp(b ln a) for a > 0 and exactly for an
// integer b. Each value is computed with as many more digits as its argument's size and its
// own smallness cost (an argument reduction of sin, the cancellation of exp(x) − 1 near 0),
// so that it comes out with the digits asked for.
#pragma once

#include <ginac/ginac.h>

#include <optional>
#include <string>

namespace impact::compile {

/// log1p(x) = log(1 + x) and expm1(x) = exp(x) − 1, as the C library computes them without
/// the cancellation of 1 + x and exp(x) − 1 near x = 0: candidate forms of a kernel's output
/// (verify/cancellation.h) that a kernel calls as std::log1p and std::expm1.
DECLARE_FUNCTION_1P(log1p)
DECLARE_FUNCTION_1P(expm1)

/// Whether a kernel can call std::`function`: abs (std::fabs), sin, cos, tan, asin, acos,
/// atan, atan2, exp, log, log1p, expm1, sinh, cosh, tanh and pow.
bool is_library_function(const std::string& function);

/// Whether std::`function` is odd in its first argument (sin, tan, asin, atan, atan2, sinh,
/// tanh): f(-x) = -f(x), the sign of a zero argument kept.
bool is_odd_function(const std::string& function);

/// std::`function`(a, b) (b is atan2's x and pow's exponent, and unused by the others) to
/// `digits` significant decimal digits, computed by CLN from a and b taken exactly: a
/// rational where the value is rational (pow to an integer power; a function at the point
/// where it is 0, such as sin 0, log 1, acos 1; exp 0, cos 0 and cosh 0, which are 1), a
/// float of `digits` digits otherwise. Nothing where the function has no finite real value:
/// outside its domain (log of x <= 0, log1p of x <= -1, asin and acos of |x| > 1), atan2(0, 0),
/// pow of 0 to a power <= 0 and of a negative number to a power that is not an integer, and
/// exp, sinh, cosh, tanh or pow of arguments so large (|x| > 10^5, |b log a| > 10^5) that the
/// value is beyond every floating-point type's range or within a rounding of its limit.
std::optional<cln::cl_R> exact_value(const std::string& function, const cln::cl_R& a, const cln::cl_R& b,
                                     long digits);

} // namespace impact::compile
