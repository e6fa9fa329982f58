#include "engine/expr/domain.h"

#include <fmt/format.h>

#include <cln/rational.h>
#include <cln/real.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <regex>
#include <stdexcept>

namespace impact::engine {
namespace {

// A bound as the file writes it, when it was read from one; else the number.
std::string format_bound(double value, const std::string& written)
{
    return written.empty() ? fmt::format("{}", value) : written;
}

// The exact rational value of a double.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

// A number as the file writes it (3, 1/2, 0.25), exactly; no sign.
GiNaC::numeric exact_number(const std::string& text)
{
    const auto slash = text.find('/');
    if (slash != std::string::npos)
        return exact_number(text.substr(0, slash)) / exact_number(text.substr(slash + 1));
    const auto point = text.find('.');
    if (point == std::string::npos)
        return GiNaC::numeric(text.c_str());
    const std::string digits = text.substr(0, point) + text.substr(point + 1);
    return GiNaC::numeric(digits.c_str()) / GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(int(text.size() - point - 1)));
}

// A bound the interval's pattern matched (-1/2, 0.25, Pi/2, -3*Pi/4, 0.5*Pi), exactly.
GiNaC::ex exact_end(const std::string& written)
{
    std::string text;
    for (const char c : written)
        if (c != ' ' && c != '\t')
            text += c;
    int sign = 1;
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
        sign = text[0] == '-' ? -1 : 1;
        text.erase(0, 1);
    }
    const auto pi = text.find("Pi");
    if (pi == std::string::npos)
        return sign * exact_number(text);
    // [k*]Pi[/n]
    GiNaC::numeric k = 1;
    if (pi > 0)
        k = exact_number(text.substr(0, pi - 1));   // the '*' before Pi dropped
    const std::string after = text.substr(pi + 2);
    if (!after.empty())
        k /= exact_number(after.substr(1));           // the '/' after Pi dropped
    return sign * k * GiNaC::Pi;
}

// An end as a double: the number the file writes, or, for an end of π, the double nearest
// it on the inside of the interval (towards +infinity for a lower end).
double double_of_end(const GiNaC::ex& end, const std::string& text, bool is_lower)
{
    if (!end.has(GiNaC::Pi)) {
        // As the file writes it: a/b as the quotient of their doubles.
        const auto slash = text.find('/');
        if (slash == std::string::npos)
            return std::strtod(text.c_str(), nullptr);
        return std::strtod(text.substr(0, slash).c_str(), nullptr) /
               std::strtod(text.substr(slash + 1).c_str(), nullptr);
    }
    double d = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(end)).to_double();
    const int beyond = sign_of_constant(end - exact(d));   // > 0: the end lies above d
    if (is_lower && beyond > 0)
        d = std::nextafter(d, INFINITY);
    if (!is_lower && beyond < 0)
        d = std::nextafter(d, -INFINITY);
    return d;
}

} // namespace

int sign_of_constant(const GiNaC::ex& constant)
{
    const GiNaC::ex e = GiNaC::normal(constant);
    if (e.is_zero())
        return 0;
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return GiNaC::ex_to<GiNaC::numeric>(e).is_positive() ? 1 : -1;
    // Not zero (π is transcendental, so a rational function of it with rational
    // coefficients that does not normalise to 0 is not 0): 40 digits tell its sign.
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 40;
    const GiNaC::ex value = GiNaC::evalf(e);
    GiNaC::Digits = saved;
    if (!GiNaC::is_a<GiNaC::numeric>(value) || !value.info(GiNaC::info_flags::real))
        throw std::invalid_argument("not a real constant");
    return GiNaC::ex_to<GiNaC::numeric>(value).is_positive() ? 1 : -1;
}

std::string latex_of_bound(const std::string& text)
{
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "Pi") == 0) {
            // 3*Pi/4 as 3\pi/4
            if (!out.empty() && out.back() == '*')
                out.pop_back();
            out += "\\pi";
            ++i;
        } else if (text[i] != ' ') {
            out += text[i];
        }
    }
    return out;
}

GiNaC::ex domain::exact_lower() const
{
    return lower_text.empty() ? GiNaC::ex(exact(lower)) : exact_end(lower_text);
}

