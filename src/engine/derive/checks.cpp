// The checks of a derivation file, each proven or reported with its residual: identities
// and inequalities under the declared domains and the check's own assumptions, claims about
// quantities defined by cases proven case by case, continuity at the cases' borders, and
// limits (by a method that establishes them, or evaluated nearer and nearer the point).
#include "engine/derive/deriver.h"

#include "engine/cases/cases.h"
#include "engine/derive/declarations.h"
#include "engine/expr/derivative.h"
#include "engine/expr/infix.h"
#include "engine/expr/dimensional.h"
#include "engine/kernel/kernel_build.h"
#include "engine/paper/reconcile.h"
#include "engine/solve/solve.h"

#include <fmt/format.h>

#include <cctype>
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <iterator>
#include <set>

namespace impact::engine::detail {

// `paper_claim`: the claim transcribes the paper's text, whose dimensions are a finding
// (hold_to_account), not the file's mistake.
check_result deriver::run_check(const spec::check& spec_check, bool paper_claim)
{
    if (spec_check.continuity)
        return run_continuity(spec_check);
    check_result c;
    c.name = spec_check.name.value;
    c.statement = spec_check.claim.value;
    c.because = spec_check.because.value;
    c.where = spec_check.claim.where;
    const claim_sides sides = out_.symbols.parse_claim(spec_check.claim);
    check_derivatives(sides.lhs, spec_check.claim.where);
    check_derivatives(sides.rhs, spec_check.claim.where);
    c.written = written(spec_check.claim);
    c.op = sides.op;
    c.stated = sides.lhs == sides.rhs;
    if (!paper_claim)
        check_relation(out_.symbols, c.stated, spec_check.claim.where);
    GiNaC::ex lhs = resolve(sides.lhs), rhs = resolve(sides.rhs);

    // Symmetries compare a result at changed inputs with the result itself:
    // `left_at` substitutes (all at once) into the left side only.
    const assumptions given = assumptions_of(spec_check);
    GiNaC::exmap left_at;
    moved_places placed;
    for (const spec::binding& b : spec_check.left_at) {
        const GiNaC::ex symbol = out_.symbols.at(b.name).symbol;
        refuse_derived_value(symbol, b, c.name, "left_at");
        left_at[symbol] = out_.symbols.parse(b.expression);
        refuse_derivative(left_at[symbol], b.expression, "left_at's value");
        c.left_at.emplace_back(symbol, left_at[symbol]);
        placed[symbol] = b.expression.where;
    }
    // Values not shown inside the domains the claim was derived under: the claim is
    // said, and proven, where they are.
    std::vector<std::string> where_moved;
    if (!left_at.empty())
        where_moved = check_moved_inputs(out_.symbols, left_at, given, placed, "left_at");
    // A quantity defined by cases on the left stands for its cases at the changed
    // inputs: a copy of it whose cases have `left_at` substituted, conditions and values.
    std::map<GiNaC::ex, std::vector<case_value>, GiNaC::ex_is_less> moved;
    if (!left_at.empty()) {
        GiNaC::exmap to = left_at;
        for (const auto& [symbol, pieces] : cases_)
            if (lhs.has(symbol)) {
                const GiNaC::symbol& named = GiNaC::ex_to<GiNaC::symbol>(symbol);
                // Named as the quantity: the same quantity, at other inputs.
                const GiNaC::symbol copy(named.get_name(), named.get_TeX_name());
                std::vector<case_value> shifted = pieces;
                for (case_value& one : shifted) {
                    one.lhs = one.lhs.subs(left_at, GiNaC::subs_options::no_pattern);
                    one.rhs = one.rhs.subs(left_at, GiNaC::subs_options::no_pattern);
                    one.value = one.value.subs(left_at, GiNaC::subs_options::no_pattern);
                }
                // Both sides are compared in one case only when the change leaves its
                // conditions as they were (a Galilean boost, the spheres exchanged).
                if (!same_conditions(pieces, shifted))
                    throw error(c.where, fmt::format("check '{}': left_at changes the conditions of the cases of "
                                                     "'{}', so the two sides may fall in different cases; a "
                                                     "symmetry of a quantity defined by cases must leave its "
                                                     "conditions unchanged",
                                                     c.name, named.get_name()));
                to[symbol] = copy;
                moved.emplace(copy, std::move(shifted));
            }
        lhs = lhs.subs(to, GiNaC::subs_options::no_pattern);
    }

    GiNaC::exmap at;
    placed.clear();
    for (const spec::binding& b : spec_check.at) {
        const quantity& q = out_.symbols.at(b.name);
        refuse_derived_value(q.symbol, b, c.name, "at");
        at[q.symbol] = out_.symbols.parse(b.expression);
        refuse_derivative(at[q.symbol], b.expression, "at's value");
        check_special_value(q, at[q.symbol], b.expression.where);
        c.at.emplace_back(q.symbol, at[q.symbol]);
        placed[q.symbol] = b.expression.where;
    }
    if (!at.empty())
        for (std::string& condition : check_moved_inputs(out_.symbols, at, given, placed, "at"))
            where_moved.push_back(std::move(condition));
    if (!at.empty()) {
        try {
            lhs = lhs.subs(at);
            rhs = rhs.subs(at);
        } catch (...) {
            rethrow_at(c.where, fmt::format("check '{}' at its special values", c.name));
        }
        std::vector<std::string> values;
        for (const spec::binding& b : spec_check.at)
            values.push_back(fmt::format("{} = {}", b.name.value, b.expression.value));
        c.statement += fmt::format(" at {}", fmt::join(values, ", "));
    }
    if (!where_moved.empty())
        c.statement += fmt::format(", where {}", fmt::join(where_moved, " and "));

    for (const spec::binding& b : spec_check.assuming) {
        const GiNaC::ex symbol = out_.symbols.at(b.name).symbol;
        c.assuming.emplace_back(symbol, given.domains.at(symbol).to_string());
    }

    c.lhs = lhs;
    c.rhs = rhs;
    // Where the claim is defined, as written and as derived: each condition proven from the
    // domains, or attached to the claim, which is then proven (or sampled) where they hold.
    const std::vector<condition> needs = needs_of_claim(c.written, sides, left_at, at, lhs, rhs);
    const settled_conditions settled = settle(needs, given);
    const assumptions under = where(given, settled.attached);
    const auto defined_where = [&](check_result& done) {
        done.outcome.where = settled.attached;
        done.outcome.defined = settled.proven;
        // A case's own conditions (a divisor of its value its condition does not make
        // non-zero): the check holds where they hold too.
        for (const check_result::part& p : done.parts)
            add_conditions(done.outcome.where, p.outcome.where);
        // Defined nowhere in the domains: not a claim about anything.
        if (!settled.never.empty() && done.outcome.holds()) {
            done.outcome.what = verdict::status::failed;
            done.outcome.method = fmt::format("defined nowhere in the domains: {} never holds there",
                                              to_string(settled.never));
        }
        return done;
    };
    std::optional<case_split> split = cases_in(lhs, rhs, c.where);
    if (!split && !moved.empty())
        split.emplace();   // only the left side is defined by cases: its copies are named
    if (split) {
        split->named = split->symbols.empty() ? moved.size() : split->symbols.size();
        for (const auto& [copy, pieces] : moved) {
            // Split together only with quantities whose cases have the same conditions.
            if (!split->pieces.empty() && !same_conditions(split->pieces.front(), pieces))
                throw different_conditions(c.where, GiNaC::ex_to<GiNaC::symbol>(copy).get_name(),
                                           ginac_syntax(split->symbols.front(), out_.symbols.order()));
            split->symbols.push_back(copy);
            split->pieces.push_back(pieces);
        }
        if (spec_check.limit) {
            // The limit in every case that arises near the point, whatever its condition:
            // a quantity that takes one case's value or another's has the limit they share
            // (a fixed sphere's velocity, sticking or sliding); a case whose condition
            // fails near the point (sliding as mu -> infinity) is left out.
            c.limit = limit_point_of(*spec_check.limit);
            if (c.op != relation::equal)
                throw error(spec_check.limit->written.where, "a limit check claims an equality: lim lhs = rhs");
            prove_case_by_case(
                c, *split, at, out_.symbols, given, run_,
                [&](const GiNaC::ex& l, const GiNaC::ex& r) {
                    std::optional<GiNaC::ex> value;
                    std::optional<limit_method> how;
                    return check_limit(l, r, *c.limit, given, value, how);
                },
                c.limit);
            c.statement += fmt::format(" in the limit {}", spec_check.limit->written.value);
            return defined_where(c);
        }
        prove_case_by_case(c, *split, at, out_.symbols, under, run_);
        return defined_where(c);
    }
    if (spec_check.limit) {
        c.limit = limit_point_of(*spec_check.limit);
        if (c.op != relation::equal)
            throw error(spec_check.limit->written.where, "a limit check claims an equality: lim lhs = rhs");
        c.outcome = check_limit(lhs, rhs, *c.limit, given, c.value, c.limit_by);
        c.statement += fmt::format(" in the limit {}", spec_check.limit->written.value);
    } else if (c.op == relation::equal) {
        c.outcome = prove_equal(lhs, rhs, out_.symbols, run_, when_unproven::sample, settled.attached, &under);
        c.value = lhs;
    } else if (auto through = prove_inequality_through(lhs, c.op, rhs, proven_identities(), out_.symbols, under)) {
        c.outcome = std::move(*through);
    } else {
        c.outcome = prove_inequality(lhs, c.op, rhs, out_.symbols, under);
        // Samples drawn at random miss where a claim fails on a thin set (dE < 0 fails
        // where v_M = v_m): an inequality left sampled is tried at the domains' simple
        // values too, and fails at the first point found, decided exactly.
        if (c.outcome.what == verdict::status::sampled)
            if (auto point = find_counterexample(lhs, c.op, rhs, out_.symbols, under); point && point->exact) {
                std::vector<std::string> values;
                for (const auto& [symbol, value] : point->point)
                    values.push_back(fmt::format("{} = {}", out_.symbols.text(symbol), out_.symbols.text(value)));
                c.outcome.what = verdict::status::failed;
                c.outcome.method = fmt::format("fails at {}: {} {} {} is false (though {} sampled points held)",
                                               fmt::join(values, ", "), out_.symbols.text(point->lhs),
                                               to_string(c.op), out_.symbols.text(point->rhs), c.outcome.samples);
                c.fails_at = std::move(point);
            }
    }
    return defined_where(c);
}

// The equalities proven so far, without special values or changed domains: what an
// inequality may be proven through.
std::vector<proven_identity> deriver::proven_identities() const
{
    std::vector<proven_identity> identities;
    for (const check_result& c : out_.checks)
        if (c.op == relation::equal && c.outcome.what == verdict::status::proven && c.at.empty() &&
            c.left_at.empty() && !c.limit && c.assuming.empty() && c.parts.empty())
            identities.push_back({c.display_of.empty() ? fmt::format("the check '{}'", c.name)
                                                       : fmt::format("the display form of {}", c.display_of),
                                  substituted(c.stated.lhs(), {}), substituted(c.stated.rhs(), {})});
    return identities;
}

// A check that would split on two quantities whose cases have different conditions.
error deriver::different_conditions(const source_location& where, const std::string& one, const std::string& other)
{
    return error(where, fmt::format("the check uses '{}' and '{}', both defined by cases with different conditions: "
                                    "a check may split on the cases of quantities whose conditions are the same",
                                    one, other));
}

// The quantities defined by cases that a check's sides use, if any: one, or several
// whose cases have the same conditions (split together, case by case).
std::optional<case_split> deriver::cases_in(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const source_location& where) const
{
    std::optional<case_split> found;
    for (const auto& [symbol, pieces] : cases_)
        if (lhs.has(symbol) || rhs.has(symbol)) {
            if (!found) {
                found.emplace();
            } else if (!same_conditions(found->pieces.front(), pieces)) {
                throw different_conditions(where, ginac_syntax(found->symbols.front(), out_.symbols.order()),
                                           ginac_syntax(symbol, out_.symbols.order()));
            }
            found->symbols.push_back(symbol);
            found->pieces.push_back(pieces);
        }
    // cases_ is ordered by GiNaC's order of symbols, which may differ between runs: the
    // split is written in the order of the names.
    if (found && found->symbols.size() > 1) {
        std::vector<std::size_t> order(found->symbols.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        const auto name = [this](const GiNaC::ex& s) { return ginac_syntax(s, out_.symbols.order()); };
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return name(found->symbols[a]) < name(found->symbols[b]);
        });
        case_split sorted;
        for (const std::size_t i : order) {
            sorted.symbols.push_back(found->symbols[i]);
            sorted.pieces.push_back(found->pieces[i]);
        }
        found = std::move(sorted);
    }
    return found;
}

