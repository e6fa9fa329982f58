#include "engine/solve/solve.h"

#include "engine/solve/eliminate.h"
#include "engine/solve/trigonometric.h"
#include "engine/expr/normal_form.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace impact::engine {

namespace {

// Each radical whose radicand holds a radical itself (|g_t| of rough spheres in space: the
// square root of a sum of squares that holds the distance sqrt(r.r)) with its radicand
// expanded: normal() leaves such a radicand in whichever form GiNaC's order of terms
// gave it in this run, and a derived value is typeset and compared as it stands.
struct expand_nested_radicands : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& x) override
    {
        if (GiNaC::is_a<GiNaC::power>(x) && !x.op(1).info(GiNaC::info_flags::integer) && has_radical(x.op(0)))
            return GiNaC::pow(GiNaC::expand(x.op(0).map(*this)), x.op(1));
        return x.map(*this);
    }
};

} // namespace

GiNaC::ex simplified(const GiNaC::ex& e, const assumptions& given)
{
    expand_nested_radicands expand_nested;
    return expand_nested(simplified_as_normalised(e, given));
}

GiNaC::ex simplified_as_normalised(const GiNaC::ex& e, const assumptions& given)
{
    // factor() is by far the engine's most expensive call; a long numerator is left
    // expanded (a derivation states the form it wants typeset as its display form).
    constexpr std::size_t longest_factored = 4;
    const auto [numer, denom] = unique_numer_denom(simplify_radicals(e, given), given.order);
    auto factored = [&](const GiNaC::ex& p) {
        return p.nops() > longest_factored ? p : factor_polynomial(p, *given.run);
    };
    return simplify_radicals(factored(numer) / factored(denom), given);
}

namespace {

std::string join(const std::vector<spec::text>& items)
{
    std::string out;
    for (const spec::text& item : items)
        out += (out.empty() ? "" : ", ") + item.value;
    return out;
}

// A solution's value in its simplest form: as `simplified`, with each radical standing
// as a symbol while the rest is factored (√2 √(gh) m + √2 √(gh) M → √2 √(gh) (m + M)).
GiNaC::ex simplest(const GiNaC::ex& value, const assumptions& given)
{
    const GiNaC::ex e = simplify_radicals(value, given);
    if (!has_radical(e))
        return simplified(e, given);
    GiNaC::exmap to_symbols, back;
    struct radicals : GiNaC::map_function {
        GiNaC::exmap &to, &from;
        radicals(GiNaC::exmap& t, GiNaC::exmap& f) : to(t), from(f) {}
        GiNaC::ex operator()(const GiNaC::ex& part) override
        {
            if (GiNaC::is_a<GiNaC::power>(part) && !part.op(1).info(GiNaC::info_flags::integer)) {
                // A number's root past its first power (GiNaC writes 2·√2 as 2^(3/2)):
                // the whole powers stand outside, so that they cancel (2^(3/2)/4 = √2/2).
                const GiNaC::ex& exponent = part.op(1);
                if (GiNaC::is_a<GiNaC::numeric>(part.op(0)) && exponent.info(GiNaC::info_flags::rational) &&
                    GiNaC::ex_to<GiNaC::numeric>(exponent).denom() == 2 &&
                    GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(exponent)) > 1) {
                    const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(exponent);
                    const GiNaC::numeric whole = k.is_positive() ? (k - GiNaC::numeric(1, 2)) : (k + GiNaC::numeric(1, 2));
                    return GiNaC::pow(part.op(0), whole) *
                           (*this)(GiNaC::pow(part.op(0), k.is_positive() ? GiNaC::numeric(1, 2) : GiNaC::numeric(-1, 2)));
                }
                auto found = to.find(part);
                if (found == to.end()) {
                    const GiNaC::ex standing = GiNaC::realsymbol();
                    found = to.emplace(part, standing).first;
                    from.emplace(standing, part);
                }
                return found->second;
            }
            return part.map(*this);
        }
    } replace(to_symbols, back);
    const GiNaC::ex plain = replace(e);
    const GiNaC::ex nd = GiNaC::normal(plain).numer_denom();
    auto factored = [&](const GiNaC::ex& p) { return p.nops() > 4 ? p : factor_polynomial(p, *given.run); };
    return simplify_radicals((factored(nd.op(0)) / factored(nd.op(1))).subs(back, GiNaC::subs_options::no_pattern),
                             given);
}

