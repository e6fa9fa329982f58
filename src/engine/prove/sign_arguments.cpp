#include "engine/prove/sign_arguments.h"

#include "engine/prove/sturm.h"

#include <fmt/format.h>

#include <vector>

namespace impact::engine {
namespace {

// The distinct roots of a square-free q strictly between the ends (Sturm's theorem, with
// a root at a finite end divided out first, so that neither end is a root), and the
// sign changes counted at each end.
struct root_count {
    int roots = 0;
    int at_lower = 0, at_upper = 0;
};

root_count roots_inside(GiNaC::ex q, const GiNaC::ex& s, const closed_interval& range)
{
    for (const auto& end : {range.lower, range.upper})
        if (end && q.degree(s) > 0 && q.subs(s == *end).is_zero())
            q = GiNaC::quo(q, s - *end, s);
    if (q.degree(s) == 0)
        return {};
    const std::vector<GiNaC::ex> sequence = sturm_sequence(q, s);
    root_count c;
    c.at_lower = sign_changes(sequence, s, range.lower, false);
    c.at_upper = sign_changes(sequence, s, range.upper, true);
    c.roots = c.at_lower - c.at_upper;
    return c;
}

// A point strictly inside the domain.
GiNaC::numeric inner_point(const closed_interval& range)
{
    if (range.lower && range.upper)
        return (*range.lower + *range.upper) / 2;
    if (range.lower)
        return *range.lower + 1;
    if (range.upper)
        return *range.upper - 1;
    return 0;
}

// A sign in words, for prose: "positive", "non-negative", ...
std::string in_words(const sign_set& s)
{
    if (!s.negative && !s.zero && s.positive)
        return "positive";
    if (!s.negative && s.positive)
        return "non-negative";
    if (s.negative && !s.zero && !s.positive)
        return "negative";
    if (s.negative && !s.positive)
        return "non-positive";
    return s.zero && !s.negative && !s.positive ? "zero" : "of unknown sign";
}

std::string interval_text(const closed_interval& range, const std::function<std::string(const GiNaC::ex&)>& text)
{
    return fmt::format("({}, {})", range.lower_shown ? text(*range.lower_shown) : "-infinity",
                       range.upper_shown ? text(*range.upper_shown) : "infinity");
}

} // namespace

std::optional<reasoned_sign> sturm_sign(const GiNaC::ex& e, const GiNaC::ex& s, const domain& range,
                                        const std::function<std::string(const GiNaC::ex&)>& text)
{
    const GiNaC::ex p = GiNaC::expand(e);
    if (!GiNaC::is_a<GiNaC::symbol>(s) || !rational_polynomial_in(p, s) || p.degree(s) < 1)
        return std::nullopt;
    // p = c · O · E², with O the product of its factors of odd multiplicity and E of even
    // (square-free factorisation): p has the sign of c·O wherever E does not vanish.
    const GiNaC::ex factors = GiNaC::sqrfree(p, GiNaC::lst{s});
    GiNaC::exvector parts;
    if (GiNaC::is_a<GiNaC::mul>(factors))
        parts.assign(factors.begin(), factors.end());
    else
        parts.push_back(factors);
    GiNaC::ex odd = 1, even = 1;
    for (const GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::even))
            even *= f.op(0);
        else if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint))
            odd *= f.op(0);   // f^(2k+1): the sign of f, and its roots are f's
        else
            odd *= f;
    }
    odd = GiNaC::expand(odd);
    even = GiNaC::expand(even);
    const closed_interval closure = closure_of(range);
    const root_count changing = roots_inside(odd, s, closure);
    if (changing.roots != 0)
        return std::nullopt;
    const GiNaC::numeric inside = inner_point(closure);
    const int interior = sign_of(odd.subs(s == inside));
    if (interior == 0)
        return std::nullopt;   // an inner point is a root only if the count were wrong
    // Zero where E has a root inside, or p vanishes at an end the domain holds.
    const int touching = roots_inside(even, s, closure).roots;
    std::vector<std::string> zeros;
    for (const auto& [end, in] : {std::make_pair(closure.lower, closure.lower_in),
                                  std::make_pair(closure.upper, closure.upper_in)})
        if (end && in && p.subs(s == *end).is_zero())
            zeros.push_back(fmt::format("{} = {}", text(s), text(*end)));
    const bool zero = touching > 0 || !zeros.empty();
    const sign_set result{interior < 0, zero, interior > 0};

    const std::string where = interval_text(closure, text);
    // The value read is O's (p's, when it has no repeated factor): p itself may vanish
    // at the inner point, where E does.
    std::string words = fmt::format(
        "by Sturm's theorem, {} has no root {}in {} (sign changes of its Sturm sequence: {} at {}, {} at {}), "
        "and {} {} at {} = {}",
        text(odd), even.is_equal(1) ? "" : "of odd multiplicity ", where, changing.at_lower,
        closure.lower_shown ? text(*closure.lower_shown) : "-infinity", changing.at_upper,
        closure.upper_shown ? text(*closure.upper_shown) : "infinity", text(odd.subs(s == inside)),
        sign_set::exactly(interior).describe(), text(s), text(inside));
    if (touching > 0)
        words += fmt::format("; it touches zero at the roots of {} (an even power)", text(even));
    if (!zeros.empty())
        words += fmt::format("; it is 0 at {}", fmt::join(zeros, " and "));
    sign_reason why(words);
    why.typeset.say("by Sturm's theorem, ")
        .math(odd)
        .say(fmt::format(" has no root{} inside the domain of ", even.is_equal(1) ? "" : " of odd multiplicity"))
        .math(s)
        .say(fmt::format(" (sign changes of its Sturm sequence: {} and {} at the ends), and is ", changing.at_lower,
                         changing.at_upper))
        .math(odd.subs(s == inside))
        .say(fmt::format(", {}, at ", in_words(sign_set::exactly(interior))))
        .math(s == inside);
    if (zero)
        why.typeset.say("; it may vanish (at a root of an even power or an end of the domain)");
    return std::make_pair(result, why);
}

