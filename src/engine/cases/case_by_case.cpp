// A check proven case by case (cases.h, prove_case_by_case): each case's values put in, the
// claim proven under its condition, a case that cannot arise (at special values, near a
// limit) holding nothing to prove; the parts' verdicts combined.
#include "engine/cases/case_proofs.h"

#include "engine/algebra/polynomial.h"
#include "engine/prove/condition_proof.h"
#include "engine/prove/definedness.h"
#include "engine/expr/infix.h"
#include "engine/prove/limit.h"
#include "engine/expr/normal_form.h"
#include "engine/prove/prove.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <optional>

namespace impact::engine {

using namespace cases_detail;

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
    const GiNaC::ex value = condition_form(c).value.subs(symbols.abbreviations(), GiNaC::subs_options::no_pattern);
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

// Whether f and e are one quantity as a condition on e needs it: e itself, |u| beside |v|
// with u = ±v, or sqrt(X) beside its radicand X (sqrt(X) != 0 is X > 0 where it is real).
bool same_quantity_anew(const GiNaC::ex& f, const GiNaC::ex& e)
{
    const auto abs_of = [](const GiNaC::ex& x) -> std::optional<GiNaC::ex> {
        if (GiNaC::is_a<GiNaC::function>(x) && GiNaC::ex_to<GiNaC::function>(x).get_name() == "abs")
            return x.op(0);
        return std::nullopt;
    };
    if (const auto u = abs_of(f), v = abs_of(e); u && v)
        return GiNaC::expand(*u - *v).is_zero() || GiNaC::expand(*u + *v).is_zero();
    // Expanded, a radicand can keep sqrt(S)^3 beside S sqrt(S): normal() makes them one.
    if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).is_equal(GiNaC::numeric(1, 2)))
        return GiNaC::normal(GiNaC::expand(f.op(0)) - e).is_zero();
    return false;
}

// The same, each pair worked out once a run (every check split on J_t asks of its cases'
// divisors, and normal() of a radicand in space takes a tenth of a second).
bool same_quantity(const GiNaC::ex& f, const GiNaC::ex& e)
{
    if (f.is_equal(e))
        return true;
    if (!GiNaC::is_a<GiNaC::function>(f) && !GiNaC::is_a<GiNaC::power>(f))
        return false;
    static std::map<GiNaC::ex, bool, GiNaC::ex_is_less> known;
    const GiNaC::ex key = GiNaC::lst{f, e};
    if (const auto it = known.find(key); it != known.end())
        return it->second;
    return known[key] = same_quantity_anew(f, e);
}

// A condition on e that the case's condition proves, through a factor f of one of its
// terms that is the same quantity (e, |e|, sqrt(e)): a radicand e proven of the form the
// condition writes it in (a sum of squares, whose sign its expansion hides); or, under a
// strict condition C = A f + R > 0 with R <= 0 proven, A f > -R >= 0, so f != 0 (the
// sliding contact's slip: q (1 + b) (M + m) |g_t| > mu (1 + eps) ... s_n >= 0 gives
// |g_t| > 0).
bool implied_by_condition(const condition& need, const case_value& one, const assumptions& given)
{
    constexpr std::size_t effort = 100;
    const nonnegative_form form = condition_form(one);
    const GiNaC::exvector terms = GiNaC::is_a<GiNaC::add>(form.value)
                                      ? GiNaC::exvector(form.value.begin(), form.value.end())
                                      : GiNaC::exvector{form.value};
    for (const GiNaC::ex& term : terms) {
        const GiNaC::exvector factors =
            GiNaC::is_a<GiNaC::mul>(term) ? GiNaC::exvector(term.begin(), term.end()) : GiNaC::exvector{term};
        for (const GiNaC::ex& f : factors) {
            if (!same_quantity(f, need.expr))
                continue;
            // The radicand as the condition writes it (a sum of squares, which expanded
            // hides its sign): the need proven of that form.
            if (GiNaC::is_a<GiNaC::power>(f)) {
                const sign_set radicand = prove_sign(f.op(0), with_effort(given, effort)).sign;
                if (need.need == condition::kind::nonnegative ? radicand.is_nonnegative()
                    : need.need == condition::kind::positive  ? radicand.is_positive()
                                                              : !radicand.zero && radicand.is_known())
                    return true;
            }
            if (!form.strict)
                continue;   // A f >= -R >= 0 says nothing of f != 0
            // e > 0 needs f >= 0: a |.| or a root (f != 0 is then f > 0, and the radicand's > 0).
            const bool nonnegative_factor =
                GiNaC::is_a<GiNaC::power>(f) ||
                (GiNaC::is_a<GiNaC::function>(f) && GiNaC::ex_to<GiNaC::function>(f).get_name() == "abs");
            if (need.need != condition::kind::nonzero && !nonnegative_factor)
                continue;
            const sign_set rest = prove_sign(term - form.value, with_effort(given, effort)).sign;
            if (rest.is_nonnegative())
                return true;
        }
    }
    return false;
}