GiNaC::ex domain::exact_upper() const
{
    return upper_text.empty() ? GiNaC::ex(exact(upper)) : exact_end(upper_text);
}

bool domain::is_positive() const
{
    switch (what) {
    case kind::positive: return true;
    case kind::interval: return lower > 0 || (lower == 0 && lower_open);
    default: return false;
    }
}

bool domain::is_nonnegative() const
{
    switch (what) {
    case kind::positive:
    case kind::nonnegative: return true;
    case kind::interval: return lower >= 0;
    default: return false;
    }
}

bool domain::contains(double x) const
{
    switch (what) {
    case kind::real: return std::isfinite(x);
    case kind::positive: return x > 0 && std::isfinite(x);
    case kind::nonnegative: return x >= 0 && std::isfinite(x);
    case kind::interval: break;
    }
    return (lower_open ? x > lower : x >= lower) && (upper_open ? x < upper : x <= upper);
}

bool domain::closure_contains(double x) const
{
    switch (what) {
    case kind::real: return std::isfinite(x);
    case kind::positive:
    case kind::nonnegative: return x >= 0 && std::isfinite(x);
    case kind::interval: break;
    }
    return x >= lower && x <= upper;
}

namespace {

// A domain as its lowest and highest values (exact; none when infinite), each open or not.
struct ends {
    std::optional<GiNaC::ex> low, high;
    bool low_open = true, high_open = true;
};

ends ends_of(const domain& d)
{
    switch (d.what) {
    case domain::kind::real: return {};
    case domain::kind::positive: return {GiNaC::ex(0), std::nullopt, true, true};
    case domain::kind::nonnegative: return {GiNaC::ex(0), std::nullopt, false, true};
    case domain::kind::interval: break;
    }
    return {d.exact_lower(), d.exact_upper(), d.lower_open, d.upper_open};
}

} // namespace

bool domain::contains(const GiNaC::ex& constant) const
{
    const ends e = ends_of(*this);
    const int above = e.low ? sign_of_constant(constant - *e.low) : 1;
    const int below = e.high ? sign_of_constant(*e.high - constant) : 1;
    return (above > 0 || (above == 0 && !e.low_open)) && (below > 0 || (below == 0 && !e.high_open));
}

bool domain::closure_contains(const GiNaC::ex& constant) const
{
    const ends e = ends_of(*this);
    return (!e.low || sign_of_constant(constant - *e.low) >= 0) && (!e.high || sign_of_constant(*e.high - constant) >= 0);
}

bool domain::within(const domain& outer) const
{
    const ends in = ends_of(*this), out = ends_of(outer);
    // -1, 0, 1 as a is below, at or above b; none for -infinity or +infinity.
    const auto low_inside = [&] {
        if (!out.low)
            return true;
        if (!in.low)
            return false;
        const int s = sign_of_constant(*in.low - *out.low);
        return s > 0 || (s == 0 && (in.low_open || !out.low_open));
    };
    const auto high_inside = [&] {
        if (!out.high)
            return true;
        if (!in.high)
            return false;
        const int s = sign_of_constant(*out.high - *in.high);
        return s > 0 || (s == 0 && (in.high_open || !out.high_open));
    };
    return low_inside() && high_inside();
}

std::string domain::to_string() const
{
    switch (what) {
    case kind::real: return "real";
    case kind::positive: return infinity_included ? "(0, +inf]" : "positive";
    case kind::nonnegative: return infinity_included ? "[0, +inf]" : "nonnegative";
    case kind::interval: break;
    }
    return fmt::format("{}{}, {}{}", lower_open ? '(' : '[', format_bound(lower, lower_text),
                       format_bound(upper, upper_text), upper_open ? ')' : ']');
}

std::string domain::to_latex() const
{
    switch (what) {
    case kind::real: return "\\in \\mathbb{R}";
    case kind::positive: return infinity_included ? "\\in (0, +\\infty]" : "> 0";
    case kind::nonnegative: return infinity_included ? "\\in [0, +\\infty]" : "\\geq 0";
    case kind::interval: break;
    }
    return fmt::format("\\in {}{}, {}{}", lower_open ? '(' : '[', latex_of_bound(format_bound(lower, lower_text)),
                       latex_of_bound(format_bound(upper, upper_text)), upper_open ? ')' : ']');
}

