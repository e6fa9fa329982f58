#include "report/pdf.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impact::report {
namespace fs = std::filesystem;

std::string read_file(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

namespace {

// The auxiliary files whose change means another run is needed.
std::string auxiliary_state(const fs::path& folder)
{
    std::string state;
    for (const char* extension : {".aux", ".toc", ".lof", ".lot", ".out"})
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == extension)
                state += entry.path().filename().string() + "\n" + read_file(entry.path());
    return state;
}

} // namespace

scratch_folder::scratch_folder(const std::string& purpose)
{
    std::string pattern = (fs::temp_directory_path() / ("impact-" + purpose + "-XXXXXX")).string();
    if (!::mkdtemp(pattern.data()))
        throw std::runtime_error("cannot create a scratch folder for " + purpose);
    path = pattern;
}

scratch_folder::~scratch_folder()
{
    std::error_code ignored;
    fs::remove_all(path, ignored);
}

bool have_pdflatex()
{
    return std::system("pdflatex --version > /dev/null 2>&1") == 0;
}

namespace {

// What a command prints on its standard output (nothing when it cannot run).
std::string output_of(const std::string& command)
{
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[4096];
        for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
            out.append(buffer, n);
        ::pclose(pipe);
    }
    return out;
}

} // namespace

const std::string& tex_installation()
{
    static const std::string identity = [] {
        std::string text = output_of("pdflatex --version 2>/dev/null");
        std::istringstream databases(output_of("kpsewhich -all ls-R 2>/dev/null"));
        for (std::string path; std::getline(databases, path);) {
            std::error_code failed;
            const auto size = fs::file_size(path, failed);
            const auto when = fs::last_write_time(path, failed);
            text += fmt::format("{} {} {}\n", path, failed ? 0 : size,
                                failed ? 0 : static_cast<long long>(when.time_since_epoch().count()));
        }
        return text;
    }();
    return identity;
}

std::vector<std::string> latex_log_problems(const std::string& log)
{
    std::vector<std::string> problems;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        const bool error = line.rfind("! ", 0) == 0;
        const bool undefined = line.find("LaTeX Warning:") != std::string::npos &&
                               (line.find("undefined") != std::string::npos ||
                                line.find("multiply defined") != std::string::npos ||
                                line.find("Label(s) may have changed") != std::string::npos);
        const bool missing = line.rfind("Missing character", 0) == 0;
        if (error || undefined || missing)
            problems.push_back(line);
    }
    return problems;
}

std::vector<std::string> latex_overfull_boxes(const std::string& log, double tolerance_pt)
{
    std::vector<std::string> found;
    std::istringstream lines(log);
    std::string line;
    while (std::getline(lines, line)) {
        const auto at = line.find("Overfull \\hbox (");
        if (at == std::string::npos)
            continue;
        const double points = std::strtod(line.c_str() + at + 16, nullptr);
        if (points > tolerance_pt)
            found.push_back(line);
    }
    return found;
}

pdf_build compile_latex(const std::map<std::string, std::string>& files, const std::string& main)
{
    const scratch_folder scratch("latex");
    for (const auto& [relative, contents] : files) {
        const fs::path path = scratch.path / relative;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << contents;
    }
    const fs::path stem = fs::path(main).stem();
    // Fixed dates (SOURCE_DATE_EPOCH), unwrapped log lines, no shell escape.
    const std::string command =
        fmt::format("cd '{}' && SOURCE_DATE_EPOCH=0 FORCE_SOURCE_DATE=1 max_print_line=10000 "
                    "pdflatex -interaction=nonstopmode -halt-on-error -no-shell-escape '{}' > /dev/null 2>&1",
                    scratch.path.string(), main);
    pdf_build build;
    std::string before = auxiliary_state(scratch.path);
    for (build.runs = 1; build.runs <= 5; ++build.runs) {
        const int status = std::system(command.c_str());
        build.log = read_file(scratch.path / (stem.string() + ".log"));
        if (status != 0) {
            build.problems = latex_log_problems(build.log);
            if (build.problems.empty())
                build.problems.push_back(fmt::format("pdflatex failed (status {})", status));
            return build;
        }
        const std::string after = auxiliary_state(scratch.path);
        if (after == before)
            break;
        before = after;
    }
    build.problems = latex_log_problems(build.log);
    build.pdf = read_file(scratch.path / (stem.string() + ".pdf"));
    build.ok = build.problems.empty() && !build.pdf.empty();
    return build;
}

} // namespace impact::report
