// The paper held to account in a derivation's LaTeX fragment: each printed line and claim
// the derivation compares, what it prints or says, the verdict, and for a disagreement
// what is derived and the smallest change that reconciles the two (in the report, a
// sentence pointing to the errata table instead); and the paper's angles in degrees.
#include "emit/errata.h"
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <vector>

namespace impact::emit {
namespace detail {

// A printed or derived form: inline when short, else displayed and broken.
bool fragment_writer::displayed(const GiNaC::ex& e, const written_form* w) const
{
    return wants_display(e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w));
}

std::string fragment_writer::form(const GiNaC::ex& e, const written_form* w) const
{
    if (!displayed(e, w))
        return "$" + (e.info(GiNaC::info_flags::relation) ? relation_math(e, w) : math(e, w)) + "$";
    if (e.info(GiNaC::info_flags::relation))
        return display(math(e.lhs(), w), "=", e.rhs(), w);
    return display("", "", e, w);
}

// A claim as checked, too wide for a line: displayed (its two sides on lines of their own
// when its left side is wide), its special values, domains or changed inputs after it.
std::string fragment_writer::checked_display(const engine::check_result& t) const
{
    const std::string shown = checked_claim_latex(t, order_);
    const std::string lhs = claim_lhs(t, &t.written);
    std::string out = latex_width(lhs) > content_width - 40
                          ? "\n\\begin{align*}\n" + rows("", t.stated.lhs(), &t.written, "", "") + " \\\\\n" +
                                rows("", t.stated.rhs(), &t.written, "", latex_relation(t.op)) + "\n\\end{align*}\n"
                          : display(lhs, latex_relation(t.op), t.stated.rhs(), &t.written);
    const std::string conditions = shown.substr(shown.find('$', 1) + 1);
    if (conditions.size() > 2)
        out += capitalised(conditions.substr(2)) + ".\n";
    return out;
}

// Each of the paper's items: what it prints or says, the verdict, and for a
// disagreement what is derived and the smallest change that reconciles the two.
// Text after a displayed formula starts a new sentence.
std::string fragment_writer::paper() const
{
    const std::vector<engine::text_comparison> words = engine::text_comparisons(d_.source);
    if (d_.paper_checks.empty() && words.empty())
        return "";
    // In the report, whose errata table has a row for each (\impacterratatable, its
    // section's label), a sentence that says where, with the count: each finding printed
    // once. A fragment pasted alone lists them.
    std::size_t agree = 0, disagrees = 0, undecided = 0;
    std::vector<std::string> disagree;   // their places, each once
    for (const engine::text_comparison& t : words) {
        const std::string v = engine::to_string(t.verdict);
        agree += v == "agrees";
        disagrees += v == "disagrees";
        undecided += v == "undecided";
        if (v == "disagrees" && std::find(disagree.begin(), disagree.end(), paper_text(t.paper)) == disagree.end())
            disagree.push_back(paper_text(t.paper));
    }
    for (const std::vector<std::size_t>& row : emit::errata_rows(d_)) {
        const std::string v = row_verdict(d_, row);
        agree += v == "agrees";
        disagrees += v == "disagrees";
        undecided += v == "undecided";
        const std::string place = paper_text(d_.paper_checks[row.front()].paper);
        if (v == "disagrees" && std::find(disagree.begin(), disagree.end(), place) == disagree.end())
            disagree.push_back(place);
    }
    std::vector<std::string> counts;
    if (agree > 0)
        counts.push_back(fmt::format("{} {}", agree, agree == 1 ? "agrees" : "agree"));
    if (!disagree.empty())
        counts.push_back(fmt::format("{} {} ({})", disagrees, disagrees == 1 ? "disagrees" : "disagree",
                                     fmt::join(disagree, "; ")));
    if (undecided > 0)
        counts.push_back(fmt::format("{} undecided", undecided));
    std::string out = "\n\\paragraph{The paper, held to account.}\n\\ifdefined\\impacterratatable\n" +
                      fmt::format("The paper's printed lines and claims that this derivation compares are rows of the "
                                  "table in Section~\\ref{{\\impacterratatable}}, with their findings: {}.\n",
                                  fmt::join(counts, ", ")) +
                      "\\else\n\\begin{itemize}\n";
    // One item per finding: a misprint that one finding explains in several components of
    // one equation (Eq. 9's v'_m) is shown once, the other components named.
    // The claims checked of one quote are one item when all are proven (what was proven of
    // each said beside it), and an item each otherwise, so that each failure is said: the
    // quote in the first, each saying what it checked.
    struct item {
        std::vector<std::size_t> row;
        bool checked_apart = false;   // one of several checks of one quote that do not all hold
        bool same_quote = false;      // ... and not the first: the quote is not repeated
    };
    std::vector<item> items;
    for (const std::vector<std::size_t>& row : emit::errata_rows(d_)) {
        if (d_.paper_checks[row.front()].what == engine::paper_comparison::kind::claim && row.size() > 1 &&
            row_verdict(d_, row) != "agrees")
            for (std::size_t k : row)
                items.push_back({{k}, true, k != row.front()});
        else
            items.push_back({row});
    }
    for (const item& it : items) {
        const std::vector<std::size_t>& row = it.row;
        const engine::paper_comparison p = in_the_papers_units(d_.paper_checks[row.front()]);
        const std::string what = subject(p);
        out += fmt::format("\\item {}, {}: ", paper_text(p.paper), what);
        bool after_display = false;
        if (p.what == engine::paper_comparison::kind::claim) {
            out += it.same_quote ? std::string("the same words") : fmt::format("``{}''", latex_prose(p.printed_text));
            if (it.checked_apart && p.test)
                out += ", checked as " + checked_claim_latex(*p.test, order_);
        } else {
            const std::string printed = as_printed(p);
            after_display = wants_display(printed);
            out += "printed " + read_as(p) + (after_display ? shown_as_printed(p) : "$" + printed + "$");
        }
        const std::string verdict = comparison_verdict(p);
        if (p.agrees()) {
            // A claim: what was proven, so that two claims of one sentence read apart; one
            // too wide for the line displayed after the item's words (the errata table,
            // which has no room for it, refers here).
            std::vector<std::string> proven;
            std::string displays;
            for (std::size_t k : row)
                if (const engine::paper_comparison c = in_the_papers_units(d_.paper_checks[k]);
                    c.what == engine::paper_comparison::kind::claim && c.test) {
                    const std::string shown = checked_claim_latex(*c.test, order_);
                    if (latex_width(shown) < 260 && shown.find("\\frac{\\frac") == std::string::npos) {
                        proven.push_back(shown);
                        continue;
                    }
                    displays += checked_display(*c.test);
                }
            // A claim the paper says does not hold agrees by being refuted, not proven.
            const bool refuted = std::all_of(row.begin(), row.end(), [&](std::size_t k) {
                const engine::paper_comparison& c = d_.paper_checks[k];
                return c.test && c.test->said_false;
            });
            const std::string how = refuted ? "refuted, as the paper says" : "proven";
            const std::string checked =
                proven.empty() ? "" : " (" + how + ": " + fmt::format("{}", fmt::join(proven, "; ")) + ")";
            const std::string also =
                displays.empty() ? "" : (proven.empty() ? "; " + how + ":" : "; and " + how + ":") + displays;
            out += after_display ? "It agrees" + checked + (also.empty() ? ".\n" : also)
                                 : " --- agrees" + checked + (also.empty() ? ".\n" : also);
            continue;
        }
        out += fmt::format(after_display ? (verdict == "disagrees" ? "It \\textbf{{{}}}" : "It is \\textbf{{{}}}")
                                         : " --- \\textbf{{{}}}",
                           verdict);
        if (verdict == "undecided") {
            out += ": neither proven nor refuted (" + latex_prose(p.agreement.method) + ").\n";
            continue;
        }
        if (p.what != engine::paper_comparison::kind::claim || p.agreement.what == engine::verdict::status::failed) {
            const auto [derived, written] = derived_form(p);
            // After a long quote the line has little room left: a derived form of any
            // width is displayed.
            const bool wide = p.what == engine::paper_comparison::kind::claim &&
                              latex_width(derived.info(GiNaC::info_flags::relation) ? relation_math(derived, written)
                                                                                   : math(derived, written)) > 150;
            after_display = wide || displayed(derived, written);
            out += ": derived " + (wide ? shown(derived, written) : form(derived, written));
        } else {
            after_display = false;
        }
        // A dimensional inconsistency is said as such, then the change that mends it.
        const std::string dimensions = findings(p, finding_kind::dimensions);
        const std::string changes = findings(p, finding_kind::changes);
        std::string tail;
        if (!dimensions.empty())
            tail += after_display ? capitalised(dimensions) : "; it is " + dimensions;
        // Findings that say what holds instead ("the reverse holds: ...", "it holds for ... instead")
        // are no edit: "smallest change" names only an edit of the printed form.
        const bool edit = p.what != engine::paper_comparison::kind::claim ||
                          std::any_of(p.findings.begin(), p.findings.end(),
                                      [](const engine::finding& f) { return f.corrected.has_value(); });
        if (!changes.empty())
            tail += after_display && tail.empty() ? (edit ? "Smallest change: " + changes : capitalised(changes))
                                                  : (edit ? "; smallest change: " + changes : "; " + changes);
        else if (p.what == engine::paper_comparison::kind::claim && p.test)
            tail += after_display && tail.empty() ? capitalised(unreconciled(p, 250)) : "; " + unreconciled(p, 250);
        if (row.size() > 1) {
            std::vector<std::string> others;
            for (std::size_t k = 1; k < row.size(); ++k)
                others.push_back(subject(d_.paper_checks[row[k]]));
            tail += (tail.empty() && after_display ? "" : ". ") +
                    fmt::format("The same misprint, with the same smallest change, is in {}", listing(others));
        }
        out += tail + (tail.empty() && after_display ? "\n" : ".\n");
    }
    // The words compared: claims no derivation settles (undecided, and why), references.
    for (const engine::text_comparison& t : words) {
        const std::string verdict = engine::to_string(t.verdict);
        out += fmt::format("\\item {}, {}: ``{}'' --- {}: {}.\n", paper_text(t.paper),
                           t.what == engine::text_comparison::kind::reference ? "reference entry" : "claim",
                           latex_prose(t.printed), verdict == "agrees" ? verdict : "\\textbf{" + verdict + "}",
                           latex_prose(t.finding));
    }
    return out + "\\end{itemize}\n\\fi\n";
}

} // namespace detail

