// Compiling LaTeX into PDF with pdflatex from TeX Live (scripts/setup.sh installs it).
//
// The files are written into a scratch folder, pdflatex runs there until the
// cross-references settle, and the log is searched for what a reader would call
// broken: LaTeX errors, undefined references or citations, and labels still changing.
// pdflatex runs with SOURCE_DATE_EPOCH and FORCE_SOURCE_DATE set, so that together with
// the report's \pdfinfoomitdate and \pdftrailerid{} the PDF is the same bytes every time.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace impact::report {

struct pdf_build {
    bool ok = false;                   ///< a PDF was made and the log shows no problem
    std::string pdf;                   ///< the PDF's bytes
    std::string log;                   ///< the last run's log
    std::vector<std::string> problems; ///< errors, undefined references, ... (one line each)
    int runs = 0;
};

/// Writes `files` (path relative to the scratch folder → contents) and compiles `main`.
pdf_build compile_latex(const std::map<std::string, std::string>& files, const std::string& main);

/// What is wrong according to a pdflatex log: `! ...` errors, undefined references and
/// citations, and requests to rerun. Empty when nothing is.
std::vector<std::string> latex_log_problems(const std::string& log);

/// Overfull boxes in a log wider than `tolerance_pt`, one line each.
std::vector<std::string> latex_overfull_boxes(const std::string& log, double tolerance_pt);

/// A file's bytes (empty when it cannot be read).
std::string read_file(const std::filesystem::path& path);

/// A folder of its own under the system's temporary folder (`impact-<purpose>-XXXXXX`),
/// removed with everything in it when done with.
struct scratch_folder {
    explicit scratch_folder(const std::string& purpose);
    ~scratch_folder();
    scratch_folder(const scratch_folder&) = delete;
    scratch_folder& operator=(const scratch_folder&) = delete;
    std::filesystem::path path;
};

/// True when pdflatex can be run.
bool have_pdflatex();

/// What identifies the TeX installation, part of the key of every cached PDF: pdflatex's
/// version banner, and the path, size and time of each of its file databases (`ls-R`),
/// which change whenever a TeX package is installed, removed or updated. Computed once.
const std::string& tex_installation();

} // namespace impact::report
