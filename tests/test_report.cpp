// The compiled report: output/report.tex and every derivation's fragment go through
// pdflatex without a LaTeX error, an undefined reference or a line running into the
// margin, and the PDF is the same bytes on every run.
#define BOOST_TEST_MODULE test_report
#include <boost/test/unit_test.hpp>

#include "report/pdf.h"
#include "report/report_tex.h"
#include "engine/library/library.h"
#include "spec/derivation.h"
#include "pipeline/regenerate.h"
#include "report/figures.h"
#include "report/report.h"
#include "support.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using namespace impact;

namespace {

// The committed output/ and the derivation files it was made from. test_cli_output proves
// that output/ is, byte for byte, what a regeneration writes now; so the report, its
// fragments and its figures are compiled and read here as committed, and the project is not
// derived a second time in this test (which took 90 of its 140 s).
struct committed {
    std::map<std::string, std::string> files;    ///< each file under output/, by its path there
    std::vector<spec::derivation> derivations;   ///< derivations/*.toml, read, in the order of their names
    committed()
    {
        files = impact::testing::everything_under(IMPACT_SOURCE_DIR "/output");
        std::vector<std::filesystem::path> paths;
        for (const auto& entry : std::filesystem::directory_iterator(IMPACT_SOURCE_DIR "/derivations"))
            if (entry.path().extension() == ".toml")
                paths.push_back(entry.path());
        std::sort(paths.begin(), paths.end());
        for (const std::filesystem::path& path : paths)
            derivations.push_back(spec::read_derivation(path.string()));
    }
};

const committed& output()
{
    static const committed c;
    return c;
}

// The derivations whose kernels the report's figures plot, with those they use, derived
// here (a few seconds): Fig. 2 the plane's collide (Eq. 9), Fig. 3 scatter_angle (Eq. 14),
// beyond the paper the rough plane's collide_rough.
const engine::library& plotted()
{
    static const engine::library lib = [] {
        const impact::testing::temporary_folder folder("impact-test-report-plotted");
        impact::testing::copy_derivations(folder.root, [](const std::string& name) {
            for (const char* plotted : {"eq03_", "eq04_", "eq08_", "eq09_", "eq11_", "eq12_", "eq14_", "fn10_",
                                        "rough_sticking.", "rough_plane.", "paper_order."})
                if (name.rfind(plotted, 0) == 0)
                    return true;
            return false;
        });
        return engine::derive_folder(folder.root);
    }();
    return lib;
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
    for (const spec::derivation& d : output().derivations) {
        const std::string path = "latex/" + d.id.value + ".tex";
        const report::pdf_build pdf = report::compile_latex(minimal_document(path, output().files.at(path)), "main.tex");
        BOOST_TEST(pdf.ok, path + ":\n" + joined(pdf.problems));
    }
}

BOOST_AUTO_TEST_CASE(the_report_includes_every_derivation_the_errata_and_the_figures)
{
    const std::string& tex = output().files.at("report.tex");
    // Every derivation: the paper's before the errata, those beyond it (rough spheres, no
    // `paper`) in the chapter after the figures.
    const auto beyond = tex.find("\\section{Beyond the paper: rough spheres}");
    BOOST_TEST_REQUIRE(beyond != std::string::npos);
    BOOST_TEST(beyond > tex.find("\\section{Figures}"));
    int rough = 0;
    BOOST_TEST(output().derivations.size() >= 19u);
    for (const spec::derivation& d : output().derivations) {
        const auto at = tex.find("\\input{latex/" + d.id.value + "}");
        BOOST_TEST_REQUIRE(at != std::string::npos, d.id.value);
        BOOST_TEST((at > beyond) == !d.paper.has_value(), d.id.value);
        rough += !d.paper.has_value();
    }
    BOOST_TEST(rough >= 2);
    BOOST_TEST(tex.find("\\section{The paper, held to account}") != std::string::npos);
    // What Z3 confirmed, said in the introduction (the regeneration's Z3 stage, which only the
    // committed output has: the report is made here from it).
    BOOST_TEST(tex.find("Z3 re-checked every proof it can state: it confirmed ") != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/billiard}") != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/scatter_angle}") != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/rough_beta_eff}") > beyond);
    // The errata table says which of the paper's items disagree: Eq. 7 lost its primes.
    BOOST_TEST(tex.find("Eq.~(7) (Sect.~\\ref{impact:inelastic_line}) & restitution (equation) & \\textbf{disagrees}") !=
                   std::string::npos);
}