std::optional<reasoned_sign> monotone_sign(const GiNaC::ex& e, const GiNaC::ex& s, const domain& range,
                                           const std::function<reasoned_sign(const GiNaC::ex&)>& sign,
                                           const std::function<std::string(const GiNaC::ex&)>& text)
{
    // The ends exactly (Pi/2 as it is): the slope's sign is known on the domain, not beyond.
    std::optional<GiNaC::ex> lower_end, upper_end;
    if (range.what == domain::kind::positive || range.what == domain::kind::nonnegative)
        lower_end = GiNaC::ex(0);
    if (range.what == domain::kind::interval) {
        lower_end = range.exact_lower();
        upper_end = range.exact_upper();
    }
    if (!GiNaC::is_a<GiNaC::symbol>(s) || !lower_end || !e.is_polynomial(s))
        return std::nullopt;
    const GiNaC::ex p = GiNaC::expand(e);
    if (p.degree(s) < 2)
        return std::nullopt;
    const GiNaC::ex slope = GiNaC::expand(GiNaC::diff(p, GiNaC::ex_to<GiNaC::symbol>(s)));
    const auto [rising, why_rising] = sign(slope);
    if (rising.negative && rising.positive)
        return std::nullopt;
    const bool increasing = !rising.negative;
    // Between its values at the ends of the closure: from its value at the lower end
    // upwards when increasing, downwards when decreasing (and towards the upper end's
    // value, when there is one).
    const GiNaC::ex at_lower = GiNaC::normal(p.subs(s == *lower_end));
    const reasoned_sign low = sign(at_lower);
    std::optional<reasoned_sign> high;
    GiNaC::ex at_upper;
    if (upper_end) {
        at_upper = GiNaC::normal(p.subs(s == *upper_end));
        high = sign(at_upper);
    }
    sign_set result{true, true, true};
    const GiNaC::ex* end_value = nullptr;
    const GiNaC::ex* end = nullptr;
    const sign_set* end_sign = nullptr;
    // increasing: p >= p(lower), p <= p(upper); decreasing: p <= p(lower), p >= p(upper).
    const sign_set& from_lower = low.first;
    if (increasing ? !from_lower.negative : !from_lower.positive) {
        result = increasing ? sign_set{false, from_lower.zero, true} : sign_set{true, from_lower.zero, false};
        end_value = &at_lower;
        end = &*lower_end;
        end_sign = &from_lower;
    } else if (high && (increasing ? !high->first.positive : !high->first.negative)) {
        result = increasing ? sign_set{true, high->first.zero, false} : sign_set{false, high->first.zero, true};
        end_value = &at_upper;
        end = &*upper_end;
        end_sign = &high->first;
    } else {
        return std::nullopt;
    }
    const std::string derivative = fmt::format("d/d{} = {}", text(s), text(slope));
    sign_reason why(fmt::format("{} in {} on {} ({} {}, {}), so {} than its value at {} = {}: {} {}",
                                increasing ? "increasing" : "decreasing", text(s), range.to_string(), derivative,
                                rising.describe(), why_rising.words,
                                result.positive ? "no less" : "no more", text(s), text(*end), text(*end_value),
                                end_sign->describe()));
    why.typeset.say(fmt::format("{} in ", increasing ? "increasing" : "decreasing"))
        .math(s)
        .say(" (its derivative ")
        .math(slope)
        .say(fmt::format(" is {}), so no {} than ", in_words(rising), result.positive ? "less" : "more"))
        .math(*end_value)
        .say(fmt::format(", which is {}, its value at ", in_words(*end_sign)))
        .math(s == *end);
    return std::make_pair(result, why);
}

} // namespace impact::engine