// Where a value lies with respect to its unknown's domain: proven inside, proven
// outside, or not settled (then it stays admissible).
struct placement {
    enum class where { inside, outside, unsettled } at = where::unsettled;
    std::string words;
    std::vector<sign_step> proof;
};

placement place(const GiNaC::ex& value, const GiNaC::ex& unknown, const domain& range, const assumptions& given)
{
    // value − lower ≥ 0 (> 0 when the end is open), and upper − value likewise.
    struct bound {
        GiNaC::ex distance;   // must be >= 0, or > 0 when strict
        bool strict;
        std::string claim;    // the bound in words, e.g. "V > 0"
    };
    const std::string name = given.text(unknown);
    std::vector<bound> bounds;
    switch (range.what) {
    case domain::kind::real: return {placement::where::inside, "", {}};
    case domain::kind::positive: bounds.push_back({value, true, name + " > 0"}); break;
    case domain::kind::nonnegative: bounds.push_back({value, false, name + " >= 0"}); break;
    case domain::kind::interval:
        bounds.push_back({value - range.exact_lower(), range.lower_open,
                          fmt::format("{} {} {}", name, range.lower_open ? ">" : ">=", given.text(range.exact_lower()))});
        bounds.push_back({range.exact_upper() - value, range.upper_open,
                          fmt::format("{} {} {}", name, range.upper_open ? "<" : "<=", given.text(range.exact_upper()))});
        break;
    }
    placement p;
    p.at = placement::where::inside;
    for (const bound& b : bounds) {
        const sign_proof proof = prove_sign(b.distance, given);
        const bool holds = !proof.sign.negative && !(b.strict && proof.sign.zero);
        const bool fails = !proof.sign.positive && (b.strict || !proof.sign.zero);
        // "V > 0, but -sqrt(2)*sqrt(g*h) < 0"; a number is named: "T > 0, but T = 0".
        const std::string shown = GiNaC::is_a<GiNaC::numeric>(value)
                                      ? fmt::format("{} = {}", name, given.text(value))
                                      : fmt::format("{} {}", given.text(b.distance), proof.sign.describe());
        if (fails) {
            p = {placement::where::outside, fmt::format("{}, but {}", b.claim, shown), proof.steps};
            return p;
        }
        if (!holds) {
            p.at = placement::where::unsettled;
            p.words = fmt::format("{} is not proven: {} is {}", b.claim, given.text(b.distance), proof.sign.describe());
        } else if (p.at == placement::where::inside) {
            p.words += (p.words.empty() ? "" : "; ") + fmt::format("{}: {}", b.claim, shown);
            p.proof.insert(p.proof.end(), proof.steps.begin(), proof.steps.end());
        }
    }
    return p;
}

std::string values_text(const std::vector<std::pair<GiNaC::ex, GiNaC::ex>>& values, const symbol_table& symbols)
{
    std::string out;
    for (const auto& [u, v] : values)
        out += fmt::format("{}{} = {}", out.empty() ? "" : ", ", symbols.text(u), symbols.text(v));
    return out;
}

// The solution checked in each equation it solves.
std::vector<check_result> substituted_back(const std::vector<const equation*>& used, const solution& s,
                                           const std::string& which, const solve_context& context)
{
    GiNaC::exmap values;
    for (const auto& [u, v] : s.values)
        values[u] = v;
    std::vector<check_result> checks;
    for (const equation* e : used) {
        const GiNaC::ex put = context.resolve(e->relation).subs(values, GiNaC::subs_options::no_pattern);
        // A root of sin x = w such as x = π − asin w gives sin(π − asin w): written sin(asin w).
        const GiNaC::ex substituted = quarter_turns_reduced(put);
        check_result c;
        c.name = fmt::format("{} holds for the {}", e->name, which);
        c.statement = e->name;
        c.stated = e->relation;
        c.because = substituted.is_equal(put) ? "the solution substituted back into the equation it solves"
                                              : "the solution substituted back into the equation it solves, "
                                                "sin, cos and tan of y + k*Pi/2 written as functions of y";
        c.lhs = substituted.lhs();
        c.rhs = substituted.rhs();
        c.outcome = prove_equal(c.lhs, c.rhs, context.symbols, context.run);
        c.where = e->where;
        checks.push_back(std::move(c));
    }
    return checks;
}