// A folder of the paper's derivations alone, none beyond it: the report still compiles
// (no chapter beyond the paper, no figure, and nothing refers to what is absent).
BOOST_AUTO_TEST_CASE(a_folder_without_derivations_beyond_the_paper_compiles)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    const impact::testing::temporary_folder folder("impact-test-report");
    std::filesystem::copy_file(IMPACT_SOURCE_DIR "/derivations/eq08_inelastic_line.toml",
                               folder.root / "eq08_inelastic_line.toml");
    const engine::library lib = engine::derive_folder(folder.root.string());
    const pipeline::file_set files = pipeline::generate(lib);
    std::map<std::string, std::string> pdfs;
    BOOST_CHECK_NO_THROW(pdfs = report::figures_and_report(lib, files));
    BOOST_TEST(pdfs.count("report.pdf") == 1u);
    // Eq. 8 derives none of the kernels the figures plot: none is drawn.
    for (const auto& [path, contents] : pdfs)
        BOOST_TEST(path.rfind("figures/", 0) != 0u, path);
}

// Some of the plotted derivations, as a library of their own (derived once, above).
engine::library subset(const std::vector<std::string>& ids)
{
    engine::library lib;
    for (const std::string& id : ids) {
        lib.derived.emplace(id, plotted().derived.at(id));
        lib.order.push_back(id);
    }
    return lib;
}

std::vector<std::string> names_of(const std::vector<report::figure>& figures)
{
    std::vector<std::string> names;
    for (const report::figure& f : figures)
        names.push_back(f.name);
    return names;
}

// A figure plots a kernel compiled into Impact: it is drawn where the folder derives that
// kernel (Fig. 2 the plane's collide, Fig. 3 scatter_angle, beyond the paper the plane's
// collide_rough), and the report's text speaks of the figures it holds.
BOOST_AUTO_TEST_CASE(the_report_draws_the_figures_whose_kernels_the_folder_derives)
{
    using names = std::vector<std::string>;
    BOOST_TEST(names_of(report::figures_of(plotted())) == (names{"billiard", "scatter_angle", "rough_beta_eff"}),
               boost::test_tools::per_element());

    // Eq. 8 alone: no figure, and no section that would hold one.
    const engine::library line = subset({"inelastic_line"});
    BOOST_TEST(report::figures_of(line).empty());
    std::string tex = report::report_tex(line.in_order(), report::figures_of(line));
    BOOST_TEST(tex.find("\\section{Figures}") == std::string::npos);
    BOOST_TEST(tex.find("figures/") == std::string::npos);
    BOOST_TEST(tex.find("sec:beyond") == std::string::npos);
    BOOST_TEST(tex.find("\\title{General Collisions of Smooth Spheres") != std::string::npos);
    BOOST_TEST(tex.find("compares every equation and claim of the paper with what is derived.") != std::string::npos);

    // Eq. 14 (with Eq. 12, which it uses): Fig. 3 alone, numbered 3.
    const engine::library scatter = subset({"billiard_transfer", "scatter_angle"});
    BOOST_TEST(names_of(report::figures_of(scatter)) == names{"scatter_angle"}, boost::test_tools::per_element());
    tex = report::report_tex(scatter.in_order(), report::figures_of(scatter));
    BOOST_TEST(tex.find("recomputes the paper's Fig.~3 with") != std::string::npos);
    BOOST_TEST(tex.find("\\setcounter{figure}{2}\n\\input{figures/scatter_angle}") != std::string::npos);
    BOOST_TEST(tex.find("figures/billiard") == std::string::npos);

    // The 3D collide is not the plane's: no billiard. The rough plane's kernel: its figure,
    // in the chapter beyond the paper with the derivations that have no place in it.
    const engine::library space = subset({"inelastic_line", "inelastic_space"});
    BOOST_TEST(report::figures_of(space).empty());
    const engine::library rough = subset({"inelastic_line", "rough_sticking", "rough_plane"});
    BOOST_TEST(names_of(report::figures_of(rough)) == names{"rough_beta_eff"}, boost::test_tools::per_element());
    tex = report::report_tex(rough.in_order(), report::figures_of(rough));
    BOOST_TEST(tex.find("\\section{Figures}") == std::string::npos);
    const auto beyond = tex.find("\\section{Beyond the paper: rough spheres}");
    BOOST_TEST_REQUIRE(beyond != std::string::npos);
    BOOST_TEST(tex.find("\\input{figures/rough_beta_eff}") > beyond);
    BOOST_TEST(tex.find("\\input{latex/rough_plane}") > beyond);
    BOOST_TEST(tex.find("\\input{latex/inelastic_line}") < beyond);
}

