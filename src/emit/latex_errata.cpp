// The paper held to account, typeset: prose with its mathematics, the findings of the
// engine (words and the expressions and dimensions they name), and the rows of the
// report's errata table, with the forms too wide for a cell set as numbered displays
// under the table.
#include "emit/errata.h"
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace impact::emit {
namespace {

// The width of a table cell's math, set in 8 pt inline: about 0.75 of its displayed width.
double cell_width(const std::string& math)
{
    return 0.75 * latex_width(math);
}

// Inline math in a table cell breaks after + - = at its outer level, never inside
// \frac or \sqrt: such math must fit its column whole.
bool fits(const std::string& math, double column_pt)
{
    const bool unbreakable = math.find("\\frac") != std::string::npos || math.find("\\sqrt") != std::string::npos;
    return !(unbreakable && cell_width(math) > column_pt - 4) && math.find("\\frac{\\frac") == std::string::npos;
}

// A dimension as a physicist names it, with its SI unit: "a momentum
// ($\mathrm{kg\,m\,s^{-1}}$)", "$\mathrm{kg^{-1}}$", "a pure number".
std::string dimension_latex(const engine::dimension& d)
{
    if (d.is_pure_number())
        return "a pure number";
    const auto name = d.familiar_name();
    const std::string unit = detail::si_unit_latex(d);
    return name ? *name + " (" + unit + ")" : unit;
}

} // namespace

std::string finding_latex(const engine::finding& f, const term_order& order, const written_form* written,
                          const engine::paper_comparison* of)
{
    // The printed form itself, named by a finding (a spurious m in the whole of Eq. 12's
    // third line), as the paper prints it: its terms, factors and signs as transcribed.
    const auto& tree = of && of->what != engine::paper_comparison::kind::claim ? of->written.tree()
                                                                               : std::optional<written_form::node>();
    auto is_printed = [&](const GiNaC::ex& e) {
        if (!tree || e.info(GiNaC::info_flags::relation) || of->printed.info(GiNaC::info_flags::relation))
            return false;
        return GiNaC::normal(e - of->printed).is_zero() || GiNaC::normal(e + of->printed).is_zero();
    };
    std::string out;
    for (const engine::finding::part& p : f.parts) {
        switch (p.what) {
        case engine::finding::part::kind::words: out += latex_prose(p.words); break;
        case engine::finding::part::kind::math:
            if (is_printed(p.value)) {
                out += "$" + latex_as_written(*tree, order) + "$";
                break;
            }
            if (p.term) {
                // A term named whatever its sign: as the paper writes it, without a minus
                // its written order would put in front (-eps M (v_m - v_M) for M eps (v_M - v_m)).
                std::string term = latex(p.value, order, written);
                if (term.rfind("-", 0) == 0) {
                    const std::string negated = latex(-p.value, order, written);
                    if (negated.rfind("-", 0) != 0)
                        term = negated;
                }
                out += "$" + term + "$";
                break;
            }
            out += "$" +
                   (GiNaC::is_a<GiNaC::relational>(p.value)
                        ? latex(p.value.lhs(), order, written) + " " + detail::latex_relation(p.op) + " " +
                              latex(p.value.rhs(), order, written)
                        : latex(p.value, order, written)) +
                   "$";
            break;
        case engine::finding::part::kind::tends:
            out += "$" + latex(p.value, order) + " \\to " + (p.point ? latex(*p.point, order) : "\\infty") + "$";
            break;
        case engine::finding::part::kind::dimension: out += dimension_latex(p.dim); break;
        }
    }
    return out;
}

std::string comparison_verdict(const engine::paper_comparison& p)
{
    switch (p.agreement.what) {
    case engine::verdict::status::proven: return "agrees";
    case engine::verdict::status::sampled: return "undecided";
    case engine::verdict::status::failed: break;
    }
    // A limit no method established is not refuted: the claim is undecided.
    if (p.test && p.test->limit && !p.test->value)
        return "undecided";
    return "disagrees";
}

namespace {

// How a proven verdict was reached (verdict::basis), in words.
std::string proven_by(const engine::verdict& v)
{
    using basis = engine::verdict::basis;
    switch (v.how) {
    case basis::zero_difference: return "the difference of the sides simplifies to $0$";
    case basis::signs:
        return GiNaC::is_a<GiNaC::numeric>(v.residual) ? "by arithmetic"
                                                       : "the sign of each factor of the difference of the sides "
                                                         "follows from the domains";
    case basis::identity:
        return "through an identity proven before it, one of whose sides is the difference of the sides, and "
               "the other's sign follows from the domains";
    case basis::constant_factor: return "one equation is the other multiplied by a constant";
    case basis::same_difference: return "the two equations have the same difference of sides";
    case basis::angles:
        return "both angles lie in $[0, \\pi]$, where $\\cos$ is one-to-one, and their cosines are proven equal";
    case basis::counterexample: return "refuted at a point of the domains";
    case basis::decided:
        return "the angles written over a basis, every $\\sin$, $\\cos$ and $\\tan$ through the sine and cosine of "
               "the base angles, reduced modulo $\\sin^2 + \\cos^2 = 1$ (exponentials over a basis of exponents), "
               "leave no difference";
    case basis::none: break;
    }
    return "";
}

// How a limit was established, in words.
std::string limit_by(const engine::limit_method& how)
{
    if (how.at_infinity)
        return "the limit from the leading term in $1/t$, with $t \\to 0^+$ the reciprocal of the growing quantity";
    return how.how == engine::limit_method::kind::substitution
               ? "the limit by substitution, the expression being continuous there"
               : "the limit from the leading term of the series at the point";
}

} // namespace

std::string agreement_text(const engine::paper_comparison& p)
{
    const std::string verdict = comparison_verdict(p);
    const bool said_false = p.what == engine::paper_comparison::kind::claim && p.test && p.test->said_false;
    if (verdict == "undecided") {
        if (said_false && p.agreement.samples == 0)
            return p.test->parts.empty()
                       ? "neither proven nor refuted: no proof that it holds, and no point of the domains found "
                         "where it fails"
                       : "neither proven nor refuted: no proof that it holds in every case, and no point is "
                         "searched for where it fails, case by case";
        if (p.agreement.what == engine::verdict::status::sampled)
            return fmt::format("neither proven nor refuted: no proof was found, and it holds at each of {} sampled "
                               "points of the declared domains (40 digits)",
                               p.agreement.samples);
        return "neither proven nor refuted: no method established the limit";
    }
    if (verdict != "agrees")
        return "";
    if (said_false && p.test->fails_at)
        return p.test->fails_at->exact
                   ? "refuted, as the paper says: it fails at the point shown, its sides evaluated exactly"
                   : "refuted, as the paper says: it fails at the point shown, its sides evaluated to 50 and 80 "
                     "digits and far apart";
    using kind = engine::paper_comparison::kind;
    const std::string head = p.what == kind::claim ? "proven" : p.what == kind::given ? "proven equivalent"
                                                                                     : "proven equal";
    std::string how;
    if (p.what == kind::claim && p.test) {
        const engine::check_result& c = *p.test;
        if (!c.parts.empty())
            how = c.continuity ? "the cases agree where they meet"
                               : fmt::format("case by case, in each of its {} cases", c.parts.size());
        else if (c.limit_by)
            how = limit_by(*c.limit_by) + "; then " + proven_by(c.outcome);
        else
            how = proven_by(c.outcome);
    } else {
        how = proven_by(p.agreement);
    }
    return how.empty() ? head : head + ": " + how;
}

std::pair<GiNaC::ex, const written_form*> result_beside(const engine::derivation& d,
                                                        const engine::paper_comparison& p,
                                                        const engine::result& r)
{
    // One component of a vector the paper prints whole (Eq. 9's R^T (...), read component by
    // component under one quote), agreeing: proven equal, the printed form is the derived
    // one in the paper's variables (its frame), where the display is in the derivation's.
    const auto component = [&] {
        return !p.quote.empty() && std::count_if(d.paper_checks.begin(), d.paper_checks.end(),
                                                 [&](const engine::paper_comparison& q) {
                                                     return q.paper == p.paper && q.quote == p.quote;
                                                 }) > 1;
    };
    if (p.agrees() && !p.printed.info(GiNaC::info_flags::relation) && !p.printed.is_equal(r.display) &&
        component())
        return {p.printed, &p.written};
    if (const auto corrected = corrected_form(p, r.display))
        return {*corrected, &p.written};
    return {r.display, &r.written};
}

std::optional<GiNaC::ex> corrected_form(const engine::paper_comparison& p, const GiNaC::ex& shown)
{
    if (p.agrees() || p.what == engine::paper_comparison::kind::claim)
        return std::nullopt;
    const auto symbols_of = [](const GiNaC::ex& e) {
        std::set<GiNaC::ex, GiNaC::ex_is_less> found;
        for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it))
                found.insert(*it);
        return found;
    };
    std::optional<GiNaC::ex> found;
    for (const engine::finding& f : p.findings) {
        if (!f.corrected)
            continue;
        if (found)
            return std::nullopt;   // several changes reconcile it: no one form is the derived
        found = f.corrected;
    }
    if (!found)
        return std::nullopt;
    // The shown form in the variables of the printed form mended (Appendix A's M, which the
    // misprint lost) is in the paper's variables already.
    const auto mended = symbols_of(*found);
    const auto in_shown = symbols_of(shown);
    if (std::includes(mended.begin(), mended.end(), in_shown.begin(), in_shown.end(), GiNaC::ex_is_less()))
        return std::nullopt;
    return found;
}

