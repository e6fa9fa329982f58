// The C library functions a kernel calls, and their values computed by CLN (compile/functions.h).
#include "compile/functions.h"

#include <cln/cln.h>

#include <array>
#include <algorithm>
#include <cmath>

namespace impact::compile {

namespace {

// ⌊log10 |x|⌋ within one, for x ≠ 0: from its binary exponent (|x| = m 2^e, m in [1/2, 1)).
long decimal_exponent(const cln::cl_R& x)
{
    const cln::cl_F f = cln::cl_float(cln::abs(x), cln::float_format(20));
    return static_cast<long>(std::floor(static_cast<double>(cln::float_exponent(f) - 1) * 0.30102999566398120));
}

// x as a float of `digits` decimal digits (a rational rounded once; a float of fewer digits exactly).
cln::cl_F to_float(const cln::cl_RA& x, long digits)
{
    return cln::cl_float(x, cln::float_format(static_cast<unsigned long>(digits)));
}

// The largest argument of exp (and of sinh, cosh, pow's exp(b ln a)) computed: e^(10^5) is
// 10^43429, beyond every floating-point type (long double ends at 10^4932).
const cln::cl_RA largest_exponent = 100000;

// std::f(a, b) with a and b exact, computed in floats of `work` digits; nothing where it has
// no finite real value. Its error is about 10^-work of the value times the condition that
// `exact_value` adds digits for.
std::optional<cln::cl_R> at_precision(const std::string& f, const cln::cl_RA& a, const cln::cl_RA& b, long work)
{
    const auto x = [&] { return to_float(a, work); };
    if (f == "sin")
        return cln::sin(x());
    if (f == "cos")
        return cln::cos(x());
    if (f == "atan")
        return cln::atan(x());
    if (f == "atan2")  // the angle of the point (b, a)
        return cln::atan(to_float(b, work), x());
    if (f == "asin" || f == "acos") {
        // √((1−a)(1+a)), the product exact: no cancellation near |a| = 1.
        const cln::cl_F c = cln::sqrt(to_float((1 - a) * (1 + a), work));
        return f == "asin" ? cln::atan(c, x()) : cln::atan(x(), c);
    }
    if (f == "exp")
        return cln::exp(x());
    if (f == "expm1")
        return cln::exp(x()) - 1;
    if (f == "log")
        return cln::ln(x());
    if (f == "log1p")  // 1 + a exact
        return cln::ln(to_float(1 + a, work));
    if (f == "sinh")
        return cln::sinh(x());
    if (f == "cosh")
        return cln::cosh(x());
    if (f == "pow")  // a > 0
        return cln::exp(to_float(b, work) * cln::ln(x()));
    return std::nullopt;
}

// The digits that an argument's size costs: sin and cos reduce it modulo 2π (an absolute
// error of 10^-work |a|), exp, sinh, cosh and pow's exp(b ln a) multiply their argument's
// relative error by its size.
long argument_cost(const std::string& f, const cln::cl_RA& a, const cln::cl_RA& b)
{
    cln::cl_R size = 0;
    if (f == "sin" || f == "cos" || f == "exp" || f == "expm1" || f == "sinh" || f == "cosh")
        size = a;
    else if (f == "pow")
        size = b * cln::ln(to_float(a, 20));
    return cln::zerop(size) ? 0 : std::max(0L, decimal_exponent(size) + 1);
}

} // namespace

namespace {

GiNaC::ex log1p_eval(const GiNaC::ex& x)
{
    if (x.is_zero())
        return 0;
    return log1p(x).hold();
}

GiNaC::ex expm1_eval(const GiNaC::ex& x)
{
    if (x.is_zero())
        return 0;
    return expm1(x).hold();
}

// A real number's value to GiNaC's Digits, as exact_value computes it; nothing for anything else.
std::optional<GiNaC::ex> number_value(const char* f, const GiNaC::ex& x)
{
    if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real())
        return std::nullopt;
    const cln::cl_R a = cln::the<cln::cl_R>(GiNaC::ex_to<GiNaC::numeric>(x).to_cl_N());
    if (const auto v = exact_value(f, a, 0, GiNaC::Digits))
        return GiNaC::ex(GiNaC::numeric(cln::cl_N(*v)));
    return std::nullopt;
}

GiNaC::ex log1p_evalf(const GiNaC::ex& x)
{
    if (const auto v = number_value("log1p", x))
        return *v;
    return log1p(x).hold();
}

GiNaC::ex expm1_evalf(const GiNaC::ex& x)
{
    if (const auto v = number_value("expm1", x))
        return *v;
    return expm1(x).hold();
}

} // namespace