double uniform_stream::next()
{
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double draw(const domain& range, uniform_stream& stream)
{
    const double u = stream.next();
    switch (range.what) {
    case domain::kind::real: return -10 + 20 * u;
    case domain::kind::positive: return std::exp(std::log(20.0) * (2 * u - 1));
    case domain::kind::nonnegative: return 20 * u;
    case domain::kind::interval: break;
    }
    // Open bounds are never drawn: u < 1 keeps the upper one out; nudge off the lower one.
    double value = range.lower + (range.upper - range.lower) * u;
    if (range.lower_open && value == range.lower)
        value = std::nextafter(value, range.upper);
    return value;
}

domain parse_domain(const std::string& text, const source_location& where)
{
    domain d;
    if (text == "real")
        return d;
    if (text == "positive") {
        d.what = domain::kind::positive;
        return d;
    }
    if (text == "nonnegative") {
        d.what = domain::kind::nonnegative;
        return d;
    }
    // Up to +infinity: included, [0, +inf] or (0, +inf]; or not, (0, +inf) and [0, +inf),
    // the interval positive and nonnegative name. (-inf, +inf) is the real line.
    static const std::regex to_infinity(R"(^\s*([\[\(])\s*0\s*,\s*\+?inf\s*([\]\)])\s*$)");
    static const std::regex whole_line(R"(^\s*\(\s*-inf\s*,\s*\+?inf\s*\)\s*$)");
    std::smatch end;
    if (std::regex_match(text, end, to_infinity)) {
        d.what = end[1] == "(" ? domain::kind::positive : domain::kind::nonnegative;
        d.infinity_included = end[2] == "]";
        return d;
    }
    if (std::regex_match(text, whole_line))
        return d;
    // Below 0 (negative, (-inf, 0)): a quantity of that sign is declared by its magnitude.
    static const std::regex below_zero(R"(^\s*(negative|nonpositive|[\[\(]\s*-inf\s*,\s*0\s*[\]\)])\s*$)");
    if (std::regex_match(text, below_zero))
        throw error(where, fmt::format("domain '{}': a quantity below 0 is declared by its magnitude, positive (or "
                                       "nonnegative), and written with its sign where it is used (a depth d, "
                                       "positive, at height -d)",
                                       text));
    // An interval with bounds numbers or multiples of π: [0, 1], (0, 1], [-1/2, 3), (0, Pi/2),
    // [-3*Pi/4, Pi].
#define IMPACT_NUMBER R"([0-9]+(?:\.[0-9]+)?(?:/[0-9]+)?)"
#define IMPACT_END R"([-+]?\s*(?:)" IMPACT_NUMBER R"((?:\s*\*\s*Pi(?:\s*/\s*[0-9]+)?)?|Pi(?:\s*/\s*[0-9]+)?))"
    static const std::regex interval(R"(^\s*([\[\(])\s*()" IMPACT_END R"()\s*,\s*()" IMPACT_END
                                     R"()\s*([\]\)])\s*$)");
#undef IMPACT_END
#undef IMPACT_NUMBER
    std::smatch match;
    if (!std::regex_match(text, match, interval))
        throw error(where, fmt::format("domain '{}' is not understood; write real, positive, "
                                       "nonnegative, an interval such as [0, 1] or (0, Pi/2) (its ends integers, "
                                       "decimals or fractions, 1000, not 1e3, or such a number times Pi: Pi, -Pi/2, "
                                       "3*Pi/4), [0, +inf] or (0, +inf)",
                                       text));
    d.what = domain::kind::interval;
    d.lower_open = match[1] == "(";
    d.lower_text = match[2];
    d.upper_text = match[3];
    d.upper_open = match[4] == ")";
    GiNaC::ex low, high;
    try {
        low = exact_end(d.lower_text);
        high = exact_end(d.upper_text);
    } catch (const std::exception&) {
        throw error(where, fmt::format("domain '{}': an end divides by zero", text));
    }
    d.lower = double_of_end(low, d.lower_text, true);
    d.upper = double_of_end(high, d.upper_text, false);
    if (sign_of_constant(high - low) <= 0 || !std::isfinite(d.lower) || !std::isfinite(d.upper))
        throw error(where, fmt::format("domain '{}' is an empty interval", text));
    return d;
}

} // namespace impact::engine
