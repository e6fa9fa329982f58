// The steps of a derivation's LaTeX fragment, as a textbook sets out a derivation: each
// step in words (solved for, defined, divided, rearranged), what it gives, and the checks
// it proves; a quantity defined by cases, as cases (latex_fragment.cpp writes the whole).
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace impact::emit {
namespace detail {

std::string fragment_writer::step_checks(const engine::step_result& s) const
{
    std::string out;
    for (const engine::check_result& c : s.checks) {
        // A define by cases proves its cases cover every value: said of the quantity, typeset.
        const bool covering = !s.cases.empty() && c.name.rfind("the cases of ", 0) == 0;
        const std::string said = covering ? fmt::format("The cases of ${}$ cover every value", math(s.cases_of))
                                          : capitalised(latex_text(c.name));
        out += fmt::format("{}: {}.\n", said, status_text(c.outcome, order_));
    }
    return out;
}

std::vector<int> fragment_writer::step_items() const
{
    std::vector<int> items(d_.steps.size(), 0);
    int listed = 0;
    for (std::size_t i = 0; i < d_.steps.size(); ++i) {
        const engine::step_result& s = d_.steps[i];
        const spec::step* source = i < d_.source.steps.size() ? &d_.source.steps[i] : nullptr;
        // Givens that state their unknowns' values already (M = m, v_M = 0): nothing to solve
        // and no equation to show; before any listed step only, where "substituted in what
        // follows" is true of all.
        if (listed == 0 && s.what == spec::step::kind::solve && source && s.solutions.size() <= 1 &&
            givens_state(s, *source))
            continue;
        // A copy of a quantity under another name (τ again, to compare with another printed
        // line): the same symbol, the same value, nothing for the reader to follow.
        if (s.what == spec::step::kind::define && s.values.size() == 1 && s.as_written &&
            math(*s.as_written) == math(s.values[0].first))
            continue;
        items[i] = ++listed;
    }
    return items;
}

int fragment_writer::item_deriving(const GiNaC::ex& symbol, std::size_t before) const
{
    const std::vector<int> items = step_items();
    for (std::size_t i = 0; i < before && i < d_.steps.size(); ++i)
        for (const auto& value : d_.steps[i].values)
            if (value.first.is_equal(symbol))
                return items[i];
    return 0;
}

std::string fragment_writer::steps() const
{
    if (d_.steps.empty())
        return "";
    const std::vector<int> items = step_items();
    std::string before, out;
    for (std::size_t i = 0; i < d_.steps.size(); ++i) {
        const engine::step_result& s = d_.steps[i];
        const spec::step* source = i < d_.source.steps.size() ? &d_.source.steps[i] : nullptr;
        const std::string because = s.because.empty() ? "" : " (" + latex_prose(s.because) + ")";
        if (items[i] == 0) {
            // Givens that state their values: said once, in words, before the steps.
            if (s.what == spec::step::kind::solve)
                before += solve_step(s, source, because);
            continue;
        }
        out += "\\item ";
        switch (s.what) {
        case spec::step::kind::solve: out += solve_step(s, source, because); break;
        case spec::step::kind::define: out += define_step(s, because); break;
        case spec::step::kind::quotient: out += quotient_step(s, source, because); break;
        case spec::step::kind::rearrange: out += rearrange_step(s, source, because); break;
        }
    }
    const std::string head = "\n\\paragraph{Derivation.}\n" + before;
    return out.empty() ? head : head + "\\begin{enumerate}\n" + out + "\\end{enumerate}\n";
}

// Whether the step's equations are the givens `unknown = value` of each of its values, as
// written: solving them restates them.
bool fragment_writer::givens_state(const engine::step_result& s, const spec::step& source) const
{
    if (s.values.empty() || source.equations.size() != s.values.size())
        return false;
    for (const auto& [unknown, value] : s.values) {
        bool stated = false;
        for (const spec::text& name : source.equations)
            for (const engine::equation& g : d_.givens)
                if (g.name == name.value && g.relation.lhs().is_equal(unknown) && g.relation.rhs().is_equal(value))
                    stated = true;
        if (!stated)
            return false;
    }
    return true;
}

std::string fragment_writer::solve_step(const engine::step_result& s, const spec::step* source,
                                        const std::string& because) const
{
    std::vector<std::string> equations, unknowns;
    if (source)
        for (const spec::text& e : source->equations)
            equations.push_back(ref(e.value));
    for (const auto& value : s.values)
        unknowns.push_back("$" + math(value.first) + "$");
    // Givens that state their unknowns' values: said in words (before the numbered steps,
    // or as a step after others).
    if (source && s.solutions.size() <= 1 && givens_state(s, *source))
        return fmt::format("{} give {} directly{}; they are substituted in what follows.\n",
                           capitalised(listing(equations)), listing(unknowns), because);
    // The result an unknown is, as its file displays it; none when it is no such result.
    const auto displayed_result = [this](const GiNaC::ex& unknown) -> const engine::result* {
        const engine::result* r = GiNaC::is_a<GiNaC::symbol>(unknown)
                                      ? d_.find_result(GiNaC::ex_to<GiNaC::symbol>(unknown).get_name())
                                      : nullptr;
        return r && r->cases.empty() && !r->written.empty() && r->symbol.is_equal(unknown) ? r : nullptr;
    };
    // Every unknown a result shown and numbered in the results, as the file displays it: the
    // results are not set out twice; the step refers to them.
    std::vector<std::string> numbered;
    for (const auto& [unknown, value] : s.values)
        if (const engine::result* r = displayed_result(unknown))
            if (const auto ref = result_cited(*r))
                numbered.push_back(*ref);
    std::string out;
    if (!numbered.empty() && numbered.size() == s.values.size() && s.solutions.size() <= 1) {
        // By their tags, which have commas of their own: "Eq. (8), right, first line; ...".
        out = fmt::format("Solving {} for {}{} gives the results below ({}).\n", listing(equations),
                          listing(unknowns), because, fmt::join(numbered, "; "));
    } else {
        out = fmt::format("Solving {} for {}{} gives\n\\begin{{align*}}\n", listing(equations), listing(unknowns),
                          because);
        // Each value as a textbook shows it: the result's display form when the unknown is a
        // result (Eq. 8's v'_M, collected in eps as the paper prints it), else factored or
        // collected, and said which.
        std::vector<std::string> hows;
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            const auto& [unknown, value] = s.values[i];
            const engine::result* r = displayed_result(unknown);
            const bool displayed = r != nullptr;
            const textbook_value shown = displayed ? textbook_value{r->display, ""} : textbook(value);
            out += rows(math(unknown), shown.value, displayed ? &r->written : nullptr, "") +
                   (i + 1 < s.values.size() ? " \\\\\n" : "\n");
            if (!shown.how.empty())
                hows.push_back(fmt::format("${}$ {}", math(unknown), shown.how));
        }
        out += "\\end{align*}\n";
        if (!hows.empty())
            out += "Shown: " + listing(hows) + ".\n";
        out += rejected_solutions(s);
    }
    const bool all_proven = std::all_of(s.checks.begin(), s.checks.end(), [](const engine::check_result& c) {
        return c.outcome.what == engine::verdict::status::proven;
    });
    if (all_proven && !s.checks.empty())
        out += fmt::format("Substituted back, {} satisfies {}: \\textbf{{proven}}.\n",
                           s.solutions.size() > 1 ? "each solution" : "the solution",
                           equations.size() == 1 ? equations.front() : "each of " + listing(equations));
    else
        out += step_checks(s);
    return out;
}

// The solutions of a non-linear system other than the one kept, each with why it is
// rejected: the domain of an unknown it leaves, or the condition of the step it meets.
std::string fragment_writer::rejected_solutions(const engine::step_result& s) const
{
    std::vector<std::string> rejected;
    for (const engine::solution& found : s.solutions) {
        if (found.kept())
            continue;
        std::vector<std::string> values;
        for (const auto& [symbol, value] : found.values)
            values.push_back(math(symbol) + " = " + math(value));
        std::string why;
        if (found.outcome == engine::solution::fate::outside_domain)
            why = fmt::format("${} {}$", math(found.unknown), found.range.to_latex());
        else
            why = fmt::format("${} = {}$: {}", math(found.condition.lhs()), math(found.condition.rhs()),
                              latex_text(found.why));
        rejected.push_back(fmt::format("${}$ ({})", fmt::format("{}", fmt::join(values, ",\\ ")), why));
    }
    if (rejected.empty())
        return "";
    return fmt::format("The equations have {} solutions; rejected: {}.\n", s.solutions.size(), listing(rejected));
}

std::string fragment_writer::cases_math(const std::vector<engine::case_value>& cases, bool derived) const
{
    std::vector<std::string> rows;
    for (const engine::case_value& c : cases)
        rows.push_back(fmt::format("{} & \\text{{if }} {} {} {}",
                                   derived ? math(c.value) : math(c.as_written, &c.written),
                                   math(derived ? c.lhs : c.written_lhs), latex_relation(c.op),
                                   math(derived ? c.rhs : c.written_rhs)));
    return fmt::format("\\begin{{cases}} {} \\end{{cases}}", fmt::join(rows, " \\\\ "));
}

std::string fragment_writer::case_condition(const engine::case_value& c) const
{
    const std::string derived = fmt::format("{} {} {}", math(c.lhs), latex_relation(c.op), math(c.rhs));
    if (latex_width(derived) < 0.6 * content_width)
        return derived;
    return written_condition(c);
}

std::string fragment_writer::written_condition(const engine::case_value& c) const
{
    return fmt::format("{} {} {}", math(c.written_lhs), latex_relation(c.op), math(c.written_rhs));
}

std::optional<std::string> fragment_writer::derived_cases_rows(const std::string& lhs,
                                                               const std::vector<engine::case_value>& cases,
                                                               const std::string& tag, bool must) const
{
    const std::string whole = cases_math(cases, true);
    if (latex_width(lhs) + latex_width(whole) < content_width - 40)
        return fmt::format("  {} &= {}{}", lhs, whole, tag.empty() ? "" : " " + tag);
    const std::string notag = tag.empty() ? "" : " \\notag";
    // Every case in at most three lines that fit, or the cases as the file writes them
    // (|J_t| = (1 + beta) m_t G_t / d^2 rather than G_t's radicand spelled out over pages).
    bool fits = true;
    for (const engine::case_value& c : cases) {
        const std::vector<std::string> lines =
            latex_lines(textbook(c.value).value, order_, nullptr, content_width - 60);
        fits = fits && lines.size() <= 3 &&
               std::all_of(lines.begin(), lines.end(),
                           [](const std::string& line) { return latex_width(line) <= content_width - 40; });
    }
    if (!fits && !must)
        return std::nullopt;
    std::string out;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const engine::case_value& c = cases[i];
        if (i > 0)
            out += " \\\\\n";
        out += fmt::format("  & \\text{{if }} {}:{} \\\\\n", fits ? case_condition(c) : written_condition(c), notag);
        // One equation, one number: the block's rows are unnumbered but its last, which
        // carries the tag (a row left bare would take a number of its own).
        const std::string last = i + 1 == cases.size() ? tag : tag.empty() ? "" : "\\notag";
        if (fits)
            out += rows(lhs, textbook(c.value).value, nullptr, last);
        else
            out += rows(lhs, c.as_written, &c.written, last);
    }
    return out;
}

