// The standalone report, `output/report.tex`: every derivation's fragment, the errata
// table (the paper held to account) and the figures, in one LaTeX document.
#pragma once

#include "verify/proofs.h"

#include "engine/derivation/derivation.h"
#include "report/figures.h"
#include "spec/outline.h"

#include <string>
#include <vector>

namespace impact::report {

/// The report's LaTeX source. Where a derivation has a place in the paper (its `paper`),
/// the paper's report: it \input's `latex/<id>.tex` for each derivation of the paper (in the
/// order given) and the paper's `figures` (`figures/<name>`); then, in the chapter beyond the
/// paper (on rough spheres when their figure is among `figures`), the derivations that have
/// no `paper` and the figures the paper has not. Otherwise (a folder of one's own) a report
/// of its derivations, titled so, with the figures it is given. The errata table, typeset
/// from the derivations' comparisons in the paper's order when `outline` gives it, is there
/// when some file transcribes a printed line or claim. The PDF it makes is the same bytes on
/// every run (no dates, no trailer id). With `z3`, its introduction says in one sentence
/// how many of the proven claims Z3 confirmed.
std::string report_tex(const std::vector<const engine::derivation*>& derivations, const std::vector<figure>& figures,
                       const spec::paper_outline* outline = nullptr, const verify::proof_checks* z3 = nullptr);

/// The preamble the report and the test documents share (packages, PDF determinism).
std::string report_preamble();

} // namespace impact::report