// A teacher's own folder (tests/examples: a spring, a pendulum, a thrown ball ...): a report
// of its derivations, titled so, with none of the paper's figures or chapters; the claims of
// the textbook one file transcribes held to account; it compiles.
BOOST_AUTO_TEST_CASE(a_folder_of_ones_own_derivations_gets_a_report_of_its_own)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    const engine::library lib = engine::derive_folder(IMPACT_SOURCE_DIR "/tests/examples");
    const pipeline::file_set files = pipeline::generate(lib);
    std::map<std::string, std::string> report;
    BOOST_REQUIRE_NO_THROW(report = report::figures_and_report(lib, files));
    for (const auto& [path, contents] : report)
        BOOST_TEST(path.rfind("figures/", 0) != 0u, path);
    BOOST_TEST(report.count("report.pdf") == 1u);
    const std::string& tex = report.at("report.tex");
    BOOST_TEST(tex.find("\\title{Derivations\\\\[0.3em]") != std::string::npos);
    BOOST_TEST(tex.find("General Collisions") == std::string::npos);
    BOOST_TEST(tex.find("Beyond the paper") == std::string::npos);
    BOOST_TEST(tex.find("Figures") == std::string::npos);
    const auto errata = tex.find("\\section{The text, held to account}");
    BOOST_TEST_REQUIRE(errata != std::string::npos);
    // Every file of the folder derived, each in the report before its errata.
    std::size_t files_there = 0;
    for (const auto& entry : std::filesystem::directory_iterator(IMPACT_SOURCE_DIR "/tests/examples"))
        files_there += entry.path().extension() == ".toml";
    BOOST_TEST(lib.order.size() == files_there);
    BOOST_TEST(files_there >= 10u);
    for (const engine::derivation* d : lib.in_order())
        BOOST_TEST(tex.find("\\input{latex/" + d->id() + "}") < errata, d->id());
    // errata.md alike, and every generated file names the folder the files are in.
    const std::string& md = files.at("errata.md");
    BOOST_TEST(md.rfind("<!-- Generated by Impact from examples/; do not edit. -->\n# The text held to account\n", 0) == 0u,
               md.substr(0, 200));
    BOOST_TEST(md.find("General Collisions") == std::string::npos);
    BOOST_TEST(tex.rfind("% Generated by Impact from examples/; do not edit.\n", 0) == 0u);
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

