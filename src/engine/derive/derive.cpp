#include "engine/derive/derive.h"

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

namespace impact::engine {
namespace {

// The state of a derivation while its steps run.
class deriver {
public:
    deriver(const spec::derivation& source, const derived_by_id& done, proof_cache& run) : done_(done), run_(run)
    {
        out_.source = source;
    }

    derivation run()
    {
        const spec::derivation& s = out_.source;
        add_dimensions(out_.symbols, s.dimensions);
        for (const spec::symbol& declaration : s.symbols)
            out_.symbols.declare(declaration);
        check_definitions(out_.symbols, s, run_);
        check_assumptions_hold_together(out_.symbols, s, declared_assumptions(out_.symbols, run_));
        infer_definitions(out_.symbols, s);
        for (const spec::use& u : s.uses)
            import(u);
        for (const spec::given& g : s.givens)
            add_given(g);
        for (const spec::step& st : s.steps)
            run_step(st);
        // A fault found while putting values in (a diff by a quantity a later step derives)
        // is told at its place.
        for (const spec::result& r : s.results)
            try {
                add_result(r);
            } catch (...) {
                rethrow_at(r.name.where, fmt::format("result '{}'", r.name.value));
            }
        locate_by_members();
        for (const spec::check& c : s.checks)
            try {
                out_.checks.push_back(run_check(c));
            } catch (...) {
                rethrow_at(c.claim.where, fmt::format("check '{}'", c.name.value));
            }
        for (const spec::claim& c : s.claims)
            try {
                out_.paper_checks.push_back(hold_to_account(c));
            } catch (...) {
                rethrow_at(c.test.claim.where, fmt::format("claim '{}'", c.test.name.value));
            }
        find_swapped_values(out_.paper_checks);
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
            } catch (...) {
                rethrow_at(k.name.where, fmt::format("kernel '{}'", k.name.value));
            }
        return std::move(out_);
    }

private:
    // Replaces every derived quantity by its value and every abbreviation by its definition.
    GiNaC::ex resolve(const GiNaC::ex& e) const
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
    GiNaC::ex substituted(const GiNaC::ex& e, const GiNaC::exmap& abbreviations) const
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

    void set_value(const GiNaC::ex& symbol, const GiNaC::ex& value)
    {
        values_[symbol] = value;
        resolved_.clear();
    }

    // diff(f, x) as the file writes it: x an input (no step derives it, no abbreviation
    // stands for it), and f free of quantities defined by cases, which have no one value to
    // differentiate.
    void check_derivatives(const GiNaC::ex& e, const source_location& where) const
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
    void refuse_derivative(const GiNaC::ex& value, const spec::text& written, const char* where) const
    {
        if (has_derivative(value) || has_derivative(substituted(value, out_.symbols.abbreviations())))
            throw error(written.where, fmt::format("{} '{}' takes a derivative: diff(f, x) belongs in the claim, "
                                                   "not in a value put into it",
                                                   where, written.value));
    }

    // A derived quantity is not an input: its value follows from theirs, and a value put in
    // its place (`at`, `left_at`) would change nothing in the claim, whose sides are written
    // in the inputs.
    void refuse_derived_value(const GiNaC::ex& symbol, const spec::binding& b, const std::string& check,
                              const char* field) const
    {
        if (values_.count(symbol) || cases_.count(symbol))
            throw error(b.name.where, fmt::format("check '{}': {} gives '{}' a value, but a step derives it; "
                                                  "change the quantities it is derived from",
                                                  check, field, b.name.value));
    }

    engine::resolver resolver() const
    {
        return [this](const GiNaC::ex& e) { return resolve(e); };
    }

    GiNaC::ex symbol_of(const spec::text& name) const { return out_.symbols.at(name).symbol; }

    // How `text` is written, read here once for the printers, which never read the file.
    written_form written(const spec::text& text) const
    {
        return written_form::read(text.value,
                                  [this](const std::string& piece) { return out_.symbols.parse({piece, {}}); });
    }

