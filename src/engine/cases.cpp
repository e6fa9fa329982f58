#include "engine/cases.h"

#include "engine/infix.h"

#include <fmt/format.h>

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

bool nonnegative(const sign_set& s) { return !s.negative; }
bool positive(const sign_set& s) { return !s.negative && !s.zero; }

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

bool has_select(const GiNaC::ex& e)
{
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::function>(*it) && GiNaC::ex_to<GiNaC::function>(*it).get_name() == "select_positive")
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
    // Each condition as a sign of D, the first condition's C.
    const GiNaC::ex d = GiNaC::normal(condition_form(cases.front()).value);
    sign_set covered{false, false, false};
    std::vector<std::string> signs;
    for (const case_value& one : cases) {
        const nonnegative_form f = condition_form(one);
        const auto k = constant_ratio(f.value, d);
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

verdict prove_in_case(const GiNaC::ex& lhs, relation op, const GiNaC::ex& rhs, const case_value& c,
                      const symbol_table& symbols, const assumptions& given)
{
    const verdict alone = prove_inequality(lhs, op, rhs, symbols, given);
    if (alone.what == verdict::status::proven)
        return alone;

    const GiNaC::exmap abbreviations = symbols.abbreviations();
    const bool upper = op == relation::less_equal || op == relation::less;
    const bool strict = op == relation::less || op == relation::greater;
    // The claim as G >= 0 (> 0), the condition as C >= 0 (> 0).
    const GiNaC::ex g = GiNaC::normal((upper ? rhs - lhs : lhs - rhs).subs(abbreviations));
    nonnegative_form condition = condition_form(c);
    condition.value = GiNaC::normal(condition.value.subs(abbreviations));
    const std::string under = fmt::format("under {}", condition_text(c, given.order));

    // G = q C with q >= 0 (q > 0 and C > 0 for a strict claim).
    if (!condition.value.is_zero()) {
        const GiNaC::ex q = GiNaC::normal(g / condition.value);
        const sign_proof p = prove_sign(q, given);
        if (strict ? (positive(p.sign) && condition.strict) : nonnegative(p.sign)) {
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
        const GiNaC::ex r = GiNaC::normal(g - condition.value);
        const sign_proof p = prove_sign(r, given);
        if (nonnegative(p.sign) && (!strict || positive(p.sign) || condition.strict)) {
            verdict v;
            v.what = verdict::status::proven;
            v.residual = 0;
            v.proof = p.steps;
            v.method = fmt::format("{}: {} = ({}) + ({}), the condition's side plus a term {}", under,
                                   given.text(g), given.text(condition.value), given.text(r), p.sign.describe());
            return v;
        }
    }
    // A bound on one symbol by a number (x <= 1): the sign proof run again on the symbol's
    // domain narrowed by it.
    if (const auto bound = bound_domain(c, given)) {
        assumptions narrowed = given;
        narrowed.domains[bound->first] = bound->second;
        narrowed.known = std::make_shared<worked_out>();
        verdict v = prove_inequality(lhs, op, rhs, symbols, narrowed);
        if (v.what == verdict::status::proven) {
            v.method = fmt::format("{}, {} in {}: {}", under, ginac_syntax(bound->first, symbols.order()),
                                   bound->second.to_string(), v.method);
            return v;
        }
    }
    verdict v = alone;
    if (v.what == verdict::status::sampled)
        v.method = fmt::format("not proven {}; sampled over the whole domain, where it holds: {}", under, v.method);
    else
        v.method = fmt::format("not proven {} (it fails somewhere in the whole domain): {}", under, v.method);
    return v;
}

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
            // The boundary C_i = 0, solved for the first declared quantity it is linear in.
            const GiNaC::ex top = GiNaC::expand(ci.numer());
            std::optional<std::pair<GiNaC::ex, GiNaC::ex>> at;
            for (const quantity& q : symbols.all()) {
                if (q.definition || !top.has(q.symbol) || top.degree(q.symbol) != 1 || top.ldegree(q.symbol) < 0)
                    continue;
                const GiNaC::ex a = top.coeff(q.symbol, 1);
                if (a.has(q.symbol) || GiNaC::normal(a).is_zero())
                    continue;
                at.emplace(q.symbol, GiNaC::normal(-top.coeff(q.symbol, 0) / a));
                break;
            }
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