namespace {

// The text of a PDF, as pdftotext reads it.
std::string pdf_text(const std::string& pdf)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("impact-test-report-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "report.pdf", std::ios::binary) << pdf;
    }
    const std::string command = "pdftotext -q '" + (dir / "report.pdf").string() + "' '" +
                                (dir / "report.txt").string() + "'";
    BOOST_TEST_REQUIRE(std::system(command.c_str()) == 0, "pdftotext failed (poppler-utils)");
    std::ifstream in(dir / "report.txt", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove_all(dir);
    return text;
}

// Code that must not reach the typeset text: the derivation files' syntax (eps, ->, ASCII
// products and powers, sqrt(...), backticks) and Impact's internal names (_after, _line2).
std::vector<std::string> code_tokens(const std::string& text)
{
    static const std::pair<const char*, const char*> tokens[] = {
        {"eps", "\\beps\\b"},
        {"->", "->"},
        {"ASCII product", "[A-Za-z0-9)]\\s*\\*\\s*[A-Za-z0-9(]"},
        {"^(", "\\^\\("},
        {"sqrt(", "sqrt\\("},
        {"_after", "_after"},
        {"_line2", "_line[0-9]"},
        {"backtick", "`"},
        {"too long for the table", "too long for the table"},
        {"R^T", "R\\^T"},
        {"v_par", "v_par|v_perp|_1par|_1perp"},
        {"<=", "<=|>="},
    };
    std::vector<std::string> found;
    for (const auto& [name, pattern] : tokens) {
        const std::regex re(pattern);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
            const auto at = static_cast<std::size_t>(it->position());
            const std::size_t from = at < 30 ? 0 : at - 30;
            found.push_back(std::string(name) + ": ..." + text.substr(from, 70) + "...");
        }
    }
    return found;
}

} // namespace

// The report looked at as a reader sees it: each page rendered (pdftoppm, grey, 40 dots an
// inch). A page must have something on it, and nothing may be drawn in the outer 1.5 cm of
// either side (the text block starts 2 cm in): a line, table, display or picture too wide
// for the page shows there, whatever the log says.
namespace {

struct rendered_page {
    std::size_t ink = 0;         // pixels darker than mid-grey
    std::size_t in_margins = 0;  // ... within 1.5 cm of the left or right edge
};

std::vector<rendered_page> rendered_pages(const std::string& pdf)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("impact-test-render-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "report.pdf", std::ios::binary) << pdf;
    }
    constexpr int dpi = 40;
    const std::string command = "pdftoppm -q -gray -r " + std::to_string(dpi) + " '" + (dir / "report.pdf").string() +
                                "' '" + (dir / "page").string() + "'";
    BOOST_TEST_REQUIRE(std::system(command.c_str()) == 0, "pdftoppm failed (poppler-utils)");
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().extension() == ".pgm")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // page-01.pgm, page-02.pgm, ...: one width of number
    std::vector<rendered_page> pages;
    for (const std::filesystem::path& file : files) {
        std::ifstream in(file, std::ios::binary);
        std::string magic;
        std::size_t width = 0, height = 0, most = 0;
        in >> magic >> width >> height >> most;
        in.get();  // the one whitespace before the pixels
        BOOST_TEST_REQUIRE((magic == "P5" && most == 255 && width > 0 && height > 0), file.string());
        std::string pixels(width * height, '\0');
        in.read(pixels.data(), static_cast<std::streamsize>(pixels.size()));
        BOOST_TEST_REQUIRE(static_cast<std::size_t>(in.gcount()) == pixels.size(), file.string());
        const std::size_t band = static_cast<std::size_t>(1.5 * dpi / 2.54);
        rendered_page page;
        for (std::size_t y = 0; y < height; ++y)
            for (std::size_t x = 0; x < width; ++x)
                if (static_cast<unsigned char>(pixels[y * width + x]) < 128) {
                    ++page.ink;
                    page.in_margins += x < band || x >= width - band;
                }
        pages.push_back(page);
    }
    std::filesystem::remove_all(dir);
    return pages;
}

} // namespace

