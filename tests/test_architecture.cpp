// The stages point only forward: every `#include "folder/..."` under src/ is one that
// ARCHITECTURE.md's table "Which folder may include which" allows, and every folder of
// src/ is in that table. The engine is a folder of sub-stages (src/engine/expr/, ...), each
// a stage of its own in the table (`engine/expr`), and holds no file of its own.
#define BOOST_TEST_MODULE test_architecture
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path source_dir = IMPACT_SOURCE_DIR;

std::string read(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The table's rows: folder → the folders it may include.
std::map<std::string, std::set<std::string>> allowed_by(const std::string& architecture)
{
    std::map<std::string, std::set<std::string>> allowed;
    const std::size_t heading = architecture.find("## Which folder may include which");
    BOOST_TEST_REQUIRE(heading != std::string::npos, "ARCHITECTURE.md has no table of includes");
    std::istringstream lines(architecture.substr(heading));
    const std::regex row(R"(^\| *([a-z_/]+) *\|([^|]*)\|$)");
    const std::regex name("[a-z_/]+");
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (!std::regex_match(line, m, row) || m[1] == "folder")
            continue;
        std::set<std::string>& to = allowed[m[1]];
        const std::string list = m[2];
        for (auto it = std::sregex_iterator(list.begin(), list.end(), name); it != std::sregex_iterator(); ++it)
            to.insert(it->str());
    }
    return allowed;
}

// Every include of another folder under src/: "from -> to (file)".
struct edge {
    std::string from, to, file;
};

// The stage a path under src/ belongs to: its folder, or `engine/<sub-stage>` for the
// engine's sub-folders.
std::string stage_of(const fs::path& relative)
{
    auto part = relative.begin();
    const std::string folder = part->string();
    if (folder != "engine" || ++part == relative.end())
        return folder;
    const fs::path rest = *part;
    return std::next(part) == relative.end() ? folder : folder + "/" + rest.string();
}

std::vector<edge> includes_under(const fs::path& src)
{
    std::vector<edge> edges;
    const std::regex include(R"(#include\s+"([a-z_/]+)/[^"/]+")");
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        if (!entry.is_regular_file())
            continue;
        const std::string from = stage_of(entry.path().lexically_relative(src));
        const std::string text = read(entry.path());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
            const std::string to = (*it)[1];
            if (to != from)
                edges.push_back({from, to, entry.path().lexically_relative(source_dir).string()});
        }
    }
    return edges;
}

} // namespace

BOOST_AUTO_TEST_CASE(every_include_between_folders_is_an_arrow_of_architecture_md)
{
    const auto allowed = allowed_by(read(source_dir / "ARCHITECTURE.md"));
    const std::vector<edge> edges = includes_under(source_dir / "src");
    BOOST_TEST_REQUIRE(edges.size() > 20u);   // the includes were found at all
    for (const edge& e : edges) {
        const auto row = allowed.find(e.from);
        BOOST_TEST((row != allowed.end() && row->second.count(e.to) == 1),
                   e.file << " includes " << e.to << "/, and ARCHITECTURE.md has no arrow " << e.from << " -> "
                          << e.to);
    }
}

BOOST_AUTO_TEST_CASE(every_folder_of_src_is_a_stage_of_architecture_md)
{
    const auto allowed = allowed_by(read(source_dir / "ARCHITECTURE.md"));
    for (const auto& entry : fs::directory_iterator(source_dir / "src")) {
        const std::string folder = entry.path().filename().string();
        if (!entry.is_directory() || folder == "engine")
            continue;
        BOOST_TEST(allowed.count(folder) == 1u, "src/" << folder << " is not in ARCHITECTURE.md's table");
    }
    std::size_t sub_stages = 0;
    for (const auto& entry : fs::directory_iterator(source_dir / "src" / "engine")) {
        const std::string name = "engine/" + entry.path().filename().string();
        BOOST_TEST(entry.is_directory(), "src/" << name << " is a file of the engine outside its sub-stages");
        if (entry.is_directory()) {
            BOOST_TEST(allowed.count(name) == 1u, "src/" << name << " is not in ARCHITECTURE.md's table");
            ++sub_stages;
        }
    }
    BOOST_TEST(sub_stages >= 6u);   // the engine is split at all
}

// Whatever includes the engine names the sub-stage it includes, not the engine as a whole.
BOOST_AUTO_TEST_CASE(an_include_of_the_engine_names_its_sub_stage)
{
    for (const edge& e : includes_under(source_dir / "src"))
        BOOST_TEST(e.to != "engine", e.file << " includes a header directly under src/engine/");
}

BOOST_AUTO_TEST_CASE(the_table_allows_no_arrow_backwards)
{
    // Each stage may include only stages listed on earlier rows (or the generated kernels):
    // the table itself has no cycle, so no two stages can call each other.
    const std::string architecture = read(source_dir / "ARCHITECTURE.md");
    const auto allowed = allowed_by(architecture);
    std::vector<std::string> order;
    std::istringstream lines(architecture.substr(architecture.find("## Which folder may include which")));
    const std::regex row(R"(^\| *([a-z_/]+) *\|)");
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_search(line, m, row) && m[1] != "folder")
            order.push_back(m[1]);
    }
    BOOST_TEST_REQUIRE(order.size() == allowed.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        for (const std::string& to : allowed.at(order[i]))
            BOOST_TEST((to == "impact" ||
                        std::find(order.begin(), order.begin() + static_cast<long>(i), to) != order.begin() + static_cast<long>(i)),
                       order[i] << " may include " << to << ", which is not an earlier row");
}

// A file a reader holds in their head: none under src/ over 600 lines. A file that grows past
// it is split by what its parts do (ARCHITECTURE.md says what each file of a stage holds).
BOOST_AUTO_TEST_CASE(no_source_file_is_over_600_lines)
{
    std::size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(source_dir / "src")) {
        if (!entry.is_regular_file())
            continue;
        const std::string text = read(entry.path());
        const auto lines = std::count(text.begin(), text.end(), '\n');
        BOOST_TEST(lines <= 600, entry.path().lexically_relative(source_dir).string() << " has " << lines << " lines");
        ++files;
    }
    BOOST_TEST(files > 100u);   // the sources were found at all
}
