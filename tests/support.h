// What the end-to-end tests share: running a command and reading back a folder.
#pragma once

#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace impact::testing {

struct run_result {
    bool exited = false;   ///< false when the process was killed
    int status = -1;       ///< its exit status when it exited
    std::string output;    ///< stdout and stderr together
};

/// Runs a shell command, capturing what it prints.
inline run_result run_command(const std::string& command)
{
    run_result r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    BOOST_REQUIRE(pipe);
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe))
        r.output += buffer.data();
    const int status = pclose(pipe);
    r.exited = WIFEXITED(status);
    r.status = r.exited ? WEXITSTATUS(status) : -1;
    return r;
}

/// Runs the `impact` binary under test with `arguments`.
inline run_result run_impact(const std::string& arguments)
{
    return run_command(std::string(IMPACT_BINARY) + " " + arguments);
}

/// Every file under `root` (none if it does not exist), by relative path, with its bytes.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& root)
{
    std::map<std::string, std::string> files;
    if (!std::filesystem::exists(root))
        return files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file())
            continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        files[std::filesystem::relative(entry.path(), root).generic_string()] = bytes.str();
    }
    return files;
}

/// Everything under `root`, without following links: each file's bytes, each link as
/// "-> target", each folder as "folder"; so that a test sees any change a command made.
inline std::map<std::string, std::string> everything_under(const std::filesystem::path& root)
{
    namespace fs = std::filesystem;
    std::map<std::string, std::string> found;
    std::error_code ignored;
    if (!fs::exists(fs::symlink_status(root, ignored)))
        return found;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string relative = fs::relative(entry.path(), root).generic_string();
        if (entry.is_symlink())
            found[relative] = "-> " + fs::read_symlink(entry.path()).string();
        else if (entry.is_directory())
            found[relative] = "folder";
        else {
            std::ifstream in(entry.path(), std::ios::binary);
            std::ostringstream bytes;
            bytes << in.rdbuf();
            found[relative] = bytes.str();
        }
    }
    return found;
}

/// A folder of a test's own under the system's temporary folder, `<prefix>-<pid>-<n>`, empty
/// when made and removed with everything in it at the end.
struct temporary_folder {
    std::filesystem::path root;
    explicit temporary_folder(const std::string& prefix)
    {
        static int n = 0;
        root = std::filesystem::temp_directory_path() /
               (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
        std::filesystem::remove_all(root);
        std::filesystem::create_directories(root);
    }
    ~temporary_folder() { std::filesystem::remove_all(root); }
    temporary_folder(const temporary_folder&) = delete;
    temporary_folder& operator=(const temporary_folder&) = delete;
};

/// Writes `files` (relative path -> contents, as Impact's stages give them) under `root`.
inline void write_files(const std::filesystem::path& root, const std::map<std::string, std::string>& files)
{
    for (const auto& [path, contents] : files) {
        std::filesystem::create_directories((root / path).parent_path());
        std::ofstream(root / path, std::ios::binary) << contents;
    }
}

/// The paper's smooth spheres: every derivation file of the project's but the rough spheres'.
/// A dozen kernels, Z3's problems, a report and two figures, at a third of the cost of the
/// folder without the 3D rough spheres (whose proofs take most of Z3's time).
inline bool smooth_spheres(const std::string& name)
{
    return name.rfind("rough_", 0) != 0;
}

/// Copies into `to` the project's derivation files (and the paper's order of places) whose
/// names `keep` accepts.
template <class Keep>
void copy_derivations(const std::filesystem::path& to, Keep keep)
{
    std::filesystem::create_directories(to);
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(IMPACT_SOURCE_DIR) / "derivations"))
        if (keep(entry.path().filename().string()))
            std::filesystem::copy_file(entry.path(), to / entry.path().filename());
}

/// Makes `folder` look like an earlier Impact's output: `previous.txt`, listed in the
/// marker Impact keeps there (its format as docs/cli.md gives it).
inline void previous_output(const std::filesystem::path& folder)
{
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "previous.txt") << "the previous output\n";
    std::ofstream(folder / ".impact-output") << "# Written by Impact.\nprevious.txt\n";
}

/// The lines of `text`.
inline std::vector<std::string> lines_of(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

} // namespace impact::testing
