// The report stage: the figures, computed with the generated kernels (Figs. 2 and 3),
// report.tex and the compiled report.pdf, from the derived library and the LaTeX
// fragments that emit wrote.
//
// The sources (`report_sources`) are made on the thread that derived the library, since
// they print GiNaC expressions; compiling them (`compile_report`) touches no GiNaC object
// and runs pdflatex in scratch folders, so that the pipeline runs it beside the choice of
// kernel forms. Each figure's picture is compiled on its own, into the PDF that its
// figure includes, and the report after them: with a cache, a PDF is compiled only when
// its sources or the TeX installation changed, so that a changed derivation recompiles
// the report and not the figures.
//
// Compiled against the generated kernel headers (build/generated/kernels), which the
// build's kernel generator writes from the stages before this one.
#pragma once

#include "engine/library/library.h"
#include "verify/proofs.h"

#include <functional>
#include <map>
#include <string>

namespace impact::cache {
class store;
}

namespace impact::report {

struct compile_options {
    cache::store* store = nullptr;                     ///< PDFs kept by their sources' content, or none
    std::function<void(const std::string&)> doing;     ///< told what is being compiled, for a progress line
};

/// figures/*.dat, figures/*.tex and report.tex for the derived library (with `z3`, the count
/// of proven claims Z3 confirmed in its introduction).
std::map<std::string, std::string> report_sources(const engine::library& lib, const verify::proof_checks* z3 = nullptr);

/// figures/<name>_plot.pdf for each figure (compiled side by side) and report.pdf, from
/// `sources`: report_sources' files and the latex/<id>.tex fragments the report \input's.
/// Throws `impact::error` when pdflatex is missing or a document does not compile cleanly.
std::map<std::string, std::string> compile_report(const std::map<std::string, std::string>& sources,
                                                  const compile_options& options = {});

/// report_sources and compile_report in one: every file of the report, for the derived
/// library whose other generated files are `generated`.
std::map<std::string, std::string> figures_and_report(const engine::library& lib,
                                                      const std::map<std::string, std::string>& generated,
                                                      const compile_options& options = {});

} // namespace impact::report
