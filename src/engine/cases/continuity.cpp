// The continuity of a quantity defined by cases (cases.h, prove_continuity): for each two
// cases that share a boundary, the boundary solved for a declared quantity it is linear in,
// and the two values proven equal there.
#include "engine/cases/case_proofs.h"
#include "engine/cases/radicals_named.h"

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

using namespace cases_detail;

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

} // namespace impact::engine
