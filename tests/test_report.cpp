// The compiled report: output/report.tex and every derivation's fragment go through
// pdflatex without a LaTeX error, an undefined reference or a line running into the
// margin, and the PDF is the same bytes on every run.
#define BOOST_TEST_MODULE test_report
#include <boost/test/unit_test.hpp>

#include "report/pdf.h"
#include "report/report_tex.h"
#include "engine/library.h"
#include "pipeline/regenerate.h"
#include "report/report.h"

#include <string>

using namespace impact;

namespace {

struct generated {
    engine::library lib;
    pipeline::file_set files;
    generated()
    {
        lib = engine::derive_all(engine::read_directory(IMPACT_SOURCE_DIR "/derivations"));
        files = pipeline::generate(lib);
        for (auto& [path, contents] : report::figures_and_report(lib, files))
            files[path] = contents;
    }
};

const generated& output()
{
    static const generated g;
    return g;
}

std::string joined(const std::vector<std::string>& lines)
{
    std::string out;
    for (const std::string& line : lines)
        out += line + "\n";
    return out;
}

// A document that \input's one file, with the packages a fragment says it needs.
std::map<std::string, std::string> minimal_document(const std::string& path, const std::string& contents)
{
    return {{path, contents},
            {"main.tex", "\\documentclass{article}\n\\usepackage{amsmath,amssymb}\n\\begin{document}\n\\input{" +
                             path + "}\n\\end{document}\n"}};
}

} // namespace

BOOST_AUTO_TEST_CASE(the_report_compiles_without_errors_undefined_references_or_overfull_lines)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex(), "pdflatex is missing: run scripts/setup.sh");
    std::map<std::string, std::string> sources;
    for (const auto& [path, contents] : output().files)
        if (path.rfind("latex/", 0) == 0 || path.rfind("figures/", 0) == 0 || path == "report.tex")
            sources[path] = contents;
    const report::pdf_build pdf = report::compile_latex(sources, "report.tex");
    BOOST_TEST(pdf.ok, joined(pdf.problems));
    BOOST_TEST(pdf.pdf.rfind("%PDF-", 0) == 0u);
    const auto overfull = report::latex_overfull_boxes(pdf.log, 2.0);
    BOOST_TEST(overfull.empty(), joined(overfull));
    // Every font embedded as a Type 1 outline: no bitmap (.pk) font made on the fly.
    BOOST_TEST(pdf.log.find("pk>") == std::string::npos, "a bitmap font is embedded");
    // What regeneration commits is this PDF.
    BOOST_TEST((output().files.at("report.pdf") == pdf.pdf), "a second build gives other bytes");
}

BOOST_AUTO_TEST_CASE(every_fragment_compiles_alone_in_a_minimal_document)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    for (const engine::derivation* d : output().lib.in_order()) {
        const std::string path = "latex/" + d->id() + ".tex";
        const report::pdf_build pdf = report::compile_latex(minimal_document(path, output().files.at(path)), "main.tex");
        BOOST_TEST(pdf.ok, path + ":\n" + joined(pdf.problems));
    }
}

BOOST_AUTO_TEST_CASE(the_report_includes_every_derivation_the_errata_and_both_figures)
{
    const std::string& tex = output().files.at("report.tex");
    for (const engine::derivation* d : output().lib.in_order())
        BOOST_TEST(tex.find("\\input{latex/" + d->id() + "}") != std::string::npos, d->id());
    BOOST_TEST(tex.find("\\section{The paper, held to account}") != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/billiard}") != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/scatter_angle}") != std::string::npos);
    // The errata table says which of the paper's items disagree: Eq. 7 lost its primes.
    BOOST_TEST(tex.find("Eq.~7 & restitution") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_latex_error_or_an_undefined_reference_is_caught)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    const report::pdf_build undefined =
        report::compile_latex(minimal_document("x.tex", "See \\eqref{nowhere}.\n"), "main.tex");
    BOOST_TEST(!undefined.ok);
    BOOST_TEST(joined(undefined.problems).find("Reference `nowhere' on page 1 undefined") != std::string::npos,
               joined(undefined.problems));
    const report::pdf_build broken = report::compile_latex(minimal_document("x.tex", "$\\frac{1}{$\n"), "main.tex");
    BOOST_TEST(!broken.ok);
    BOOST_TEST(!broken.problems.empty());
}

BOOST_AUTO_TEST_CASE(the_same_document_gives_the_same_pdf_bytes)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    const std::map<std::string, std::string> doc = {
        {"main.tex", "\\documentclass{article}\n" + report::report_preamble() +
                         "\\begin{document}\n\\section{A}\\label{a} See \\ref{a}: $\\frac{1}{2} m v'^{2}_{m}$.\n"
                         "\\end{document}\n"}};
    const report::pdf_build first = report::compile_latex(doc, "main.tex");
    const report::pdf_build second = report::compile_latex(doc, "main.tex");
    BOOST_TEST_REQUIRE(first.ok, joined(first.problems));
    BOOST_TEST((first.pdf == second.pdf));
}