// The declared domains, narrowed by the check's `assuming`.
assumptions deriver::assumptions_of(const spec::check& spec_check) const
{
    assumptions given = declared_assumptions(out_.symbols, run_);
    if (!spec_check.assuming.empty())
        given.known = std::make_shared<worked_out>();
    for (const spec::binding& b : spec_check.assuming) {
        const quantity& q = out_.symbols.at(b.name);
        given.domains[q.symbol] = narrowed_domain(q, b.expression);
    }
    if (!spec_check.assuming.empty())
        check_assumptions_hold_together(out_.symbols, out_.source, given, spec_check.assuming.front().name.where);
    return given;
}

// `continuity = "J_t"`: the cases of J_t agree where their conditions meet.
check_result deriver::run_continuity(const spec::check& spec_check)
{
    const spec::text& name = *spec_check.continuity;
    const quantity& q = out_.symbols.at(name);
    const auto found = cases_.find(q.symbol);
    if (found == cases_.end())
        throw error(name.where, fmt::format("continuity of '{}': it is not defined by cases", name.value));
    check_result c = prove_continuity(name.value, found->second, out_.symbols, run_, name.where);
    c.name = spec_check.name.value;
    c.continuity = true;
    c.statement = fmt::format("{} is continuous where its cases meet", name.value);
    c.because = spec_check.because.value;
    c.stated = q.symbol == q.symbol;
    return c;
}

