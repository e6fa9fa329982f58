#include "engine/solve.h"

#include <cln/rational.h>
#include <cln/real.h>
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace impact::engine {

GiNaC::ex simplified(const GiNaC::ex& e, const assumptions& given)
{
    // factor() is by far the engine's most expensive call; a long numerator is left
    // expanded (a derivation states the form it wants typeset as its display form).
    constexpr std::size_t longest_factored = 4;
    const GiNaC::ex nd = GiNaC::normal(simplify_radicals(e, given)).numer_denom();
    auto factored = [&](const GiNaC::ex& p) {
        return p.nops() > longest_factored ? p : factor_polynomial(p, *given.run);
    };
    return simplify_radicals(factored(nd.op(0)) / factored(nd.op(1)), given);
}

namespace {

std::string join(const std::vector<spec::text>& items)
{
    std::string out;
    for (const spec::text& item : items)
        out += (out.empty() ? "" : ", ") + item.value;
    return out;
}

// Why a system could not be solved, said at the step by the caller.
struct unsolvable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

bool has_any(const GiNaC::ex& e, const std::vector<GiNaC::ex>& symbols)
{
    for (const GiNaC::ex& s : symbols)
        if (e.has(s))
            return true;
    return false;
}

// lhs − rhs (or an expression) as a polynomial: the numerator of its normal form, expanded.
GiNaC::ex polynomial_of(const GiNaC::ex& e)
{
    const GiNaC::ex difference = GiNaC::is_a<GiNaC::relational>(e) ? e.lhs() - e.rhs() : e;
    return GiNaC::expand(GiNaC::normal(difference).numer_denom().op(0));
}

// √n = k√r for a positive rational n, k the largest square taken out of it by trial
// division (numbers in derivations are small): √8 = 2√2, √(9/2) = 3√2/2.
GiNaC::ex root_of_number(const GiNaC::numeric& n)
{
    if (!n.is_rational() || !n.is_positive())
        return GiNaC::sqrt(GiNaC::ex(n));   // GiNaC::sqrt(numeric) would be a float
    GiNaC::numeric whole = n.numer() * n.denom(), outside = 1;
    for (GiNaC::numeric k = 2; k < 1000 && k * k <= whole; ++k) {
        while (GiNaC::irem(whole, k * k).is_zero()) {
            whole = GiNaC::iquo(whole, k * k);
            outside *= k;
        }
    }
    return outside * GiNaC::sqrt(GiNaC::ex(whole)) / n.denom();
}

// √d up to its sign: the square of each factor is taken out whatever the factor's sign,
// since both roots ±√d are taken (√((a − b)² c) → (a − b)√c).
GiNaC::ex root_up_to_sign(const GiNaC::ex& d, proof_cache& run)
{
    const GiNaC::ex nd = GiNaC::normal(d).numer_denom();
    GiNaC::ex outside = 1, inside = 1;
    for (int part = 0; part < 2; ++part) {
        const GiNaC::ex f = factor_polynomial(nd.op(part), run);
        GiNaC::exvector factors;
        if (GiNaC::is_a<GiNaC::mul>(f))
            factors.assign(f.begin(), f.end());
        else
            factors.push_back(f);
        for (const GiNaC::ex& g : factors) {
            GiNaC::ex base = g;
            GiNaC::numeric k = 1;
            if (GiNaC::is_a<GiNaC::power>(g) && g.op(1).info(GiNaC::info_flags::posint)) {
                base = g.op(0);
                k = GiNaC::ex_to<GiNaC::numeric>(g.op(1));
            }
            const GiNaC::numeric half = k.is_even() ? k / 2 : (k - 1) / 2;
            const GiNaC::ex out = GiNaC::pow(base, half), in = GiNaC::pow(base, k - 2 * half);
            outside = part == 0 ? outside * out : outside / out;
            inside = part == 0 ? inside * in : inside / in;
        }
    }
    // A positive number comes out of the root as far as it is a square; the rest of
    // the root is kept whole.
    GiNaC::numeric number = 1;
    GiNaC::ex rest = 1;
    const GiNaC::ex parts = GiNaC::is_a<GiNaC::mul>(inside) ? inside : GiNaC::ex(GiNaC::lst{inside});
    for (const GiNaC::ex& f : parts) {
        if (GiNaC::is_a<GiNaC::numeric>(f))
            number *= GiNaC::ex_to<GiNaC::numeric>(f);
        else
            rest *= f;
    }
    if (number.is_positive())
        return outside * root_of_number(number) * GiNaC::sqrt(rest);
    return outside * GiNaC::sqrt(inside);
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

// Every solution of polynomial equations, by elimination (see solve.h). A branch whose
// equations reduce to a non-zero constant has no solution and ends there; a quadratic
// whose discriminant is proven negative has no real root.
class eliminator {
public:
    eliminator(const symbol_table& symbols, const assumptions& given) : symbols_(symbols), given_(given) {}

    std::vector<GiNaC::exmap> found;
    std::size_t dead_ends = 0;     // branches found inconsistent
    std::vector<std::string> complex;  // quadratics without real roots, in words

    void run(const std::vector<GiNaC::ex>& equations, const std::vector<GiNaC::ex>& unknowns,
             const GiNaC::exmap& values)
    {
        std::vector<GiNaC::ex> left;
        for (const GiNaC::ex& e : equations) {
            const GiNaC::ex p = polynomial_of(e);
            if (p.is_zero())
                continue;
            if (!has_any(p, unknowns)) {
                ++dead_ends;
                return;
            }
            left.push_back(p);
        }
        if (unknowns.empty()) {
            found.push_back(values);
            return;
        }
        if (left.empty())
            throw unsolvable(fmt::format("the equations do not determine {}: the system is underdetermined",
                                         names(unknowns)));
        // An unknown that an equation holds linearly, with a coefficient free of the
        // unknowns: u = −c₀/c₁, substituted everywhere.
        for (const GiNaC::ex& p : left) {
            for (const GiNaC::ex& u : unknowns) {
                if (!p.is_polynomial(u) || p.degree(u) != 1 || has_any(p.coeff(u, 1), unknowns))
                    continue;
                eliminate(left, p, unknowns, u, -p.coeff(u, 0) / p.coeff(u, 1), values);
                return;
            }
        }
        // An equation in one unknown of degree two: a u² + b u + c = 0.
        for (const GiNaC::ex& p : left) {
            std::vector<GiNaC::ex> in;
            for (const GiNaC::ex& u : unknowns)
                if (p.has(u))
                    in.push_back(u);
            if (in.size() != 1 || !p.is_polynomial(in.front()) || p.degree(in.front()) != 2)
                continue;
            const GiNaC::ex u = in.front();
            const GiNaC::ex a = p.coeff(u, 2), b = p.coeff(u, 1), c = p.coeff(u, 0);
            const GiNaC::ex discriminant = GiNaC::expand(b * b - 4 * a * c);
            const sign_set s = prove_sign(discriminant, given_).sign;
            if (!s.positive && !s.zero) {
                complex.push_back(fmt::format("{} = 0 has no real root (b^2 - 4 a c = {} < 0)", symbols_.text(p),
                                              symbols_.text(discriminant)));
                return;
            }
            const GiNaC::ex root = discriminant.is_zero() ? GiNaC::ex(0) : root_up_to_sign(discriminant, *given_.run);
            eliminate(left, p, unknowns, u, (-b + root) / (2 * a), values);
            if (!root.is_zero())
                eliminate(left, p, unknowns, u, (-b - root) / (2 * a), values);
            return;
        }
        std::string degrees;
        for (const GiNaC::ex& p : left)
            for (const GiNaC::ex& u : unknowns)
                if (p.has(u))
                    degrees += fmt::format("{}{} = 0 is {} in {}", degrees.empty() ? "" : "; ", symbols_.text(p),
                                           p.is_polynomial(u) ? fmt::format("of degree {}", p.degree(u))
                                                              : std::string("not polynomial"),
                                           symbols_.text(u));
        throw unsolvable(fmt::format("the system is not linear in {}, and eliminating the unknowns it holds "
                                     "linearly leaves no equation of degree 2 or less in one unknown ({})",
                                     names(unknowns), degrees));
    }

private:
    void eliminate(const std::vector<GiNaC::ex>& left, const GiNaC::ex& used, const std::vector<GiNaC::ex>& unknowns,
                   const GiNaC::ex& u, const GiNaC::ex& value, const GiNaC::exmap& values)
    {
        const GiNaC::exmap one{{u, value}};
        std::vector<GiNaC::ex> rest;
        for (const GiNaC::ex& p : left)
            if (!p.is_equal(used))
                rest.push_back(p.subs(one, GiNaC::subs_options::no_pattern));
        std::vector<GiNaC::ex> others;
        for (const GiNaC::ex& v : unknowns)
            if (!v.is_equal(u))
                others.push_back(v);
        GiNaC::exmap now;
        for (const auto& [symbol, earlier] : values)
            now[symbol] = earlier.subs(one, GiNaC::subs_options::no_pattern);
        now[u] = value;
        run(rest, others, now);
    }

    std::string names(const std::vector<GiNaC::ex>& unknowns) const
    {
        std::string out;
        for (const GiNaC::ex& u : unknowns)
            out += (out.empty() ? "" : ", ") + symbols_.text(u);
        return out;
    }

    const symbol_table& symbols_;
    const assumptions& given_;
};

// Where a value lies with respect to its unknown's domain: proven inside, proven
// outside, or not settled (then it stays admissible).
struct placement {
    enum class where { inside, outside, unsettled } at = where::unsettled;
    std::string words;
    std::vector<sign_step> proof;
};

// The exact rational value of a bound written in a derivation file.
GiNaC::numeric exact(double value)
{
    return GiNaC::numeric(cln::cl_N(cln::rational(cln::cl_DF(value))));
}

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
        bounds.push_back({value - exact(range.lower), range.lower_open,
                          fmt::format("{} {} {}", name, range.lower_open ? ">" : ">=", given.text(exact(range.lower)))});
        bounds.push_back({exact(range.upper) - value, range.upper_open,
                          fmt::format("{} {} {}", name, range.upper_open ? "<" : "<=", given.text(exact(range.upper)))});
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
        const GiNaC::ex substituted = context.resolve(e->relation).subs(values, GiNaC::subs_options::no_pattern);
        check_result c;
        c.name = fmt::format("{} holds for the {}", e->name, which);
        c.statement = e->name;
        c.stated = e->relation;
        c.because = "the solution substituted back into the equation it solves";
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
    if (linear) {
        found.emplace_back(linear->begin(), linear->end());
    } else {
        eliminator solver(context.symbols, given);
        try {
            solver.run(std::vector<GiNaC::ex>(system.begin(), system.end()), unknown_list, {});
        } catch (const unsolvable& e) {
            throw error(st.where, e.what());
        }
        found = std::move(solver.found);
        complex = std::move(solver.complex);
    }
    if (found.empty())
        throw error(st.where, complex.empty() ? std::string("the system is inconsistent: it has no solution")
                                              : fmt::format("the system has no real solution: {}",
                                                            fmt::join(complex, "; ")));

    // Each solution simplified, in the order the unknowns are listed; a double root once.
    std::vector<solution> solutions;
    for (const GiNaC::exmap& values : found) {
        solution s;
        for (const GiNaC::ex& u : unknown_list)
            s.values.emplace_back(u, simplest(values.at(u), given));
        const bool repeated = std::any_of(solutions.begin(), solutions.end(), [&](const solution& other) {
            for (std::size_t i = 0; i < s.values.size(); ++i)
                if (prove_equal(s.values[i].second, other.values[i].second, context.symbols, context.run).what !=
                    verdict::status::proven)
                    return false;
            return true;
        });
        if (!repeated)
            solutions.push_back(std::move(s));
    }

    // Kept or rejected: by the unknowns' domains, then by the step's conditions.
    std::vector<bool> condition_used(conditions.size(), false);
    for (solution& s : solutions) {
        for (const auto& [u, value] : s.values) {
            const placement p = place(value, u, *context.symbols.domain_of(u), given);
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
        if (!s.kept())
            continue;
        GiNaC::exmap values;
        for (const auto& [u, v] : s.values)
            values[u] = v;
        for (std::size_t i = 0; i < conditions.size(); ++i) {
            const GiNaC::ex holds = conditions[i].subs(values, GiNaC::subs_options::no_pattern);
            if (prove_equal(holds.lhs(), holds.rhs(), context.symbols, context.run).what == verdict::status::proven) {
                s.outcome = solution::fate::condition;
                s.condition = context.symbols.parse_equation(st.reject[i]);
                s.why = st.reject_because.value;
                s.proof.clear();
                condition_used[i] = true;
                break;
            }
        }
    }
    for (std::size_t i = 0; i < conditions.size(); ++i)
        if (!condition_used[i])
            throw error(st.reject[i].where, fmt::format("the condition {} holds for none of the solutions: {}",
                                                        st.reject[i].value, [&] {
                                                            std::vector<std::string> all;
                                                            for (const solution& s : solutions)
                                                                all.push_back(values_text(s.values, context.symbols));
                                                            return fmt::format("{}", fmt::join(all, "; "));
                                                        }()));

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
