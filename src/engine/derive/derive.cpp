#include "engine/derive/derive.h"

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
#include <chrono>
#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <iterator>
#include <set>

namespace impact::engine {
namespace detail {

derivation deriver::run()
{
    const spec::derivation& s = out_.source;
    // Each part's wall time, for `impact derive --timings`.
    auto started = std::chrono::steady_clock::now();
    const auto timed = [&](std::string part) {
        const auto now = std::chrono::steady_clock::now();
        out_.timings.emplace_back(std::move(part), std::chrono::duration<double>(now - started).count());
        started = now;
    };
    add_dimensions(out_.symbols, s.dimensions);
    for (const spec::symbol& declaration : s.symbols)
        out_.symbols.declare(declaration);
    check_definitions(out_.symbols, s, run_);
    check_assumptions_hold_together(out_.symbols, s, declared_assumptions(out_.symbols, run_));
    infer_definitions(out_.symbols, s);
    // What each abbreviation's definition needs (A = sqrt(x): x >= 0), as written and as
    // read, for every value and claim that uses it: GiNaC puts the definition in and may
    // simplify its condition away (sqrt(A)^4 is x^2, A = x/x is 1). Twice, so that one
    // defined through another declared after it has that one's needs too.
    for (int pass = 0; pass < 2; ++pass)
        for (const spec::symbol& declaration : s.symbols)
            if (declaration.definition)
                if (const quantity& q = out_.symbols.at(declaration.name); q.definition) {
                    const written_form as_written = written(*declaration.definition);
                    needs_[q.symbol] = needs_of(*q.definition, &as_written);
                }
    for (const spec::use& u : s.uses)
        import(u);
    for (const spec::given& g : s.givens)
        add_given(g);
    timed("quantities, definitions and given equations");
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        run_step(s.steps[i]);
        timed(fmt::format("step {} (line {})", i + 1, s.steps[i].where.line));
    }
    // A fault found while putting values in (a diff by a quantity a later step derives)
    // is told at its place.
    for (const spec::result& r : s.results)
        try {
            add_result(r);
        } catch (...) {
            rethrow_at(r.name.where, fmt::format("result '{}'", r.name.value));
        }
    locate_by_members();
    timed("results");
    for (const spec::check& c : s.checks)
        try {
            out_.checks.push_back(run_check(c));
            timed("check " + c.name.value);
        } catch (...) {
            rethrow_at(c.claim.where, fmt::format("check '{}'", c.name.value));
        }
    for (const spec::claim& c : s.claims)
        try {
            out_.paper_checks.push_back(hold_to_account(c));
            timed("paper claim " + c.test.name.value);
        } catch (...) {
            rethrow_at(c.test.claim.where, fmt::format("claim '{}'", c.test.name.value));
        }
    find_swapped_values(out_.paper_checks);
    timed("the paper's values compared");
    // A kernel computes a quantity defined by cases as a select of its cases' values,
    // each as the file writes it (its quantities replaced by their values), not as
    // simplified: normal() multiplies a radicand out (|G_t| = sqrt(G_t . G_t) as about
    // fifty terms, which cancel to nothing in float when the sphere spins fast about the
    // normal), where the file writes a sum of squares. Its condition is as written already.
    GiNaC::exmap selects;
    for (const auto& [symbol, pieces] : cases_) {
        std::vector<case_value> computed = pieces;
        for (case_value& c : computed)
            c.value = resolve(c.as_written);
        selects[symbol] = select_of(computed);
    }
    const engine::resolver in_kernels = [this, &selects](const GiNaC::ex& e) {
        return resolve(e).subs(selects, GiNaC::subs_options::no_pattern);
    };
    for (const spec::kernel& k : s.kernels)
        try {
            out_.kernels.push_back(build_kernel(k, out_, in_kernels, run_));
            timed("kernel " + k.name.value);
        } catch (...) {
            rethrow_at(k.name.where, fmt::format("kernel '{}'", k.name.value));
        }
    return std::move(out_);
}

// Replaces every derived quantity by its value and every abbreviation by its definition.
GiNaC::ex deriver::resolve(const GiNaC::ex& e) const
{
    // The same expressions are resolved again and again (checks, claims, forms): kept
    // until a step derives a new value.
    const auto known = resolved_.find(e);
    if (known != resolved_.end())
        return known->second;
    // diff(f, x) is taken once f is in the inputs (engine/expr/derivative.h); never of a
    // quantity defined by cases, which stays a symbol here and would differentiate to 0.
    const GiNaC::ex put_in = substituted(e, out_.symbols.abbreviations());
    if (has_derivative(put_in))
        for (GiNaC::const_preorder_iterator it = put_in.preorder_begin(); it != put_in.preorder_end(); ++it)
            if (is_derivative(*it))
                for (const auto& [symbol, pieces] : cases_)
                    if (it->op(0).has(symbol))
                        throw std::invalid_argument(fmt::format(
                            "diff: '{}' is defined by cases, and a derivative is taken of one expression only",
                            out_.symbols.text(symbol)));
    const GiNaC::ex now = derivatives_taken(put_in);
    resolved_.emplace(e, now);
    return now;
}

// Every derived quantity replaced by its value, and each of `abbreviations` by its
// definition, until nothing changes (a value may hold other derived quantities).
GiNaC::ex deriver::substituted(const GiNaC::ex& e, const GiNaC::exmap& abbreviations) const
{
    GiNaC::ex now = e;
    for (int depth = 0; depth < 8; ++depth) {
        const GiNaC::ex next = now.subs(values_, GiNaC::subs_options::no_pattern)
                                   .subs(abbreviations, GiNaC::subs_options::no_pattern);
        if (next.is_equal(now))
            break;
        now = next;
    }
    return now;
}

void deriver::set_value(const GiNaC::ex& symbol, const GiNaC::ex& value)
{
    values_[symbol] = value;
    resolved_.clear();
    needs_[symbol] = needs_of(value, nullptr);
}

// diff(f, x) as the file writes it: x an input (no step derives it, no abbreviation
// stands for it), and f free of quantities defined by cases, which have no one value to
// differentiate.
void deriver::check_derivatives(const GiNaC::ex& e, const source_location& where) const
{
    if (!has_derivative(e))
        return;
    if (is_derivative(e)) {
        const GiNaC::ex& x = e.op(1);
        const std::string written = fmt::format("diff({}, {})", out_.symbols.text(e.op(0)), out_.symbols.text(x));
        if (!GiNaC::is_a<GiNaC::symbol>(x))
            throw error(where, fmt::format("{}: the second argument is the quantity to differentiate by, a "
                                           "declared symbol's name",
                                           written));
        if (values_.count(x) || cases_.count(x) || out_.symbols.abbreviations().count(x))
            throw error(where, fmt::format("{}: '{}' is derived, not an input; differentiate by a quantity it is "
                                           "derived from",
                                           written, out_.symbols.text(x)));
        const GiNaC::ex f = substituted(e.op(0), out_.symbols.abbreviations());
        for (const auto& [symbol, pieces] : cases_)
            if (f.has(symbol))
                throw error(where, fmt::format("{}: '{}' is defined by cases, and a derivative is taken of one "
                                               "expression only",
                                               written, out_.symbols.text(symbol)));
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        check_derivatives(e.op(i), where);
}

// A value put into a claim (`at`, `left_at`, a limit's point) is an expression of the
// inputs: a derivative is taken in the claim itself, where its variable stays free.
void deriver::refuse_derivative(const GiNaC::ex& value, const spec::text& written, const char* where) const
{
    if (has_derivative(value) || has_derivative(substituted(value, out_.symbols.abbreviations())))
        throw error(written.where, fmt::format("{} '{}' takes a derivative: diff(f, x) belongs in the claim, "
                                               "not in a value put into it",
                                               where, written.value));
}

// A derived quantity is not an input: its value follows from theirs, and a value put in
// its place (`at`, `left_at`) would change nothing in the claim, whose sides are written
// in the inputs.
void deriver::refuse_derived_value(const GiNaC::ex& symbol, const spec::binding& b, const std::string& check,
                               const char* field) const
{
    if (values_.count(symbol) || cases_.count(symbol))
        throw error(b.name.where, fmt::format("check '{}': {} gives '{}' a value, but a step derives it; "
                                              "change the quantities it is derived from",
                                              check, field, b.name.value));
}

engine::resolver deriver::resolver() const
{
    return [this](const GiNaC::ex& e) { return resolve(e); };
}

// How `text` is written, read here once for the printers, which never read the file.
written_form deriver::written(const spec::text& text) const
{
    return written_form::read(text.value,
                              [this](const std::string& piece) { return out_.symbols.parse({piece, {}}); });
}

// `[[use]]`: results of an earlier derivation, expressed in this one's symbols.
void deriver::import(const spec::use& u)
{
    const auto found = done_.find(u.derivation.value);
    if (found == done_.end())
        throw error(u.derivation.where,
                    fmt::format("uses derivation '{}', which does not exist", u.derivation.value));
    const derivation& other = found->second;
    for (const spec::binding& b : u.results) {
        const std::string& name = b.name.value;
        const bool a_name = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
                            std::all_of(name.begin(), name.end(), [](char c) {
                                return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                            });
        if (!a_name)
            throw error(b.name.where, fmt::format("'{}' is not a name to import a result under (letters, digits "
                                                  "and _); write \"name = result\"",
                                                  name));
        if (const auto earlier = imported_.find(name); earlier != imported_.end())
            throw error(b.name.where, fmt::format("'{}' is imported twice (as {}, then as {}); give each result "
                                                  "a name of its own",
                                                  name, earlier->second, b.expression.value));
        imported_.emplace(name, b.expression.value);
        const result* r = other.find_result(b.expression.value);
        if (!r)
            throw error(b.expression.where, fmt::format("derivation '{}' has no result '{}'",
                                                        u.derivation.value, b.expression.value));
        // The other derivation's symbols become this one's, matched by name.
        GiNaC::exmap rename;
        for (const quantity& q : other.symbols.all())
            if (r->value.has(q.symbol))
                rename[q.symbol] = out_.symbols.adopt(q).symbol;
        const quantity* local = out_.symbols.find(b.name.value);
        if (!local) {
            quantity q = *other.symbols.find(r->name);
            q.name = b.name.value;
            q.where = b.name.where;
            local = &out_.symbols.adopt(q);
        }
        // Named after a symbol its own value is written in, it would stand for itself.
        const GiNaC::ex value = r->value.subs(rename);
        if (value.has(local->symbol))
            throw error(b.name.where, fmt::format("results entry \"{} = {}\": {} = {} is written in '{}' itself; "
                                                  "import it under another name",
                                                  name, b.expression.value, b.expression.value,
                                                  out_.symbols.text(value), name));
        set_value(local->symbol, value);
        // What it needs there and could not be proven there (as written there, too), in
        // this derivation's symbols; what was proven there is proven under domains it takes.
        for (const quantity& q : other.symbols.all())
            for (const condition& c : r->attached)
                if (!rename.count(q.symbol) && c.expr.has(q.symbol))
                    rename[q.symbol] = out_.symbols.adopt(q).symbol;
        add_conditions(needs_[local->symbol],
                       rewritten(r->attached, [&](const GiNaC::ex& e) { return e.subs(rename); }, out_.symbols));
    }
}

void deriver::add_given(const spec::given& g)
{
    if (find_equation(g.name.value))
        throw error(g.name.where, fmt::format("equation '{}' is defined twice", g.name.value));
    equations_.push_back({g.name.value, out_.symbols.parse_equation(g.equation), g.because.value,
                          g.paper ? g.paper->value : std::string(), g.equation.where, written(g.equation)});
    out_.givens.push_back(equations_.back());
    check_relation(out_.symbols, equations_.back().relation, g.equation.where);
    if (g.printed) {
        // The paper's printing of a given equation must be equivalent to it.
        paper_comparison p;
        p.what = paper_comparison::kind::given;
        p.subject = g.name.value;
        p.paper = g.paper ? g.paper->value : std::string();
        p.printed_text = g.printed->value;
        p.quote = g.quote ? g.quote->value : std::string();
        p.printed = out_.symbols.parse_equation(*g.printed);
        p.written = written(*g.printed);
        p.derived = equations_.back().relation;
        p.agreement = prove_equivalent(p.printed, p.derived, out_.symbols, run_);
        if (!p.agrees())
            p.findings = reconcile_equation(p.printed, p.derived, out_.symbols, resolver(), run_);
        add_dimension_finding(p);
        p.where = g.printed->where;
        out_.paper_checks.push_back(std::move(p));
    }
}

const equation* deriver::find_equation(const std::string& name) const
{
    for (const equation& e : equations_)
        if (e.name == name)
            return &e;
    return nullptr;
}

const equation& deriver::equation_at(const spec::text& name) const
{
    if (const equation* e = find_equation(name.value))
        return *e;
    throw error(name.where, fmt::format("no equation named '{}' (neither given nor made by a step)", name.value));
}

void deriver::run_step(const spec::step& st)
{
    step_result r;
    r.what = st.what;
    r.because = st.because.value;
    r.where = st.where;
    try {
        switch (st.what) {
        case spec::step::kind::solve: solve(st, r); break;
        case spec::step::kind::define: define(st, r); break;
        case spec::step::kind::quotient: quotient(st, r); break;
        case spec::step::kind::rearrange: rearrange(st, r); break;
        }
        // What the step derives has the dimension of what it derives it for.
        const source_location& at = st.what == spec::step::kind::define ? st.expression.where : st.where;
        for (const auto& [symbol, value] : r.values)
            check_value(out_.symbols, symbol, value, at);
        if (r.yields)
            check_relation(out_.symbols, r.yields->relation, st.where);
        // Where the values it derives are defined: proven from the domains, or attached.
        std::vector<condition> needs;
        for (const auto& [symbol, value] : r.values)
            add_conditions(needs, in_inputs(needs_[symbol]));
        settled_conditions settled = settle(needs, declared_assumptions(out_.symbols, run_));
        r.attached = std::move(settled.attached);
        r.defined = std::move(settled.proven);
        infer_definitions(out_.symbols, out_.source);   // abbreviations of what is now known
    } catch (...) {
        rethrow_at(st.where, fmt::format("step {} ({})", out_.steps.size() + 1, r.description));
    }
    out_.steps.push_back(std::move(r));
}

// Solves equations for unknowns (engine/solve/solve.h); every solution is substituted back.
void deriver::solve(const spec::step& st, step_result& r)
{
    const solve_context context{out_.symbols, run_, resolver(),
                                [this](const spec::text& name) -> const equation& { return equation_at(name); },
                                values_};
    for (const auto& [symbol, value] : solve_equations(st, context, r))
        set_value(symbol, value);
}

void deriver::define(const spec::step& st, step_result& r)
{
    const GiNaC::ex s = symbol_of(st.name);
    if (values_.count(s) || cases_.count(s))
        throw error(st.name.where, fmt::format("'{}' is already derived by an earlier step", st.name.value));
    if (!st.cases.empty())
        return define_by_cases(st, s, r);
    r.description = fmt::format("define {} = {}", st.name.value, st.expression.value);
    // Radicals of squares come out by the declared signs: sqrt(u^2) = u for u >= 0.
    r.as_written = out_.symbols.parse(st.expression);
    check_derivatives(*r.as_written, st.expression.where);
    r.written = written(st.expression);
    const GiNaC::ex value = simplified(resolve(*r.as_written), declared_assumptions(out_.symbols, run_));
    std::vector<condition> needs = needs_of(*r.as_written, &r.written);
    set_value(s, value);
    add_conditions(needs_[s], needs);
    r.values.emplace_back(s, value);
}

// A value by cases: each condition an inequality and each value of the quantity's
// dimension; the quantity keeps no single value (it stays a symbol in what uses it,
// and a check on it is proven case by case), and the cases are proven to cover every value.
void deriver::define_by_cases(const spec::step& st, const GiNaC::ex& s, step_result& r)
{
    r.description = fmt::format("define {} by {} cases", st.name.value, st.cases.size());
    r.cases_of = s;
    const assumptions declared = declared_assumptions(out_.symbols, run_);
    for (const spec::case_of& one : st.cases) {
        case_value c;
        c.where = one.where;
        const claim_sides when = out_.symbols.parse_claim(one.when);
        if (when.op == relation::equal)
            throw error(one.when.where, fmt::format("condition \"{}\" must be an inequality (<, <=, >, >=), "
                                                    "not an equation", one.when.value));
        check_relation(out_.symbols, when.lhs == when.rhs, one.when.where);
        c.op = when.op;
        c.written_lhs = when.lhs;
        c.written_rhs = when.rhs;
        c.lhs = resolve(when.lhs);
        c.rhs = resolve(when.rhs);
        for (const auto& [other, pieces] : cases_)
            if (c.lhs.has(other) || c.rhs.has(other))
                throw error(one.when.where, fmt::format("condition \"{}\" uses '{}', itself defined by cases",
                                                        one.when.value, ginac_syntax(other, out_.symbols.order())));
        c.as_written = out_.symbols.parse(one.as);
        c.written = written(one.as);
        c.value = simplified(resolve(c.as_written), declared);
        for (const auto& [other, pieces] : cases_)
            if (c.value.has(other))
                throw error(one.as.where, fmt::format("value \"{}\" uses '{}', itself defined by cases",
                                                      one.as.value, ginac_syntax(other, out_.symbols.order())));
        check_value(out_.symbols, s, c.value, one.as.where);
        r.cases.push_back(std::move(c));
    }
    r.checks.push_back(prove_exhaustive(st.name.value, r.cases, out_.symbols));
    cases_[s] = r.cases;
    resolved_.clear();
}

// Divides one equation by another side by side (Eq. 2's route); valid where the
// divisor is non-zero, which is recorded as the step's assumption.
void deriver::quotient(const spec::step& st, step_result& r)
{
    r.description = fmt::format("divide {} by {}", st.equations[0].value, st.equations[1].value);
    const equation& top = equation_at(st.equations[0]);
    const equation& bottom = equation_at(st.equations[1]);
    const GiNaC::ex a = resolve(top.relation);
    const GiNaC::ex b = resolve(bottom.relation);
    if (b.lhs().is_zero() || b.rhs().is_zero())
        throw error(st.where, fmt::format("equation '{}' has a side that is zero: division by zero", bottom.name));
    const GiNaC::ex lhs = simplified(a.lhs() / b.lhs(), declared_assumptions(out_.symbols, run_));
    const GiNaC::ex rhs = simplified(a.rhs() / b.rhs(), declared_assumptions(out_.symbols, run_));
    r.assumptions.push_back(b.lhs() != 0);
    add_step_equation(st.name, lhs == rhs, r);
}

// States an equation in a new form, proven equivalent to its source.
void deriver::rearrange(const spec::step& st, step_result& r)
{
    r.description = fmt::format("rearrange {} into {}", st.source.value, st.expression.value);
    const equation& from = equation_at(st.source);
    const GiNaC::ex into = out_.symbols.parse_equation(st.expression);
    check_result c;
    c.name = fmt::format("{} is equivalent to {}", st.name.value, from.name);
    c.statement = st.expression.value;
    c.stated = into;
    c.because = "the rearranged equation differs from its source by a non-zero constant factor";
    c.lhs = resolve(into);
    c.rhs = resolve(from.relation);
    c.outcome = prove_equivalent(c.lhs, c.rhs, out_.symbols, run_);
    c.where = st.expression.where;
    r.checks.push_back(c);
    add_step_equation(st.name, into, r, written(st.expression));
}

void deriver::add_step_equation(const spec::text& name, const GiNaC::ex& relation, step_result& r,
                            written_form as_written)
{
    if (find_equation(name.value))
        throw error(name.where, fmt::format("equation '{}' is defined twice", name.value));
    equation e{name.value, relation, r.description, "", name.where, std::move(as_written)};
    equations_.push_back(e);
    r.yields = e;
}

void deriver::add_result(const spec::result& spec_result)
{
    const quantity& q = out_.symbols.at(spec_result.name);
    if (const auto by_cases = cases_.find(q.symbol); by_cases != cases_.end()) {
        if (spec_result.display || spec_result.printed)
            throw error(spec_result.name.where, fmt::format("result '{}' is defined by cases: it has no single "
                                                            "'display' or 'printed' form",
                                                            spec_result.name.value));
        result r;
        r.name = q.name;
        r.symbol = q.symbol;
        r.value = q.symbol;
        r.display = q.symbol;
        r.paper = spec_result.paper ? spec_result.paper->value : std::string();
        r.cases = by_cases->second;
        out_.results.push_back(std::move(r));
        return;
    }
    const auto value = values_.find(q.symbol);
    if (value == values_.end())
        throw error(spec_result.name.where,
                    fmt::format("result '{}' is not derived by any step", spec_result.name.value));
    result r;
    r.name = q.name;
    r.symbol = q.symbol;
    r.value = value->second;
    r.display = r.value;
    r.paper = spec_result.paper ? spec_result.paper->value : std::string();
    std::vector<condition> needs = in_inputs(needs_[q.symbol]);
    const assumptions declared = declared_assumptions(out_.symbols, run_);
    if (spec_result.display) {
        r.display = out_.symbols.parse(*spec_result.display);
        r.written = written(*spec_result.display);
        check_value(out_.symbols, r.symbol, r.display, spec_result.display->where, "its display form");
        add_conditions(needs, needs_of(r.display, &r.written));
    }
    settled_conditions settled = settle(needs, declared);
    r.attached = settled.attached;
    r.defined = settled.proven;
    if (spec_result.display) {
        check_result c;
        c.name = fmt::format("display form of {}", q.name);
        c.display_of = q.name;
        c.statement = spec_result.display->value;
        c.stated = r.symbol == r.display;
        c.because = "the form typeset must equal the derived result";
        c.lhs = r.display;
        c.rhs = r.value;
        c.outcome = prove_equal(resolve(r.display), r.value, out_.symbols, run_, when_unproven::sample, r.attached);
        c.outcome.where = r.attached;
        c.outcome.defined = r.defined;
        c.where = spec_result.display->where;
        out_.checks.push_back(std::move(c));
    }
    if (spec_result.printed) {
        paper_comparison p;
        p.subject = q.name;
        p.paper = r.paper;
        p.printed_text = spec_result.printed->value;
        p.quote = spec_result.quote ? spec_result.quote->value : std::string();
        p.printed = out_.symbols.parse(*spec_result.printed);
        p.written = written(*spec_result.printed);
        p.derived = r.value;
        p.agreement = prove_equal(resolve(p.printed), r.value, out_.symbols, run_);
        if (!p.agrees())
            p.findings = reconcile_expression(p.printed, r.value, out_.symbols, resolver(), run_);
        add_dimension_finding(p);
        p.where = spec_result.printed->where;
        out_.paper_checks.push_back(std::move(p));
    }
    out_.results.push_back(std::move(r));
}

// A printed member of a line that disagrees, beside one of the same line that agrees:
// the factor where they part is the misprint, of the edits of equal size that reconcile
// it (Eq. 14's first line).
void deriver::locate_by_members()
{
    using kind = paper_comparison::kind;
    for (paper_comparison& p : out_.paper_checks) {
        if (p.what != kind::result || p.agrees() || !p.written.tree())
            continue;
        for (const paper_comparison& q : out_.paper_checks) {
            if (&q == &p || q.what != kind::result || q.paper != p.paper || !q.agrees() || !q.written.tree())
                continue;
            const auto found =
                locate_by_member(*p.written.tree(), *q.written.tree(), p.derived, out_.symbols, resolver(), run_);
            if (!found)
                continue;
            // The dimensions stay said first; the edits give way to the factor.
            std::vector<finding> kept;
            for (const finding& f : p.findings)
                if (std::any_of(f.parts.begin(), f.parts.end(),
                                [](const finding::part& part) { return part.what == finding::part::kind::dimension; }))
                    kept.push_back(f);
            kept.push_back(*found);
            p.findings = std::move(kept);
            p.reconciliations = plain_texts(p.findings, out_.symbols);
            break;
        }
    }
}

// A printed form of the wrong dimension says so first: it is often the clearest
// account of a misprint (a momentum where an energy belongs).
void deriver::add_dimension_finding(paper_comparison& p) const
{
    if (const auto found = printed_dimension_finding(out_.symbols, p.printed, p.derived))
        p.findings.insert(p.findings.begin(), *found);
    p.reconciliations = plain_texts(p.findings, out_.symbols);
}

} // namespace detail

derivation derive(const spec::derivation& source, const derived_by_id& done, proof_cache& run)
{
    return detail::deriver(source, done, run).run();
}

derivation derive(const spec::derivation& source, const derived_by_id& done)
{
    proof_cache own;
    return derive(source, done, own);
}

} // namespace impact::engine
