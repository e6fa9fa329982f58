#include "simulate/regeneration.h"

#include "emit/pdf.h"
#include "emit/report.h"
#include "simulate/figures.h"

#include <fmt/format.h>

namespace impact::simulate {

pipeline::file_set figures_and_report(const pipeline::library& lib, const pipeline::file_set& generated)
{
    pipeline::file_set files;
    for (auto& [path, contents] : figure_files())
        files[path] = contents;
    files["report.tex"] = emit::report_tex(lib.in_order(), {"figures/billiard", "figures/scatter_angle"});

    if (!emit::have_pdflatex())
        throw error({"report.tex", 0, 0}, "pdflatex is not installed; run scripts/setup.sh to install TeX Live");
    std::map<std::string, std::string> sources;
    for (const auto& [path, contents] : generated)
        if (path.rfind("latex/", 0) == 0)
            sources[path] = contents;
    for (const auto& [path, contents] : files)
        sources[path] = contents;
    const emit::pdf_build pdf = emit::compile_latex(sources, "report.tex");
    if (!pdf.ok)
        throw error({"report.tex", 0, 0},
                    fmt::format("the report does not compile cleanly: {}",
                                pdf.problems.empty() ? std::string("no PDF") : pdf.problems.front()));
    files["report.pdf"] = pdf.pdf;
    return files;
}

} // namespace impact::simulate
