// What `impact regenerate` adds to the files of the pipeline: the figures, computed
// with the generated kernels, and the report (report.tex and the compiled report.pdf).
//
// This lives apart from src/pipeline/ because it is compiled against the generated
// kernel headers (build/generated/kernels), which the pipeline itself generates.
#pragma once

#include "pipeline/regenerate.h"

namespace impact::simulate {

/// figures/*.dat and figures/*.tex, report.tex and report.pdf, for the derived library
/// whose other generated files are `generated` (the report \input's latex/<id>.tex).
/// Throws `impact::error` when pdflatex is missing or the report does not compile cleanly.
pipeline::file_set figures_and_report(const pipeline::library& lib, const pipeline::file_set& generated);

} // namespace impact::simulate