BOOST_AUTO_TEST_CASE(every_page_of_the_report_has_ink_and_none_in_its_margins)
{
    const std::vector<rendered_page> pages = rendered_pages(output().files.at("report.pdf"));
    BOOST_TEST_REQUIRE(pages.size() > 10u);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        BOOST_TEST(pages[i].ink > 100u, "page " << i + 1 << " is blank");
        BOOST_TEST(pages[i].in_margins == 0u, "page " << i + 1 << ": " << pages[i].in_margins << " pixels in the margins");
    }
}

BOOST_AUTO_TEST_CASE(the_render_check_finds_a_picture_in_the_margin)
{
    BOOST_TEST_REQUIRE(report::have_pdflatex());
    // A rule 25 cm wide on an A4 page with the report's margins: it reaches past both edges' bands.
    const report::pdf_build wide = report::compile_latex(
        {{"main.tex", "\\documentclass[a4paper]{article}\n\\usepackage[a4paper,margin=2cm]{geometry}\n"
                      "\\begin{document}\n\\noindent\\hspace*{-3cm}\\rule{25cm}{2mm}\n\\end{document}\n"}},
        "main.tex");
    BOOST_TEST_REQUIRE(!wide.pdf.empty());
    const std::vector<rendered_page> pages = rendered_pages(wide.pdf);
    BOOST_TEST_REQUIRE(pages.size() == 1u);
    BOOST_TEST(pages[0].in_margins > 0u);
}

BOOST_AUTO_TEST_CASE(the_typeset_report_has_no_code_in_its_text)
{
    const std::string text = pdf_text(output().files.at("report.pdf"));
    BOOST_TEST_REQUIRE(text.find("The paper, held to account") != std::string::npos);
    const auto found = code_tokens(text);
    BOOST_TEST(found.empty(), joined(found));
}

BOOST_AUTO_TEST_CASE(the_typeset_text_names_no_derivation_or_quantity_by_its_identifier)
{
    // An identifier in the prose (rough\_sticking, J\_stick) is set with \_ in the LaTeX,
    // which pdftotext reads as a space: it is found in the sources. So is code in typewriter
    // type (a command, a file, a kernel's C++ name), which a physicist pasting the text would
    // have to take out.
    std::vector<std::string> found;
    std::size_t scanned = 0;
    for (const auto& [path, text] : output().files) {
        const bool tex = path.size() > 4 && path.compare(path.size() - 4, 4, ".tex") == 0;
        if (!tex || (path != "report.tex" && path.rfind("latex/", 0) != 0 && path.rfind("figures/", 0) != 0))
            continue;
        ++scanned;
        // What is typeset: every line but the comments (the file's provenance).
        std::string typeset;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);)
            if (line.rfind("%", 0) != 0)
                typeset += line + "\n";
        for (const char* code : {"\\_", "\\texttt", ".toml", "impact::"})
            for (std::size_t at = typeset.find(code); at != std::string::npos; at = typeset.find(code, at + 2))
                found.push_back(path + ": ..." + typeset.substr(at < 30 ? 0 : at - 30, 60) + "...");
    }
    BOOST_TEST(scanned > 10u);
    BOOST_TEST(found.empty(), joined(found));
}

BOOST_AUTO_TEST_CASE(the_code_token_check_finds_code)
{
    // The check itself can fail: each token it looks for, found in a line of code.
    BOOST_TEST(code_tokens("At eps = 1 the collision is elastic").size() == 1u);
    BOOST_TEST(code_tokens("it holds for v -> 0").size() == 1u);
    BOOST_TEST(code_tokens("the sign of the term M*eps").size() == 2u);
    BOOST_TEST(code_tokens("tau_line2 and v_M_after").size() == 2u);
    BOOST_TEST(code_tokens("sqrt(x) and x^(1/2)").size() == 2u);
    // Words that merely contain the letters are prose: "keeps", "steps".
    BOOST_TEST(code_tokens("the cue ball keeps its steps").empty());
}

