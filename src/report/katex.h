// Formulas typeset for the web pages by KaTeX (Debian's libjs-katex), run with Node.js when
// the pages are written, so that a page needs no JavaScript to show its mathematics. Each
// formula becomes KaTeX's HTML with its MathML beside it (for screen readers); the fonts and
// the style sheet are copied beside the pages.
#pragma once

#include "report/html_tex.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace impact::report::katex {

/// Where KaTeX is: `$IMPACT_KATEX` (a folder holding katex.js, katex.min.css and fonts/),
/// else /usr/share/javascript/katex.
std::string folder();

/// Why the pages cannot be typeset here (node or KaTeX missing), or nothing.
std::optional<std::string> missing();

/// What identifies the KaTeX installation and the node running it, for the cache's keys.
const std::string& installation();

/// A formula and the page it is on, named in an error.
struct request {
    html::formula formula;
    std::string page;
};

/// Each formula typeset, in order (identical formulas typeset once). Throws `impact::error`
/// naming the page and the formula KaTeX cannot typeset, with KaTeX's own message.
std::vector<std::string> typeset(const std::vector<request>& formulas);

/// KaTeX's style sheet and the fonts it names (woff2), by their paths under output/html/
/// (`katex/katex.min.css`, `katex/fonts/KaTeX_Main-Regular.woff2`, ...).
std::map<std::string, std::string> assets();

} // namespace impact::report::katex
