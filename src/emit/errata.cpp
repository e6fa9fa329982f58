#include "emit/errata.h"

#include "emit/latex.h"
#include "engine/expr/order.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace impact::emit {
namespace {

// A table cell: pipes escaped, line breaks flattened.
std::string cell(std::string text)
{
    std::string out;
    for (char c : text) {
        if (c == '|')
            out += "\\|";
        else if (c == '\n')
            out += ' ';
        else
            out += c;
    }
    return out;
}

// Mathematics for a renderer of Markdown with LaTeX math (`$...$`).
std::string math(const GiNaC::ex& e, const engine::term_order& order, const engine::written_form* written)
{
    if (e.info(GiNaC::info_flags::relation))
        return "$" + latex(e.lhs(), order, written) + " = " + latex(e.rhs(), order, written) + "$";
    return "$" + latex(e, order, written) + "$";
}

const char* kind_name(engine::paper_comparison::kind k)
{
    switch (k) {
    case engine::paper_comparison::kind::result: return "equation";
    case engine::paper_comparison::kind::given: return "equation";
    case engine::paper_comparison::kind::claim: return "claim";
    }
    return "";
}

} // namespace

std::vector<std::vector<std::size_t>> errata_rows(const engine::derivation& d, bool claims_of_one_quote)
{
    const auto& all = d.paper_checks;
    constexpr auto claim = engine::paper_comparison::kind::claim;
    std::vector<std::vector<std::size_t>> rows;
    std::vector<bool> done(all.size(), false);
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (done[i])
            continue;
        const engine::paper_comparison& p = all[i];
        std::vector<std::size_t> row = {i};
        for (std::size_t j = i + 1; j < all.size(); ++j) {
            const engine::paper_comparison& q = all[j];
            if (done[j] || q.paper != p.paper || q.what != p.what)
                continue;
            // The components that share this row's misprint: the same equation, the same finding.
            const bool one_misprint = p.what != claim && !p.agrees() && !q.agrees() && !p.reconciliations.empty() &&
                                      q.reconciliations == p.reconciliations;
            // The claims checked of one quote: what the paper says there, one finding.
            const bool one_quote = claims_of_one_quote && p.what == claim && q.printed_text == p.printed_text;
            if (one_misprint || one_quote) {
                row.push_back(j);
                done[j] = true;
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string one_finding(const std::vector<std::string>& each, const std::vector<bool>& agrees,
                        const std::vector<std::string>& labels)
{
    static const char* const ordinals[] = {"1st", "2nd", "3rd"};
    const auto ordinal = [](std::size_t i) {
        return i < 3 ? std::string(ordinals[i]) : fmt::format("{}th", i + 1);
    };
    // A check by its label ("the contrapositive"), else by its place in the row.
    const auto labelled = [&](std::size_t i) { return i < labels.size() && !labels[i].empty(); };
    const auto name = [&](std::size_t i) { return labelled(i) ? labels[i] : "the " + ordinal(i) + " check"; };
    // Some agree and some do not: what each that does not is found, then the others named.
    if (agrees.size() == each.size() && std::count(agrees.begin(), agrees.end(), true) > 0 &&
        std::count(agrees.begin(), agrees.end(), false) > 0) {
        std::string out;
        std::vector<std::size_t> agreeing;
        for (std::size_t i = 0; i < each.size(); ++i) {
            if (agrees[i])
                agreeing.push_back(i);
            else
                out += fmt::format("{}{}: {}", out.empty() ? "" : "; ", name(i), each[i]);
        }
        const bool any_label = std::any_of(agreeing.begin(), agreeing.end(), labelled);
        std::string named;
        for (std::size_t k = 0; k < agreeing.size(); ++k)
            named += (k == 0 ? "" : k + 1 == agreeing.size() ? " and " : ", ") +
                     (any_label ? name(agreeing[k]) : ordinal(agreeing[k]));
        if (!any_label)
            named = "the " + named + (agreeing.size() == 1 ? " check" : " checks");
        return out + fmt::format("; {} {} with the paper", named, agreeing.size() == 1 ? "agrees" : "agree");
    }
    if (each.empty())
        return "";
    const bool two = each.size() == 2;
    if (std::all_of(each.begin(), each.end(), [&](const std::string& e) { return e == each.front(); })) {
        if (each.front() == "as checked, it does not hold")
            return two ? "as checked, neither holds" : "as checked, none holds";
        if (each.front().rfind("proven", 0) == 0)
            return (two ? "both " : "all ") + each.front();
        // Said of a claim the paper says does not hold, when each of its checks holds.
        static const std::string holds = "it holds, where the paper says it does not";
        if (each.front().rfind(holds, 0) == 0)
            return (two ? "both hold" : "all hold") + std::string(", where the paper says they do not") +
                   each.front().substr(holds.size());
        return each.front();
    }
    // The same finding of each, of different values ("the reverse holds: 2/3 < 1", "the
    // reverse holds: 1/3 < 2/3": values said to increase that decrease), said once.
    const std::size_t colon = each.front().find(": ");
    const std::string head = colon == std::string::npos ? "" : each.front().substr(0, colon);
    if (!head.empty() && head.rfind("proven", 0) != 0 && head.find(';') == std::string::npos &&
        std::all_of(each.begin(), each.end(), [&](const std::string& e) {
            return e.rfind(head + ": ", 0) == 0 && e.find("; ") == std::string::npos;
        })) {
        std::string out = head + " in each check: ";
        for (std::size_t i = 0; i < each.size(); ++i)
            out += (i == 0 ? "" : i + 1 == each.size() ? " and " : ", ") + each[i].substr(head.size() + 2);
        return out;
    }
    std::string out;
    for (std::size_t i = 0; i < each.size(); ++i)
        out += fmt::format("{}{}: {}", i == 0 ? "" : "; ", name(i), each[i]);
    return out;
}

std::string one_finding(const std::vector<const engine::paper_comparison*>& claims,
                        const std::function<std::string(const engine::paper_comparison&)>& change_of)
{
    std::vector<std::string> each, labels;
    std::vector<bool> agrees;
    for (const engine::paper_comparison* c : claims) {
        each.push_back(change_of(*c));
        agrees.push_back(comparison_verdict(*c) == "agrees");
        labels.push_back(c->label);
    }
    return one_finding(each, agrees, labels);
}

std::string not_compared_sentence(const paper_count& n, const std::function<std::string(const std::string&)>& place,
                                  const std::function<std::string(const std::string&)>& why)
{
    std::string out;
    for (std::size_t i = 0; i < n.not_compared.size(); ++i)
        out += fmt::format("{}{} ({}){}", i == 0 ? " Not compared: " : "; ", place(n.not_compared[i]->paper.value),
                           why(n.not_compared[i]->because.value), i + 1 == n.not_compared.size() ? "." : "");
    return out;
}

std::string row_verdict(const engine::derivation& d, const std::vector<std::size_t>& row)
{
    std::string worst = "agrees";
    for (std::size_t k : row) {
        const std::string v = comparison_verdict(d.paper_checks[k]);
        if (v == "disagrees" || (v == "undecided" && worst == "agrees"))
            worst = v;
    }
    return worst;
}

const std::string& errata_entry::place() const
{
    return words ? words->paper : derivation->paper_checks[comparisons.front()].paper;
}

std::vector<errata_entry> errata_entries(const std::vector<const engine::derivation*>& derivations,
                                         const spec::paper_outline* outline)
{
    std::vector<errata_entry> entries;
    for (const engine::derivation* d : derivations) {
        for (std::vector<std::size_t>& row : errata_rows(*d))
            entries.push_back(errata_entry{d, std::move(row), std::nullopt});
        for (engine::text_comparison& t : engine::text_comparisons(d->source))
            entries.push_back(errata_entry{d, {}, std::move(t)});
    }
    if (!outline)
        return entries;
    std::vector<std::pair<std::size_t, errata_entry>> placed;
    for (errata_entry& e : entries) {
        const std::optional<std::size_t> at = outline->position(e.place());
        if (!at)
            throw error(e.words ? e.words->where : e.derivation->paper_checks[e.comparisons.front()].where,
                        fmt::format("the paper's place '{}' is not listed in {}, which gives the order of the "
                                    "errata: add it there, where the paper prints it",
                                    e.place(), outline->file));
        placed.emplace_back(*at, std::move(e));
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    entries.clear();
    for (auto& [at, e] : placed)
        entries.push_back(std::move(e));
    return entries;
}

std::size_t compared_places(const std::vector<const engine::derivation*>& derivations)
{
    std::set<std::string> places;
    for (const engine::derivation* d : derivations) {
        for (const engine::paper_comparison& p : d->paper_checks)
            places.insert(p.paper);
        for (const engine::text_comparison& t : engine::text_comparisons(d->source))
            places.insert(t.paper);
    }
    return places.size();
}

bool of_the_paper(const std::vector<const engine::derivation*>& derivations)
{
    return std::any_of(derivations.begin(), derivations.end(),
                       [](const engine::derivation* d) { return d->source.paper.has_value(); });
}

paper_count count_paper(const std::vector<const engine::derivation*>& derivations)
{
    paper_count n;
    n.compared = compared_places(derivations);
    std::set<std::string> not_compared;
    for (const engine::derivation* d : derivations) {
        for (const std::vector<std::size_t>& row : errata_rows(*d)) {
            const std::string verdict = row_verdict(*d, row);
            ++n.rows;
            ++(verdict == "agrees" ? n.agree : verdict == "undecided" ? n.undecided : n.disagree);
        }
        for (const engine::text_comparison& t : engine::text_comparisons(d->source)) {
            ++n.rows;
            ++(t.verdict == engine::text_comparison::outcome::agrees      ? n.agree
               : t.verdict == engine::text_comparison::outcome::undecided ? n.undecided
                                                                          : n.disagree);
        }
        for (const spec::not_compared& line : d->source.uncompared)
            if (not_compared.insert(line.paper.value).second)
                n.not_compared.push_back(&line);
    }
    n.lines = n.compared + n.not_compared.size();
    return n;
}

std::string errata_markdown(const std::vector<const engine::derivation*>& derivations,
                            const spec::paper_outline* outline)
{
    const paper_count n = count_paper(derivations);
    const std::string folder = engine::source_folder(derivations);
    const bool of_the_paper = emit::of_the_paper(derivations);
    std::string out = "<!-- Generated by Impact from " + folder + "; do not edit. -->\n" +
                      (of_the_paper ? "# The paper held to account\n\n" : "# The text held to account\n\n");
    if (n.lines == 0)
        return out + "No derivation file in `" + folder + "` transcribes a printed line or claim of a text (a "
                     "`printed` form, a `[[claim]]`, a `[[not_compared]]` place): there is nothing to compare.\n";
    const std::string rules =
        "An equation agrees when it is proven equal to the derived result (an equation of the "
        "paper's: proven equivalent); a claim agrees when it is proven, and is undecided when it can "
        "be neither proven nor refuted, or when no derivation can settle it (a statement about "
        "experiment, an assumption about real bodies), with the reason. For each disagreement the "
        "smallest change that reconciles the two is given, when one edit, or two, do. Each row is one "
        "finding: a claim of the text (the claims checked of one quote together, each check shown), "
        "or a printed form; a misprint that one finding explains in several components of one "
        "equation is one row. Mathematics is LaTeX between dollar signs.\n\n";
    if (of_the_paper)
        out += "Every equation that *General Collisions of Smooth Spheres* prints, and every claim its text "
               "makes about them, as transcribed in `" + folder + "`, compared with what Impact derives. " + rules +
               "Each row names its place in the paper: a line of a displayed equation (\"Eq. 12, line 2\"), "
               "an equation or a sentence of the text (\"Sec. III C, after Eq. 14, 5th sentence\"), a "
               "footnote. One place may be compared in more than one row (the components of a vector, two "
               "claims of one sentence quoted apart). The paper's lines and claims are listed, typed from the paper, in "
               "`tests/test_paper_lines.cpp`, which fails when one it lists as compared is not.\n\n";
    else
        out += "Every equation and claim of the text the files in `" + folder + "` transcribe (their `paper` "
               "fields name its places), compared with what Impact derives. " + rules;
    out += outline ? "The rows follow the paper, in the order it prints their places (`" + folder +
                         std::string(spec::paper_outline_name) + "`).\n\n"
                   : std::string("The rows go derivation by derivation.\n\n");
    out += fmt::format("{} printed lines and claims of the paper, {} of them compared, in {} rows: {} agree, {} "
                       "disagree, {} undecided.",
                       n.lines, n.compared, n.rows, n.agree, n.disagree, n.undecided);
    const auto as_is = [](const std::string& text) { return text; };
    out += not_compared_sentence(n, as_is, as_is);
    out += "\n\n| Where | Kind | Item | Verdict | Printed | Derived | Finding |\n"
           "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const errata_entry& entry : errata_entries(derivations, outline)) {
        const engine::derivation* d = entry.derivation;
        if (entry.words) {
            const engine::text_comparison& t = *entry.words;
            const std::string verdict = engine::to_string(t.verdict);
            const bool reference = t.what == engine::text_comparison::kind::reference;
            out += fmt::format("| {} | {} | {} | {} | {} | — | {} |\n", cell(t.paper), reference ? "reference" : "claim",
                               reference ? "entry" : "claim", verdict == "agrees" ? verdict : "**" + verdict + "**",
                               cell(t.printed), cell(t.finding));
            continue;
        }
        const engine::term_order order = engine::declaration_order(d->symbols);
        const std::vector<std::size_t>& row = entry.comparisons;
        // Each comparison as shown: a claim in degrees answered in degrees.
        std::vector<engine::paper_comparison> shown;
        for (std::size_t k : row)
            shown.push_back(in_the_papers_units(d->paper_checks[k]));
        const engine::paper_comparison& p = shown.front();
        const bool claim = p.what == engine::paper_comparison::kind::claim;
        std::vector<std::string> items, printed, derived;
        for (const engine::paper_comparison& c : shown) {
            // The derived form in the variables the paper prints: the printed form mended, or the
            // result as its file displays it.
            const engine::result* r =
                c.what == engine::paper_comparison::kind::result ? d->find_result(c.subject) : nullptr;
            // A claim: what was checked (its special values or limit), which its words state.
            const auto beside = [&] {
                const auto [form, written] = result_beside(*d, c, *r);
                return math(form, order, written);
            };
            derived.push_back(claim && c.test ? "checked: " + cell(checked_claim_latex(*c.test, order))
                              : r             ? beside()
                                              : math(c.derived, order, nullptr));
            // As the paper prints it: the transcription's terms and factors, nothing merged.
            // A form the file reads in other terms (a component of R^T v): the paper's text first.
            printed.push_back((c.quote.empty() ? "" : cell(c.quote) + ", read as ") +
                              (claim              ? cell(c.printed_text)
                               : c.written.tree() ? "$" + latex_as_written(*c.written.tree(), order) + "$"
                                                  : math(c.printed, order, &c.written)));
            const engine::quantity* q = d->symbols.find(c.subject);
            std::string name = c.subject;
            std::replace(name.begin(), name.end(), '_', ' ');
            items.push_back(claim ? "claim" : q && r ? math(q->symbol, order, nullptr) : name);
        }
        // What was found, comparison by comparison.
        auto change_of = [&](const engine::paper_comparison& c) -> std::string {
            if (std::string said = agreement_text(c); !said.empty())
                return cell(said);
            std::vector<std::string> said;
            for (const engine::finding& f : c.findings)
                said.push_back(cell(finding_latex(f, order, &c.written, &c)));
            if (said.empty() && c.test)
                said.push_back("as checked, it does not hold");
            return said.empty() ? "no edit, or two, reconciles it; see the derived form"
                                : fmt::format("{}", fmt::join(said, "; "));
        };
        std::string change = change_of(p);
        if (claim && row.size() > 1) {
            // The claims of one quote: one finding, each check's outcome where they differ.
            std::vector<const engine::paper_comparison*> claims;
            for (const engine::paper_comparison& c : shown)
                claims.push_back(&c);
            change = one_finding(claims, change_of);
            printed.resize(1);
            for (std::size_t i = 1; i < derived.size(); ++i)
                if (derived[i].rfind("checked: ", 0) == 0)
                    derived[i].erase(0, 9);
        } else if (!p.agrees() && comparison_verdict(p) != "undecided" && row.size() > 1) {
            change += fmt::format("; one misprint, in each of the {} components", row.size());
        }
        const std::string verdict = row_verdict(*d, row);
        out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", cell(p.paper), kind_name(p.what),
                           claim ? std::string("claim") : fmt::format("{}", fmt::join(items, ", ")),
                           verdict == "agrees" ? verdict : "**" + verdict + "**", fmt::join(printed, "; "),
                           fmt::join(derived, "; "), change);
    }
    return out;
}

} // namespace impact::emit
