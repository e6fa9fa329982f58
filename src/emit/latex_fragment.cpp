// The LaTeX fragment of a derivation: quantities, givens, steps and results, typeset as a
// textbook's derivation. This file writes the whole, the printing every part shares, the
// quantities and the givens; the steps are latex_steps.cpp's, the results
// latex_results.cpp's, its checks latex_claims.cpp's and the paper's printed forms
// latex_paper.cpp's.
#include "emit/latex.h"
#include "emit/latex_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace impact::emit {
namespace detail {

// "Eq. 8" → "Eq.~8" in running text.
// A place in the paper as a physicist cites it: "Eq. 3, line 2" is "Eq.~(3), second
// line", "Sec. III C, after Eq. 14, 5th sentence" "Sec. III C, after Eq.~(14), 5th
// sentence", "Appendix A, line 5" "Appendix A, fifth line".
std::string paper_text(const std::string& paper)
{
    static const char* const ordinals[] = {"first",   "second", "third",    "fourth",  "fifth",
                                           "sixth",   "seventh", "eighth",  "ninth",   "tenth",
                                           "eleventh", "twelfth", "thirteenth"};
    std::string out;
    std::size_t at = 0;
    while (at < paper.size()) {
        const bool eq = paper.compare(at, 4, "Eq. ") == 0;
        const bool line = paper.compare(at, 5, "line ") == 0 && (at == 0 || paper[at - 1] == ' ');
        if (eq || line) {
            std::size_t end = at + (eq ? 4 : 5);
            while (end < paper.size() && std::isalnum(static_cast<unsigned char>(paper[end])))
                ++end;
            const std::string number = paper.substr(at + (eq ? 4 : 5), end - at - (eq ? 4 : 5));
            const bool whole = !number.empty() && std::all_of(number.begin(), number.end(), [](char c) {
                return std::isdigit(static_cast<unsigned char>(c));
            });
            if (eq && !number.empty()) {
                out += "Eq.~(" + latex_text(number) + ")";
                at = end;
                continue;
            }
            if (line && whole && std::stoul(number) >= 1 && std::stoul(number) <= std::size(ordinals)) {
                out += std::string(ordinals[std::stoul(number) - 1]) + " line";
                at = end;
                continue;
            }
        }
        out += latex_text(std::string(1, paper[at]));
        ++at;
    }
    return out;
}

std::string condition_latex(const engine::condition& c, const term_order& order)
{
    const auto [left, right] = engine::condition_sides(c.expr);   // x \\neq y, r_x^2 + r_y^2 > 0
    const char* op = c.need == engine::condition::kind::nonzero    ? "\\neq"
                     : c.need == engine::condition::kind::positive ? ">"
                                                                   : "\\geq";
    return fmt::format("{} {} {}", latex(left, order), op, latex(right, order));
}

std::string conditions_latex(const std::vector<engine::condition>& conditions, const term_order& order)
{
    std::vector<std::string> each;
    for (const engine::condition& c : conditions)
        each.push_back("$" + condition_latex(c, order) + "$");
    return listing(each);
}

std::string status_text(const engine::verdict& v, const term_order& order)
{
    const std::string where = v.where.empty() ? "" : ", where " + conditions_latex(v.where, order);
    switch (v.what) {
    case engine::verdict::status::proven: return "\\textbf{proven}" + where;
    case engine::verdict::status::sampled: return fmt::format("\\textit{{sampled ({} points)}}{}", v.samples, where);
    case engine::verdict::status::failed: break;
    }
    return "\\textbf{FAILED}";
}

std::string capitalised(std::string text)
{
    // A one-letter name opening the sentence is a symbol, kept as written: sphere m is not
    // sphere M ("m's velocity along the line of action").
    const bool symbol = text.size() >= 2 && std::isalpha(static_cast<unsigned char>(text[0])) &&
                        !std::isalpha(static_cast<unsigned char>(text[1])) && text[1] != '-';
    const bool article = text.size() >= 2 && (text[0] == 'a' || text[0] == 'A') && text[1] == ' ';
    if (!text.empty() && (!symbol || article))
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

// Joins items as "a, b and c".
std::string listing(const std::vector<std::string>& items)
{
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0)
            out += i + 1 == items.size() ? " and " : ", ";
        out += items[i];
    }
    return out;
}