// A definition as its file writes it, its parentheses kept ((v'_M - v'_m) - (v_M - v_m),
// which GiNaC would flatten), when it fits a line; else broken as GiNaC reads it.
std::string fragment_writer::as_defined(const std::string& lhs, const GiNaC::ex& value, const written_form& w) const
{
    if (const auto& tree = w.tree(); tree && tree->what != written_form::node::kind::relation) {
        const std::string written = latex_as_written(*tree, order_);
        if (latex_width(lhs) + latex_width(written) < content_width - 60)
            return fmt::format("  {} &= {}", lhs, written);
    }
    return rows(lhs, value, &w, "");
}

std::string fragment_writer::define_step(const engine::step_result& s, const std::string& because) const
{
    std::string out;
    if (!s.cases.empty()) {
        const std::string symbol = math(s.cases_of);
        out += fmt::format("Defining ${}${} by cases:\n\\begin{{align*}}\n  {} &= {}", symbol, because, symbol,
                           cases_math(s.cases, false));
        // What the cases come to in the declared quantities, when that differs.
        std::string too_long;
        if (cases_math(s.cases, true) != cases_math(s.cases, false)) {
            if (const auto derived = derived_cases_rows(symbol, s.cases, "", false))
                out += " \\\\\n" + *derived;
            else
                too_long = fmt::format("Written out in the declared quantities, its cases would take more than three "
                                       "lines each; what follows uses ${}$ by name.\n",
                                       symbol);
        }
        return out + "\n\\end{align*}\n" + too_long + step_checks(s);
    }
    for (const auto& [symbol, value] : s.values) {
        out += fmt::format("Defining ${}${}:\n\\begin{{align*}}\n", math(symbol), because);
        // The definition as written, then what it comes to when that differs.
        const std::optional<GiNaC::ex>& as_written = s.as_written;
        const written_form& w = s.written;
        // What it comes to: the result's display form when it is a result, else the value
        // as a textbook shows it (factored or collected, which is said).
        const engine::result* r = d_.find_result(GiNaC::ex_to<GiNaC::symbol>(symbol).get_name());
        const bool displayed = r && r->cases.empty() && !r->written.empty() &&
                               !(as_written && math(*as_written, &w) == math(r->display, &r->written));
        const textbook_value shown = displayed ? textbook_value{r->display, ""} : textbook(value);
        const written_form* shown_written = displayed ? &r->written : nullptr;
        std::string how, after;
        if (as_written && !as_written->is_equal(value) && math(*as_written, &w) != math(value) &&
            math(*as_written, &w) != math(shown.value, shown_written)) {
            out += as_defined(math(symbol), *as_written, w);
            // What it comes to: a numbered result is referred to (its value is in the results),
            // unless it is defined as another quantity by name (v'_{M,par} = v'_M of Eq. 3), when
            // the value is what the step says; otherwise the value, unless written out in the
            // declared quantities it takes more lines than its definition, or more than three (a contact point's velocity
            // spelled out in every spin and radius): the quantity is then used by name.
            const double side = latex_width(math(symbol));
            const auto lines_of = [&](const GiNaC::ex& e, const written_form* written) {
                return latex_lines(e, order_, written, std::max(content_width - side - 14, 150.0),
                                   std::max(content_width - side - 20, 150.0))
                    .size();
            };
            const std::optional<std::string> numbered =
                displayed && !GiNaC::is_a<GiNaC::symbol>(*as_written) ? result_cited(*r) : std::nullopt;
            // Defined as a quantity an earlier step derives (v'_{M,perp} = v_{M,perp}, which
            // the rotation of step 1 gives): its value is there, not set out again.
            const int earlier = GiNaC::is_a<GiNaC::symbol>(*as_written) ? item_deriving(*as_written, static_cast<std::size_t>(&s - d_.steps.data())) : 0;
            if (earlier > 0) {
                after = fmt::format("Step~{} gives ${}$.\n", earlier, math(*as_written));
            } else if (numbered) {
                after = fmt::format("Its value is the result below ({}).\n", *numbered);
            } else if (displayed || lines_of(shown.value, shown_written) <=
                                        std::min<std::size_t>(3, lines_of(*as_written, &w) + 1)) {
                // Set out when it reads about as easily as the definition: at most three
                // lines, and at most one more than the definition takes.
                out += " \\\\\n" + rows("", shown.value, shown_written, "", "=", side);
                how = shown.how;
            } else {
                after = fmt::format("Written out in the declared quantities, it would take more {}; what follows uses "
                                    "${}$ by name.\n",
                                    lines_of(shown.value, shown_written) > 3 ? "than three lines"
                                                                             : "lines than its definition",
                                    math(symbol));
            }
            out += "\n";
        } else if (as_written) {
            out += as_defined(math(symbol), *as_written, w) + "\n";
        } else {
            out += rows(math(symbol), shown.value, shown_written, "") + "\n";
            how = shown.how;
        }
        out += "\\end{align*}\n" + after;
        if (!how.empty())
            out += "The value is shown " + how + ".\n";
    }
    return out + step_checks(s);
}