BOOST_AUTO_TEST_CASE(the_errata_table_names_quantities_not_identifiers_and_groups_a_misprint)
{
    const std::string& tex = output().files.at("report.tex");
    const auto begin = tex.find("\\begin{longtable}");
    const auto end = tex.find("\\end{longtable}");
    BOOST_TEST_REQUIRE((begin != std::string::npos && end != std::string::npos));
    const std::string table = tex.substr(begin, end - begin);
    // Identifiers of the derivation files stay out of the table.
    for (const char* identifier : {"tau\\_line", "\\_after", "texttt"})
        BOOST_TEST(table.find(identifier) == std::string::npos, identifier);
    // Eq. 9 prints v'_m with the sign of eps M (v_M - v_m) wrong: one row for its
    // parallel and both lab-frame components.
    BOOST_TEST(table.find("$v'_{m,\\parallel}$, $v'_{m,x}$ and $v'_{m,y}$ & \\textbf{disagrees}") != std::string::npos);
    BOOST_TEST(tex.find("one misprint, in each of the 3 components") != std::string::npos);
    // Eq. 12: the sentence blamed is the one calling tau the transferred share.
    BOOST_TEST(table.find("Let $\\tau$ denote the transfer rate") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_errata_table_has_a_row_per_claim_and_says_undecided_with_why)
{
    const std::string& tex = output().files.at("report.tex");
    const auto begin = tex.find("\\begin{longtable}");
    const auto end = tex.find("\\end{longtable}");
    BOOST_TEST_REQUIRE((begin != std::string::npos && end != std::string::npos));
    const std::string table = tex.substr(begin, end - begin);
    // Rows of the table whose place starts with `place`.
    auto rows_at = [&table](const std::string& place) {
        std::vector<std::string> rows;
        for (auto at = table.find("\n" + place + " (Sect."); at != std::string::npos;
             at = table.find("\n" + place + " (Sect.", at + 1))
            rows.push_back(table.substr(at + 1, table.find("\\\\\n", at) - at));
        return rows;
    };
    // Claims are never counted ("2 claims"). The 5th sentence after Eq. 14 makes two claims
    // (90 degrees when v_par >> v_perp, 0 degrees when v_par << v_perp) with the limits
    // swapped: one finding, said once for both checks, one row that disagrees.
    BOOST_TEST(table.find(" claims &") == std::string::npos);
    const std::vector<std::string> swapped = rows_at("Sec. III C, after Eq.~(14), 5th sentence");
    BOOST_TEST_REQUIRE(swapped.size() == 1u);
    BOOST_TEST(swapped[0].find("\\textbf{disagrees}") != std::string::npos, swapped[0]);
    BOOST_TEST(swapped[0].find("& the values are swapped: $\\theta$ is $0^\\circ$ for $v_{1,\\perp} \\to 0$ and "
                               "$90^\\circ$ for $v_{1,\\perp} \\to \\infty$") != std::string::npos,
               swapped[0]);
    BOOST_TEST(swapped[0].find("the 1st check") == std::string::npos, swapped[0]);
    // What no derivation can settle, typed from the paper: Sec. III's opening about
    // experiment, undecided with the reason; never "disagrees".
    const std::vector<std::string> opening = rows_at("Sec. III, 1st paragraph");
    BOOST_TEST_REQUIRE(opening.size() == 1u);
    BOOST_TEST(opening[0].find("\\textbf{undecided}") != std::string::npos, opening[0]);
    BOOST_TEST(opening[0].find("experiment") != std::string::npos, opening[0]);
    BOOST_TEST(opening[0].find("disagrees") == std::string::npos, opening[0]);
    // The counts, as typed from the paper (tests/test_paper_lines.cpp lists them): 134
    // printed lines and claims (its references one each), all compared.
    BOOST_TEST(tex.find("The paper has 134 printed lines and claims; 134 of them are compared") != std::string::npos);
    BOOST_TEST(tex.find("Not compared") == std::string::npos);
}