// The limit's symbol and point (an expression, or infinity), inside the symbol's domain.
check_result::limit_point deriver::limit_point_of(const spec::limit_point& l) const
{
    check_result::limit_point p;
    const quantity& q = out_.symbols.at(l.symbol);
    p.symbol = q.symbol;
    p.to_infinity = l.to_infinity;
    if (!l.to_infinity)
        p.point = out_.symbols.parse(l.point);
    if (!l.to_infinity)
        refuse_derivative(p.point, l.point, "the limit's point");
    check_limit_point(q, p.point, p.to_infinity, l.written.where);
    return p;
}

// No method established the limit: the difference of the sides evaluated (60 digits)
// ever nearer the point, 10^-4 to 10^-24 away from inside the domain (10^4 to 10^24 for
// infinity), the other inputs at two points of their domains. Sampled where it falls below
// 10^-12 at the nearest and never grows from 10^-16 of the way on; failed as before
// otherwise (the verdict's method says what it came to).
void deriver::approach_numerically(const GiNaC::ex& difference, const check_result::limit_point& p,
                               const assumptions& given, verdict& v) const
{
    const auto inside = [](const domain* d, const GiNaC::numeric& x) { return !d || d->contains(x.to_double()); };
    const domain* near_domain = out_.symbols.domain_of(p.symbol);
    std::size_t tested = 0;
    for (const GiNaC::numeric& other : {GiNaC::numeric(1), GiNaC::numeric(3, 7)}) {
        GiNaC::exmap at;
        for (GiNaC::const_preorder_iterator it = difference.preorder_begin(); it != difference.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(p.symbol) && !at.count(*it)) {
                const auto d = given.domains.find(*it);
                const domain* range = d != given.domains.end() ? &d->second : out_.symbols.domain_of(*it);
                GiNaC::numeric value = other;
                if (!inside(range, value) && range && range->what == domain::kind::interval)
                    value = GiNaC::numeric((range->lower + range->upper) / 2);
                if (!inside(range, value))
                    return;
                at[*it] = value;
            }
        GiNaC::numeric last;
        bool settled = false, grew = false;
        for (int k = 4; k <= 24; k += 4) {
            const GiNaC::numeric h = GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(-k));
            GiNaC::numeric x;
            if (p.to_infinity) {
                x = GiNaC::numeric(1) / h;
            } else {
                const GiNaC::ex point = p.point.subs(at).evalf();
                if (!GiNaC::is_a<GiNaC::numeric>(point))
                    return;
                const GiNaC::numeric centre = GiNaC::ex_to<GiNaC::numeric>(point);
                x = inside(near_domain, centre + h) ? centre + h : centre - h;
                if (!inside(near_domain, x))
                    return;
            }
            at[p.symbol] = x;
            GiNaC::ex value;
            const long digits = GiNaC::Digits;
            try {
                GiNaC::Digits = 60;
                value = difference.subs(at, GiNaC::subs_options::no_pattern).evalf();
                GiNaC::Digits = digits;
            } catch (const std::exception&) {
                GiNaC::Digits = digits;
                return;
            }
            if (!GiNaC::is_a<GiNaC::numeric>(value) || !value.info(GiNaC::info_flags::real))
                return;
            const GiNaC::numeric size = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(value));
            grew = grew || (k >= 16 && size > last);   // growing again near the point
            settled = size < GiNaC::numeric(1, 1000000000000LL);
            last = size;
        }
        if (!settled || grew) {
            v.method += fmt::format("; evaluated nearer and nearer the point, the difference of the sides is "
                                    "still {:.3g} at 10^-24 of it",
                                    last.to_double());
            return;
        }
        ++tested;
    }
    v.what = verdict::status::sampled;
    v.samples = tested;
    v.method = "no method established the limit (substitution, series, leading term); evaluated at 10^-4 to "
               "10^-24 of the point (60 digits), at two points of the other inputs' domains, the difference of "
               "the sides falls below 10^-12";
}