fragment_writer::fragment_writer(const engine::derivation& d, const engine::derived_by_id* used)
    : d_(d), used_(used), order_(engine::declaration_order(d.symbols))
{
    int g = 0;
    for (const engine::equation& e : d.givens)
        tags_[e.name] = fmt::format("G{}", ++g);
    int s = 0;
    for (const engine::step_result& st : d.steps)
        if (st.yields)
            tags_[st.yields->name] = fmt::format("S{}", ++s);
}

std::string fragment_writer::write()
{
    std::string out = fmt::format("% Generated by Impact from {}; do not edit.\n"
                                  "% Needs \\usepackage{{amsmath,amssymb}}.\n",
                                  d_.source_name());
    out += fmt::format("\\subsection{{{}{}}}\\label{{{}}}\n", latex_text(d_.source.title.value),
                       d_.source.paper ? " (" + paper_text(d_.source.paper->value) + ")" : "", latex_label(d_));
    if (!d_.source.summary.value.empty())
        out += latex_prose(d_.source.summary.value) + "\n";
    out += quantities();
    out += givens();
    out += steps();
    out += results();
    out += checks();
    out += paper();
    return out;
}

std::string fragment_writer::math(const GiNaC::ex& e, const written_form* w) const
{
    if (w)
        return latex(e, order_, w);
    auto found = printed_.find(e);
    if (found == printed_.end())
        found = printed_.emplace(e, latex(e, order_)).first;
    return found->second;
}

std::string fragment_writer::relation_math(const GiNaC::ex& r, const written_form* w, engine::relation op) const
{
    return math(r.lhs(), w) + " " + latex_relation(op) + " " + math(r.rhs(), w);
}

const textbook_value& fragment_writer::textbook(const GiNaC::ex& e) const
{
    auto found = textbooks_.find(e);
    if (found == textbooks_.end())
        found = textbooks_.emplace(e, textbook_form(e, order_)).first;
    return found->second;
}

// `lhs &= rhs` rows of an align, the right side broken over lines when long; the last
// line gets `tag`. Every line starts at the alignment point, after the widest left side
// of the block (`align_at`, by default this one's). A left side too wide to leave room
// gets a line of its own, the relation starting the next.
std::string fragment_writer::rows(const std::string& lhs, const GiNaC::ex& rhs, const written_form* w,
                                  const std::string& tag, const char* relation, double align_at) const
{
    // The tag, set at the right of the last line, takes about 5 pt a character and a gap.
    double tag_width = 0;
    if (const auto at = tag.find("\\tag"); at != std::string::npos) {
        const auto open = tag.find('{', at);
        tag_width = 5.0 * static_cast<double>(tag.find('}', open) - open - 1) + 25;
    }
    const double side = align_at >= 0 ? align_at : latex_width(lhs);
    const bool own_line = side > 0.4 * content_width;
    const double indent = own_line ? 20 : side;
    const double first = content_width - indent - 14 - tag_width;
    const double others = content_width - indent - 20 - tag_width;
    const std::vector<std::string> lines =
        latex_lines(rhs, order_, w, std::max(first, 150.0), std::max(others, 150.0));
    const std::string notag = tag.empty() ? "" : " \\notag";
    std::string out = own_line ? fmt::format("  & {}{} \\\\\n  &\\qquad {} {}", lhs, notag, relation, lines.front())
                               : fmt::format("  {} &{} {}", lhs, relation, lines.front());
    for (std::size_t i = 1; i < lines.size(); ++i)
        out += fmt::format("{} \\\\\n  &\\qquad {}{{}}{}", notag, own_line ? "\\quad " : "", lines[i]);
    return out + (tag.empty() ? "" : " " + tag);
}

std::string fragment_writer::ref(const std::string& equation) const
{
    const auto tag = tags_.find(equation);
    if (tag == tags_.end())
        return latex_text(equation);
    return fmt::format("\\eqref{{{}:{}}}", latex_label(d_), equation);
}

