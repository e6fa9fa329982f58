#include "report/report.h"

#include "report/pdf.h"
#include "report/report_tex.h"
#include "report/figures.h"

#include "spec/error.h"

#include <fmt/format.h>

namespace impact::report {

std::map<std::string, std::string> figures_and_report(const engine::library& lib,
                                                      const std::map<std::string, std::string>& generated)
{
    std::map<std::string, std::string> files;
    for (auto& [path, contents] : figure_files())
        files[path] = contents;
    files["report.tex"] = report::report_tex(lib.in_order(), {"figures/billiard", "figures/scatter_angle"});

    if (!report::have_pdflatex())
        throw error({"report.tex", 0, 0}, "pdflatex is not installed; run scripts/setup.sh to install TeX Live");
    std::map<std::string, std::string> sources;
    for (const auto& [path, contents] : generated)
        if (path.rfind("latex/", 0) == 0)
            sources[path] = contents;
    for (const auto& [path, contents] : files)
        sources[path] = contents;
    const report::pdf_build pdf = report::compile_latex(sources, "report.tex");
    if (!pdf.ok)
        throw error({"report.tex", 0, 0},
                    fmt::format("the report does not compile cleanly: {}",
                                pdf.problems.empty() ? std::string("no PDF") : pdf.problems.front()));
    files["report.pdf"] = pdf.pdf;
    return files;
}

} // namespace impact::report
