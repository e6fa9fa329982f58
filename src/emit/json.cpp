#include "emit/json.h"

#include "emit/latex.h"

#include "engine/cases/cases.h"

#include "engine/expr/infix.h"
#include "engine/paper/references.h"
#include "engine/expr/order.h"

#include <nlohmann/json.hpp>

namespace impact::emit {
namespace {

using engine::ginac_syntax;
using engine::term_order;

using json = nlohmann::ordered_json;

// Where a check, a result or a step's values are defined: "where", the conditions attached
// (the claim is said only where they hold), and how many the domains proved.
void add_conditions(json& j, const std::vector<engine::condition>& where, const std::vector<engine::condition>& defined)
{
    for (const engine::condition& c : where)
        j["where"].push_back({{"condition", c.text}, {"because", c.because}});
    if (!defined.empty())
        j["defined_conditions_proven"] = defined.size();
}

json check_json(const engine::check_result& c, const term_order& order, const verify::proof_checks* z3)
{
    json j;
    j["name"] = c.name;
    j["status"] = engine::to_string(c.outcome);
    // What Z3 made of a proven check: confirmed, refuted, resource limit, unknown, or not
    // expressible with why (verify/proofs.h).
    if (z3)
        if (const std::string* status = z3->status(c))
            j["z3"] = *status;
    if (c.continuity)
        j["continuity"] = c.cases_of;
    else if (!GiNaC::is_a<GiNaC::relational>(c.stated))   // a check stated in words (cases exhaustive)
        j["claim"] = c.statement;
    else
        j["claim"] = ginac_syntax(c.stated.lhs(), order) + " " + engine::to_string(c.op) + " " +
                     ginac_syntax(c.stated.rhs(), order);
    // Proven case by case (or, for continuity, boundary by boundary).
    for (const engine::check_result::part& part : c.parts)
        j["parts"].push_back({{"under", part.under}, {"status", engine::to_string(part.outcome)},
                              {"method", part.outcome.method}});
    if (c.limit)
        j["limit"] = ginac_syntax(c.limit->symbol, order) + " -> " +
                     (c.limit->to_infinity ? std::string("infinity") : ginac_syntax(c.limit->point, order));
    for (const auto& [symbol, value] : c.left_at)
        j["left_at"][ginac_syntax(symbol, order)] = ginac_syntax(value, order);
    for (const auto& [symbol, range] : c.assuming)
        j["assuming"][ginac_syntax(symbol, order)] = range;
    for (const engine::sign_step& step : c.outcome.proof)
        j["proof"].push_back(step.words);
    for (const auto& [symbol, value] : c.at)
        j["at"][ginac_syntax(symbol, order)] = ginac_syntax(value, order);
    j["method"] = c.outcome.method;
    add_conditions(j, c.outcome.where, c.outcome.defined);
    if (c.outcome.what == engine::verdict::status::sampled)
        j["samples"] = c.outcome.samples;
    if (!c.outcome.holds())
        j["residual"] = ginac_syntax(c.outcome.residual, order);
    return j;
}

json derivation_json(const engine::derivation& d, const verify::proof_checks* z3)
{
    const term_order order = engine::declaration_order(d.symbols);
    json j;
    j["id"] = d.id();
    j["title"] = d.source.title.value;
    j["file"] = d.source_name();
    j["paper"] = d.source.paper ? d.source.paper->value : "";
    // Each symbol with its domain and dimension ("" where the file gives none).
    j["symbols"] = json::object();
    for (const engine::quantity& q : d.symbols.all()) {
        json sj;
        sj["domain"] = q.range.to_string();
        sj["dimension"] = q.dim ? q.dim->to_string() : "";
        sj["si_unit"] = q.dim ? q.dim->si_unit() : "";
        j["symbols"][q.name] = sj;
    }
    j["results"] = json::object();
    for (const engine::result& r : d.results)
        j["results"][r.name] = ginac_syntax(r.value, order);
    // A result defined by cases: each case's condition and value.
    for (const engine::result& r : d.results)
        for (const engine::case_value& c : r.cases)
            j["cases"][r.name].push_back({{"when", engine::condition_text(c, order)},
                                          {"value", ginac_syntax(c.value, order)}});
    j["display"] = json::object();
    for (const engine::result& r : d.results)
        j["display"][r.name] = ginac_syntax(r.display, order);
    // Where each result is defined, and where the values of each step are.
    for (const engine::result& r : d.results)
        if (!r.attached.empty() || !r.defined.empty())
            add_conditions(j["defined_where"]["results"][r.name], r.attached, r.defined);
    for (std::size_t i = 0; i < d.steps.size(); ++i)
        if (!d.steps[i].attached.empty() || !d.steps[i].defined.empty())
            add_conditions(j["defined_where"]["steps"][std::to_string(i + 1)], d.steps[i].attached, d.steps[i].defined);
    // The solutions of the steps whose equations are not linear, kept and rejected.
    for (const engine::step_result& s : d.steps) {
        for (const engine::solution& found : s.solutions) {
            static const char* const fates[] = {"kept", "outside its domain", "rejected by the step"};
            json sj;
            sj["step"] = s.description;
            for (const auto& [symbol, value] : found.values)
                sj["values"][ginac_syntax(symbol, order)] = ginac_syntax(value, order);
            sj["status"] = fates[static_cast<int>(found.outcome)];
            if (found.outcome == engine::solution::fate::outside_domain)
                sj["domain"] = ginac_syntax(found.unknown, order) + " in " + found.range.to_string();
            if (found.outcome == engine::solution::fate::condition)
                sj["condition"] = ginac_syntax(found.condition.lhs(), order) + " = " +
                                  ginac_syntax(found.condition.rhs(), order);
            sj["why"] = found.why;
            for (const engine::sign_step& step : found.proof)
                sj["proof"].push_back(step.words);
            j["solutions"].push_back(sj);
        }
    }
    j["checks"] = json::array();
    for (const engine::check_result* c : d.all_checks())
        j["checks"].push_back(check_json(*c, order, z3));
    j["paper_checks"] = json::array();
    for (const engine::paper_comparison& p : d.paper_checks) {
        static const char* const kinds[] = {"printed result", "printed equation", "claim"};
        json pj;
        pj["paper"] = p.paper;
        pj["kind"] = kinds[static_cast<int>(p.what)];
        pj["subject"] = p.subject;
        pj["agrees"] = p.agrees();
        // agrees, disagrees, or undecided (sampled only, or a limit no method settles): the
        // errata's verdict, never "disagrees" for a claim that is not refuted.
        pj["verdict"] = comparison_verdict(p);
        pj["status"] = engine::to_string(p.agreement);
        if (z3 && p.test)
            if (const std::string* status = z3->status(*p.test))
                pj["z3"] = *status;
        pj["printed"] = p.printed_text;
        if (!p.quote.empty())
            pj["printed_as"] = p.quote;   // the paper's own text, which `printed` reads
        pj["derived"] = p.derived.info(GiNaC::info_flags::relation)
                            ? ginac_syntax(p.derived.lhs(), order) + " = " + ginac_syntax(p.derived.rhs(), order)
                            : ginac_syntax(p.derived, order);
        if (!p.agrees()) {
            pj["method"] = p.agreement.method;
            pj["smallest_change"] = p.reconciliations;
        }
        if (!p.label.empty())
            pj["label"] = p.label;   // how a finding names the claim among those of its quote
        if (p.test && p.test->said_false) {
            // The paper says the claim does not hold: it agrees when refuted at a point.
            pj["said_not_to_hold"] = true;
            if (p.test->fails_at) {
                for (const auto& [symbol, value] : p.test->fails_at->point)
                    pj["fails_at"][ginac_syntax(symbol, order)] = ginac_syntax(value, order);
                pj["sides_there"] = {ginac_syntax(p.test->fails_at->lhs, order),
                                     ginac_syntax(p.test->fails_at->rhs, order)};
            }
        }
        j["paper_checks"].push_back(pj);
    }
    // The words compared: claims no derivation can settle (undecided with the reason), and
    // the references, each against its citations.
    for (const engine::text_comparison& t : engine::text_comparisons(d.source)) {
        json pj;
        pj["paper"] = t.paper;
        pj["kind"] = t.what == engine::text_comparison::kind::reference ? "reference" : "claim";
        pj["subject"] = t.subject;
        pj["agrees"] = t.verdict == engine::text_comparison::outcome::agrees;
        pj["verdict"] = engine::to_string(t.verdict);
        pj["printed"] = t.printed;
        pj["reason"] = t.finding;
        j["paper_checks"].push_back(pj);
    }
    // Lines of the paper nothing compares, with why.
    j["not_compared"] = json::array();
    for (const spec::not_compared& line : d.source.uncompared)
        j["not_compared"].push_back({{"paper", line.paper.value}, {"because", line.because.value}});
    j["kernels"] = json::array();
    for (const engine::kernel& k : d.kernels) {
        json kj;
        kj["name"] = k.name;
        kj["inputs"] = json::array();
        for (const engine::kernel_parameter& p : k.parameters)
            kj["inputs"].push_back(p.name);
        kj["outputs"] = json::object();
        for (const engine::kernel_output& o : k.outputs) {
            if (!o.is_array) {
                kj["outputs"][o.member] = ginac_syntax(o.values.front(), order);
                continue;
            }
            kj["outputs"][o.member] = json::array();
            for (const GiNaC::ex& component : o.values)
                kj["outputs"][o.member].push_back(ginac_syntax(component, order));
        }
        j["kernels"].push_back(kj);
    }
    return j;
}

// Each result's displayed form and each check's claim as the report typesets them
// ("latex"), and each check's proof typeset ("proof_latex").
void add_typeset(json& j, const engine::derivation& d)
{
    const term_order order = engine::declaration_order(d.symbols);
    j["latex"] = json::object();
    for (const engine::result& r : d.results)
        j["latex"][r.name] = latex(r.display, order);
    const std::vector<std::string> proofs = checks_proofs_latex(d);
    std::size_t c = 0;
    for (const engine::check_result* check : d.all_checks()) {
        const std::string typeset = claim_latex(d, *check);
        j["checks"][c]["latex"] = typeset;
        j["checks"][c]["proof_latex"] = proofs[c];
        ++c;
    }
}

} // namespace

std::string derivation_json_with_latex(const engine::derivation& d)
{
    json j = derivation_json(d, nullptr);
    add_typeset(j, d);
    return j.dump(2) + "\n";
}

std::string derivations_json(const std::vector<const engine::derivation*>& derivations, const verify::proof_checks* z3)
{
    json j;
    j["generator"] = "Impact";
    j["derivations"] = json::array();
    for (const engine::derivation* d : derivations) {
        json one = derivation_json(*d, z3);
        add_typeset(one, *d);
        j["derivations"].push_back(std::move(one));
    }
    return j.dump(2) + "\n";
}

} // namespace impact::emit
