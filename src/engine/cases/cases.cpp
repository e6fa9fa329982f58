#include "engine/cases/cases.h"

#include "engine/prove/condition_proof.h"
#include "engine/expr/infix.h"
#include "engine/prove/limit.h"
#include "engine/expr/normal_form.h"
#include "engine/prove/prove.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>

namespace impact::engine {
namespace {

// The condition as `C >= 0` (or `C > 0` when `strict`).
struct nonnegative_form {
    GiNaC::ex value;
    bool strict = false;
};

nonnegative_form condition_form(const case_value& c)
{
    const bool upper = c.op == relation::less_equal || c.op == relation::less;
    return {upper ? c.rhs - c.lhs : c.lhs - c.rhs, c.op == relation::less || c.op == relation::greater};
}

// A non-zero rational k with a = k b, if there is one.
std::optional<GiNaC::numeric> constant_ratio(const GiNaC::ex& a, const GiNaC::ex& b)
{
    if (b.is_zero())
        return std::nullopt;
    const GiNaC::ex ratio = GiNaC::normal(a / b);
    if (!GiNaC::is_a<GiNaC::numeric>(ratio) || ratio.is_zero())
        return std::nullopt;
    const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(ratio);
    if (!k.is_real())
        return std::nullopt;
    return k;
}

// The weakest of the parts: failed if one failed, sampled if one was sampled.
verdict combined(const std::vector<check_result::part>& parts, const std::string& what)
{
    verdict v;
    v.what = verdict::status::proven;
    v.residual = 0;
    std::vector<std::string> lines;
    for (const check_result::part& p : parts) {
        if (p.outcome.what == verdict::status::failed) {
            v.what = verdict::status::failed;
            v.residual = p.outcome.residual;
        } else if (p.outcome.what == verdict::status::sampled && v.what == verdict::status::proven) {
            v.what = verdict::status::sampled;
            v.samples = p.outcome.samples;
        }
        lines.push_back(fmt::format("{}: {} ({})", p.under, to_string(p.outcome), p.outcome.method));
    }
    v.method = fmt::format("{}: {}", what, fmt::join(lines, "; "));
    return v;
}

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
    const bool strict = op == relation::less || op == relation::greater;
    domain out = d;
    if (op == relation::less_equal || op == relation::less) {
        if (d.what == domain::kind::interval) {
            if (!(x < d.upper || (x == d.upper && strict && !d.upper_open)))
                return std::nullopt;
            out.upper = x;
            out.upper_open = strict;
        } else if (d.what == domain::kind::positive || d.what == domain::kind::nonnegative) {
            out = domain{domain::kind::interval, 0, x, d.what == domain::kind::positive, strict};
        } else {
            return std::nullopt;
        }
    } else {
        if (d.what == domain::kind::interval) {
            if (!(x > d.lower || (x == d.lower && strict && !d.lower_open)))
                return std::nullopt;
            out.lower = x;
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


GiNaC::ex select_eval(const GiNaC::ex& c, const GiNaC::ex& a, const GiNaC::ex& b)
{
    if (GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(c).is_positive() ? a : b;
    return select_positive(c, a, b).hold();
}

GiNaC::ex select_evalf(const GiNaC::ex& c, const GiNaC::ex& a, const GiNaC::ex& b)
{
    const GiNaC::ex at = c.evalf();
    if (GiNaC::is_a<GiNaC::numeric>(at) && GiNaC::ex_to<GiNaC::numeric>(at).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(at).is_positive() ? a.evalf() : b.evalf();
    return select_positive(at, a.evalf(), b.evalf()).hold();
}

} // namespace

REGISTER_FUNCTION(select_positive, eval_func(select_eval).evalf_func(select_evalf))

GiNaC::ex select_of(const std::vector<case_value>& cases)
{
    GiNaC::ex rest = cases.back().value;
    for (std::size_t i = cases.size() - 1; i-- > 0;) {
        const nonnegative_form f = condition_form(cases[i]);
        rest = f.strict ? select_positive(f.value, cases[i].value, rest)
                        : select_positive(-f.value, rest, cases[i].value);
    }
    return rest;
}

bool is_select(const GiNaC::ex& e)
{
    return GiNaC::is_the_function<select_positive_SERIAL>(e);
}

bool has_select(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (is_select(*it))
            return true;
    return false;
}

std::string condition_text(const case_value& c, const term_order& order)
{
    return fmt::format("{} {} {}", ginac_syntax(c.lhs, order), to_string(c.op), ginac_syntax(c.rhs, order));
}

check_result prove_exhaustive(const std::string& name, const std::vector<case_value>& cases,
                              const symbol_table& symbols)
{
    check_result c;
    c.name = fmt::format("the cases of {} cover every value", name);
    c.statement = c.name;
    c.because = "each value of the quantities must fall in a case";
    c.where = cases.front().where;
    c.stated = 0;
    c.lhs = 0;
    c.rhs = 0;
    c.outcome.residual = 0;
    // Each condition as a sign of D, the first condition's C. Compared as written first: a
    // condition with a radical of a radical (|g_t| in space, whose square holds the
    // distance sqrt(r.r)) may normalise to forms normal() cannot compare, though it is the
    // first's, turned.
    const GiNaC::ex first = condition_form(cases.front()).value;
    const GiNaC::ex d = normal_written_once(first, symbols.order());
    sign_set covered{false, false, false};
    std::vector<std::string> signs;
    for (const case_value& one : cases) {
        const nonnegative_form f = condition_form(one);
        auto k = constant_ratio(f.value, first);
        if (!k)
            k = constant_ratio(f.value, d);
        if (!k) {
            c.outcome.what = verdict::status::failed;
            c.outcome.residual = f.value;
            c.outcome.method = fmt::format("the condition {} is not a sign of {} as the first is: the cases are not "
                                           "proven to cover every value",
                                           condition_text(one, symbols.order()), ginac_syntax(d, symbols.order()));
            return c;
        }
        // C = k D >= 0 (> 0): D >= 0 for k > 0, D <= 0 for k < 0.
        const bool up = k->is_positive();
        if (up)
            covered.positive = true;
        else
            covered.negative = true;
        if (!f.strict)
            covered.zero = true;
        signs.push_back(fmt::format("D {} 0", f.strict ? (up ? ">" : "<") : (up ? ">=" : "<=")));
    }
    (void)symbols;
    if (covered.negative && covered.zero && covered.positive) {
        c.outcome.what = verdict::status::proven;
        c.outcome.method = fmt::format("with D = {}, the conditions read {}: together every sign of D",
                                       ginac_syntax(d, symbols.order()), fmt::join(signs, ", "));
    } else {
        c.outcome.what = verdict::status::failed;
        c.outcome.residual = d;
        c.outcome.method = fmt::format("with D = {}, the conditions read {}: D {} is in no case",
                                       ginac_syntax(d, symbols.order()), fmt::join(signs, ", "),
                                       !covered.negative ? "< 0" : !covered.zero ? "= 0" : "> 0");
    }
    return c;
}

namespace {

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
        const sign_proof p = prove_sign(GiNaC::normal(term.subs(abbreviations)), with_effort(given, try_effort));
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
    const GiNaC::ex g = normal_written_once((upper ? rhs - lhs : lhs - rhs).subs(abbreviations), given.order);
    nonnegative_form condition = condition_form(c);
    condition.value = normal_written_once(condition.value.subs(abbreviations), given.order);
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
    if (!condition.value.is_zero()) {
        const GiNaC::ex q = normal_written_once(g / condition.value, given.order);
        const sign_proof p = prove_sign(q, with_effort(given, try_effort));
        if ((strict ? (p.sign.is_positive() && condition.strict) : p.sign.is_nonnegative()) &&
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
        const sign_proof p = prove_sign(r, with_effort(given, try_effort));
        if (p.sign.is_nonnegative() && (!strict || p.sign.is_positive() || condition.strict)) {
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

// The condition of `c` proven false under `given`: the case does not arise. Asked where a
// condition may have become one the domains decide (at special values, for a sign of
// what is under |.|), and only of a condition whose factors are sums of a few terms or
// multiples of an abbreviation of declared sign (the spheres approach: mu (1 + eps) D_t s_n
// at b = -1): a sign proof of a long sum that holds somewhere costs seconds and finds
// nothing.
bool cannot_arise(const case_value& c, const symbol_table& symbols, const assumptions& given)
{
    constexpr std::size_t most_terms = 4;
    const auto few_terms = [&](const GiNaC::ex& product) {
        const auto short_enough = [&](GiNaC::ex factor) {
            if (GiNaC::is_a<GiNaC::power>(factor))
                factor = factor.op(0);
            return !GiNaC::is_a<GiNaC::add>(factor) || factor.nops() <= most_terms ||
                   assumed_multiple(factor, given).has_value();
        };
        if (!GiNaC::is_a<GiNaC::mul>(product))
            return short_enough(product);
        for (std::size_t i = 0; i < product.nops(); ++i)
            if (!short_enough(product.op(i)))
                return false;
        return true;
    };
    const nonnegative_form f = condition_form(c);
    const GiNaC::ex value = without_abs(GiNaC::normal(f.value.subs(symbols.abbreviations())), given);
    if (!few_terms(value.numer())) {
        const GiNaC::ex top = GiNaC::expand(value.numer());
        if (GiNaC::is_a<GiNaC::add>(top) && top.nops() > most_terms &&
            !few_terms(given.run ? factor_polynomial(top, *given.run) : factor_polynomial(top)))
            return false;
    }
    const sign_set s = prove_sign(value, given).sign;
    return f.strict ? !s.positive : (!s.positive && !s.zero);
}

// True when `e` is, as written, a sum of products of even powers and positive numbers
// (r_x^2 + r_y^2, G_tx^2 + G_ty^2 + G_tz^2): >= 0 without expanding it.
bool sum_of_squares(const GiNaC::ex& e)
{
    if (GiNaC::is_a<GiNaC::numeric>(e))
        return !GiNaC::ex_to<GiNaC::numeric>(e).is_negative() && GiNaC::ex_to<GiNaC::numeric>(e).is_real();
    if (GiNaC::is_a<GiNaC::power>(e))
        return e.op(1).info(GiNaC::info_flags::even);
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e))
        return std::all_of(e.begin(), e.end(), [](const GiNaC::ex& part) { return sum_of_squares(part); });
    return false;
}

// Each square root that is an abbreviation's definition (d = sqrt(r.r), G_t = sqrt(G_t.G_t))
// written as a quantity of its own, named as the abbreviation: a new symbol (the
// abbreviation's own would be replaced by its definition again), >= 0, or > 0 where its
// radicand is proven positive. A claim proven under a case's condition for every value
// of such a quantity is proven for its own value in particular, and the proof never
// expands the radicand's square (in space a polynomial of hundreds of terms).
class radicals_named : public GiNaC::map_function {
public:
    // Only roots of radicands proven >= 0 (a sum of squares): a radicand that may be
    // negative, written as the square of its root, would be taken for >= 0.
    radicals_named(const symbol_table& symbols, const assumptions& given)
    {
        for (const quantity& q : symbols.all()) {
            if (!q.definition)
                continue;
            const GiNaC::ex inputs = symbols.in_inputs(*q.definition);
            if (!GiNaC::is_a<GiNaC::power>(inputs) || !inputs.op(1).is_equal(GiNaC::numeric(1, 2)))
                continue;
            if (sum_of_squares(inputs.op(0)) || prove_sign(inputs.op(0), with_effort(given, 100)).sign.is_nonnegative())
                roots_.push_back({GiNaC::expand(inputs.op(0)), q, GiNaC::symbol(q.name, q.latex), false});
        }
    }

    GiNaC::ex operator()(const GiNaC::ex& part) override
    {
        if (GiNaC::is_a<GiNaC::power>(part) && part.op(1).info(GiNaC::info_flags::rational) &&
            !part.op(1).info(GiNaC::info_flags::integer) && GiNaC::ex_to<GiNaC::numeric>(part.op(1)).denom() == 2) {
            auto known = match_.find(part.op(0));
            if (known == match_.end()) {
                const GiNaC::ex radicand = GiNaC::expand(part.op(0));
                std::size_t which = roots_.size();
                for (std::size_t i = 0; i < roots_.size(); ++i)
                    if (roots_[i].radicand.is_equal(radicand))
                        which = i;
                known = match_.emplace(part.op(0), which).first;
            }
            if (known->second < roots_.size()) {
                root& r = roots_[known->second];
                r.used = true;
                return GiNaC::pow(r.atom, GiNaC::ex_to<GiNaC::numeric>(part.op(1)).mul(2));
            }
        }
        // The radicand itself (d^2 written r.r): the square of its root.
        if (GiNaC::is_a<GiNaC::add>(part))
            for (root& r : roots_)
                if (GiNaC::is_a<GiNaC::add>(r.radicand) && r.radicand.nops() == part.nops() &&
                    GiNaC::expand(part).is_equal(r.radicand)) {
                    r.used = true;
                    return GiNaC::pow(r.atom, 2);
                }
        return part.map(*this);
    }

    /// `given` with the domains of the roots used: >= 0, > 0 where declared or where the
    /// radicand is proven > 0.
    assumptions with_domains(const assumptions& given, std::vector<std::string>& words) const
    {
        assumptions named = given;
        named.known = std::make_shared<worked_out>();
        for (const root& r : roots_) {
            if (!r.used)
                continue;
            // Declared positive (d: the centres are distinct), or a radicand proven so.
            const bool positive = r.of.range.what == domain::kind::positive ||
                                  prove_sign(r.radicand, given).sign.is_positive();
            named.domains[r.atom] = domain{positive ? domain::kind::positive : domain::kind::nonnegative};
            words.push_back(fmt::format("{} {} 0", r.of.name, positive ? ">" : ">="));
        }
        return named;
    }

    bool any_used() const
    {
        return std::any_of(roots_.begin(), roots_.end(), [](const root& r) { return r.used; });
    }

private:
    struct root {
        GiNaC::ex radicand;   // in the inputs, expanded
        quantity of;
        GiNaC::ex atom;
        bool used;
    };
    std::vector<root> roots_;
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> match_;
};

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

bool same_conditions(const std::vector<case_value>& a, const std::vector<case_value>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].op != b[i].op || !GiNaC::normal(a[i].lhs - b[i].lhs).is_zero() ||
            !GiNaC::normal(a[i].rhs - b[i].rhs).is_zero())
            return false;
    return true;
}

namespace {

// The case's condition C >= 0 (> 0) false as x -> infinity: C polynomial in x (mu J_n
// beside a sticking impulse free of mu) tends to -infinity where its leading coefficient,
// its k-th derivative in x, the first free of x, is proven negative. No expansion (C holds
// the slip's length, a root of hundreds of terms in space), and nothing decided where the
// coefficient's sign is not proven at once (the masses' limits: every case arises).
bool cannot_arise_near(const case_value& c, const check_result::limit_point& near, const symbol_table& symbols,
                       const assumptions& given)
{
    constexpr std::size_t effort = 100;
    const GiNaC::ex value = condition_form(c).value.subs(symbols.abbreviations());
    if (!near.to_infinity || !value.has(near.symbol) || !value.is_polynomial(near.symbol))
        return false;
    GiNaC::ex derivative = value;
    for (int k = 1; k <= 8 && derivative.has(near.symbol); ++k)
        derivative = derivative.diff(GiNaC::ex_to<GiNaC::symbol>(near.symbol));
    // A sum with square roots is normalised before its sign is sought, which takes seconds
    // in space; a coefficient whose sign shows is a product (the masses' is a difference).
    if (derivative.has(near.symbol) || (GiNaC::is_a<GiNaC::add>(derivative) && has_radical(derivative)))
        return false;
    const sign_set s = prove_sign(derivative, with_effort(given, effort)).sign;
    return !s.positive && !s.zero;
}

} // namespace

void prove_case_by_case(check_result& c, const case_split& split, const GiNaC::exmap& at,
                        const symbol_table& symbols, const assumptions& given, proof_cache& run,
                        const std::function<verdict(const GiNaC::ex&, const GiNaC::ex&)>& prove,
                        const std::optional<check_result::limit_point>& near)
{
    std::vector<std::string> names;
    for (const GiNaC::ex& s : split.symbols)
        names.push_back(ginac_syntax(s, symbols.order()));
    const std::size_t named = std::min(split.named, names.size());
    c.cases_of = fmt::format("{}", fmt::join(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(named), " and "));
    const std::size_t count = split.pieces.front().size();
    for (std::size_t i = 0; i < count; ++i) {
        case_value one = split.pieces.front()[i];
        check_result::part part;
        part.first = i + 1;
        if (!at.empty()) {
            one.lhs = one.lhs.subs(at);
            one.rhs = one.rhs.subs(at);
        }
        // A value at special values where its case does not arise may not exist (k/(1 + b)
        // at b = -1): it is worked out only where the case arises.
        GiNaC::exmap in_case;
        std::vector<std::string> values;
        for (std::size_t k = 0; k < split.symbols.size(); ++k) {
            GiNaC::ex value = split.pieces[k][i].value;
            try {
                if (!at.empty())
                    value = value.subs(at);
            } catch (const std::exception&) {
                value = split.pieces[k][i].value;
            }
            in_case[split.symbols[k]] = value;
            if (k >= named)
                continue;
            values.push_back(fmt::format("{} = {}", names[k], given.text(value)));
            if (named > 1) {
                case_value each = split.pieces[k][i];
                each.value = value;
                each.lhs = one.lhs;
                each.rhs = one.rhs;
                part.in_cases.emplace_back(split.symbols[k], std::move(each));
            }
        }
        one.value = in_case[split.symbols.front()];
        part.in_case = one;
        part.under = fmt::format("case {} ({}, where {})", i + 1, fmt::join(values, ", "),
                                 condition_text(one, given.order));
        // At special values a condition may be a comparison of numbers, or one the domains
        // contradict: a case whose condition is false holds nothing to prove.
        const GiNaC::ex gap = GiNaC::normal(one.rhs - one.lhs);
        bool arises = true;
        if (GiNaC::is_a<GiNaC::numeric>(gap) && GiNaC::ex_to<GiNaC::numeric>(gap).is_real()) {
            const GiNaC::numeric g = GiNaC::ex_to<GiNaC::numeric>(gap);   // rhs - lhs
            arises = one.op == relation::less_equal      ? g >= 0
                     : one.op == relation::less          ? g > 0
                     : one.op == relation::greater_equal ? g <= 0
                                                         : g < 0;
            if (!arises)
                part.outcome.method = "the case does not arise: its condition is false at these values";
        } else if (!at.empty() && cannot_arise(one, symbols, given)) {
            arises = false;
            part.outcome.method = "the case does not arise: the domains make its condition false";
        } else if (near && cannot_arise_near(one, *near, symbols, given)) {
            arises = false;
            part.outcome.method = fmt::format("the case does not arise near the limit {} -> {}: its condition is "
                                              "false there",
                                              given.text(near->symbol),
                                              near->to_infinity ? "infinity" : given.text(near->point));
        }
        if (!arises) {
            part.outcome.what = verdict::status::proven;
            part.outcome.residual = 0;
        } else {
            const GiNaC::ex lhs = c.lhs.subs(in_case, GiNaC::subs_options::no_pattern);
            const GiNaC::ex rhs = c.rhs.subs(in_case, GiNaC::subs_options::no_pattern);
            part.outcome = prove                    ? prove(lhs, rhs)
                           : c.op == relation::equal ? prove_equal(lhs, rhs, symbols, run)
                                                     : prove_in_case(lhs, c.op, rhs, one, symbols, given);
        }
        c.parts.push_back(std::move(part));
    }
    c.outcome = combine_cases(c.parts);
}

namespace {

// A declared quantity the boundary `top` = 0 is linear in, with its coefficient and its
// value there.
struct boundary_candidate {
    std::size_t length;   ///< of the value, printed
    GiNaC::ex symbol, coefficient, value;
};

// Every such quantity, the shortest value first (the first in declaration order among
// equals).
std::vector<boundary_candidate> linear_candidates(const GiNaC::ex& top, const symbol_table& symbols)
{
    std::vector<boundary_candidate> candidates;
    for (const quantity& q : symbols.all()) {
        // Not under a radical (degree() throws on sqrt(x)): linear means polynomial first.
        if (q.definition || !top.has(q.symbol) || !top.is_polynomial(q.symbol) || top.degree(q.symbol) != 1 ||
            top.ldegree(q.symbol) < 0)
            continue;
        const GiNaC::ex a = top.coeff(q.symbol, 1);
        if (a.has(q.symbol) || GiNaC::normal(a).is_zero())
            continue;
        const GiNaC::ex value = GiNaC::normal(-top.coeff(q.symbol, 0) / a);
        candidates.push_back({ginac_syntax(value, symbols.order()).size(), q.symbol, a, value});
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const boundary_candidate& x, const boundary_candidate& y) { return x.length < y.length; });
    return candidates;
}

// The boundary `top` = 0 of two cases solved for the declared quantity it is linear in
// whose value there is the shortest (mu = (1 + b) m_t |g_t| / J_n rather than a mass),
// its coefficient proven non-zero where one can be; none if it is linear in none. The
// candidates are tried shortest first (the first in declaration order among equals), and
// the first whose coefficient is proven non-zero is taken: a sign proof that fails can
// take seconds on a long coefficient (where the boundary holds the slip's length, in
// space), and those after the first proven one are not needed; nor is one for a
// coefficient seen taking both signs at points of the domains (it cannot be proven of one).
std::optional<std::pair<GiNaC::ex, GiNaC::ex>> solved_boundary(const GiNaC::ex& top, const symbol_table& symbols,
                                                               proof_cache& run)
{
    const std::vector<boundary_candidate> candidates = linear_candidates(top, symbols);
    if (candidates.empty())
        return std::nullopt;
    const assumptions given = declared_assumptions(symbols, run);
    for (const boundary_candidate& c : candidates) {
        if (takes_both_signs(c.coefficient, given))
            continue;
        const sign_set s = prove_sign(c.coefficient, given).sign;
        if (!s.zero && (!s.positive || !s.negative))
            return std::make_pair(c.symbol, c.value);
    }
    return std::make_pair(candidates.front().symbol, candidates.front().value);
}

// Two cases' values agree on their boundary, with each square root that is an abbreviation
// a quantity of its own (radicals_named) in the condition and in both values: the boundary
// solved for a declared quantity it is linear in (the shortest value first, as
// solved_boundary takes them), the values there equal as rational functions, and the
// quantity's coefficient proven non-zero. A root solved out of the condition and the
// same root in a value are then one quantity, however GiNaC would write them expanded (the
// wall's sliding impulse, mu (1 + eps) s_n/|n|, at the mu where (1 + b) q G_t meets it).
// Nothing when no root is named or no such quantity is found.
std::optional<check_result::part> meet_with_roots_named(const case_value& first, const case_value& second,
                                                        const symbol_table& symbols, proof_cache& run)
{
    const assumptions declared = declared_assumptions(symbols, run);
    radicals_named named(symbols, declared);
    const GiNaC::ex condition = GiNaC::normal(named(condition_form(first).value));
    const GiNaC::ex a = named(first.value), b = named(second.value);
    if (!named.any_used())
        return std::nullopt;
    std::vector<std::string> words;
    const assumptions roots = named.with_domains(declared, words);
    const GiNaC::ex top = GiNaC::expand(condition.numer());
    // Each whose values agree there has its coefficient's sign proven (the costly part:
    // the first proven is taken).
    for (const boundary_candidate& c : linear_candidates(top, symbols)) {
        const GiNaC::exmap on{{c.symbol, c.value}};
        if (!GiNaC::normal(a.subs(on, GiNaC::subs_options::no_pattern) - b.subs(on, GiNaC::subs_options::no_pattern))
                 .is_zero())
            continue;
        const sign_set sign = prove_sign(c.coefficient, roots).sign;
        if (sign.zero || (sign.positive && sign.negative))
            continue;
        check_result::part part;
        part.under = fmt::format("at {} = {}", ginac_syntax(c.symbol, symbols.order()),
                                 ginac_syntax(c.value, symbols.order()));
        part.boundary = {c.symbol, c.value};
        part.outcome.what = verdict::status::proven;
        part.outcome.residual = 0;
        part.outcome.method = fmt::format("difference normalises to zero, with the square roots that are "
                                          "abbreviations as quantities of their own ({})",
                                          fmt::join(words, ", "));
        part.outcome.how = verdict::basis::zero_difference;
        return part;
    }
    return std::nullopt;
}

} // namespace

check_result prove_continuity(const std::string& name, const std::vector<case_value>& cases,
                              const symbol_table& symbols, proof_cache& run, const source_location& where)
{
    check_result c;
    c.cases_of = name;
    c.where = where;
    c.stated = 0;
    c.lhs = 0;
    c.rhs = 0;
    for (std::size_t i = 0; i < cases.size(); ++i)
        for (std::size_t j = i + 1; j < cases.size(); ++j) {
            const GiNaC::ex ci = GiNaC::normal(condition_form(cases[i]).value);
            const GiNaC::ex cj = GiNaC::normal(condition_form(cases[j]).value);
            if (!constant_ratio(cj, ci))
                continue;
            check_result::part part;
            part.first = i + 1;
            part.second = j + 1;
            if (std::optional<check_result::part> met = meet_with_roots_named(cases[i], cases[j], symbols, run)) {
                met->first = i + 1;
                met->second = j + 1;
                met->under = fmt::format("cases {} and {} {}", i + 1, j + 1, met->under);
                c.parts.push_back(std::move(*met));
                continue;
            }
            // The boundary C_i = 0, solved once for all the cases that share it.
            const GiNaC::ex top = GiNaC::expand(ci.numer());
            const auto known = run.boundaries.find(top);
            const std::optional<std::pair<GiNaC::ex, GiNaC::ex>> at =
                known != run.boundaries.end() ? known->second
                                              : run.boundaries.emplace(top, solved_boundary(top, symbols, run)).first->second;
            if (!at) {
                part.under = fmt::format("cases {} and {} at {} = 0", i + 1, j + 1, ginac_syntax(ci, symbols.order()));
                part.outcome.what = verdict::status::failed;
                part.outcome.residual = ci;
                part.outcome.method = "the boundary is linear in no declared quantity: it cannot be substituted";
            } else {
                part.under = fmt::format("cases {} and {} at {} = {}", i + 1, j + 1, ginac_syntax(at->first, symbols.order()),
                                         ginac_syntax(at->second, symbols.order()));
                part.boundary = *at;
                const GiNaC::exmap on{{at->first, at->second}};
                const GiNaC::ex vi = cases[i].value.subs(on, GiNaC::subs_options::no_pattern);
                const GiNaC::ex vj = cases[j].value.subs(on, GiNaC::subs_options::no_pattern);
                part.outcome = prove_equal(vi, vj, symbols, run);
            }
            c.parts.push_back(std::move(part));
        }
    if (c.parts.empty())
        throw error(where, fmt::format("no two cases of '{}' share a boundary (conditions that are signs of one "
                                       "expression): continuity cannot be checked",
                                       name));
    c.outcome = combined(c.parts, "the values of the cases agree where they meet");
    return c;
}

verdict combine_cases(const std::vector<check_result::part>& parts)
{
    return combined(parts, "case by case");
}

} // namespace impact::engine