// Where the case's values are defined: each condition (a divisor, a radicand) proven from
// the domains, or from the case's condition (the sliding impulse's divisor |g_t|, which only
// its case makes non-zero: implied_by_condition), or attached to the case, which is then
// proven where it holds.
settled_conditions defined_in_case(const GiNaC::exmap& in_case, const case_value& one, const symbol_table& symbols,
                                   const assumptions& given)
{
    // (Of one condition in two forms, add_conditions keeps the plainer, whichever value,
    // in GiNaC's order of the symbols, comes first.)
    std::vector<condition> needs;
    for (const auto& [symbol, value] : in_case)
        add_conditions(needs, definedness(value, symbols));
    settled_conditions settled = settle(needs, given);
    if (settled.attached.empty())
        return settled;
    // A condition that bounds one symbol (x > 0, mu <= 1) narrows its domain: 1/x where
    // x > 0. (Narrowed, the domains start what they have worked out afresh: a longer
    // condition is left to implied_by_condition.)
    // Its symbols are gathered first: a condition of several (the slip's, a root of hundreds
    // of terms in space) is neither expanded nor searched once per symbol of the domains.
    const nonnegative_form form = condition_form(one);
    GiNaC::exset in_bound;
    gather_symbols(form.value, in_bound);
    std::optional<assumptions> narrowed;
    if (in_bound.size() == 1 && given.domains.count(*in_bound.begin()) != 0) {
        const GiNaC::ex symbol = *in_bound.begin();
        const GiNaC::ex bound = GiNaC::expand(form.value);
        if (bound.is_polynomial(symbol) && bound.degree(symbol) == 1 &&
            GiNaC::is_a<GiNaC::numeric>(bound.coeff(symbol, 1)) && GiNaC::is_a<GiNaC::numeric>(bound.coeff(symbol, 0)))
            narrowed = where(given, {{bound, form.strict ? condition::kind::positive : condition::kind::nonnegative,
                                      "", ""}});
    }
    std::vector<condition> attached;
    for (const condition& c : settled.attached) {
        const bool proven = (narrowed && settle({c}, *narrowed).attached.empty()) || implied_by_condition(c, one, given);
        (proven ? settled.proven : attached).push_back(c);
    }
    settled.attached = std::move(attached);
    return settled;
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
            const settled_conditions defined = defined_in_case(in_case, one, symbols, given);
            const assumptions under = where(given, defined.attached);
            const bool attached = !defined.attached.empty();
            part.outcome = prove                    ? prove(lhs, rhs)
                           : c.op == relation::equal ? attached ? prove_equal(lhs, rhs, symbols, run,
                                                                              when_unproven::sample, defined.attached,
                                                                              &under)
                                                                : prove_equal(lhs, rhs, symbols, run)
                                                     : prove_in_case(lhs, c.op, rhs, one, symbols, under);
            part.outcome.where = defined.attached;
            part.outcome.defined = defined.proven;
        }
        c.parts.push_back(std::move(part));
    }
    c.outcome = combine_cases(c.parts);
}

verdict combine_cases(const std::vector<check_result::part>& parts)
{
    return combined(parts, "case by case");
}

} // namespace impact::engine