namespace detail {

// The words of a comparison's findings, in LaTeX, joined by semicolons: `which` of them,
// those about dimensions, the changes, or all.
std::string fragment_writer::findings(const engine::paper_comparison& p, finding_kind which) const
{
    std::string out;
    for (const engine::finding& f : p.findings) {
        const bool dimensional = std::any_of(f.parts.begin(), f.parts.end(), [](const engine::finding::part& part) {
            return part.what == engine::finding::part::kind::dimension;
        });
        if ((which == finding_kind::dimensions && !dimensional) || (which == finding_kind::changes && dimensional))
            continue;
        // Parts of the printed form a finding names are turned the way the paper writes them.
        out += (out.empty() ? "" : "; ") + finding_latex(f, order_, p.written.empty() ? nullptr : &p.written, &p);
    }
    return out;
}

// What a comparison is about: the quantity's symbol, an equation's name in words, or
// "claim".
std::string fragment_writer::subject(const engine::paper_comparison& p) const
{
    if (p.what == engine::paper_comparison::kind::claim)
        return "claim";
    if (const engine::quantity* q = d_.symbols.find(p.subject); q && p.what == engine::paper_comparison::kind::result)
        return "$" + math(q->symbol) + "$";
    std::string name = p.subject;
    std::replace(name.begin(), name.end(), '_', ' ');
    return latex_text(name) + " (equation)";
}

// What to say of a disagreement no edit, or two, reconciles: for a claim, the claim as
// checked (which the table does not show otherwise) does not hold; for a printed form,
// the derived form beside it is what is right.
std::string fragment_writer::unreconciled(const engine::paper_comparison& p, double width) const
{
    if (p.what != engine::paper_comparison::kind::claim || !p.test)
        return "no edit, or two, reconciles it; the derived form is what holds";
    const engine::check_result& c = *p.test;
    const std::string checked = claim_math(c, order_, &c.written);
    // Too wide to set inline where it is said: the claim as checked is displayed beside it.
    if (!fits(checked, width) || latex_width(checked) > width)
        return "the claim, as checked, does not hold";
    std::string out = "as checked, $" + checked + "$";
    std::vector<std::string> at;
    for (const auto& [symbol, value] : c.at)
        at.push_back(fmt::format("${} = {}$", math(symbol), math(value)));
    if (!at.empty())
        out += " at " + listing(at);
    return out + ", it does not hold";
}

// The derived form to set beside a printed one: the result as its file displays it, or
// the printed form mended when that display is in variables the printed form does not use
// (corrected_form), else as derived.
std::pair<GiNaC::ex, const written_form*> fragment_writer::derived_form(const engine::paper_comparison& p) const
{
    if (p.what == engine::paper_comparison::kind::result)
        if (const engine::result* r = d_.find_result(p.subject))
            return result_beside(d_, p, *r);
    // Else as a textbook shows it: factored, or collected (a root's argument likewise).
    return {textbook(p.derived).value, nullptr};
}

// An expression or an equation as a display, broken over lines.
std::string fragment_writer::shown(const GiNaC::ex& e, const written_form* w) const
{
    if (e.info(GiNaC::info_flags::relation))
        return display(math(e.lhs(), w), "=", e.rhs(), w);
    return display("", "", e, w);
}

// A printed form as the paper prints it: the transcription's own terms, factors and
// parentheses, nothing merged (written_form::tree); GiNaC's reading of it only when the
// text could not be followed.
std::string fragment_writer::as_printed(const engine::paper_comparison& p) const
{
    if (const auto& tree = p.written.tree())
        return latex_as_written(*tree, order_);
    return p.printed.info(GiNaC::info_flags::relation) ? relation_math(p.printed, &p.written)
                                                       : math(p.printed, &p.written);
}

// The paper's own text of a printed form the file reads in other terms (one component of
// R^T v^(C)', a name the paper does not use), then "read as": what precedes the form as
// read; empty for a form read as printed.
std::string fragment_writer::read_as(const engine::paper_comparison& p) const
{
    return p.quote.empty() ? "" : latex_prose(p.quote) + ", read as ";
}

// The same as a display, a long right side broken before a + or -.
std::string fragment_writer::shown_as_printed(const engine::paper_comparison& p) const
{
    const auto& tree = p.written.tree();
    if (!tree)
        return shown(p.printed, &p.written);
    using node = written_form::node;
    const bool relation = tree->what == node::kind::relation && tree->children.size() == 2;
    const std::string lhs = relation ? latex_as_written(tree->children[0], order_) : "";
    const char* op = !relation ? "" : tree->name == "<=" ? "\\leq" : tree->name == ">=" ? "\\geq" : tree->name.c_str();
    const double room = content_width - latex_width(lhs) - 34;
    const std::vector<std::string> lines =
        latex_lines_as_written(relation ? tree->children[1] : *tree, order_, std::max(room, 150.0));
    std::string out = fmt::format("\n\\begin{{align*}}\n  {} &{} {}", lhs, op, lines.front());
    for (std::size_t i = 1; i < lines.size(); ++i)
        out += " \\\\\n  &\\qquad " + lines[i];
    return out + "\n\\end{align*}\n";
}

// A row of the report's errata table, one finding (emit::errata_rows): a claim, a printed
// form, or the consecutive components of one line that one misprint explains (Eq. 9's
// lab-frame components). Forms wider than their column are set under the table as
// numbered displays (T1), (T2), ...
void fragment_writer::errata_row(errata_table& table, const std::vector<std::size_t>& group) const
{
    constexpr double printed_pt = 122, derived_pt = 99, change_pt = 78;
    // Each comparison as shown: a claim in degrees answered in degrees.
    std::vector<engine::paper_comparison> all;
    for (const engine::paper_comparison& c : d_.paper_checks)
        all.push_back(in_the_papers_units(c));
    const engine::paper_comparison& p = all[group.front()];
    std::vector<std::string> subjects;
    for (std::size_t k : group)
        if (subjects.empty() || p.what != engine::paper_comparison::kind::claim)
            subjects.push_back(subject(all[k]));
    const std::string verdict = row_verdict(d_, group);
    const bool agrees = verdict == "agrees";
    const bool claim = p.what == engine::paper_comparison::kind::claim;

    std::string printed, printed_math;
    if (p.what == engine::paper_comparison::kind::claim)
        printed = "``" + latex_prose(p.printed_text) + "''";
    else
        printed_math = as_printed(p);
    const auto [derived, derived_written] = derived_form(p);
    // Beside every printed form, agreeing or not, what Impact derived (a claim shows what
    // was checked instead).
    const std::string derived_math = claim ? ""
                                     : derived.info(GiNaC::info_flags::relation)
                                         ? relation_math(derived, derived_written)
                                         : math(derived, derived_written);
    // What was found, comparison by comparison; a claim shows what was checked beside
    // it, so that it does not hold is then enough.
    auto change_of = [&](const engine::paper_comparison& c) {
        if (std::string said = agreement_text(c); !said.empty())
            return said;
        std::string found = findings(c);
        if (found.empty())
            found = c.what == engine::paper_comparison::kind::claim && c.test ? "as checked, it does not hold"
                                                                             : unreconciled(c, change_pt);
        return found;
    };
    std::string change = change_of(p);
    if (claim && group.size() > 1) {
        // The claims of one quote: one finding, each check's outcome where they differ.
        std::vector<const engine::paper_comparison*> claims;
        for (std::size_t k : group)
            claims.push_back(&all[k]);
        change = one_finding(claims, change_of);
    } else if (!agrees && verdict == "disagrees" && group.size() > 1) {
        change += fmt::format("; one misprint, in each of the {} components", group.size());
    }

    bool to_display = (!printed_math.empty() && !fits(read_as(p) + printed_math, printed_pt)) ||
                      (!derived_math.empty() && !fits(derived_math, derived_pt));
    for (std::size_t k : group)
        for (const engine::finding& f : all[k].findings)
            for (const engine::finding::part& part : f.parts)
                if (part.what == engine::finding::part::kind::math &&
                    !fits(part.value.info(GiNaC::info_flags::relation) ? relation_math(part.value, nullptr, part.op)
                                                                       : math(part.value),
                          change_pt))
                    to_display = true;
    std::string printed_cell = printed.empty() ? read_as(p) + "$" + printed_math + "$" : printed;
    std::string checks_displayed;
    std::string derived_cell = derived_math.empty() ? "" : "$" + derived_math + "$";
    // A claim: what was checked (at its special values, or its limit), when it fits.
    if (claim && p.test) {
        std::vector<std::string> each;
        for (std::size_t k : group)
            if (all[k].test)
                each.push_back(checked_claim_latex(*all[k].test, order_));
        // Each check on a line of its own in the cell, when each fits.
        const bool each_fits = std::all_of(each.begin(), each.end(), [&](const std::string& c) {
            return fits(c, derived_pt) && cell_width(c) <= 2.5 * derived_pt;
        });
        if (each_fits) {
            derived_cell = "checked: " + fmt::format("{}", fmt::join(each, ";\\newline "));
        } else {
            // Too wide for the cell: displayed under the table, so that the table is whole.
            for (std::size_t k : group)
                if (all[k].test)
                    checks_displayed += checked_display(*all[k].test);
            to_display = true;
        }
    }
    std::string change_cell = change;
    if (to_display) {
        const std::string mark = fmt::format("(T{})", ++table.displayed);
        const std::string see = "display " + mark + " below";
        table.displays += fmt::format("\\item[{}] {}, {}: ", mark, paper_text(p.paper), listing(subjects));
        // A claim's words stay in the row's cell: the display shows what was checked.
        if (!printed_math.empty()) {
            table.displays += "printed " + read_as(p) + shown_as_printed(p);
            printed_cell = see;
        }
        if (!derived_math.empty()) {
            table.displays += "Derived" + shown(derived, derived_written);
            derived_cell = see;
        }
        if (!checks_displayed.empty()) {
            table.displays += "checked as" + checks_displayed;
            derived_cell = see;
        }
        if (!agrees) {
            table.displays += (derived_math.empty() ? " " : "") + capitalised(change) + ".\n";
            change_cell = see;
        } else {
            table.displays += "It agrees (" + change + ").\n";
        }
    }
    table.rows += fmt::format("{} (Sect.~\\ref{{{}}}) & {} & {} & {} & {} & {} \\\\\n", paper_text(p.paper),
                              latex_label(d_), listing(subjects),
                              agrees ? verdict : "\\textbf{" + verdict + "}", printed_cell, derived_cell,
                              change_cell);
}

// A comparison of the paper's words: a claim no derivation settles (undecided, with the
// reason), or an entry of its references (agrees, or what is wrong with it).
void fragment_writer::errata_row(errata_table& table, const engine::text_comparison& t) const
{
    const std::string verdict = engine::to_string(t.verdict);
    const bool reference = t.what == engine::text_comparison::kind::reference;
    table.rows += fmt::format("{} (Sect.~\\ref{{{}}}) & {} & {} & ``{}'' & & {} \\\\\n", paper_text(t.paper),
                              latex_label(d_), reference ? "reference entry" : "claim",
                              verdict == "agrees" ? verdict : "\\textbf{" + verdict + "}", latex_prose(t.printed),
                              capitalised(latex_prose(t.finding)));
}

} // namespace detail

errata_table latex_errata(const std::vector<const engine::derivation*>& derivations,
                          const spec::paper_outline* outline)
{
    errata_table table;
    for (const errata_entry& e : errata_entries(derivations, outline)) {
        const detail::fragment_writer writer(*e.derivation);
        if (e.words)
            writer.errata_row(table, *e.words);
        else
            writer.errata_row(table, e.comparisons);
    }
    return table;
}

} // namespace impact::emit
