// A claim decided in one case (cases.h, prove_in_case): proven under the case's condition by
// its factor or remainder, the terms of one sign set aside, a bound narrowing a domain, or
// the square roots that are abbreviations named; |x| of a real x taken apart by its sign.
#include "engine/cases/case_proofs.h"
#include "engine/cases/radicals_named.h"

#include "engine/prove/condition_proof.h"
#include "engine/expr/infix.h"
#include "engine/prove/limit.h"
#include "engine/expr/normal_form.h"
#include "engine/prove/prove.h"
#include "engine/prove/seen_at_points.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace impact::engine {

using namespace cases_detail;

namespace {

// A number a domain's bound (a double) holds exactly: an integer or a dyadic fraction.
bool exact_bound(const GiNaC::numeric& n)
{
    if (!n.is_rational())
        return false;
    const GiNaC::numeric d = n.denom();
    if (!d.is_integer() || d > 1 << 20)
        return false;
    const long den = d.to_long();
    return (den & (den - 1)) == 0;
}

// The condition `s op n` (or `n op s`), with s a symbol and n a number, as a narrower
// domain of s; none when the condition is not such a bound, or does not narrow s's domain
// in a way a domain can say (an upper bound on a real quantity).
std::optional<std::pair<GiNaC::ex, domain>> bound_domain(const case_value& c, const assumptions& given)
{
    GiNaC::ex s = c.lhs, n = c.rhs;
    relation op = c.op;
    if (!GiNaC::is_a<GiNaC::symbol>(s)) {
        std::swap(s, n);
        op = op == relation::less_equal ? relation::greater_equal
             : op == relation::less     ? relation::greater
             : op == relation::greater  ? relation::less
                                        : relation::less_equal;
    }
    if (!GiNaC::is_a<GiNaC::symbol>(s) || !GiNaC::is_a<GiNaC::numeric>(n) ||
        !exact_bound(GiNaC::ex_to<GiNaC::numeric>(n)))
        return std::nullopt;
    const auto found = given.domains.find(s);
    const domain d = found != given.domains.end() ? found->second : domain{};
    const double x = GiNaC::ex_to<GiNaC::numeric>(n).to_double();
    // The bound's text too, which its exact value is read from (domain::exact_upper).
    std::ostringstream written;
    written << n;
    const bool strict = op == relation::less || op == relation::greater;
    domain out = d;
    if (op == relation::less_equal || op == relation::less) {
        if (d.what == domain::kind::interval) {
            if (!(x < d.upper || (x == d.upper && strict && !d.upper_open)))
                return std::nullopt;
            out.upper = x;
            out.upper_text = written.str();
            out.upper_open = strict;
        } else if (d.what == domain::kind::positive || d.what == domain::kind::nonnegative) {
            out = domain{domain::kind::interval, 0, x, d.what == domain::kind::positive, strict, "0", written.str()};
        } else {
            return std::nullopt;
        }
    } else {
        if (d.what == domain::kind::interval) {
            if (!(x > d.lower || (x == d.lower && strict && !d.lower_open)))
                return std::nullopt;
            out.lower = x;
            out.lower_text = written.str();
            out.lower_open = strict;
        } else if ((x > 0 || (x == 0 && strict)) && d.what != domain::kind::positive) {
            out = domain{domain::kind::positive};
        } else if (x == 0 && d.what == domain::kind::real) {
            out = domain{domain::kind::nonnegative};
        } else {
            return std::nullopt;
        }
    }
    if (out.what == domain::kind::interval &&
        (out.lower > out.upper || (out.lower == out.upper && (out.lower_open || out.upper_open))))
        return std::nullopt;
    return std::make_pair(s, out);
}

std::optional<verdict> prove_under(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                                   const symbol_table& symbols, const assumptions& given);

// The signs one try under a case's condition may work out (assumptions::effort).
constexpr std::size_t try_effort = 40000;

// A claim G >= 0 whose G is written as a sum, argued as a textbook does: the terms whose
// sign the domains alone settle (-(1 - eps^2) m_r g_n^2/2 <= 0) set aside, and the rest
// proven under the condition. The whole sum spelled out over a common denominator makes
// the condition's argument search long polynomials (the energy of sliding rough spheres:
// a minute, against a second for its tangential term alone). None when no term is set
// aside or the rest is not proven.
std::optional<verdict> prove_by_terms(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                                      const symbol_table& symbols, const assumptions& given)
{
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    // The sum's terms as written: -(a + b) and 2 (a + b) are sums too.
    GiNaC::ex difference = upper ? rhs - lhs : lhs - rhs;
    if (GiNaC::is_a<GiNaC::mul>(difference)) {
        GiNaC::ex sum, factor = 1;
        for (const GiNaC::ex& f : difference) {
            if (GiNaC::is_a<GiNaC::add>(f) && sum.is_zero())
                sum = f;
            else
                factor *= f;
        }
        if (!sum.is_zero() && GiNaC::is_a<GiNaC::numeric>(factor)) {
            GiNaC::ex spread = 0;
            for (const GiNaC::ex& term : sum)
                spread += factor * term;
            difference = spread;
        }
    }
    if (!GiNaC::is_a<GiNaC::add>(difference))
        return std::nullopt;
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    GiNaC::ex rest = 0;
    std::vector<std::string> aside;
    std::vector<sign_step> steps;
    bool some_positive = false;
    // In the order of their text: GiNaC's order of terms may change from one build to the next.
    std::vector<std::pair<std::string, GiNaC::ex>> terms;
    for (const GiNaC::ex& term : difference)
        terms.emplace_back(given.text(term), term);
    std::sort(terms.begin(), terms.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [text, term] : terms) {
        const sign_proof p = prove_sign(GiNaC::normal(term.subs(abbreviations, GiNaC::subs_options::no_pattern)), with_effort(given, try_effort));
        if (p.sign.is_nonnegative()) {
            aside.push_back(text);
            steps.insert(steps.end(), p.steps.begin(), p.steps.end());
            some_positive = some_positive || p.sign.is_positive();
        } else {
            rest += term;
        }
    }
    if (aside.empty())
        return std::nullopt;
    std::optional<verdict> v;
    if (rest.is_zero()) {
        if (strict && !some_positive)
            return std::nullopt;
        v.emplace();
        v->what = verdict::status::proven;
        v->residual = 0;
        v->method = "nothing is left";
    } else {
        const relation rest_op = strict && !some_positive ? relation::greater : relation::greater_equal;
        v = prove_under(rest, rest_op, GiNaC::ex(0), c, symbols, given);
        if (!v || v->what != verdict::status::proven)
            return std::nullopt;
    }
    v->proof.insert(v->proof.begin(), steps.begin(), steps.end());
    v->method = fmt::format("the term{} {} {} by the signs of {} factors, and the rest: {}",
                            aside.size() == 1 ? "" : "s", fmt::join(aside, ", "),
                            aside.size() == 1 ? (some_positive ? "is > 0" : "is >= 0")
                                              : (some_positive ? "are >= 0, one > 0" : "are >= 0"),
                            aside.size() == 1 ? "its" : "their", v->method);
    return v;
}

// The claim proven under the case's condition, or none (nothing sampled). Each argument
// is a try with an effort of its own: one that would search for minutes in one order of
// GiNaC's terms gives way to the next.
std::optional<verdict> prove_under(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                                   const symbol_table& symbols, const assumptions& given)
{
    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    // The claim as G >= 0 (> 0), the condition as C >= 0 (> 0).
    // Each form written once (normal_form.h): which argument proves the claim, and how it
    // is told, must not follow GiNaC's order of terms.
    const GiNaC::ex g = normal_written_once((upper ? rhs - lhs : lhs - rhs).subs(abbreviations, GiNaC::subs_options::no_pattern), given.order);
    nonnegative_form condition = condition_form(c);
    condition.value = normal_written_once(condition.value.subs(abbreviations, GiNaC::subs_options::no_pattern), given.order);
    const std::string under = fmt::format("under {}", condition_text(c, given.order));

    if (g.is_zero() && !strict) {
        verdict v;
        v.what = verdict::status::proven;
        v.residual = 0;
        v.method = "its two sides are equal";
        return v;
    }
    // G = q C with q >= 0 (q > 0 and C > 0 for a strict claim), q's denominator proven
    // non-zero: where it vanishes (C = mu J_n at mu = 0) G = q C says nothing.
    // Each try is made only where its goal is not seen false at a point of the domains
    // (seen_at_points.h): there its search finds nothing, in seconds for sliding rough spheres.
    if (!condition.value.is_zero()) {
        const GiNaC::ex q = normal_written_once(g / condition.value, given.order);
        const bool seen_false = seen_against(q, strict, given) || seen_of_both_signs(q.denom(), given);
        const sign_proof p = seen_false ? sign_proof{} : prove_sign(q, with_effort(given, try_effort));
        if (!seen_false && (strict ? (p.sign.is_positive() && condition.strict) : p.sign.is_nonnegative()) &&
            !prove_sign(q.denom(), with_effort(given, try_effort)).sign.zero) {
            verdict v;
            v.what = verdict::status::proven;
            v.residual = 0;
            v.proof = p.steps;
            v.method = fmt::format("{}: {} = ({})*({}), a factor {} times the condition's", under, given.text(g),
                                   given.text(q), given.text(condition.value), p.sign.describe());
            return v;
        }
    }
    // G = C + r with r >= 0 (and one of them > 0 for a strict claim).
    {
        const GiNaC::ex r = normal_written_once(g - condition.value, given.order);
        const bool seen_false = seen_against(r, false, given);
        const sign_proof p = seen_false ? sign_proof{} : prove_sign(r, with_effort(given, try_effort));
        if (!seen_false && p.sign.is_nonnegative() && (!strict || p.sign.is_positive() || condition.strict)) {
            verdict v;
            v.what = verdict::status::proven;
            v.residual = 0;
            v.proof = p.steps;
            v.method = fmt::format("{}: {} = ({}) + ({}), the condition's side plus a term {}", under,
                                   given.text(g), given.text(condition.value), given.text(r), p.sign.describe());
            return v;
        }
    }
    // The terms of one sign set aside, or the signs alone; tried after the condition's
    // factor and remainder, which settle the common claim (a bound the condition is a
    // multiple of, the friction cone's) at once where these search long polynomials.
    if (auto by_terms = prove_by_terms(lhs, op, rhs, c, symbols, given))
        return by_terms;
    if (!seen_against(g, strict, given))
        if (auto alone = prove_inequality_by_signs(lhs, op, rhs, symbols, with_effort(given, try_effort)))
            return alone;
    // A bound on one symbol by a number (x <= 1): the sign proof run again on the symbol's
    // domain narrowed by it.
    if (const auto bound = bound_domain(c, given)) {
        assumptions narrowed = given;
        narrowed.domains[bound->first] = bound->second;
        narrowed.known = std::make_shared<worked_out>();
        if (auto v = prove_inequality_by_signs(lhs, op, rhs, symbols, with_effort(narrowed, try_effort))) {
            v->method = fmt::format("{}, {} in {}: {}", under, ginac_syntax(bound->first, symbols.order()),
                                    bound->second.to_string(), v->method);
            return v;
        }
    }
    if (!condition.value.is_zero())
        if (auto v = divided_by_condition(g, strict, condition.value, condition.strict, with_effort(given, try_effort))) {
            v->method = fmt::format("{}: {}", under, v->method);
            return *v;
        }
    return std::nullopt;
}

// Not proven under the condition of `c`: the verdict over the whole domain, sampled where
// it holds (never proven), failed where it does not (which may be outside the case).
verdict unproven_in_case(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                         const symbol_table& symbols, const assumptions& given)
{
    verdict v = prove_inequality(lhs, op, rhs, symbols, given);
    const std::string under = fmt::format("under {}", condition_text(c, given.order));
    if (v.what == verdict::status::sampled)
        v.method = fmt::format("not proven {}; sampled over the whole domain, where it holds: {}", under, v.method);
    else if (v.what == verdict::status::failed)
        v.method = fmt::format("not proven {} (it fails somewhere in the whole domain): {}", under, v.method);
    return v;
}

// The claim under the case's condition with the square roots that are abbreviations as
// quantities of their own (radicals_named); none when there are none, or it is not proven so.
std::optional<verdict> prove_with_roots_named(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs,
                                              const case_value& c, const symbol_table& symbols,
                                              const assumptions& given)
{
    radicals_named named(symbols, given);
    case_value here = c;
    const GiNaC::ex l = named(lhs), r = named(rhs);
    here.lhs = named(c.lhs);
    here.rhs = named(c.rhs);
    if (!named.any_used())
        return std::nullopt;
    std::vector<std::string> words;
    const assumptions roots = named.with_domains(given, words);
    auto v = prove_under(l, op, r, here, symbols, roots);
    if (!v || v->what != verdict::status::proven)
        return std::nullopt;
    v->method = fmt::format("with the square roots that are abbreviations as quantities of their own ({}): {}",
                            fmt::join(words, ", "), v->method);
    return v;
}

} // namespace

