// The sign of a sum: of terms of one sign; a multiple of an abbreviation declared with a
// domain; linear in one bounded symbol, or affine in a bounded symbol or its square, by its
// signs at the ends of the interval; by Sturm's theorem or monotonicity (sign_arguments.h);
// factored; or A - B with A, B >= 0 through A^2 - B^2.
#include "engine/prove/sign_prover.h"

#include "engine/prove/angles.h"
#include "engine/prove/seen_at_points.h"
#include "engine/prove/sign_arguments.h"

#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>
#include <optional>

namespace impact::engine {

std::pair<sign_set, sign_reason> sign_prover::sum_sign(const GiNaC::ex& e, int depth) const
{
    sign_set r = sign_set::exactly(0);
    std::vector<sign_set> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        terms.push_back(sign(e.op(i), depth).first);
        r = plus(r, terms.back());
    }
    if (r.is_known())
        return {r, "a sum of terms of one sign"};
    if (auto assumed = assumed_sign(e))
        return *assumed;

    if (auto linear = linear_in_bounded_symbol(e))
        return *linear;
    // Of six terms or more and seen to take both signs (seen_at_points.h), it has none to
    // prove: the arguments below, which factor it and search its symbols (seconds for the
    // conditions of sliding rough spheres), would find none.
    if (e.nops() >= 6 && seen_of_both_signs(e, given_))
        return {r, "a sum of terms of unknown sign"};
    if (auto affine = affine_in_bounded_symbol(e, depth))
        return *affine;
    // sin and cos as bounded quantities (sign_of_functions.cpp) before monotonicity, which
    // would settle for >= 0 where > 0 holds (m c^2 + E - E cos(theta), increasing in c from 0).
    if (auto bounded = bounded_functions_sign(e, depth, true))
        return *bounded;
    if (auto argued = argued_sign(e, depth))
        return *argued;
    const bool radical = has_radical(e);

    // A sum without a radical that factors (one that came here as a factor of a product
    // with a radical, which is not factored whole: sqrt(k) (a^2 - 2 a b + b^2)): the
    // signs of its factors.
    if (!radical && depth < 3) {
        const GiNaC::ex f = factored(e);
        if (!f.is_equal(e) && (GiNaC::is_a<GiNaC::mul>(f) || GiNaC::is_a<GiNaC::power>(f))) {
            const auto [s, why] = sign(f, depth + 1);
            if (s.is_known()) {
                sign_reason reason(fmt::format("factored, {} {} ({})", text(f), s.describe(), why.words));
                reason.typeset.say("factored, ").math(f).say(s.negative ? (s.zero ? ", which is not positive"
                                                                                  : ", which is negative")
                                                                        : (s.zero ? ", which is not negative"
                                                                                  : ", which is positive"));
                return {s, reason};
            }
        }
    }
    // A - B with A, B >= 0 has the sign of A^2 - B^2, which has no radical where A - B
    // had one. The terms with radicals form one side and the rest the other (each
    // factored to find its sign), or else the terms are grouped by their own signs.
    // Without a radical it gains nothing: the sum is factored (above, or before it came
    // here), and A^2 - B^2 factors back into A - B and A + B, the question asked again.
    // Expanding and factoring it was most of the time of the sign proofs of rough
    // spheres with Coulomb's cases (factor() on 33 to 39 terms, 0.15 to 0.25 s each,
    // seventy times).
    if (depth < 3 && radical) {
        GiNaC::ex a = 0, b = 0;
        GiNaC::ex radicals = 0, rest = 0;
        for (std::size_t i = 0; i < e.nops(); ++i)
            (has_radical(e.op(i)) ? radicals : rest) += e.op(i);
        const sign_set of_radicals = sign(factored(radicals), depth + 1).first;
        const sign_set of_rest = sign(factored(rest), depth + 1).first;
        if (!radicals.is_zero() && !rest.is_zero() && !of_radicals.negative && !of_rest.positive) {
            a = radicals;
            b = -rest;
        } else if (!radicals.is_zero() && !rest.is_zero() && !of_radicals.positive && !of_rest.negative) {
            a = rest;
            b = -radicals;
        } else {
            for (std::size_t i = 0; i < e.nops(); ++i) {
                if (!terms[i].negative) {
                    a += e.op(i);
                } else if (!terms[i].positive) {
                    b -= e.op(i);
                } else {
                    a = b = 0;   // a term of unknown sign: no A - B
                    break;
                }
            }
        }
        const GiNaC::ex difference =
            a.is_zero() && b.is_zero() ? GiNaC::ex(0) : GiNaC::normal(GiNaC::expand(a * a - b * b));
        const auto [squares, why] =
            difference.is_zero() ? std::make_pair(sign_set::any(), sign_reason()) : sign(factored(difference), depth + 1);
        if (squares.is_known()) {
            sign_set s;
            s.positive = squares.positive;
            s.negative = squares.negative;
            s.zero = squares.zero;
            sign_reason reason(fmt::format("A - B with A, B >= 0 and A^2 - B^2 = {} {}",
                                           text(factored(difference)), squares.describe()));
            reason.typeset.say("a difference of non-negative terms whose squares differ by ")
                .math(factored(difference))
                .say(squares.negative ? ", which is negative"
                     : squares.zero   ? ", which is not negative"
                                      : ", which is positive");
            return {s, reason};
        }
    }
    // A number written with Pi or functions (2 - Pi); sines, cosines and inverse functions
    // as bounded quantities (sign_of_functions.cpp).
    if (auto constant = constant_sign(e))
        return *constant;
    if (auto bounded = bounded_functions_sign(e, depth))
        return *bounded;
    // Its numbers as one (4 - Pi in x^2 + 4 - Pi), beside the terms of known sign.
    GiNaC::ex numbers = 0;
    sign_set rest = sign_set::exactly(0);
    for (std::size_t i = 0; i < e.nops(); ++i) {
        const GiNaC::ex t = e.op(i);
        if (without_symbols(t))
            numbers += t;
        else
            rest = plus(rest, terms[i]);
    }
    if (!numbers.is_zero())
        if (const auto number = constant_sign(numbers)) {
            const sign_set all = plus(rest, number->first);
            if (all.is_known())
                return {all, fmt::format("a sum of terms of one sign, its numbers {} {}", text(numbers),
                                         number->first.describe())};
        }
    return {r, "a sum of terms of unknown sign"};
}

