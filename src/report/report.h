// The report stage: the figures, computed with the generated kernels (Figs. 2 and 3),
// report.tex and the compiled report.pdf, from the derived library and the LaTeX
// fragments that emit wrote.
//
// Compiled against the generated kernel headers (build/generated/kernels), which the
// build's kernel generator writes from the stages before this one.
#pragma once

#include "engine/library.h"

#include <map>
#include <string>

namespace impact::report {

/// figures/*.dat and figures/*.tex, report.tex and report.pdf, for the derived library
/// whose other generated files are `generated` (the report \input's latex/<id>.tex).
/// Throws `impact::error` when pdflatex is missing or the report does not compile cleanly.
std::map<std::string, std::string> figures_and_report(const engine::library& lib,
                                                      const std::map<std::string, std::string>& generated);

} // namespace impact::report
