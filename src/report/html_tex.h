// The report's LaTeX as HTML: the dialect Impact's own LaTeX writers use (report.tex and the
// derivations' fragments, emit/latex.h), turned into HTML with its mathematics set aside for
// KaTeX (report/katex.h).
//
// Text-mode LaTeX is what Impact writes and nothing more: sections and paragraphs' headings,
// lists, the aligned displays of givens and results with their tags and labels, \intertext,
// the errata's longtable, figures, \ref and \eqref, emphasis, quotes and dashes. Anything else
// is an error that names the page, the line and the command, so that no raw TeX reaches a
// page. Each formula becomes a placeholder in the HTML (`placeholder(i)`) and an entry of
// `formulas`, rendered afterwards in one batch and put in its place.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace impact::report::html {

/// A formula to render: its TeX, and whether it is displayed (a row of an align) or inline.
struct formula {
    std::string tex;
    bool display = false;
};

/// Where a \label points, and what \ref prints for it: the page (`index.html`,
/// `<id>.html`), the anchor on it, and the text ("G1", "Eq. (8), right, first line",
/// "2.3"); \eqref prints the text in parentheses.
struct target {
    std::string page;
    std::string anchor;
    std::string text;
};
using targets = std::map<std::string, target>;

/// The anchor of a label on its page: "impact:<id>:result:v_M_after" → "result-v_M_after"
/// on <id>.html, "impact:<id>" → "" (the page itself), "sec:errata" → "errata",
/// "fig:billiard" → "fig-billiard".
target place_of(const std::string& label);

/// Every label of `document` (report.tex with the files it `\input`s in place, from `files`
/// by their paths: latex/<id>.tex, figures/<name>.tex), numbered as LaTeX numbers them:
/// sections and subsections (2, 2.3), figures, and each equation by its \tag.
targets labels_of(const std::string& document, const std::map<std::string, std::string>& files);

/// What the conversion of one page gathers beside its HTML.
struct page {
    std::string html;                ///< the body, formulas as placeholders
    std::string title;               ///< the first \section's or \subsection's heading, as text
    std::vector<formula> formulas;   ///< in the order of their placeholders
};

/// The HTML of `tex`, a fragment (`name` latex/<id>.tex) or report.tex's body, with links
/// from `labels`; `page_name` is the page it goes on (links to it are `#anchor` alone).
/// `input` is called for each \input{path} of the body and returns the HTML to put there.
/// Throws `impact::error` at `name`'s line for what it cannot convert.
struct input_handler {
    virtual ~input_handler() = default;
    virtual std::string input(const std::string& path, page& into) = 0;
};
page convert(const std::string& tex, const std::string& name, const std::string& page_name, const targets& labels,
             input_handler* inputs = nullptr);

/// The placeholder of formula `i` in a page's HTML.
std::string placeholder(std::size_t i);

/// `text` escaped for HTML (&, <, >, ").
std::string escaped(const std::string& text);

} // namespace impact::report::html
