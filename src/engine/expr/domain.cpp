#include "engine/expr/domain.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <regex>

namespace impact::engine {
namespace {

// A bound as the file writes it, when it was read from one; else the number.
std::string format_bound(double value, const std::string& written)
{
    return written.empty() ? fmt::format("{}", value) : written;
}

} // namespace

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

// A domain as its lowest and highest values, each open or not.
struct ends {
    double low = -INFINITY, high = INFINITY;
    bool low_open = true, high_open = true;
};

ends ends_of(const domain& d)
{
    switch (d.what) {
    case domain::kind::real: return {};
    case domain::kind::positive: return {0, INFINITY, true, true};
    case domain::kind::nonnegative: return {0, INFINITY, false, true};
    case domain::kind::interval: break;
    }
    return {d.lower, d.upper, d.lower_open, d.upper_open};
}

} // namespace

bool domain::within(const domain& outer) const
{
    const ends in = ends_of(*this), out = ends_of(outer);
    const bool low_inside = in.low > out.low || (in.low == out.low && (in.low_open || !out.low_open));
    const bool high_inside = in.high < out.high || (in.high == out.high && (in.high_open || !out.high_open));
    return low_inside && high_inside;
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
    return fmt::format("\\in {}{}, {}{}", lower_open ? '(' : '[', format_bound(lower, lower_text),
                       format_bound(upper, upper_text), upper_open ? ')' : ']');
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
    // An interval with numeric bounds: [0, 1], (0, 1], [-1/2, 3).
    static const std::regex interval(
        R"(^\s*([\[\(])\s*([-+]?[0-9]+(?:\.[0-9]+)?(?:/[0-9]+)?)\s*,\s*([-+]?[0-9]+(?:\.[0-9]+)?(?:/[0-9]+)?)\s*([\]\)])\s*$)");
    std::smatch match;
    if (!std::regex_match(text, match, interval))
        throw error(where, fmt::format("domain '{}' is not understood; write real, positive, "
                                       "nonnegative, an interval such as [0, 1] (its ends integers, decimals or "
                                       "fractions: 1000, not 1e3), [0, +inf] or (0, +inf)",
                                       text));
    auto bound = [](const std::string& s) {
        const auto slash = s.find('/');
        if (slash == std::string::npos)
            return std::strtod(s.c_str(), nullptr);
        return std::strtod(s.substr(0, slash).c_str(), nullptr) / std::strtod(s.substr(slash + 1).c_str(), nullptr);
    };
    d.what = domain::kind::interval;
    d.lower_open = match[1] == "(";
    d.lower = bound(match[2]);
    d.upper = bound(match[3]);
    d.lower_text = match[2];
    d.upper_text = match[3];
    d.upper_open = match[4] == ")";
    if (!(d.lower < d.upper) || !std::isfinite(d.lower) || !std::isfinite(d.upper))
        throw error(where, fmt::format("domain '{}' is an empty interval", text));
    return d;
}

} // namespace impact::engine