// An argument about one symbol (sign_arguments.h): Sturm's theorem for a
// polynomial in one symbol alone, else monotonicity in a symbol bounded below.
std::optional<std::pair<sign_set, sign_reason>> sign_prover::argued_sign(const GiNaC::ex& e, int depth) const
{
    if (depth > 6)
        return std::nullopt;
    const auto write = [this](const GiNaC::ex& x) { return text(x); };
    std::vector<std::pair<GiNaC::ex, const domain*>> in;
    for (const auto& [s, d] : by_name())
        if (e.has(s))
            in.emplace_back(s, d);
    if (in.size() == 1)
        if (auto sturm = sturm_sign(e, in.front().first, *in.front().second, write))
            return sturm;
    // Trying every symbol, and again for each slope, grows as the symbols' count to the
    // depth: kept to short polynomials in a few symbols (in ten, it ran for half an hour).
    if (depth > 2 || in.size() > 4 || (GiNaC::is_a<GiNaC::add>(e) && e.nops() > 24))
        return std::nullopt;
    for (const auto& [s, d] : in) {
        auto monotone = monotone_sign(
            e, s, *d, [&](const GiNaC::ex& x) { return sign(factored(x), depth + 1); }, write);
        if (monotone)
            return monotone;
    }
    return std::nullopt;
}

