// Exact ranges of angles, and the sign of sin and cos on them (angles.h).
#include "engine/prove/angles.h"

#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace impact::engine {
namespace {

bool has_symbol(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it))
            return true;
    return false;
}

// A constant's value at `digits` digits, when it is a real number.
std::optional<GiNaC::numeric> value_at(const GiNaC::ex& c, int digits)
{
    struct digits_kept {
        decltype(GiNaC::Digits) saved = GiNaC::Digits;
        ~digits_kept() { GiNaC::Digits = saved; }
    } kept;
    try {
        GiNaC::Digits = digits;
        const GiNaC::ex v = GiNaC::evalf(c);
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real())
            return GiNaC::ex_to<GiNaC::numeric>(v);
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

exact_interval point(const GiNaC::ex& c)
{
    return {c, c, false, false, false, false};
}

exact_interval whole_line()
{
    return {0, 0, true, true, true, true};
}

// f(r) for f increasing on r, with its limits at -inf and +inf (none: infinite there).
exact_interval increasing(const exact_interval& r, GiNaC::ex (*f)(const GiNaC::ex&),
                          const std::optional<GiNaC::ex>& at_minus_infinity,
                          const std::optional<GiNaC::ex>& at_plus_infinity)
{
    exact_interval out = r;
    if (r.low_infinite) {
        out.low_infinite = !at_minus_infinity;
        out.low = at_minus_infinity.value_or(0);
        out.low_open = true;
    } else {
        out.low = f(r.low);
    }
    if (r.high_infinite) {
        out.high_infinite = !at_plus_infinity;
        out.high = at_plus_infinity.value_or(0);
        out.high_open = true;
    } else {
        out.high = f(r.high);
    }
    return out;
}

GiNaC::ex atan_of(const GiNaC::ex& x) { return GiNaC::atan(x); }
GiNaC::ex asin_of(const GiNaC::ex& x) { return GiNaC::asin(x); }
GiNaC::ex exp_of(const GiNaC::ex& x) { return GiNaC::exp(x); }
GiNaC::ex log_of(const GiNaC::ex& x) { return GiNaC::log(x); }
GiNaC::ex sinh_of(const GiNaC::ex& x) { return GiNaC::sinh(x); }
GiNaC::ex tanh_of(const GiNaC::ex& x) { return GiNaC::tanh(x); }

// The range of a function of an argument of range r.
std::optional<exact_interval> function_range(const std::string& name, const exact_interval& r)
{
    const GiNaC::ex half_pi = GiNaC::Pi / 2;
    if (name == "atan")
        return increasing(r, atan_of, -half_pi, half_pi);
    if (name == "exp")
        return increasing(r, exp_of, GiNaC::ex(0), std::nullopt);
    if (name == "sinh")
        return increasing(r, sinh_of, std::nullopt, std::nullopt);
    if (name == "tanh")
        return increasing(r, tanh_of, GiNaC::ex(-1), GiNaC::ex(1));
    if (name == "log") {
        // Defined where the argument is > 0: from its lower end when that is > 0.
        if (!r.low_infinite && sign_of_number(r.low).value_or(0) > 0)
            return increasing(r, log_of, std::nullopt, std::nullopt);
        exact_interval out = increasing(r, log_of, std::nullopt, std::nullopt);
        out.low_infinite = true;
        out.low_open = true;
        return out;
    }
    const bool in_unit = within(r, -1, false, 1, false);
    if (name == "asin")
        return in_unit ? increasing(r, asin_of, std::nullopt, std::nullopt)
                       : exact_interval{-half_pi, half_pi, false, false, false, false};
    if (name == "acos") {
        if (!in_unit)
            return exact_interval{0, GiNaC::Pi, false, false, false, false};
        // decreasing: acos(high) to acos(low)
        return exact_interval{GiNaC::acos(r.high), GiNaC::acos(r.low), r.high_open, r.low_open, false, false};
    }
    if (name == "sin" || name == "cos")
        return exact_interval{-1, 1, false, false, false, false};
    return std::nullopt;
}

} // namespace

GiNaC::ex exact_end(const domain& d, bool upper)
{
    return upper ? d.exact_upper() : d.exact_lower();
}

bool without_symbols(const GiNaC::ex& e)
{
    return !has_symbol(e);
}

std::optional<int> sign_of_number(const GiNaC::ex& c)
{
    if (GiNaC::is_a<GiNaC::numeric>(c)) {
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(c);
        if (!n.is_real())
            return std::nullopt;
        return n.is_zero() ? 0 : n.is_positive() ? 1 : -1;
    }
    if (has_symbol(c))
        return std::nullopt;
    if (GiNaC::expand(c).is_zero())
        return 0;
    const auto coarse = value_at(c, 40), fine = value_at(c, 60);
    // Far from 0 at both precisions, and of one sign: the rounding cannot have made it.
    const GiNaC::numeric tiny = GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(GiNaC::numeric(10), -25));
    if (!coarse || !fine || GiNaC::abs(*coarse) < tiny || GiNaC::abs(*fine) < tiny)
        return std::nullopt;
    if (coarse->is_positive() != fine->is_positive())
        return std::nullopt;
    return fine->is_positive() ? 1 : -1;
}

