// The standalone report, `output/report.tex`: every derivation's fragment, the errata
// table (the paper held to account) and the figures, in one LaTeX document.
#pragma once

#include "engine/derive.h"
#include "spec/outline.h"

#include <string>
#include <vector>

namespace impact::report {

/// The report's LaTeX source. It \input's `latex/<id>.tex` for each derivation of the
/// paper (in the order given) and each of `figures` (paths relative to the output folder,
/// without `.tex`); then, in the chapter "Beyond the paper: rough spheres", the derivations
/// that have no `paper` and `beyond_figures`; and it typesets the errata table from the
/// derivations' paper comparisons, in the paper's order when `outline` gives it. The PDF
/// it makes is the same bytes on every run (no dates, no trailer id).
std::string report_tex(const std::vector<const engine::derivation*>& derivations,
                       const std::vector<std::string>& figures, const std::vector<std::string>& beyond_figures,
                       const spec::paper_outline* outline = nullptr);

/// The preamble the report and the test documents share (packages, PDF determinism).
std::string report_preamble();

} // namespace impact::report
