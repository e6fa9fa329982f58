#include "verify/proofs.h"

#include "cache/store.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

namespace impact::verify {

using engine::check_result;

namespace {

// Quantities no problem may take as free: those the derivation's steps derive (their
// values are put into every check) and those defined by cases (put in case by case).
std::set<std::string> derived_names(const engine::derivation& d)
{
    std::set<std::string> names;
    for (const engine::step_result& s : d.steps) {
        for (const auto& [symbol, value] : s.values)
            if (GiNaC::is_a<GiNaC::symbol>(symbol))
                names.insert(GiNaC::ex_to<GiNaC::symbol>(symbol).get_name());
        if (!s.cases.empty() && GiNaC::is_a<GiNaC::symbol>(s.cases_of))
            names.insert(GiNaC::ex_to<GiNaC::symbol>(s.cases_of).get_name());
    }
    return names;
}

// What the derivation derives, by symbol: each step's values and each result's imported
// from another derivation (`[[use]]`, its symbols matched by name), which a display form or
// the paper's printing may still name (vMp, the velocity after, in eq11).
GiNaC::exmap derived_values(const engine::derivation& d, const engine::derived_by_id& done)
{
    GiNaC::exmap values;
    for (const spec::use& u : d.source.uses) {
        const auto other = done.find(u.derivation.value);
        if (other == done.end())
            continue;
        for (const spec::binding& b : u.results) {
            const engine::result* r = other->second.find_result(b.expression.value);
            const engine::quantity* local = d.symbols.find(b.name.value);
            if (!r || !local)
                continue;
            GiNaC::exmap rename;
            for (const engine::quantity& q : other->second.symbols.all())
                if (const engine::quantity* mine = d.symbols.find(q.name))
                    rename[q.symbol] = mine->symbol;
            values[local->symbol] = r->value.subs(rename, GiNaC::subs_options::no_pattern);
        }
    }
    for (const engine::step_result& s : d.steps)
        for (const auto& [symbol, value] : s.values)
            values[symbol] = value;
    return values;
}

// `e` with the derived quantities put in, until none is left (a value may name another).
GiNaC::ex resolved(const GiNaC::ex& e, const GiNaC::exmap& values)
{
    GiNaC::ex out = e;
    for (int i = 0; i < 8 && !values.empty(); ++i) {
        const GiNaC::ex next = out.subs(values, GiNaC::subs_options::no_pattern);
        if (next.is_equal(out))
            break;
        out = next;
    }
    return out;
}

// The cases of the quantity called `name`, from the step that defines it.
const std::vector<engine::case_value>* cases_named(const engine::derivation& d, const std::string& name)
{
    for (const engine::step_result& s : d.steps)
        if (!s.cases.empty() && GiNaC::is_a<GiNaC::symbol>(s.cases_of) &&
            GiNaC::ex_to<GiNaC::symbol>(s.cases_of).get_name() == name)
            return &s.cases;
    return nullptr;
}

smt_claim base_claim(const check_result& c, const engine::verdict& v, const std::set<std::string>& derived,
                     const GiNaC::exmap& values)
{
    smt_claim claim;
    claim.lhs = resolved(c.lhs, values);
    claim.op = c.op;
    claim.rhs = resolved(c.rhs, values);
    claim.assuming = c.assuming;
    claim.where = c.outcome.where;
    claim.goals = c.outcome.defined;
    // A part's own conditions beside the check's.
    if (&v != &c.outcome) {
        claim.where.insert(claim.where.end(), v.where.begin(), v.where.end());
        claim.goals.insert(claim.goals.end(), v.defined.begin(), v.defined.end());
    }
    claim.derived = derived;
    return claim;
}

proof_problem not_expressible(std::string part, const std::string& why)
{
    proof_problem p;
    p.part = std::move(part);
    p.smt.not_expressible = "not expressible: " + why;
    return p;
}

// The problems of one proven check.
std::vector<proof_problem> problems_of(const engine::derivation& d, const check_result& c,
                                       const std::set<std::string>& derived, const GiNaC::exmap& values)
{
    std::vector<proof_problem> out;
    const auto written = [&](proof_problem p) {
        p.smt = smt_problem_of(p.claim, d.symbols);
        out.push_back(std::move(p));
    };
    if (c.limit)
        return {not_expressible("", "a limit")};
    if (c.continuity) {
        // Where two cases meet (symbol = value there), their values agree.
        const std::vector<engine::case_value>* cases = cases_named(d, c.cases_of);
        for (const check_result::part& part : c.parts) {
            if (!cases || !part.boundary || part.first == 0 || part.second == 0 || part.first > cases->size() ||
                part.second > cases->size()) {
                out.push_back(not_expressible(part.under, "continuity where square roots are named"));
                continue;
            }
            proof_problem p;
            p.part = part.under;
            p.claim = base_claim(c, part.outcome, derived, values);
            const GiNaC::exmap at{{part.boundary->first, part.boundary->second}};
            p.claim.lhs = (*cases)[part.first - 1].value.subs(at, GiNaC::subs_options::no_pattern);
            p.claim.op = engine::relation::equal;
            p.claim.rhs = (*cases)[part.second - 1].value.subs(at, GiNaC::subs_options::no_pattern);
            written(std::move(p));
        }
        return out;
    }
    if (!c.parts.empty() && !c.cases_of.empty()) {
        // Case by case: the case's values put in, its condition assumed.
        for (const check_result::part& part : c.parts) {
            if (!part.in_case) {
                out.push_back(not_expressible(part.under, "a part with no case"));
                continue;
            }
            GiNaC::exmap in_case;
            if (!part.in_cases.empty()) {
                for (const auto& [symbol, one] : part.in_cases)
                    in_case[symbol] = one.value;
            } else if (const engine::quantity* q = d.symbols.find(c.cases_of)) {
                in_case[q->symbol] = part.in_case->value;
            } else {
                out.push_back(not_expressible(part.under, "the cases of " + c.cases_of));
                continue;
            }
            proof_problem p;
            p.part = part.under;
            p.claim = base_claim(c, part.outcome, derived, values);
            // A symmetry's copy of the quantity (left_at: the same name, other inputs) is in the
            // same case: its value there at the changed inputs.
            GiNaC::exmap moved, at;
            for (const auto& [symbol, value] : c.left_at)
                moved[symbol] = value;
            for (const auto& [symbol, value] : c.at)
                at[symbol] = value;
            for (GiNaC::const_preorder_iterator it = c.lhs.preorder_begin(); it != c.lhs.preorder_end(); ++it)
                if (GiNaC::is_a<GiNaC::symbol>(*it) && !in_case.count(*it) && !d.symbols.domain_of(*it))
                    if (const auto* cases = cases_named(d, GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
                        cases && part.first >= 1 && part.first <= cases->size())
                        in_case[*it] = (*cases)[part.first - 1]
                                           .value.subs(moved, GiNaC::subs_options::no_pattern)
                                           .subs(at, GiNaC::subs_options::no_pattern);
            p.claim.lhs = p.claim.lhs.subs(in_case, GiNaC::subs_options::no_pattern);
            p.claim.rhs = p.claim.rhs.subs(in_case, GiNaC::subs_options::no_pattern);
            p.claim.hypotheses.push_back({part.in_case->lhs, part.in_case->op, part.in_case->rhs});
            written(std::move(p));
        }
        return out;
    }
    if (!GiNaC::is_a<GiNaC::relational>(c.stated)) {
        // A statement in words: the cases of a quantity cover every value.
        for (const engine::step_result& s : d.steps)
            for (const check_result& mine : s.checks)
                if (&mine == &c && !s.cases.empty()) {
                    proof_problem p;
                    p.claim = base_claim(c, c.outcome, derived, values);
                    for (const engine::case_value& one : s.cases)
                        p.claim.any_of.push_back({one.lhs, one.op, one.rhs});
                    written(std::move(p));
                    return out;
                }
        return {not_expressible("", "a statement in words")};
    }
    proof_problem p;
    p.claim = base_claim(c, c.outcome, derived, values);
    written(std::move(p));
    return out;
}

std::string status_of(const std::vector<proof_problem>& problems)
{
    for (const proof_problem& p : problems)
        if (p.smt.not_expressible.empty() && p.answer.what == z3_answer::kind::refuted)
            return "refuted";
    for (const proof_problem& p : problems) {
        if (!p.smt.not_expressible.empty())
            return p.smt.not_expressible;
        if (p.answer.what != z3_answer::kind::confirmed)
            return to_string(p.answer);
    }
    return problems.empty() ? "not expressible: nothing to state" : "confirmed";
}

} // namespace

std::vector<proof_check> proof_checks_of(const engine::derivation& d, const engine::derived_by_id& done)
{
    const std::set<std::string> derived = derived_names(d);
    const GiNaC::exmap values = derived_values(d, done);
    std::vector<proof_check> out;
    const auto add = [&](const check_result& c, std::string label) {
        if (c.outcome.what != engine::verdict::status::proven)
            return;
        proof_check p;
        p.check = &c;
        p.label = std::move(label);
        p.problems = problems_of(d, c, derived, values);
        out.push_back(std::move(p));
    };
    for (const check_result* c : d.all_checks())
        add(*c, "check " + c->name);
    // The paper's claims Impact proves (those it says do not hold are refuted, not proven).
    for (const engine::paper_comparison& p : d.paper_checks)
        if (p.what == engine::paper_comparison::kind::claim && p.test && !p.test->said_false)
            add(*p.test, "paper claim " + p.subject);
    return out;
}

namespace {

// Answers every problem of `checks` that Z3 is given: from `store` when it keeps the
// answer, the others run together by `runner`, each text once (one text has one answer);
// then each check's status.
void answer_all(const std::vector<proof_check*>& checks, cache::store* store, proof_checks* totals,
                const z3_runner& runner, const std::function<void(std::size_t, std::size_t)>& told)
{
    const std::string option = rlimit_option();
    const std::string version = z3_version();
    std::vector<std::string> texts, keys;   // to run, each text once
    std::map<std::string, std::size_t> place;   // a key's index in `texts`
    std::vector<std::pair<proof_problem*, std::size_t>> waiting;
    for (proof_check* c : checks)
        for (proof_problem& p : c->problems) {
            if (!p.smt.not_expressible.empty())
                continue;
            if (p.smt.text.size() > z3_largest_problem) {
                p.answer.what = z3_answer::kind::resource_limit;
                p.answer.detail = fmt::format("a problem of {} characters, beyond the {} Z3 is given",
                                              p.smt.text.size(), z3_largest_problem);
                p.answer.guarded = true;
                continue;
            }
            // Kept by the problem's text, the limit and Z3's version: nothing else decides the answer.
            std::string key = fmt::format("z3 {}\n{}{}", version, option, p.smt.text);
            if (const auto same = place.find(key); same != place.end()) {
                waiting.emplace_back(&p, same->second);   // a text met before: its answer
                continue;
            }
            if (store)
                if (const std::optional<std::string> kept = store->get("z3 answer", key))
                    if (from_text(*kept, p.answer)) {
                        p.answer.guarded = p.answer.detail.rfind("stopped by the wall-clock guard", 0) == 0;
                        continue;
                    }
            place.emplace(key, texts.size());
            waiting.emplace_back(&p, texts.size());
            texts.push_back(p.smt.text);
            keys.push_back(std::move(key));
        }
    std::size_t answered = 0;
    const auto finished = [&] {
        if (told)
            told(++answered, texts.size());
    };
    std::vector<z3_run> runs;
    if (runner && !texts.empty()) {
        runs = runner(option, texts, finished);
        if (runs.size() != texts.size())
            throw std::runtime_error(fmt::format("Z3 gave {} answers to {} problems", runs.size(), texts.size()));
    } else {
        for (const std::string& text : texts) {
            const auto start = std::chrono::steady_clock::now();
            z3_answer answer = run_z3(option, text);
            runs.push_back({std::move(answer), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
            finished();
        }
    }
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (store)
            store->put("z3 answer", keys[i], to_text(runs[i].answer));
        if (totals) {
            totals->seconds += runs[i].seconds;
            ++totals->run;
        }
    }
    for (const auto& [p, i] : waiting)
        p->answer = runs[i].answer;
    for (proof_check* c : checks)
        c->status = status_of(c->problems);
}

} // namespace

void run_proof_check(proof_check& check, cache::store* store, proof_checks* totals)
{
    answer_all({&check}, store, totals, {}, {});
}

proof_checks check_proofs(const std::vector<const engine::derivation*>& derivations, const engine::derived_by_id& done,
                          cache::store* store, const std::function<void(std::size_t, std::size_t)>& told,
                          const z3_runner& runner)
{
    proof_checks all;
    std::vector<proof_check*> checks;
    all.derivations.reserve(derivations.size());
    for (const engine::derivation* d : derivations) {
        derivation_proofs& one = all.derivations.emplace_back();
        one.id = d->id();
        one.source = d->source_name();
        one.checks = proof_checks_of(*d, done);
        for (proof_check& c : one.checks)
            checks.push_back(&c);
    }
    answer_all(checks, store, &all, runner, told);
    for (derivation_proofs& one : all.derivations) {
        for (const proof_check& c : one.checks) {
            one.confirmed += c.confirmed();
            for (const proof_problem& p : c.problems)
                if (p.smt.not_expressible.empty() && !p.left_out()) {
                    ++one.problems;
                    one.unsat += p.answer.what == z3_answer::kind::confirmed;
                }
        }
        all.proven += one.checks.size();
        all.confirmed += one.confirmed;
        all.problems += one.problems;
        all.unsat += one.unsat;
    }
    return all;
}

const std::string* proof_checks::status(const check_result& c) const
{
    for (const derivation_proofs& d : derivations)
        for (const proof_check& p : d.checks)
            if (p.check == &c)
                return &p.status;
    return nullptr;
}

std::vector<std::string> proof_checks::refuted() const
{
    std::vector<std::string> lines;
    for (const derivation_proofs& d : derivations)
        for (const proof_check& c : d.checks)
            for (const proof_problem& p : c.problems)
                if (p.smt.not_expressible.empty() && p.answer.what == z3_answer::kind::refuted)
                    lines.push_back(fmt::format("{}: error: Z3 refutes a proof of Impact's: {}: {}{}: Z3's model: {}",
                                                d.source, d.id, c.label, p.part.empty() ? "" : " (" + p.part + ")",
                                                p.answer.detail));
    return lines;
}

std::string smt2_file(const derivation_proofs& d)
{
    std::string out = fmt::format(
        "; Generated by Impact from {}; do not edit.\n"
        "; The claims derivation '{}' proves, each negated under what it may assume: `z3 <this file>`\n"
        "; prints one answer per problem, in order; unsat confirms the claim (docs/language.md,\n"
        "; \"Confirmed by Z3\").\n",
        d.source, d.id);
    out += rlimit_option();
    for (const proof_check& c : d.checks)
        for (const proof_problem& p : c.problems) {
            std::string name = c.label + (p.part.empty() ? "" : ", " + p.part);
            std::replace(name.begin(), name.end(), '\n', ' ');
            if (!p.smt.not_expressible.empty()) {
                out += fmt::format("\n; {}: {}\n", name, p.smt.not_expressible);
                continue;
            }
            if (p.left_out()) {
                out += fmt::format("\n; {}: not given to z3 here: {}\n", name, to_string(p.answer));
                continue;
            }
            out += fmt::format("\n; {}\n(push)\n{}(pop)\n", name, p.smt.text);
        }
    return out;
}

} // namespace impact::verify