    // `[[use]]`: results of an earlier derivation, expressed in this one's symbols.
    void import(const spec::use& u)
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
        }
    }

    void add_given(const spec::given& g)
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

    const equation* find_equation(const std::string& name) const
    {
        for (const equation& e : equations_)
            if (e.name == name)
                return &e;
        return nullptr;
    }

    const equation& equation_at(const spec::text& name) const
    {
        if (const equation* e = find_equation(name.value))
            return *e;
        throw error(name.where, fmt::format("no equation named '{}' (neither given nor made by a step)", name.value));
    }

    void run_step(const spec::step& st)
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
            infer_definitions(out_.symbols, out_.source);   // abbreviations of what is now known
        } catch (...) {
            rethrow_at(st.where, fmt::format("step {} ({})", out_.steps.size() + 1, r.description));
        }
        out_.steps.push_back(std::move(r));
    }

    // Solves equations for unknowns (engine/solve/solve.h); every solution is substituted back.
    void solve(const spec::step& st, step_result& r)
    {
        const solve_context context{out_.symbols, run_, resolver(),
                                    [this](const spec::text& name) -> const equation& { return equation_at(name); },
                                    values_};
        for (const auto& [symbol, value] : solve_equations(st, context, r))
            set_value(symbol, value);
    }

    void define(const spec::step& st, step_result& r)
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
        set_value(s, value);
        r.values.emplace_back(s, value);
    }

    // A value by cases: each condition an inequality and each value of the quantity's
    // dimension; the quantity keeps no single value (it stays a symbol in what uses it,
    // and a check on it is proven case by case), and the cases are proven to cover every value.
    void define_by_cases(const spec::step& st, const GiNaC::ex& s, step_result& r)
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
    void quotient(const spec::step& st, step_result& r)
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
    void rearrange(const spec::step& st, step_result& r)
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

    void add_step_equation(const spec::text& name, const GiNaC::ex& relation, step_result& r,
                           written_form as_written = {})
    {
        if (find_equation(name.value))
            throw error(name.where, fmt::format("equation '{}' is defined twice", name.value));
        equation e{name.value, relation, r.description, "", name.where, std::move(as_written)};
        equations_.push_back(e);
        r.yields = e;
    }

    void add_result(const spec::result& spec_result)
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
        if (spec_result.display) {
            r.display = out_.symbols.parse(*spec_result.display);
            r.written = written(*spec_result.display);
            check_value(out_.symbols, r.symbol, r.display, spec_result.display->where, "its display form");
            check_result c;
            c.name = fmt::format("display form of {}", q.name);
            c.display_of = q.name;
            c.statement = spec_result.display->value;
            c.stated = r.symbol == r.display;
            c.because = "the form typeset must equal the derived result";
            c.lhs = r.display;
            c.rhs = r.value;
            c.outcome = prove_equal(resolve(r.display), r.value, out_.symbols, run_);
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
    void locate_by_members()
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
    void add_dimension_finding(paper_comparison& p) const
    {
        if (const auto found = printed_dimension_finding(out_.symbols, p.printed, p.derived))
            p.findings.insert(p.findings.begin(), *found);
        p.reconciliations = plain_texts(p.findings, out_.symbols);
    }

    // `paper_claim`: the claim transcribes the paper's text, whose dimensions are a finding
    // (hold_to_account), not the file's mistake.
    check_result run_check(const spec::check& spec_check, bool paper_claim = false)
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
                return c;
            }
            prove_case_by_case(c, *split, at, out_.symbols, given, run_);
            return c;
        }
        if (spec_check.limit) {
            c.limit = limit_point_of(*spec_check.limit);
            if (c.op != relation::equal)
                throw error(spec_check.limit->written.where, "a limit check claims an equality: lim lhs = rhs");
            c.outcome = check_limit(lhs, rhs, *c.limit, given, c.value, c.limit_by);
            c.statement += fmt::format(" in the limit {}", spec_check.limit->written.value);
        } else if (c.op == relation::equal) {
            c.outcome = prove_equal(lhs, rhs, out_.symbols, run_);
            c.value = lhs;
        } else if (auto through = prove_inequality_through(lhs, c.op, rhs, proven_identities(), out_.symbols, given)) {
            c.outcome = std::move(*through);
        } else {
            c.outcome = prove_inequality(lhs, c.op, rhs, out_.symbols, given);
            // Samples drawn at random miss where a claim fails on a thin set (dE < 0 fails
            // where v_M = v_m): an inequality left sampled is tried at the domains' simple
            // values too, and fails at the first point found, decided exactly.
            if (c.outcome.what == verdict::status::sampled)
                if (auto point = find_counterexample(lhs, c.op, rhs, out_.symbols, given); point && point->exact) {
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
        return c;
    }

    // The equalities proven so far, without special values or changed domains: what an
    // inequality may be proven through.
    std::vector<proven_identity> proven_identities() const
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
    static error different_conditions(const source_location& where, const std::string& one, const std::string& other)
    {
        return error(where, fmt::format("the check uses '{}' and '{}', both defined by cases with different conditions: "
                                        "a check may split on the cases of quantities whose conditions are the same",
                                        one, other));
    }

    // The quantities defined by cases that a check's sides use, if any: one, or several
    // whose cases have the same conditions (split together, case by case).
    std::optional<case_split> cases_in(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const source_location& where) const
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
    assumptions assumptions_of(const spec::check& spec_check) const
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
    check_result run_continuity(const spec::check& spec_check)
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

    // A claim of the paper's text, tested as a check. When it fails, the same claim is
    // tried at the other notable points of its limit or special value (the ends of the
    // domain, 0 and infinity): a claim made for the wrong regime is reported as such.
    paper_comparison hold_to_account(const spec::claim& claim)
    {
        paper_comparison p;
        p.what = paper_comparison::kind::claim;
        p.subject = claim.test.name.value;
        p.paper = claim.paper.value;
        p.printed_text = claim.quote.value;
        p.where = claim.test.claim.where;
        p.label = claim.label ? claim.label->value : "";
        check_result c = run_check(claim.test, true);
        p.printed = c.stated;
        p.derived = c.value ? *c.value : c.lhs;
        p.agreement = c.outcome;
        if (!claim.holds) {
            said_not_to_hold(p, claim.test, c);
            p.test = std::move(c);
            return p;
        }
        if (!p.agrees() && c.value && (claim.test.limit || !claim.test.at.empty()))
            p.findings = other_regimes(claim.test, c);
        else if (!p.agrees() && c.op == relation::equal) {
            p.findings = reconcile_expression(c.stated.rhs(), c.lhs, out_.symbols, resolver(), run_);
            if (auto found = complement_holds(c)) {
                // Either mends it: the edits of the printed side are said as the alternatives
                // (the second and later already are, to each other).
                if (!p.findings.empty())
                    p.findings.front().parts.insert(p.findings.front().parts.begin(),
                                                    {finding::part::kind::words, "or ", {}, {}, {}});
                p.findings.insert(p.findings.begin(), *found);
            }
        }
        if (p.agreement.what == verdict::status::failed && p.findings.empty() && c.parts.empty() && !c.limit)
            p.findings = what_holds_instead(claim.test, c);
        if (!p.agrees() && claim.mended)
            p.findings.insert(p.findings.begin(), mended_finding(claim));
        if (const auto found = printed_dimension_finding(out_.symbols, p.printed, p.printed))
            p.findings.insert(p.findings.begin(), *found);
        p.reconciliations = plain_texts(p.findings, out_.symbols);
        p.test = std::move(c);
        return p;
    }

    // The claim as the file mends the words (`mended`: "final" for "incident"), proven as the
    // claim is (its special values, limit, assumptions): said first when it holds. A mended
    // claim that does not hold is the file's mistake.
    finding mended_finding(const spec::claim& claim)
    {
        spec::check mended = claim.test;
        mended.claim = *claim.mended;
        mended.name.value += " (mended)";
        const check_result c = run_check(mended, true);
        if (c.outcome.what != verdict::status::proven)
            throw error(claim.mended->where,
                        fmt::format("claim '{}': the mended claim does not hold ({}): mend the words so that it does",
                                    claim.test.name.value, to_string(c.outcome)));
        return finding().say("mended, it holds: ").states(c.stated.lhs(), c.op, c.stated.rhs());
    }

    // A claim the paper says does not hold (`holds = false`, Footnote 11's "the contrapositive
    // does not hold"): it agrees when a point of the domains is found where it fails, decided
    // exactly (a counterexample), disagrees when it is proven, and is undecided otherwise.
    void said_not_to_hold(paper_comparison& p, const spec::check& spec_check, check_result& c)
    {
        c.said_false = true;
        p.findings.clear();
        switch (c.outcome.what) {
        case verdict::status::proven:
            p.agreement = verdict{};
            p.agreement.residual = c.outcome.residual;
            p.agreement.method = "it holds, where the paper says it does not: " + c.outcome.method;
            p.findings = {c.outcome.how == verdict::basis::zero_difference
                              ? finding().say("it holds, where the paper says it does not: the difference of its "
                                              "sides simplifies to ").math(GiNaC::ex(0))
                          : c.outcome.how == verdict::basis::signs && !GiNaC::is_a<GiNaC::numeric>(c.outcome.residual)
                              ? finding().say("it holds, where the paper says it does not: the sign of each factor "
                                              "of ").math(c.outcome.residual).say(" follows from the domains")
                              : finding().say("it holds, where the paper says it does not")};
            break;
        case verdict::status::sampled: break;   // undecided, as sampled
        case verdict::status::failed:
            if (c.parts.empty())
                c.fails_at = find_counterexample(c.lhs, c.op, c.rhs, out_.symbols, assumptions_of(spec_check));
            p.agreement = verdict{};
            p.agreement.residual = c.outcome.residual;
            if (c.fails_at) {
                p.agreement.what = verdict::status::proven;
                p.agreement.how = verdict::basis::counterexample;
                p.agreement.method = "refuted at a point of the domains";
            } else {
                // Not refuted at a point: undecided, with nothing sampled that held.
                p.agreement.what = verdict::status::sampled;
                p.agreement.method = c.parts.empty() ? "no point of the domains was found where it fails"
                                                     : "split by cases: no point is searched for";
            }
            break;
        }
        p.reconciliations = plain_texts(p.findings, out_.symbols);
    }

    // A share said of its complement: the text calls tau the transferred share, where Eq. 12
    // defines the share the cue ball keeps. A claim `x = rhs` about a quantity x that holds
    // with 1 - x for x.
    std::optional<finding> complement_holds(const check_result& failed)
    {
        const GiNaC::ex left = failed.stated.lhs();
        if (!GiNaC::is_a<GiNaC::symbol>(left) || (failed.lhs - left).is_zero() || !failed.at.empty() ||
            !failed.left_at.empty() || failed.limit || GiNaC::is_a<GiNaC::numeric>(failed.lhs) ||
            GiNaC::is_a<GiNaC::numeric>(failed.rhs))
            return std::nullopt;   // a number and its complement say nothing of shares
        try {
            if (prove_equal(1 - failed.lhs, failed.rhs, out_.symbols, run_, when_unproven::give_up).what !=
                verdict::status::proven)
                return std::nullopt;
        } catch (const error&) {
            throw;
        } catch (const std::exception&) {
            return std::nullopt;   // arithmetic it cannot do says nothing of shares
        }
        return finding().say("it holds with ").math(1 - left).say(" for ").math(left);
    }

    // A failed claim without a finding: the relation reversed (a > b where a < b holds:
    // "increasing" for decreasing values), else the derived value of the quantity on its
    // left (an object ball's incident speed, 0); or, for an equation, a function of its
    // left side that the right side is (the cosine of an angle printed as the angle).
    std::vector<finding> what_holds_instead(const spec::check& original, const check_result& failed)
    {
        // Said of the claim as written: not of one at special values or changed inputs.
        if (!failed.at.empty() || !failed.left_at.empty())
            return {};
        // A search that meets arithmetic it cannot do (tan at a pole) finds nothing; it never
        // stops the derivation.
        try {
            return what_holds_instead_search(original, failed);
        } catch (const error&) {
            throw;
        } catch (const std::exception&) {
            return {};
        }
    }

    std::vector<finding> what_holds_instead_search(const spec::check& original, const check_result& failed)
    {
        const GiNaC::ex left = failed.stated.lhs();
        if (failed.op != relation::equal) {
            static const std::map<relation, relation> mirrored = {{relation::less, relation::greater},
                                                                  {relation::less_equal, relation::greater_equal},
                                                                  {relation::greater, relation::less},
                                                                  {relation::greater_equal, relation::less_equal}};
            const relation reversed = mirrored.at(failed.op);
            if (prove_inequality_by_signs(failed.lhs, reversed, failed.rhs, out_.symbols, assumptions_of(original)))
                return {finding().say("the reverse holds: ").states(left, reversed, failed.stated.rhs())};
            // Neither way round: what a derived quantity on the left comes to.
            if (GiNaC::is_a<GiNaC::symbol>(left) && !(failed.lhs - left).is_zero())
                return {finding().say("derived, ").states(left, relation::equal, failed.lhs)};
            return {};
        }
        // Bars that do not belong: the change of a magnitude, |v'| - |v|, printed where the
        // change of the quantity itself is meant (Eq. 10's Delta|v_Delta|).
        if (failed.stated.has(GiNaC::abs(GiNaC::wild(0)))) {
            struct unbarred : GiNaC::map_function {
                std::vector<GiNaC::ex> inside;   // what the bars held, in the order met
                GiNaC::ex operator()(const GiNaC::ex& e) override
                {
                    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
                        inside.push_back(e.op(0));
                        return (*this)(e.op(0));
                    }
                    return e.map(*this);
                }
            } strip;
            const GiNaC::ex l = strip(failed.stated.lhs()), r = strip(failed.stated.rhs());
            if (prove_equal(resolve(l), resolve(r), out_.symbols, run_, when_unproven::give_up).what ==
                verdict::status::proven) {
                // In the order of the derivation's symbols (GiNaC's order of a sum's terms
                // follows its hashes), each once.
                const term_order order = declaration_order(out_.symbols);
                std::sort(strip.inside.begin(), strip.inside.end(),
                          [&](const GiNaC::ex& a, const GiNaC::ex& b) { return order.before(a, b); });
                strip.inside.erase(std::unique(strip.inside.begin(), strip.inside.end(),
                                               [](const GiNaC::ex& a, const GiNaC::ex& b) { return a.is_equal(b); }),
                                   strip.inside.end());
                finding f;
                f.say("it holds without the absolute values around ");
                for (std::size_t i = 0; i < strip.inside.size(); ++i) {
                    if (i > 0)
                        f.say(i + 1 == strip.inside.size() ? " and " : ", ");
                    f.math(strip.inside[i]);
                }
                return {f};
            }
        }
        // An angle (derived as an arccosine, arcsine or arctangent) set equal to its cosine,
        // sine or tangent.
        if (!GiNaC::is_a<GiNaC::symbol>(left) || !GiNaC::is_a<GiNaC::function>(failed.lhs))
            return where_it_holds(original, failed);
        const std::string inverse = GiNaC::ex_to<GiNaC::function>(failed.lhs).get_name();
        const std::map<std::string, std::pair<GiNaC::ex (*)(const GiNaC::ex&), const char*>> of = {
            {"acos", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::cos(x); }, "cosine"}},
            {"asin", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::sin(x); }, "sine"}},
            {"atan", {[](const GiNaC::ex& x) -> GiNaC::ex { return GiNaC::tan(x); }, "tangent"}}};
        const auto function = of.find(inverse);
        if (function == of.end())
            return {};
        const auto [apply, name] = function->second;
        if (prove_equal(apply(failed.lhs), failed.rhs, out_.symbols, run_).what != verdict::status::proven)
            return {};
        return {finding()
                    .say("it holds with ")
                    .math(apply(left))
                    .say(" for ")
                    .math(left)
                    .say(fmt::format(": the right side is the {} of ", name))
                    .math(left)};
    }

    // An equation that holds only where a factor of the difference of its sides vanishes:
    // the changes of velocity of Sec. II A are equal and opposite only for M = m (and
    // where nothing collides, v_M = v_m). Each factor the domains do not prove non-zero
    // must be linear in at most two symbols with numbers for coefficients (M - m, M + m,
    // M - 2), said as an equation in the first declared; one that is not leaves nothing to
    // say, since "only where" would be untrue.
    std::vector<finding> where_it_holds(const spec::check& original, const check_result& failed)
    {
        const GiNaC::ex difference = GiNaC::normal(out_.symbols.in_inputs(failed.lhs - failed.rhs));
        if (difference.is_zero() || has_radical(difference) || !difference.info(GiNaC::info_flags::rational_function))
            return {};
        const GiNaC::ex numerator = factor_polynomial(GiNaC::numer(difference), run_);
        const assumptions given = assumptions_of(original);
        std::vector<GiNaC::ex> factors;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(numerator) ? std::vector<GiNaC::ex>(numerator.begin(), numerator.end())
                                                                      : std::vector<GiNaC::ex>{numerator})
            factors.push_back(GiNaC::is_a<GiNaC::power>(f) ? f.op(0) : f);
        // The declared symbols in declaration order: the first one a factor names is set
        // on the left (M = m, as the file declares M first).
        // Each place with the declaration rank of its left side, to be said in that order
        // (GiNaC's order of factors follows its hashes, which a build may change).
        std::vector<std::pair<std::size_t, GiNaC::ex>> places;
        std::size_t other = 0;   // places that are not a symbol solved for
        const auto rank = [&](const GiNaC::ex& symbol) {
            const auto& all = out_.symbols.all();
            return static_cast<std::size_t>(std::find_if(all.begin(), all.end(), [&](const quantity& q) {
                                                return q.symbol.is_equal(symbol);
                                            }) - all.begin());
        };
        for (const GiNaC::ex& f : factors) {
            if (GiNaC::is_a<GiNaC::numeric>(f) || !prove_sign(f, given).sign.zero)
                continue;   // never zero under the domains
            std::vector<GiNaC::ex> in;
            for (const quantity& q : out_.symbols.all())
                if (f.has(q.symbol))
                    in.push_back(q.symbol);
            if (in.empty())
                return {};
            // Linear in one or two symbols, with numbers for coefficients: the first symbol
            // solved for (M = m, v_M = v_m).
            const GiNaC::ex a = f.coeff(in.front(), 1);
            const bool linear = in.size() <= 2 && f.degree(in.front()) == 1 && GiNaC::is_a<GiNaC::numeric>(a) &&
                                (in.size() == 1 || (f.degree(in.back()) == 1 &&
                                                    GiNaC::is_a<GiNaC::numeric>(f.coeff(in.back(), 1))));
            const GiNaC::ex rest = linear ? GiNaC::expand(f - a * in.front()) : GiNaC::ex(0);
            if (linear && (in.size() == 1 || (rest - rest.coeff(in.back(), 1) * in.back()).is_zero())) {
                places.emplace_back(rank(in.front()), in.front() == GiNaC::normal(-rest / a));
                continue;
            }
            // Any other factor, when short and of degree 1 in each of its symbols: two terms
            // set equal (r_x v_My = r_y v_Mx, the first with its sign), else the factor,
            // collected, set to 0.
            const GiNaC::ex e = GiNaC::expand(f);
            if (!GiNaC::is_a<GiNaC::add>(e) || e.nops() > 6 ||
                std::any_of(in.begin(), in.end(), [&](const GiNaC::ex& x) { return e.degree(x) != 1; }))
                return {};
            places.emplace_back(rank(in.front()), vanishes(e));
            ++other;
        }
        // One such factor alone restates the claim: nothing to say.
        if (places.empty() || (places.size() == 1 && other == 1))
            return {};
        const term_order order = declaration_order(out_.symbols);
        std::sort(places.begin(), places.end(), [&](const auto& x, const auto& y) {
            if (x.first != y.first)
                return x.first < y.first;
            if (!x.second.rhs().is_equal(y.second.rhs()))
                return order.before(x.second.rhs(), y.second.rhs());
            // Two set to 0: by their written form, the same in every build.
            return ginac_syntax(x.second.lhs(), out_.symbols.order()) < ginac_syntax(y.second.lhs(), out_.symbols.order());
        });
        finding said;
        said.say("it holds only where ");
        for (std::size_t i = 0; i < places.size(); ++i) {
            if (i > 0)
                said.say(i + 1 == places.size() ? " or " : ", ");
            said.math(places[i].second);
        }
        GiNaC::ex shown = 1;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(numerator) ? std::vector<GiNaC::ex>(numerator.begin(), numerator.end())
                                                                      : std::vector<GiNaC::ex>{numerator})
            shown *= GiNaC::is_a<GiNaC::power>(f) ? GiNaC::pow(collected(f.op(0)), f.op(1)) : collected(f);
        // The difference itself when it is short enough to read in a line of text.
        const GiNaC::ex whole = shown / GiNaC::denom(difference);
        std::size_t occurrences = 0;
        for (GiNaC::const_preorder_iterator it = whole.preorder_begin(); it != whole.preorder_end(); ++it)
            occurrences += GiNaC::is_a<GiNaC::symbol>(*it) ? 1 : 0;
        if (occurrences > 12)
            return {said};
        return {said.say(": the difference of its sides is ").math(whole)};
    }

    // `sum = 0` as said: its first term (by the declaration ranks of its symbols) with a
    // positive sign; two terms set equal (r_x v_My = r_y v_Mx), more collected.
    GiNaC::ex vanishes(const GiNaC::ex& sum) const
    {
        const auto& all = out_.symbols.all();
        GiNaC::exmap ones;
        const auto key = [&](const GiNaC::ex& term) {
            std::vector<std::size_t> ranks;
            for (std::size_t i = 0; i < all.size(); ++i)
                if (term.has(all[i].symbol))
                    ranks.push_back(i);
            return ranks;
        };
        for (const quantity& q : all)
            ones[q.symbol] = 1;
        std::vector<GiNaC::ex> terms(sum.begin(), sum.end());
        std::stable_sort(terms.begin(), terms.end(),
                         [&](const GiNaC::ex& a, const GiNaC::ex& b) { return key(a) < key(b); });
        const GiNaC::ex lead = terms.front().subs(ones, GiNaC::subs_options::no_pattern);
        const bool negative = GiNaC::is_a<GiNaC::numeric>(lead) && GiNaC::ex_to<GiNaC::numeric>(lead).is_negative();
        const GiNaC::ex e = negative ? GiNaC::expand(-sum) : sum;
        if (terms.size() == 2) {
            const GiNaC::ex first = negative ? -terms.front() : terms.front();
            return first == first - e;
        }
        return collected(e) == 0;
    }

    // A sum collected by the declared symbols, taken in declaration order, that each stand
    // to the first power in two or more of its terms not yet covered, when together they
    // cover every term: r_x (v_Mx - v_mx) + r_y (v_My - v_my). The sum as it was otherwise.
    GiNaC::ex collected(const GiNaC::ex& sum) const
    {
        const GiNaC::ex e = GiNaC::expand(sum);
        if (!GiNaC::is_a<GiNaC::add>(e) || e.nops() < 3)
            return sum;
        std::vector<bool> covered(e.nops(), false);
        GiNaC::lst by;
        for (const quantity& q : out_.symbols.all()) {
            std::vector<std::size_t> terms;
            for (std::size_t i = 0; i < e.nops(); ++i)
                if (!covered[i] && e.op(i).has(q.symbol) && e.op(i).degree(q.symbol) == 1)
                    terms.push_back(i);
            if (terms.size() < 2)
                continue;
            by.append(q.symbol);
            for (const std::size_t i : terms)
                covered[i] = true;
        }
        if (std::find(covered.begin(), covered.end(), false) != covered.end())
            return sum;
        return GiNaC::collect(e, by);
    }

    std::vector<finding> other_regimes(const spec::check& original, const check_result& failed)
    {
        std::vector<finding> found;
        const spec::text* symbol = nullptr;
        const spec::text* point = nullptr;
        if (original.limit) {
            symbol = &original.limit->symbol;
            point = &original.limit->written;
        } else if (original.at.size() == 1) {
            symbol = &original.at.front().name;
            point = &original.at.front().expression;
        }
        if (symbol) {
            const quantity& q = out_.symbols.at(*symbol);
            std::vector<std::string> candidates = {"0", "infinity"};
            if (q.range.what == domain::kind::interval)
                candidates = {fmt::format("{}", q.range.lower), fmt::format("{}", q.range.upper)};
            for (const std::string& other : candidates) {
                const bool infinity = other == "infinity";
                const bool same = original.limit ? original.limit->to_infinity == infinity &&
                                                       (infinity || original.limit->point.value == other)
                                                 : other == original.at.front().expression.value;
                if (same)
                    continue;
                spec::check moved = original;
                moved.at.clear();
                moved.limit = spec::limit_point{{symbol->value + " -> " + other, point->where},
                                          {symbol->value, point->where},
                                          {infinity ? "" : other, point->where},
                                          infinity};
                try {
                    if (run_check(moved).outcome.what == verdict::status::proven)
                        found.push_back(finding()
                                            .say("it holds for ")
                                            .tends(q.symbol, infinity ? std::nullopt
                                                                      : std::optional<GiNaC::ex>(out_.symbols.parse(
                                                                            spec::text{other, point->where})))
                                            .say(" instead"));
                } catch (const error&) {
                }
            }
        }
        // A regime where it holds is the one change that mends it; the derived value only when
        // none is found.
        if (found.empty())
            found.push_back(
                finding().say("the derived value is ").math(*failed.value).say(", not ").math(failed.rhs));
        return found;
    }

    // Two claims of one quote, each a limit (or a value at one point) of the same quantity,
    // as the file states it, at its own point of the same symbol, under the same assumptions,
    // that both fail, each stating the value the other derives: one misprint, the values
    // swapped (Sec. III C's "90°" and "0°"), told once for both in place of where each holds
    // instead (a dimensional finding or the claim mended are kept before it).
    void find_swapped_values(std::vector<paper_comparison>& claims) const
    {
        struct regime {
            GiNaC::ex symbol;
            std::optional<GiNaC::ex> point;   // none: infinity
            bool limit = false;
        };
        const auto regime_of = [](const check_result& c) -> std::optional<regime> {
            if (c.limit && c.at.empty())
                return regime{c.limit->symbol, c.limit->to_infinity ? std::nullopt : std::optional(c.limit->point), true};
            if (!c.limit && c.at.size() == 1)
                return regime{c.at.front().first, c.at.front().second, false};
            return std::nullopt;
        };
        const auto same = [](const GiNaC::ex& a, const GiNaC::ex& b) { return (a - b).normal().is_zero(); };
        const auto same_assumptions = [](const check_result& a, const check_result& b) {
            return a.assuming.size() == b.assuming.size() &&
                   std::equal(a.assuming.begin(), a.assuming.end(), b.assuming.begin(), [](const auto& x, const auto& y) {
                       return x.first.is_equal(y.first) && x.second == y.second;
                   });
        };
        const auto candidate = [](const paper_comparison& p) {
            return p.agreement.what == verdict::status::failed && p.test && !p.test->said_false &&
                   p.test->op == relation::equal && p.test->value && p.test->left_at.empty() && p.test->parts.empty();
        };
        const auto kept = [](const finding& f) {   // said before the change: not where it holds
            return std::any_of(f.parts.begin(), f.parts.end(),
                               [](const finding::part& part) { return part.what == finding::part::kind::dimension; }) ||
                   (!f.parts.empty() && f.parts.front().words.rfind("mended", 0) == 0);
        };
        for (std::size_t i = 0; i < claims.size(); ++i)
            for (std::size_t j = i + 1; j < claims.size(); ++j) {
                paper_comparison& a = claims[i];
                paper_comparison& b = claims[j];
                if (a.paper != b.paper || a.printed_text != b.printed_text || !candidate(a) || !candidate(b) ||
                    !same_assumptions(*a.test, *b.test))
                    continue;
                const auto at_a = regime_of(*a.test);
                const auto at_b = regime_of(*b.test);
                if (!at_a || !at_b || at_a->limit != at_b->limit || !at_a->symbol.is_equal(at_b->symbol) ||
                    !same(a.test->stated.lhs(), b.test->stated.lhs()) || same(a.test->rhs, b.test->rhs) ||
                    !same(a.test->rhs, *b.test->value) || !same(b.test->rhs, *a.test->value))
                    continue;
                const auto where = [](finding& f, const regime& r) -> finding& {
                    return r.limit ? f.say(" for ").tends(r.symbol, r.point) : f.say(" at ").math(r.symbol == *r.point);
                };
                finding swapped = finding().say("the values are swapped: ").math(a.test->stated.lhs()).say(" is ");
                where(swapped.math(*a.test->value), *at_a).say(" and ");
                where(swapped.math(*b.test->value), *at_b);
                for (paper_comparison* p : {&a, &b}) {
                    std::vector<finding> found;
                    std::copy_if(p->findings.begin(), p->findings.end(), std::back_inserter(found), kept);
                    found.push_back(swapped);
                    p->findings = std::move(found);
                    p->reconciliations = plain_texts(p->findings, out_.symbols);
                }
            }
    }

    // The limit's symbol and point (an expression, or infinity), inside the symbol's domain.
    check_result::limit_point limit_point_of(const spec::limit_point& l) const
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
    void approach_numerically(const GiNaC::ex& difference, const check_result::limit_point& p,
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

    verdict check_limit(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const check_result::limit_point& p,
                        const assumptions& given, std::optional<GiNaC::ex>& value,
                        std::optional<limit_method>& how) const
    {
        const GiNaC::exmap abbreviations = out_.symbols.abbreviations();
        const auto found = limit(lhs.subs(abbreviations), p.symbol, p.point, p.to_infinity, given);
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

    const derived_by_id& done_;
    proof_cache& run_;
    derivation out_;
    std::vector<equation> equations_;
    GiNaC::exmap values_;
    std::map<GiNaC::ex, std::vector<case_value>, GiNaC::ex_is_less> cases_;   ///< quantities defined by cases
    mutable std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> resolved_;
    std::map<std::string, std::string> imported_;   ///< the names [[use]]s gave, and the results they name
};

} // namespace

derivation derive(const spec::derivation& source, const derived_by_id& done, proof_cache& run)
{
    return deriver(source, done, run).run();
}

derivation derive(const spec::derivation& source, const derived_by_id& done)
{
    proof_cache own;
    return derive(source, done, own);
}

} // namespace impact::engine