// A quantity's SI unit, e.g. $\mathrm{kg\,m^{2}\,s^{-2}}$, or "dimensionless".
std::string si_unit_latex(const engine::dimension& d)
{
    if (d.is_pure_number())
        return "dimensionless";
    std::string out;
    for (const auto& [unit, e] : d.si_factors()) {
        if (!out.empty())
            out += "\\,";
        out += unit;
        if (e != 1) {
            std::ostringstream exponent;
            exponent << e;
            out += "^{" + exponent.str() + "}";
        }
    }
    return "$\\mathrm{" + out + "}$";
}

std::string fragment_writer::quantities() const
{
    std::string out = "\n\\paragraph{Quantities.}\n\\begin{itemize}\\setlength{\\itemsep}{0pt}\n";
    std::set<std::string> listed;
    for (const engine::quantity& q : d_.symbols.all()) {
        // A quantity under another name, for another printed line (tau again for Eq. 12's
        // second line, Delta v written with J and with eps): one symbol to the reader,
        // listed once.
        if (!listed.insert(math(q.symbol)).second)
            continue;
        if (q.definition) {
            out += fmt::format("\\item ${} = {}$", math(q.symbol), math(*q.definition, &q.written));
            // A declared domain of an abbreviation is an assumption the proofs use (s_n > 0:
            // the spheres approach).
            if (q.range.what != engine::domain::kind::real)
                out += fmt::format(", ${} {}$", math(q.symbol), q.range.to_latex());
        } else {
            out += fmt::format("\\item ${} {}$", math(q.symbol), q.range.to_latex());
        }
        if (q.dim)
            out += " (" + si_unit_latex(*q.dim) + ")";
        const std::string from = imported_from(q);
        out += q.meaning.empty() ? (from.empty() ? "" : ": " + from)
                                 : ": " + latex_prose(q.meaning) + (from.empty() ? "" : "; " + from);
        out += "\n";
    }
    return out + "\\end{itemize}\n";
}

// A quantity `[[use]]` imports is the result of another derivation: said where it is listed,
// that derivation named by its title (as its section is headed) and the result by its symbol
// there when it is written otherwise here, and by the paper's place when it has one.
std::string fragment_writer::imported_from(const engine::quantity& q) const
{
    for (const spec::use& u : d_.source.uses)
        for (const spec::binding& b : u.results) {
            if (b.name.value != q.name)
                continue;
            const std::string& id = u.derivation.value;
            const engine::derivation* other = nullptr;
            if (used_)
                if (const auto found = used_->find(id); found != used_->end())
                    other = &found->second;
            const engine::result* r = other ? other->find_result(b.expression.value) : nullptr;
            if (!other || !r)
                return fmt::format("the result {} of the derivation \\texttt{{{}}}", latex_text(b.expression.value),
                                   latex_text(id));
            const std::string there = math(r->symbol);
            std::string out = there == math(q.symbol) ? "the result" : "the result $" + there + "$";
            out += " of \\emph{" + latex_text(other->source.title.value) + "}";
            if (!r->paper.empty())
                out += ", " + paper_text(r->paper);
            else if (other->source.paper)
                out += " (" + paper_text(other->source.paper->value) + ")";
            return out;
        }
    return "";
}

std::string fragment_writer::givens() const
{
    if (d_.givens.empty())
        return "";
    std::string out = "\n\\paragraph{Given.}\n";
    for (std::size_t i = 0; i < d_.givens.size(); ++i) {
        const engine::equation& g = d_.givens[i];
        const std::string why = capitalised(latex_prose(g.because)) +
                                (g.paper.empty() ? "" : " (" + paper_text(g.paper) + ")") + ":";
        if (i == 0)
            out += why + "\n\\begin{align}\n";
        else
            out += fmt::format("\\intertext{{{}}}\n", why);
        out += rows(math(g.relation.lhs(), &g.written), g.relation.rhs(), &g.written,
                    fmt::format("\\tag{{{}}}\\label{{{}:{}}}", tags_.at(g.name), latex_label(d_), g.name));
        out += i + 1 < d_.givens.size() ? " \\\\\n" : "\n";
    }
    return out + "\\end{align}\n";
}

} // namespace detail

std::string latex_fragment_name(const engine::derivation& d)
{
    return d.id() + ".tex";
}

std::string latex_label(const engine::derivation& d)
{
    return "impact:" + d.id();
}

std::string latex_fragment(const engine::derivation& d, const engine::derived_by_id* used)
{
    return detail::fragment_writer(d, used).write();
}

} // namespace impact::emit
