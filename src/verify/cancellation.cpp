// Candidate forms without the cancellations of the transcendental functions (verify/cancellation.h).
#include "verify/cancellation.h"

#include "compile/functions.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace impact::verify {

namespace {

bool is_function(const GiNaC::ex& e, const char* name)
{
    return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name;
}

// A term c f(x) of a sum, with f the function named: c and x. A term f(x) alone has c = 1;
// f must be a factor of the term once, to the first power.
struct factored_term {
    GiNaC::ex rest;
    GiNaC::ex argument;
};

std::optional<factored_term> with_factor(const GiNaC::ex& term, const char* name)
{
    if (is_function(term, name))
        return factored_term{1, term.op(0)};
    if (!GiNaC::is_a<GiNaC::mul>(term))
        return std::nullopt;
    std::optional<factored_term> found;
    for (std::size_t i = 0; i < term.nops(); ++i)
        if (is_function(term.op(i), name)) {
            if (found)
                return std::nullopt;   // f twice: not one term c f(x)
            found = factored_term{term / term.op(i), term.op(i).op(0)};
        }
    return found;
}

// The pair of terms c f(x) and ±c of a sum, written as one: `joined(c, x, sign)` for the
// pair c f(x) + sign c, or nothing where it does not apply to that sign.
struct pairing {
    const char* function;
    int sign;   // the other term is sign · c
    GiNaC::ex (*joined)(const GiNaC::ex& c, const GiNaC::ex& x);
};

const pairing pairings[] = {
    // c cos x − c = −2c sin²(x/2): the other term u = −c, u − u cos x = 2u sin²(x/2).
    {"cos", -1, [](const GiNaC::ex& c, const GiNaC::ex& x) { return -2 * c * GiNaC::pow(GiNaC::sin(x / 2), 2); }},
    // c cos x + c = 2c cos²(x/2).
    {"cos", 1, [](const GiNaC::ex& c, const GiNaC::ex& x) { return 2 * c * GiNaC::pow(GiNaC::cos(x / 2), 2); }},
    // c cosh x − c = 2c sinh²(x/2).
    {"cosh", -1, [](const GiNaC::ex& c, const GiNaC::ex& x) { return 2 * c * GiNaC::pow(GiNaC::sinh(x / 2), 2); }},
    // c exp x − c = c expm1(x).
    {"exp", -1, [](const GiNaC::ex& c, const GiNaC::ex& x) { return c * compile::expm1(x); }},
};

// A sum with each pair of its terms that cancels written as one term, the other terms in
// their places; the sum itself where no pair does.
GiNaC::ex joined_sum(const GiNaC::ex& sum)
{
    const std::vector<GiNaC::ex> terms(sum.begin(), sum.end());
    std::vector<bool> used(terms.size(), false);
    std::vector<std::optional<GiNaC::ex>> joined(terms.size());   // at the pair's term c f(x)
    for (std::size_t i = 0; i < terms.size(); ++i)
        for (const pairing& p : pairings) {
            const std::optional<factored_term> t = used[i] ? std::nullopt : with_factor(terms[i], p.function);
            if (!t)
                continue;
            for (std::size_t j = 0; j < terms.size() && !used[i]; ++j)
                if (j != i && !used[j] && (terms[j] - p.sign * t->rest).is_zero()) {
                    used[i] = used[j] = true;
                    joined[i] = p.joined(t->rest, t->argument);
                }
        }
    if (std::none_of(joined.begin(), joined.end(), [](const auto& j) { return j.has_value(); }))
        return sum;
    GiNaC::ex result = 0;
    for (std::size_t i = 0; i < terms.size(); ++i)
        if (joined[i])
            result += *joined[i];
        else if (!used[i])
            result += terms[i];
    return result;
}

// log(1 + y) = log1p(y); log(a/b) = log1p((a − b)/b), a − b exact where a and b are close.
GiNaC::ex log_without_cancellation(const GiNaC::ex& argument)
{
    if (GiNaC::is_a<GiNaC::add>(argument))
        for (const GiNaC::ex& term : argument)
            if (term.is_equal(1))
                return compile::log1p(argument - 1);
    if (GiNaC::is_a<GiNaC::mul>(argument) && !GiNaC::numer_denom(argument).op(1).is_equal(1)) {
        const GiNaC::ex nd = GiNaC::numer_denom(argument);
        return compile::log1p((nd.op(0) - nd.op(1)) / nd.op(1));
    }
    return GiNaC::log(argument);
}

// acos(1 − y) = 2 asin(√(y/2)) and acos(−1 + y) = π − 2 asin(√(y/2)), y in [0, 2]: an angle
// near 0 (or π) from a cosine near 1 (or −1), whose rounding 1 − y loses y.
GiNaC::ex acos_without_cancellation(const GiNaC::ex& argument)
{
    if (GiNaC::is_a<GiNaC::add>(argument))
        for (const GiNaC::ex& term : argument)
            if (term.is_equal(1) || term.is_equal(-1)) {
                const GiNaC::ex y = term.is_equal(1) ? 1 - argument : argument + 1;
                const GiNaC::ex half_angle = 2 * GiNaC::asin(GiNaC::sqrt(y / 2));
                return term.is_equal(1) ? half_angle : GiNaC::Pi - half_angle;
            }
    return GiNaC::acos(argument);
}

struct rewrite : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& e) override
    {
        const GiNaC::ex inner = e.map(*this);
        if (GiNaC::is_a<GiNaC::add>(inner))
            return joined_sum(inner);
        if (is_function(inner, "log"))
            return log_without_cancellation(inner.op(0));
        if (is_function(inner, "acos"))
            return acos_without_cancellation(inner.op(0));
        return inner;
    }
};

} // namespace

GiNaC::ex without_cancellation(const GiNaC::ex& e)
{
    rewrite r;
    return r(e);
}

} // namespace impact::verify
