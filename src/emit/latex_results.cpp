// The results of a derivation's LaTeX fragment: numbered as the paper numbers them (a
// result shown for several of its printed lines once), as a textbook shows them, and
// cited by the steps that derive them (latex_fragment.cpp writes the whole).
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace impact::emit {

namespace {

// The tag of a numbered result: the paper's place as cited, "Eq.~(8), right, first line".
std::string equation_tag(const std::string& paper)
{
    return detail::paper_text(paper);
}

} // namespace

namespace detail {

// The result shown in place of `r`: an earlier result of the same symbol and the same
// display (τ of Eq. 12's second, third and fourth lines), shown once; or `r` itself.
const engine::result& fragment_writer::shown_as(const engine::result& r) const
{
    for (const engine::result& earlier : d_.results) {
        if (&earlier == &r)
            break;
        if (earlier.cases.empty() && r.cases.empty() && math(earlier.symbol) == math(r.symbol) &&
            math(earlier.display, &earlier.written) == math(r.display, &r.written))
            return earlier;
    }
    return r;
}

// The places of the results shown as `first`, cited together: "Eq.~(12), second, third
// and fourth lines" when they are lines of one equation.
std::string fragment_writer::places(const engine::result& first) const
{
    std::vector<std::string> papers;
    for (const engine::result& r : d_.results)
        if (&shown_as(r) == &first && !r.paper.empty())
            papers.push_back(r.paper);
    if (papers.size() < 2)
        return equation_tag(first.paper);
    static const char* const ordinals[] = {"first", "second", "third", "fourth", "fifth", "sixth",
                                           "seventh", "eighth", "ninth", "tenth"};
    const std::string line = ", line ";
    const std::string base = papers[0].substr(0, papers[0].rfind(line));
    std::vector<int> numbers;
    for (const std::string& paper : papers) {
        const auto at = paper.rfind(line);
        if (at == std::string::npos || paper.substr(0, at) != base)
            return equation_tag(first.paper);
        numbers.push_back(std::atoi(paper.c_str() + at + line.size()));
    }
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    if (numbers.size() == 1)
        return equation_tag(first.paper);
    std::vector<std::string> words;
    for (int n : numbers) {
        if (n < 1 || n > 10)
            return equation_tag(first.paper);
        words.push_back(ordinals[n - 1]);
    }
    return equation_tag(base) + ", " + listing(words) + " lines";
}

std::optional<std::string> fragment_writer::result_ref(const engine::result& r) const
{
    if (r.paper.empty() || &shown_as(r) != &r)
        return std::nullopt;
    return fmt::format("\\ref{{{}:result:{}}}", latex_label(d_), r.name);
}

std::optional<std::string> fragment_writer::result_cited(const engine::result& r) const
{
    const std::optional<std::string> ref = result_ref(r);
    if (!ref)
        return ref;
    const std::string tag = places(r);
    for (const engine::result& other : d_.results)
        if (&other != &r && !other.paper.empty() && &shown_as(other) == &other && places(other) == tag)
            return *ref + ", $" + math(r.symbol) + "$";
    return ref;
}

std::string fragment_writer::results() const
{
    if (d_.results.empty())
        return "";
    std::vector<const engine::result*> shown;
    for (const engine::result& r : d_.results)
        if (&shown_as(r) == &r)
            shown.push_back(&r);
    std::string out = "\n\\paragraph{Results.}\n\\begin{align}\n";
    std::vector<std::string> as_defined;   // results shown as their steps define them
    double widest = 0;
    for (const engine::result* r : shown)
        widest = std::max(widest, latex_width(math(r->symbol)));
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const engine::result& r = *shown[i];
        // The same quantity in another form right after it (Eq. 10's two lines): one chain,
        // the symbol shown once.
        const bool continued = i > 0 && r.cases.empty() && shown[i - 1]->cases.empty() &&
                               math(shown[i - 1]->symbol) == math(r.symbol);
        std::string tag = "\\notag";
        // The paper's own numbering, as cited: several results of one printed line share it.
        if (!r.paper.empty())
            tag = fmt::format("\\tag*{{{}}}\\label{{{}:result:{}}}", places(r), latex_label(d_), r.name);
        if (!r.cases.empty()) {
            out += *derived_cases_rows(math(r.symbol), r.cases, tag, true) + (i + 1 < shown.size() ? " \\\\\n" : "\n");
            continue;
        }
        // A result its file gives no display form for: as a textbook shows it, factored or
        // collected; or, when that takes more lines, or is far wider, as its step defines it,
        // in the quantities the step names (the rough spheres' v'_{M,x} = v_{M,x} - (J_n n_x +
        // J_{t,x})/M, three lines written out).
        GiNaC::ex value = !r.written.empty() ? r.display : textbook(r.display).value;
        const written_form* written = &r.written;
        if (r.written.empty())
            if (const engine::step_result* s = defining_step(r.symbol);
                s && !GiNaC::is_a<GiNaC::symbol>(*s->as_written)) {   // a bare name is no value
                // Lines it takes, a line too wide for the page (a long quotient) counted as two.
                const double first = std::max(content_width - widest - 14 - 60, 150.0);
                const auto line_count = [&](const GiNaC::ex& e, const written_form* w) {
                    const std::vector<std::string> lines = latex_lines(e, order_, w, first, first);
                    return lines.size() + (latex_width(lines.front()) > first ? 1 : 0);
                };
                const std::size_t written_out = line_count(value, written);
                const std::size_t defined = line_count(*s->as_written, &s->written);
                // On one line too, a value half as wide again as its definition (the rough
                // spheres' spins: a quotient of roots, where the step's moment over the
                // inertia reads at a glance).
                const bool wider = written_out == 1 && defined == 1 &&
                                   latex_width(math(value, written)) > 1.5 * latex_width(math(*s->as_written, &s->written));
                if ((written_out > 1 && defined < written_out) || wider) {
                    value = *s->as_written;
                    written = &s->written;
                    as_defined.push_back("$" + math(r.symbol) + "$");
                }
            }
        out += rows(continued ? "" : math(r.symbol), value, written, tag, "=", widest) +
               (i + 1 < shown.size() ? " \\\\\n" : "\n");
    }
    out += "\\end{align}\n";
    // Where results are defined, the conditions the domains do not prove: said once for the
    // results that share them.
    std::vector<std::pair<std::string, std::vector<std::string>>> defined_where;
    for (const engine::result* r : shown) {
        if (r->attached.empty())
            continue;
        const std::string conditions = conditions_latex(r->attached, order_);
        auto same = std::find_if(defined_where.begin(), defined_where.end(),
                                 [&](const auto& w) { return w.first == conditions; });
        if (same == defined_where.end())
            same = defined_where.insert(defined_where.end(), {conditions, {}});
        same->second.push_back("$" + math(r->symbol) + "$");
    }
    for (const auto& [conditions, names] : defined_where)
        out += fmt::format("{} {} defined where {}.\n", capitalised(listing(names)), names.size() == 1 ? "is" : "are",
                           conditions);
    if (!as_defined.empty())
        out += fmt::format("{} {} shown as {} step{} define{} {}, in the quantities named there: written out in the "
                           "declared quantities, {} would be longer.\n",
                           capitalised(listing(as_defined)), as_defined.size() == 1 ? "is" : "are",
                           as_defined.size() == 1 ? "its" : "their", as_defined.size() == 1 ? "" : "s",
                           as_defined.size() == 1 ? "s" : "", as_defined.size() == 1 ? "it" : "them",
                           as_defined.size() == 1 ? "it" : "each");
    return out;
}

// The define step that derives `symbol` as a single expression, written in the file.
const engine::step_result* fragment_writer::defining_step(const GiNaC::ex& symbol) const
{
    for (const engine::step_result& s : d_.steps)
        if (s.what == spec::step::kind::define && s.cases.empty() && s.as_written && s.values.size() == 1 &&
            s.values[0].first.is_equal(symbol))
            return &s;
    return nullptr;
}

} // namespace detail
} // namespace impact::emit