std::string exact_interval::to_string(const assumptions& given) const
{
    return fmt::format("{}{}, {}{}", low_open ? '(' : '[', low_infinite ? "-inf" : given.text(low),
                       high_infinite ? "+inf" : given.text(high), high_open ? ')' : ']');
}

finding& interval_said(finding& f, const exact_interval& r, const assumptions& given)
{
    if (!r.bounded())
        return f.say(r.to_string(given));
    return f.say(r.low_open ? "(" : "[").math(r.low).say(", ").math(r.high).say(r.high_open ? ")" : "]");
}

std::optional<exact_interval> range_of(const GiNaC::ex& e, const assumptions& given)
{
    if (!has_symbol(e)) {
        if (!value_at(e, 40))
            return std::nullopt;
        return point(e);
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        const auto found = given.domains.find(e);
        if (found == given.domains.end())
            return std::nullopt;
        const domain& d = found->second;
        switch (d.what) {
        case domain::kind::real: return whole_line();
        case domain::kind::positive: return exact_interval{0, 0, true, true, false, true};
        case domain::kind::nonnegative: return exact_interval{0, 0, false, true, false, true};
        case domain::kind::interval: break;
        }
        return exact_interval{exact_end(d, false), exact_end(d, true), d.lower_open, d.upper_open, false, false};
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
        exact_interval sum = point(0);
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto term = range_of(e.op(i), given);
            if (!term)
                return std::nullopt;
            sum.low = sum.low + term->low;
            sum.high = sum.high + term->high;
            sum.low_open = sum.low_open || term->low_open;
            sum.high_open = sum.high_open || term->high_open;
            sum.low_infinite = sum.low_infinite || term->low_infinite;
            sum.high_infinite = sum.high_infinite || term->high_infinite;
        }
        return sum;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        // a constant times one factor of known range
        GiNaC::ex scale = 1, rest = 1;
        for (std::size_t i = 0; i < e.nops(); ++i)
            (has_symbol(e.op(i)) ? rest : scale) *= e.op(i);
        const std::optional<int> sign = sign_of_number(scale);
        if (!sign || GiNaC::is_a<GiNaC::mul>(rest))
            return std::nullopt;
        const auto r = range_of(rest, given);
        if (!r)
            return std::nullopt;
        if (*sign == 0)
            return point(0);
        exact_interval out{scale * r->low, scale * r->high, r->low_open, r->high_open, r->low_infinite,
                           r->high_infinite};
        if (*sign < 0) {
            std::swap(out.low, out.high);
            std::swap(out.low_open, out.high_open);
            std::swap(out.low_infinite, out.high_infinite);
        }
        return out;
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        if (name == "atan2" && e.nops() == 2)
            return exact_interval{-GiNaC::Pi, GiNaC::Pi, true, false, false, false};
        if (e.nops() != 1)
            return std::nullopt;
        const auto r = range_of(e.op(0), given);
        if (!r) {
            if (name == "sin" || name == "cos")
                return exact_interval{-1, 1, false, false, false, false};
            return std::nullopt;
        }
        return function_range(name, *r);
    }
    return std::nullopt;
}

bool within(const exact_interval& r, const GiNaC::ex& low, bool low_open, const GiNaC::ex& high, bool high_open)
{
    if (r.low_infinite || r.high_infinite)
        return false;
    const std::optional<int> below = sign_of_number(r.low - low), above = sign_of_number(high - r.high);
    if (!below || !above)
        return false;
    const bool low_ok = *below > 0 || (*below == 0 && (r.low_open || !low_open));
    const bool high_ok = *above > 0 || (*above == 0 && (r.high_open || !high_open));
    return low_ok && high_ok;
}

sign_set sine_sign_on(const exact_interval& r, const GiNaC::numeric& shift)
{
    if (!r.bounded())
        return sign_set::any();
    const GiNaC::ex low = r.low + shift * GiNaC::Pi, high = r.high + shift * GiNaC::Pi;
    const auto turns = value_at(low / GiNaC::Pi, 40);
    if (!turns)
        return sign_set::any();
    // k with k*Pi <= low < (k+1)*Pi, settled exactly.
    long k = static_cast<long>(std::floor(turns->to_double()));
    for (int tries = 0; tries < 3; ++tries) {
        const std::optional<int> from = sign_of_number(low - k * GiNaC::Pi);
        const std::optional<int> to = sign_of_number(low - (k + 1) * GiNaC::Pi);
        if (!from || !to)
            return sign_set::any();
        if (*from < 0)
            --k;
        else if (*to >= 0)
            ++k;
        else
            break;
        if (tries == 2)
            return sign_set::any();
    }
    const std::optional<int> past = sign_of_number(high - (k + 1) * GiNaC::Pi);
    if (!past || *past > 0)
        return sign_set::any();
    const bool even = k % 2 == 0;
    const bool zero = (sign_of_number(low - k * GiNaC::Pi) == 0 && !r.low_open) || (*past == 0 && !r.high_open);
    return {!even, zero, even};
}

} // namespace impact::engine