verdict prove_in_case(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                      const symbol_table& symbols, const assumptions& given)
{
    // |x| for a real x: proven for x > 0, x < 0 and x = 0 apart, x written as +y, -y and 0
    // with y > 0, each absolute value then taken out.
    std::vector<GiNaC::ex> xs;
    for (const GiNaC::ex& e : {lhs, rhs, c.lhs, c.rhs})
        symbols_under_abs(e, given, xs);
    if (xs.empty() || xs.size() > 2) {
        const GiNaC::ex l = without_abs(lhs, given), r = without_abs(rhs, given);
        case_value plain = c;
        plain.lhs = without_abs(c.lhs, given);
        plain.rhs = without_abs(c.rhs, given);
        if (auto v = prove_with_roots_named(l, op, r, plain, symbols, given))
            return *v;
        if (auto v = prove_under(l, op, r, plain, symbols, given))
            return *v;
        return unproven_in_case(lhs, op, rhs, c, symbols, given);
    }
    std::vector<check_result::part> parts;
    const std::size_t branches = xs.size() == 1 ? 3 : 9;
    for (std::size_t branch = 0; branch < branches; ++branch) {
        // y > 0 is a new symbol, declared positive for the whole run: the signs worked
        // out under the declared domains hold with it.
        assumptions signed_given = given;
        GiNaC::exmap to;
        std::vector<std::string> words;
        std::size_t code = branch;
        for (const GiNaC::ex& x : xs) {
            const int which = static_cast<int>(code % 3);   // 0: x > 0, 1: x < 0, 2: x = 0
            code /= 3;
            const std::string name = GiNaC::ex_to<GiNaC::symbol>(x).get_name();
            GiNaC::ex y = GiNaC::possymbol(name, GiNaC::ex_to<GiNaC::symbol>(x).get_TeX_name());
            if (given.run) {
                const auto known = given.run->magnitudes.emplace(x, y).first;
                y = known->second;
            }
            signed_given.domains[y] = domain{domain::kind::positive};
            to[x] = which == 0 ? GiNaC::ex(y) : which == 1 ? GiNaC::ex(-y) : GiNaC::ex(0);
            words.push_back(fmt::format("{} {} 0", name, which == 0 ? ">" : which == 1 ? "<" : "="));
        }
        check_result::part part;
        part.under = fmt::format("for {}", fmt::join(words, " and "));
        case_value here = c;
        try {
            here.lhs = without_abs(c.lhs.subs(to, GiNaC::subs_options::no_pattern), signed_given);
            here.rhs = without_abs(c.rhs.subs(to, GiNaC::subs_options::no_pattern), signed_given);
        } catch (const std::exception&) {
            part.outcome.method = "the condition is not defined there";
            parts.push_back(std::move(part));
            continue;
        }
        if (cannot_arise(here, symbols, signed_given)) {
            part.outcome.what = verdict::status::proven;
            part.outcome.residual = 0;
            part.outcome.method = "the case does not arise: its condition is false there";
            parts.push_back(std::move(part));
            continue;
        }
        try {
            const GiNaC::ex l = without_abs(lhs.subs(to, GiNaC::subs_options::no_pattern), signed_given);
            const GiNaC::ex r = without_abs(rhs.subs(to, GiNaC::subs_options::no_pattern), signed_given);
            if (auto v = prove_under(l, op, r, here, symbols, signed_given))
                part.outcome = std::move(*v);
            else
                part.outcome.method = "not proven there";
        } catch (const std::exception&) {
            part.outcome.method = "the claim is not defined there";
        }
        if (part.outcome.what != verdict::status::proven)
            return unproven_in_case(lhs, op, rhs, c, symbols, given);
        parts.push_back(std::move(part));
    }
    return combined(parts, "by the sign of what is under |.|");
}

} // namespace impact::engine