std::string fragment_writer::yields(const engine::step_result& s) const
{
    if (!s.yields)
        return "";
    const std::string tag =
        fmt::format("\\tag{{{}}}\\label{{{}:{}}}", tags_.at(s.yields->name), latex_label(d_), s.yields->name);
    const written_form& w = s.yields->written;   // a rearranged form as the file writes it
    return "\\begin{align}\n" + rows(math(s.yields->relation.lhs(), &w), s.yields->relation.rhs(), &w, tag) +
           "\n\\end{align}\n";
}

std::string fragment_writer::quotient_step(const engine::step_result& s, const spec::step* source,
                                           const std::string& because) const
{
    std::string a = "an equation", b = "another";
    if (source && source->equations.size() == 2) {
        a = ref(source->equations[0].value);
        b = ref(source->equations[1].value);
    }
    std::vector<std::string> assumed;
    for (const GiNaC::ex& assumption : s.assumptions)
        assumed.push_back(fmt::format("${} \\neq {}$", math(assumption.lhs()), math(assumption.rhs())));
    std::string out = fmt::format("Dividing {} by {} side by side{}", a, b, because);
    if (!assumed.empty())
        out += fmt::format(", where {}", listing(assumed));
    return out + ", gives\n" + yields(s) + step_checks(s);
}

std::string fragment_writer::rearrange_step(const engine::step_result& s, const spec::step* source,
                                            const std::string& because) const
{
    std::string out = fmt::format("Rearranging {}{} gives\n", source ? ref(source->source.value) : "", because);
    out += yields(s);
    for (const engine::check_result& c : s.checks)
        out += fmt::format("Equivalent to {}: {}.\n", ref(source ? source->source.value : ""),
                           status_text(c.outcome, order_));
    return out;
}

} // namespace detail
} // namespace impact::emit
