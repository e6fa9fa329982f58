#include "emit/terminal.h"

#include "emit/latex.h"

#include "engine/cases/cases.h"
#include "engine/expr/dimensional.h"
#include "engine/expr/infix.h"
#include "engine/paper/references.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

namespace impact::emit {

std::string terminal_text(const engine::derivation& d)
{
    std::string out;
    const engine::term_order order = engine::declaration_order(d.symbols);
    auto text = [&](const GiNaC::ex& e) { return engine::ginac_syntax(e, order); };
    auto relation = [&](const GiNaC::ex& r) { return text(r.lhs()) + " = " + text(r.rhs()); };

    out += fmt::format("{}: {}{}\n  from {}\n", d.id(), d.source.title.value,
                       d.source.paper ? " (" + d.source.paper->value + ")" : "", d.source.file);
    out += "\ngiven\n";
    for (const engine::equation& g : d.givens)
        out += fmt::format("  {:<14} {}    [{}]\n", g.name, relation(g.relation), g.because);
    out += "\nsteps\n";
    for (std::size_t i = 0; i < d.steps.size(); ++i) {
        const engine::step_result& s = d.steps[i];
        out += fmt::format("  {}. {}\n", i + 1, s.description);
        for (const auto& [symbol, value] : s.values)
            out += fmt::format("       {} = {}\n", text(symbol), text(value));
        for (const engine::case_value& c : s.cases)
            out += fmt::format("       {} = {}    if {}\n", text(s.cases_of), text(c.value),
                               engine::condition_text(c, order));
        for (const engine::solution& found : s.solutions) {
            std::string values;
            for (const auto& [symbol, value] : found.values)
                values += (values.empty() ? "" : ", ") + text(symbol) + " = " + text(value);
            const std::string condition = found.outcome == engine::solution::fate::condition
                                              ? relation(found.condition) + ": "
                                              : std::string();
            out += fmt::format("       {}: {}{}\n", found.kept() ? "kept" : "rejected", values,
                               found.why.empty() ? "" : " (" + condition + found.why + ")");
        }
        if (s.yields)
            out += fmt::format("       {}: {}\n", s.yields->name, relation(s.yields->relation));
        for (const GiNaC::ex& a : s.assumptions)
            out += fmt::format("       assuming {} != {}\n", text(a.lhs()), text(a.rhs()));
        if (!s.attached.empty())
            out += fmt::format("       defined where {}\n", engine::to_string(s.attached));
        for (const engine::check_result& c : s.checks)
            out += fmt::format("       {}: {}\n", c.name, engine::to_string(c.outcome));
    }
    out += "\nresults\n";
    for (const engine::result& r : d.results) {
        if (!r.cases.empty()) {
            out += fmt::format("  {} by cases{}\n", r.name, r.paper.empty() ? "" : "    [" + r.paper + "]");
            for (const engine::case_value& c : r.cases)
                out += fmt::format("    {} = {}    if {}\n", r.name, text(c.value), engine::condition_text(c, order));
            continue;
        }
        out += fmt::format("  {} = {}{}{}\n", r.name, text(r.display),
                           r.attached.empty() ? "" : ", where " + engine::to_string(r.attached),
                           r.paper.empty() ? "" : "    [" + r.paper + "]");
    }
    // A check's statement holds its special values (`at`); what it assumes and where its left
    // side is taken are said after it, as the LaTeX says them, or `J = -J` would read as false.
    auto conditions = [&](const engine::check_result& c) {
        std::vector<std::string> said, left;
        for (const auto& [symbol, range] : c.assuming)
            said.push_back(fmt::format("for {} in {}", text(symbol), range));
        for (const auto& [symbol, value] : c.left_at)
            left.push_back(fmt::format("{} -> {}", text(symbol), text(value)));
        if (!left.empty())
            said.push_back(fmt::format("the left side taken at {}", fmt::join(left, ", ")));
        return said.empty() ? std::string() : fmt::format(", {}", fmt::join(said, "; "));
    };
    out += "\nchecks\n";
    for (const engine::check_result& c : d.checks) {
        out += fmt::format("  {:<18} {}: {}{}\n", engine::to_string(c.outcome), c.name, c.statement, conditions(c));
        for (const engine::check_result::part& part : c.parts)
            out += fmt::format("  {:<18}   {}: {}\n", "", part.under, engine::to_string(part.outcome));
        if (!c.outcome.holds())
            out += fmt::format("  {:<18} residual: {}\n", "", text(c.outcome.residual));
    }
    // A derivation file may leave dimensions out; what has none is not checked.
    const std::vector<std::string> without = engine::symbols_without_dimension(d.symbols);
    if (!without.empty())
        out += fmt::format("\nwithout a dimension (not checked for consistent units): {}\n", fmt::join(without, ", "));
    const std::vector<engine::text_comparison> words = engine::text_comparisons(d.source);
    if (!d.paper_checks.empty() || !words.empty() || !d.source.uncompared.empty()) {
        out += "\nthe paper, held to account\n";
        for (const engine::paper_comparison& p : d.paper_checks) {
            // The errata's verdict: a claim neither proven nor refuted is undecided.
            const std::string verdict = comparison_verdict(p);
            out += fmt::format("  {}: {} ({}): {}\n", p.paper, p.subject, engine::to_string(p.agreement),
                               verdict == "disagrees" ? "DISAGREES" : verdict);
            if (verdict == "undecided")
                out += fmt::format("      neither proven nor refuted: {}\n", p.agreement.method);
            if (verdict == "disagrees")
                out += fmt::format("      printed: {}\n      derived: {}\n", p.printed_text, text(p.derived));
            // An edit of the printed form reconciles it; a claim's other findings say what holds instead.
            // A change that is an alternative to the one before it says so ("or ..."): its label does.
            for (std::size_t i = 0; i < p.reconciliations.size(); ++i) {
                std::string said = p.reconciliations[i];
                const bool alternative = said.rfind("or ", 0) == 0;
                if (alternative)
                    said.erase(0, 3);
                const bool found = i < p.findings.size() && !p.findings[i].corrected &&
                                   p.what == engine::paper_comparison::kind::claim;
                out += fmt::format("      {}: {}\n", found ? (alternative ? "or found" : "found")
                                                         : (alternative ? "or reconciled by" : "reconciled by"),
                                   said);
            }
        }
        for (const engine::text_comparison& t : words) {
            const std::string verdict = engine::to_string(t.verdict);
            out += fmt::format("  {}: {} ({}): {}\n      {}\n", t.paper, t.subject,
                               t.what == engine::text_comparison::kind::reference ? "against its citations"
                                                                                   : "no derivation settles it",
                               verdict == "disagrees" ? "DISAGREES" : verdict, t.finding);
        }
        for (const spec::not_compared& line : d.source.uncompared)
            out += fmt::format("  {}: not compared\n      {}\n", line.paper.value, line.because.value);
    }
    return out;
}

} // namespace impact::emit
