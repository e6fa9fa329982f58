// The report as web pages, output/html/: index.html (the report's introduction, its contents,
// the errata table and the figures) and one page for each derivation, converted from the same
// LaTeX as report.pdf (report/html_tex.h), the formulas typeset by KaTeX when the pages are
// written (report/katex.h), the figures as SVG made from their PDFs (pdftocairo), KaTeX's
// style sheet and fonts and Impact's own copied beside them: pages that need neither
// JavaScript nor the network.
//
// Every result, given equation and figure keeps its LaTeX label as its anchor on its page
// (`inelastic_line.html#result-v_M_after`), every row of the errata table one made from the
// place in the paper it is about (`index.html#errata-eq-12-third-line`), so that a link to
// one survives a regeneration.
#pragma once

#include <map>
#include <string>

namespace impact::cache {
class store;
}

namespace impact::report {

/// The pages and their files, by their paths under output/ (`html/index.html`, ...), from
/// `sources`: report.tex, the fragments latex/<id>.tex and the figures' PDFs
/// figures/<name>_plot.pdf. With a store, kept by the sources' content. Throws
/// `impact::error` when node, KaTeX or pdftocairo is missing, or a formula or a command of
/// the LaTeX cannot be shown.
std::map<std::string, std::string> html_site(const std::map<std::string, std::string>& sources,
                                             cache::store* store = nullptr);

/// Where a derivation's page takes its kernels and their accuracy (emit::verification_html),
/// which are measured beside the pages: the pipeline puts them in its place.
inline constexpr const char* html_kernels_marker = "<!--kernels-->\n";

} // namespace impact::report