// Solves linear equations with lsolve (unknown = value, in the order of the unknowns);
// nullopt when they are not linear.
std::optional<std::vector<std::pair<GiNaC::ex, GiNaC::ex>>> solve_linear(const spec::step& st, const GiNaC::lst& system, const GiNaC::lst& unknowns,
                                         const solve_context& context)
{
    GiNaC::ex solution;
    try {
        solution = GiNaC::lsolve(system, unknowns);
    } catch (const std::logic_error&) {
        return std::nullopt;
    }
    if (solution.nops() == 0)
        throw error(st.where, "the system is inconsistent: it has no solution");
    for (const GiNaC::ex& s : solution) {
        for (const GiNaC::ex& u : unknowns)
            if (s.rhs().has(u))
                throw error(st.where, fmt::format("the system is singular: it does not determine {}",
                                                  context.symbols.text(s.lhs())));
    }
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> solved;
    for (const GiNaC::ex& s : solution)
        solved.emplace_back(s.lhs(), s.rhs());
    return solved;
}

} // namespace

GiNaC::exmap solve_equations(const spec::step& st, const solve_context& context, step_result& r)
{
    r.description = fmt::format("solve {} for {}", join(st.equations), join(st.unknowns));
    if (st.unknowns.size() > st.equations.size())
        throw error(st.where, fmt::format("{} unknowns but only {} equations: the system is underdetermined",
                                          st.unknowns.size(), st.equations.size()));
    const assumptions given = declared_assumptions(context.symbols, context.run);
    GiNaC::lst unknowns;
    std::vector<GiNaC::ex> unknown_list;
    for (const spec::text& u : st.unknowns) {
        const GiNaC::ex s = context.symbols.at(u).symbol;
        if (context.derived.count(s))
            throw error(u.where, fmt::format("'{}' is already derived by an earlier step", u.value));
        unknowns.append(s);
        unknown_list.push_back(s);
    }
    GiNaC::lst system;
    std::vector<const equation*> used;
    for (const spec::text& name : st.equations) {
        used.push_back(&context.equation_at(name));
        system.append(context.resolve(used.back()->relation));
    }
    std::vector<GiNaC::ex> conditions;
    for (const spec::text& condition : st.reject)
        conditions.push_back(context.resolve(context.symbols.parse_equation(condition)));

    // A linear system has one solution, found as it always was.
    const auto linear = solve_linear(st, system, unknowns, context);
    if (linear && conditions.empty()) {
        GiNaC::exmap solved;
        solution only;
        for (const auto& [u, value] : *linear) {
            solved[u] = simplified(value, given);
            r.values.emplace_back(u, solved[u]);
            only.values.emplace_back(u, solved[u]);
        }
        r.checks = substituted_back(used, only, "solution", context);
        return solved;
    }

    std::vector<GiNaC::exmap> found;
    std::vector<std::string> complex;
    std::vector<trigonometric_root> trigonometric;   // roots of sin, cos, tan = w, with their intervals
    if (linear) {
        found.emplace_back(linear->begin(), linear->end());
    } else {
        eliminator solver(context.symbols, given);
        try {
            solver.run(std::vector<GiNaC::ex>(system.begin(), system.end()), unknown_list);
        } catch (const unsolvable& e) {
            throw error(st.where, e.what());
        }
        // What a split on a coefficient or a resultant found is a solution only where it
        // satisfies every equation.
        for (const candidate& c : solver.found) {
            const bool solves = !c.unverified || std::all_of(system.begin(), system.end(), [&](const GiNaC::ex& e) {
                try {
                    return may_vanish(polynomial_of(e.subs(c.values, GiNaC::subs_options::no_pattern)), given);
                } catch (const std::exception&) {
                    return false;   // a denominator of the value vanishes
                }
            });
            if (solves)
                found.push_back(c.values);
        }
        complex = std::move(solver.complex);
        trigonometric = std::move(solver.trigonometric);
    }
    if (found.empty())
        throw error(st.where, complex.empty() ? std::string("the system is inconsistent: it has no solution")
                                              : fmt::format("the system has no real solution: {}",
                                                            fmt::join(complex, "; ")));

    // Each solution simplified, in the order the unknowns are listed; a double root once.
    // The roots of a trigonometric equation keep the intervals their values lie in.
    std::vector<solution> solutions;
    std::vector<std::vector<const trigonometric_root*>> intervals;
    for (const GiNaC::exmap& values : found) {
        solution s;
        std::vector<const trigonometric_root*> within;
        for (const GiNaC::ex& u : unknown_list) {
            s.values.emplace_back(u, simplest(values.at(u), given));
            for (const trigonometric_root& r : trigonometric)
                if (r.unknown.is_equal(u) && r.value.is_equal(values.at(u)))
                    within.push_back(&r);
        }
        const bool repeated = std::any_of(solutions.begin(), solutions.end(), [&](const solution& other) {
            for (std::size_t i = 0; i < s.values.size(); ++i)
                if (prove_equal(s.values[i].second, other.values[i].second, context.symbols, context.run).what !=
                    verdict::status::proven)
                    return false;
            return true;
        });
        if (!repeated) {
            solutions.push_back(std::move(s));
            intervals.push_back(std::move(within));
        }
    }

    // Kept or rejected: by the unknowns' domains, then by the step's conditions.
    std::vector<bool> condition_used(conditions.size(), false);
    // A condition that holds only for solutions the domains reject already: the first.
    std::vector<const solution*> condition_redundant(conditions.size(), nullptr);
    const auto condition_holds = [&](std::size_t i, const solution& s) {
        GiNaC::exmap values;
        for (const auto& [u, v] : s.values)
            values[u] = v;
        const GiNaC::ex holds = expanded_radicands(conditions[i].subs(values, GiNaC::subs_options::no_pattern));
        return prove_equal(holds.lhs(), holds.rhs(), context.symbols, context.run).what == verdict::status::proven;
    };
    for (std::size_t n = 0; n < solutions.size(); ++n) {
        solution& s = solutions[n];
        for (const auto& [u, value] : s.values) {
            const domain& range = *context.symbols.domain_of(u);
            placement p;
            // A root of sin, cos or tan = w: first by the interval its value lies in.
            const GiNaC::ex& unknown = u;   // a lambda may not capture a structured binding in C++17
            const auto root = std::find_if(intervals[n].begin(), intervals[n].end(),
                                           [&](const trigonometric_root* r) { return r->unknown.is_equal(unknown); });
            if (root != intervals[n].end()) {
                const trigonometric_root& r = **root;
                const std::string lies = fmt::format(
                    "{} lies in {}", given.text(u), interval_text(r.low, r.low_open, r.high, r.high_open, given));
                switch (place_interval(r, range)) {
                case interval_placement::inside:
                    p = {placement::where::inside,
                         fmt::format("{}, within {}: {}{}", lies, range.to_string(), r.why,
                                     r.existence.empty() ? "" : "; " + r.existence),
                         {}};
                    break;
                case interval_placement::outside:
                    p = {placement::where::outside,
                         fmt::format("{}, outside {}: {}", lies, range.to_string(), r.why), {}};
                    break;
                case interval_placement::across: p = place(value, u, range, given); break;
                }
                // Not settled, or settled by signs: the interval said beside them.
                if (p.at == placement::where::unsettled)
                    s.why += fmt::format("{}{}; {}: {}{}", s.why.empty() ? "" : "; ", p.words, lies, r.why,
                                         r.existence.empty() ? "" : "; " + r.existence);
                else if (p.at == placement::where::inside && p.words.empty())
                    p.words = fmt::format("{}: {}{}", lies, r.why, r.existence.empty() ? "" : "; " + r.existence);
            } else {
                p = place(value, u, range, given);
            }
            if (p.at == placement::where::outside) {
                s.outcome = solution::fate::outside_domain;
                s.unknown = u;
                s.range = *context.symbols.domain_of(u);
                s.why = p.words;
                s.proof = p.proof;
                break;
            }
            if (p.at == placement::where::inside && !p.words.empty()) {
                s.why += (s.why.empty() ? "" : "; ") + p.words;
                s.proof.insert(s.proof.end(), p.proof.begin(), p.proof.end());
            }
        }
        if (!s.kept()) {
            for (std::size_t i = 0; i < conditions.size(); ++i)
                if (!condition_redundant[i] && condition_holds(i, s))
                    condition_redundant[i] = &s;
            continue;
        }
        for (std::size_t i = 0; i < conditions.size(); ++i) {
            if (condition_holds(i, s)) {
                s.outcome = solution::fate::condition;
                s.condition = context.symbols.parse_equation(st.reject[i]);
                s.why = st.reject_because.value;
                s.proof.clear();
                condition_used[i] = true;
                break;
            }
        }
    }
    for (std::size_t i = 0; i < conditions.size(); ++i) {
        if (condition_used[i])
            continue;
        // It holds for a solution, but one that a domain rejects already.
        if (const solution* s = condition_redundant[i])
            throw error(st.reject[i].where,
                        fmt::format("the condition {} is redundant: it holds only for {}, which the domain of {} "
                                    "({}) already rejects ({}); remove it from reject",
                                    st.reject[i].value, values_text(s->values, context.symbols),
                                    context.symbols.text(s->unknown), s->range.to_string(), s->why));
        throw error(st.reject[i].where, fmt::format("the condition {} holds for none of the solutions: {}",
                                                        st.reject[i].value, [&] {
                                                            std::vector<std::string> all;
                                                            for (const solution& s : solutions)
                                                                all.push_back(values_text(s.values, context.symbols));
                                                            return fmt::format("{}", fmt::join(all, "; "));
                                                        }()));
    }

    std::vector<std::string> kept, rejected;
    for (const solution& s : solutions)
        (s.kept() ? kept : rejected)
            .push_back(s.kept() ? values_text(s.values, context.symbols)
                                : fmt::format("{} ({})", values_text(s.values, context.symbols),
                                              s.outcome == solution::fate::condition
                                                  ? context.symbols.text(s.condition.lhs()) + " = " +
                                                        context.symbols.text(s.condition.rhs()) + ": " + s.why
                                                  : s.why));
    if (kept.empty())
        throw error(st.where, fmt::format("every solution is rejected: {}", fmt::join(rejected, "; ")));
    if (kept.size() > 1)
        throw error(st.where,
                    fmt::format("{} solutions are admissible: {}; choose one by declaring a domain for {} "
                                "(e.g. domain = \"positive\") or by rejecting the others in the step "
                                "(reject = [\"{} = ...\"], reject_because = \"why\")",
                                kept.size(), fmt::join(kept, " and "), join(st.unknowns), st.unknowns.front().value));

    // Every solution, the kept one first, substituted back and proven.
    GiNaC::exmap solved;
    for (const bool keeping : {true, false}) {
        for (const solution& s : solutions) {
            if (s.kept() != keeping)
                continue;
            for (const auto& [u, v] : s.values) {
                if (keeping) {
                    solved[u] = v;
                    r.values.emplace_back(u, v);
                }
            }
            const std::string which =
                keeping ? "solution" : "rejected solution " + values_text(s.values, context.symbols);
            for (check_result& c : substituted_back(used, s, which, context))
                r.checks.push_back(std::move(c));
        }
    }
    std::stable_partition(solutions.begin(), solutions.end(), [](const solution& s) { return s.kept(); });
    r.solutions = std::move(solutions);
    return solved;
}

} // namespace impact::engine