engine::paper_comparison in_the_papers_units(const engine::paper_comparison& p)
{
    const std::string& words = p.printed_text;
    if (p.what != engine::paper_comparison::kind::claim ||
        (words.find("^\\circ") == std::string::npos && words.find("\u00b0") == std::string::npos))
        return p;
    // q π as the symbol "180 |q|°", its sign outside: printed, never computed with. Only a
    // whole side or a whole term of a sum (θ = π/2, θ - π/2), never a π inside a product
    // (π r² is an area).
    struct to_degrees : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& e) override
        {
            if (GiNaC::is_a<GiNaC::relational>(e) || GiNaC::is_a<GiNaC::add>(e))
                return e.map(*this);   // each side, each term
            const GiNaC::ex q = e / GiNaC::Pi;
            if (!e.has(GiNaC::Pi) || !GiNaC::is_a<GiNaC::numeric>(q) || !q.info(GiNaC::info_flags::rational))
                return e;
            const GiNaC::numeric degrees = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(q)) * 180;
            const std::string number = degrees.is_integer()
                                           ? fmt::format("{}", degrees.to_long())
                                           : fmt::format("\\tfrac{{{}}}{{{}}}", degrees.numer().to_long(),
                                                         degrees.denom().to_long());
            const GiNaC::ex angle = GiNaC::symbol(fmt::format("degrees_{}", number), number + "^\\circ");
            return GiNaC::ex_to<GiNaC::numeric>(q).is_negative() ? -angle : angle;
        }
    } degrees;
    // A claim about an angle (its left side derived as an arccosine, arcsine or arctangent):
    // its value 0 is 0° too ("the derived value is 0°, not 90°"); never the 0 of a cosine.
    const bool angle = p.test && GiNaC::is_a<GiNaC::function>(p.test->lhs) && [&] {
        const std::string name = GiNaC::ex_to<GiNaC::function>(p.test->lhs).get_name();
        return name == "acos" || name == "asin" || name == "atan";
    }();
    const GiNaC::symbol zero_degrees("degrees_0", "0^\\circ");
    const auto value = [&](const GiNaC::ex& e) -> GiNaC::ex { return angle && e.is_zero() ? zero_degrees : degrees(e); };
    engine::paper_comparison shown = p;
    shown.printed = degrees(p.printed);
    shown.derived = value(p.derived);
    for (engine::finding& f : shown.findings)
        for (engine::finding::part& part : f.parts) {
            part.value = value(part.value);
            if (part.point)
                part.point = degrees(*part.point);
        }
    if (shown.test) {
        engine::check_result& c = *shown.test;
        const GiNaC::ex stated = degrees(c.stated.lhs()) == value(c.stated.rhs());
        // The claim as its file writes it names π: set from the expression instead.
        if (!stated.is_equal(c.stated))
            c.written = written_form();
        c.stated = stated;
        c.lhs = degrees(c.lhs);
        c.rhs = value(c.rhs);
        if (c.value)
            c.value = value(*c.value);
        for (auto& [symbol, value] : c.at)
            value = degrees(value);
    }
    return shown;
}

} // namespace impact::emit