REGISTER_FUNCTION(log1p, eval_func(log1p_eval).evalf_func(log1p_evalf))
REGISTER_FUNCTION(expm1, eval_func(expm1_eval).evalf_func(expm1_evalf))

bool is_library_function(const std::string& function)
{
    static const std::array<const char*, 16> all = {"abs",  "sin",  "cos",   "tan",   "asin", "acos",
                                                    "atan", "atan2", "exp",  "log",   "log1p", "expm1",
                                                    "sinh", "cosh", "tanh", "pow"};
    return std::any_of(all.begin(), all.end(), [&](const char* f) { return function == f; });
}

bool is_odd_function(const std::string& function)
{
    return function == "sin" || function == "tan" || function == "asin" || function == "atan" ||
           function == "atan2" || function == "sinh" || function == "tanh";
}

std::optional<cln::cl_R> exact_value(const std::string& f, const cln::cl_R& a_in, const cln::cl_R& b_in, long digits)
{
    const cln::cl_RA a = cln::rational(a_in), b = cln::rational(b_in);
    const auto rounded = [&](const cln::cl_R& v) -> cln::cl_R { return to_float(cln::rational(v), digits); };
    // Exact values: a function at the point where it is rational, pow to an integer power.
    if (cln::zerop(a) && (is_odd_function(f) || f == "log1p" || f == "expm1") && f != "atan2")
        return cln::cl_RA(0);
    if (cln::zerop(a) && (f == "cos" || f == "exp" || f == "cosh"))
        return cln::cl_RA(1);
    if ((f == "log" || f == "acos") && a == 1)
        return cln::cl_RA(0);
    if (f == "atan2") {
        if (cln::zerop(a) && cln::zerop(b))
            return std::nullopt;
        if (cln::zerop(a) && cln::plusp(b))
            return cln::cl_RA(0);
    }
    if (f == "pow") {
        if (cln::zerop(a))
            return cln::plusp(b) ? std::optional<cln::cl_R>(cln::cl_RA(0)) : std::nullopt;
        if (cln::denominator(b) == 1 && cln::abs(b) <= 4096)
            return cln::expt(a, cln::numerator(b));
        if (cln::minusp(a))
            return std::nullopt;
    }
    // Outside the domain, or beyond every type's range.
    if ((f == "log" && !cln::plusp(a)) || (f == "log1p" && !(a > -1)) ||
        ((f == "asin" || f == "acos") && cln::abs(a) > 1))
        return std::nullopt;
    if ((f == "exp" || f == "expm1" || f == "sinh" || f == "cosh") && cln::abs(a) > largest_exponent) {
        if (f == "exp" && cln::minusp(a))
            return to_float(0, digits);   // below every type's least number
        if (f == "expm1" && cln::minusp(a))
            return to_float(-1, digits);
        return std::nullopt;
    }
    if (f == "pow" && cln::abs(b * cln::ln(to_float(a, 20))) > largest_exponent)
        return std::nullopt;
    // Built from others: tan = sin/cos; tanh |a| = −t/(2 + t) with t = expm1(−2|a|), odd.
    if (f == "tan") {
        const auto s = exact_value("sin", a, 0, digits + 5), c = exact_value("cos", a, 0, digits + 5);
        return rounded(*s / *c);
    }
    if (f == "tanh") {
        if (cln::abs(a) > largest_exponent)
            return to_float(cln::minusp(a) ? -1 : 1, digits);
        const cln::cl_R t = *exact_value("expm1", -2 * cln::abs(a), 0, digits + 5);
        const cln::cl_R magnitude = -t / (2 + t);
        return rounded(cln::minusp(a) ? -magnitude : magnitude);
    }
    // The digits asked for, the argument's cost, then the value's own smallness: a value
    // 10^-s computed with an absolute error of 10^-work (exp(x) − 1, ln(1 + x), the angle
    // of a point near its axis) needs s digits more. Repeated with the digits it needs.
    const long cost = argument_cost(f, a, b);
    long work = digits + 10 + cost;
    for (int attempt = 0; attempt < 8; ++attempt) {
        const std::optional<cln::cl_R> v = at_precision(f, a, b, work);
        if (!v)
            return std::nullopt;
        const long small = cln::zerop(*v) ? work : std::max(0L, -decimal_exponent(*v));
        if (work - cost - small >= digits + 5)
            return rounded(*v);
        work = digits + 10 + cost + small + 2 * attempt;
    }
    return std::nullopt;   // a value too close to 0 to find (no function here has one)
}

} // namespace impact::compile