verdict deriver::check_limit(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const check_result::limit_point& p,
                         const assumptions& given, std::optional<GiNaC::ex>& value,
                         std::optional<limit_method>& how) const
{
    const GiNaC::exmap abbreviations = out_.symbols.abbreviations();
    // A claim that holds at every value of the symbol, its right side free of it (a fixed
    // sphere's law of restitution, which holds at every mass): the left side's limit is the
    // right side's, taken without bringing the left side over one denominator (2 to 3 s for
    // each case of the rough spheres in space).
    const GiNaC::ex left = lhs.subs(abbreviations, GiNaC::subs_options::no_pattern),
                    right = rhs.subs(abbreviations, GiNaC::subs_options::no_pattern);
    const bool equal_throughout = !right.has(p.symbol) && equal_as_written(left, right);
    const auto found = limit(equal_throughout ? right : left, p.symbol, p.point, p.to_infinity, given);
    verdict v;
    if (!found) {
        v.residual = lhs;
        v.what = verdict::status::failed;
        v.method = "no method established the limit (substitution, series, leading term)";
        approach_numerically(lhs.subs(abbreviations) - rhs.subs(abbreviations), p, given, v);
        return v;
    }
    if (found->infinite) {
        v.what = verdict::status::failed;
        v.residual = found->value;
        v.method = fmt::format("the expression grows without bound ({})", found->method);
        return v;
    }
    value = found->value;
    how = found->how;
    v = prove_equal(found->value, rhs, out_.symbols, run_);
    v.method = fmt::format("limit {} ({}); {}", given.text(found->value), found->method, v.method);
    return v;
}

} // namespace impact::engine::detail