// A polynomial of degree one in a symbol s with an interval domain, or in s^2 (no odd
// power of s), whatever its other symbols: for each value of those it is an affine
// function of s (of s^2) and lies between its values at the ends of the range of s
// (of s^2: [0, max(lower^2, upper^2)] when the interval holds 0), so the signs at
// those ends settle its sign (1 - b^2 >= 0 on [-1, 1]: 1 at b = 0 and 0 at b = 1).
std::optional<std::pair<sign_set, sign_reason>> sign_prover::affine_in_bounded_symbol(const GiNaC::ex& e, int depth) const
{
    if (depth > 6)
        return std::nullopt;
    std::optional<GiNaC::ex> expanded;   // once, for the first symbol that may do
    for (const auto& [s, range] : by_name()) {
        const domain& d = *range;
        if (d.what != domain::kind::interval || !e.has(s) || !e.is_polynomial(s))
            continue;
        if (!expanded)
            expanded = GiNaC::expand(e);
        const GiNaC::ex& p = *expanded;
        const int degree = p.degree(s);
        const bool squared = degree == 2 && p.coeff(s, 1).is_zero();
        if (degree != 1 && !squared)
            continue;
        const GiNaC::ex low = exact_end(d, false), high = exact_end(d, true);
        std::vector<GiNaC::ex> ends = {low, high};
        if (squared && sign_of_number(low).value_or(1) <= 0 && sign_of_number(high).value_or(-1) >= 0)
            ends = {0, sign_of_number(-low - high).value_or(0) > 0 ? low : high};
        sign_set r{false, false, false};
        std::vector<std::string> at;
        finding typeset;
        typeset.say(squared ? "affine in " : "linear in ").math(squared ? GiNaC::pow(s, 2) : s);
        typeset.say(", so between its values at the ends of the domain of ").math(s).say(": ");
        bool known = true;
        for (const GiNaC::ex& end : ends) {
            const GiNaC::ex value = factored(p.subs(s == end));
            const auto [sign_at, why] = sign(value, depth + 1);
            known = known && sign_at.is_known();
            if (!known || (r.negative && sign_at.positive) || (r.positive && sign_at.negative)) {
                known = false;   // the other end is not worked out: this symbol settles nothing
                break;
            }
            r.negative = r.negative || sign_at.negative;
            r.positive = r.positive || sign_at.positive;
            r.zero = r.zero || sign_at.zero;
            at.push_back(fmt::format("{} {} at {} = {}", text(value), sign_at.describe(), text(s), text(end)));
            if (&end != &ends.front())
                typeset.say(" and ");
            typeset.math(value).say(sign_at.negative ? (sign_at.zero ? " is not positive" : " is negative")
                                                     : (sign_at.zero ? " is not negative" : " is positive"));
            typeset.say(" at ").math(s == end);
        }
        if (!known || (r.negative && r.positive))
            continue;
        sign_reason reason(fmt::format("{}, {} in {}, between its values at the ends: {}",
                                       squared ? "affine in " + text(GiNaC::pow(s, 2)) : "linear in " + text(s),
                                       text(s), d.to_string(), fmt::format("{}", fmt::join(at, " and "))));
        reason.typeset = typeset;
        return std::make_pair(r, reason);
    }
    return std::nullopt;
}

// A polynomial of degree one in a single symbol with an interval domain takes its
// extremes at the ends of the interval.
std::optional<std::pair<sign_set, sign_reason>> sign_prover::linear_in_bounded_symbol(const GiNaC::ex& e) const
{
    GiNaC::ex only;
    int count = 0;
    for (const auto& [symbol, range] : domains_) {
        if (e.has(symbol)) {
            only = symbol;
            ++count;
        }
    }
    if (count != 1)
        return std::nullopt;
    const domain& d = domains_.at(only);
    if (d.what != domain::kind::interval || !e.is_polynomial(only) || e.degree(only) != 1)
        return std::nullopt;
    // The values fill the interval between the values at the two ends; an end that
    // the domain excludes is approached but not attained.
    const GiNaC::ex low = e.subs(only == exact_end(d, false));
    const GiNaC::ex high = e.subs(only == exact_end(d, true));
    // Each a number (Pi allowed), compared exactly (angles.h).
    const std::optional<int> lo = sign_of_number(low), hi = sign_of_number(high), rising = sign_of_number(high - low);
    if (!lo || !hi || !rising)
        return std::nullopt;
    const int least = *rising >= 0 ? *lo : *hi, most = *rising >= 0 ? *hi : *lo;
    const bool least_open = *rising >= 0 ? d.lower_open : d.upper_open;
    const bool most_open = *rising >= 0 ? d.upper_open : d.lower_open;
    sign_set r;
    r.negative = least < 0;
    r.positive = most > 0;
    r.zero = (least < 0 && most > 0) || (least == 0 && !least_open) || (most == 0 && !most_open);
    sign_reason reason(fmt::format("linear in {} in {}: {} and {} at the ends", text(only), d.to_string(),
                                   text(low), text(high)));
    reason.typeset.say("linear in ").math(only).say(", ").math(low).say(" and ").math(high).say(
        " at the ends of its domain");
    return std::make_pair(r, reason);
}

} // namespace impact::engine
