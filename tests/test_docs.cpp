// The README and the pages of docs/: short enough to read, every relative link and anchor
// leading somewhere, and the tutorial's commands run as a reader runs them, from an empty folder.
#define BOOST_TEST_MODULE docs
#include "support.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using impact::testing::lines_of;
using impact::testing::run_command;
using impact::testing::temporary_folder;

namespace {

const fs::path source = IMPACT_SOURCE_DIR;

std::string read_text(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    BOOST_REQUIRE_MESSAGE(in, "cannot read " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void write_text(const fs::path& path, const std::string& text)
{
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// The README and every page of docs/, README first.
std::vector<fs::path> pages()
{
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(source / "docs"))
        if (entry.is_regular_file() && entry.path().extension() == ".md")
            found.push_back(entry.path());
    std::sort(found.begin(), found.end());
    found.insert(found.begin(), source / "README.md");
    return found;
}

bool is_fence(const std::string& line) { return line.rfind("```", 0) == 0; }

/// The anchor GitHub gives a heading's text: lowercased; every character but letters,
/// digits, spaces, hyphens and underscores dropped (so the backticks and brackets of
/// "`[[check]]`: claims" go); each space a hyphen. Bytes beyond ASCII are kept, as GitHub
/// keeps the letters of other scripts.
std::string slug(const std::string& heading)
{
    std::string out;
    for (const char c : heading) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_')
            out += static_cast<char>(std::tolower(u));
        else if (c == ' ')
            out += '-';
    }
    return out;
}

/// The anchors of a page's headings (`#` to `######` at the start of a line, outside fenced
/// code blocks), a repeated one numbered as GitHub numbers it: `name`, `name-1`, `name-2`.
std::set<std::string> anchors_of(const std::string& page)
{
    std::set<std::string> anchors;
    std::map<std::string, int> seen;
    bool in_code = false;
    for (const std::string& line : lines_of(page)) {
        if (is_fence(line)) {
            in_code = !in_code;
            continue;
        }
        if (in_code)
            continue;
        const auto hashes = line.find_first_not_of('#');
        if (hashes == 0 || hashes > 6 || hashes == std::string::npos || line[hashes] != ' ')
            continue;
        std::string text = line.substr(hashes + 1);
        while (!text.empty() && (text.back() == ' ' || text.back() == '#'))  // a closing run of #s
            text.pop_back();
        const std::string base = slug(text);
        const int n = seen[base]++;
        anchors.insert(n == 0 ? base : base + "-" + std::to_string(n));
    }
    return anchors;
}

struct link {
    int line;
    std::string target;
};

/// The targets of a page's inline links `[text](target)`, outside fenced code blocks and
/// inline code spans (a link whose text is code, [`x`](target), still counts).
std::vector<link> links_of(const std::string& page)
{
    std::vector<link> found;
    bool in_code = false;
    int number = 0;
    for (const std::string& raw : lines_of(page)) {
        ++number;
        if (is_fence(raw)) {
            in_code = !in_code;
            continue;
        }
        if (in_code)
            continue;
        std::string line;  // the line without its code spans
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] == '`') {
                const auto close = raw.find('`', i + 1);
                if (close != std::string::npos) {
                    i = close;
                    continue;
                }
            }
            line += raw[i];
        }
        for (auto at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
            const auto close = line.find(')', at + 2);
            if (close == std::string::npos)
                break;
            found.push_back({number, line.substr(at + 2, close - at - 2)});
        }
    }
    return found;
}

/// What is wrong with the relative links of the page at `path`, one line each: a file that
/// does not exist, or an anchor no heading of its page has. Links to the web and mail are
/// not followed.
std::vector<std::string> broken_links(const fs::path& path)
{
    std::vector<std::string> broken;
    for (const link& l : links_of(read_text(path))) {
        const std::string& target = l.target;
        if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target.rfind("mailto:", 0) == 0)
            continue;
        const auto hash = target.find('#');
        const std::string file = target.substr(0, hash);
        const std::string anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
        const fs::path to = file.empty() ? path : path.parent_path() / file;
        const std::string where = path.filename().string() + ":" + std::to_string(l.line) + ": (" + target + ") ";
        if (!fs::exists(to)) {
            broken.push_back(where + "leads to no file");
            continue;
        }
        if (!anchor.empty() && to.extension() == ".md" && anchors_of(read_text(to)).count(anchor) == 0)
            broken.push_back(where + "names no heading of " + to.filename().string());
    }
    return broken;
}

} // namespace

BOOST_AUTO_TEST_SUITE(docs)

BOOST_AUTO_TEST_CASE(the_readme_is_at_most_300_lines_and_each_docs_page_at_most_800)
{
    const std::vector<fs::path> all = pages();
    BOOST_TEST(all.size() > 1u, "docs/ holds no page");
    for (const fs::path& page : all) {
        const std::size_t lines = lines_of(read_text(page)).size();
        const std::size_t limit = page.filename() == "README.md" && page.parent_path() == source ? 300 : 800;
        BOOST_TEST(lines <= limit, page.filename().string() << " has " << lines << " lines, more than " << limit
                                                            << ": split it, and link the parts from it");
    }
}

BOOST_AUTO_TEST_CASE(a_heading_s_anchor_is_github_s)
{
    BOOST_TEST(slug("The `impact` command") == "the-impact-command");
    BOOST_TEST(slug("`[[check]]`: claims that must hold") == "check-claims-that-must-hold");
    BOOST_TEST(slug("Where Impact writes: `--output` and `--force`") == "where-impact-writes---output-and---force");
    BOOST_TEST(slug("Beside the derivation files: the paper's order of places") ==
               "beside-the-derivation-files-the-papers-order-of-places");
    BOOST_TEST(slug("The fast form: `impact::fast`") == "the-fast-form-impactfast");
    const std::set<std::string> repeated = anchors_of("# Notes\n## Notes\n```\n# Notes\n```\n### Notes ##\n");
    BOOST_TEST((repeated == std::set<std::string>{"notes", "notes-1", "notes-2"}));
}

// The checker itself finds what is broken: a typed-in page with an anchor spelt as the
// README once spelt one (#checkclaims-that-must-hold, where GitHub makes the heading
// check-claims-that-must-hold), an anchor numbered past a heading's repeats, a file that does
// not exist; and links it must leave alone (the web, mail, code).
BOOST_AUTO_TEST_CASE(a_link_to_a_heading_that_does_not_exist_is_reported)
{
    temporary_folder scratch("impact-test-docs-links");
    write_text(scratch.root / "other.md", "# Other\n\n## Notes\n\n## Notes\n");
    write_text(scratch.root / "page.md",
               "# Page\n\n"
               "### `[[check]]`: claims that must hold\n\n"
               "See [the checks](#checkclaims-that-must-hold), and [the checks](#check-claims-that-must-hold).\n"
               "[Notes](other.md#notes), [more notes](other.md#notes-1), [none](other.md#notes-2).\n"
               "[Gone](missing.md), [the web](https://example.org/#nothing), [mail](mailto:someone@example.org).\n"
               "`[code](#not-a-link)`\n"
               "```\n[in a block](#not-a-link-either)\n```\n");
    const std::vector<std::string> broken = broken_links(scratch.root / "page.md");
    const std::vector<std::string> expected = {
        "page.md:5: (#checkclaims-that-must-hold) names no heading of page.md",
        "page.md:6: (other.md#notes-2) names no heading of other.md",
        "page.md:7: (missing.md) leads to no file",
    };
    BOOST_TEST(broken == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(every_relative_link_of_the_readme_and_docs_leads_to_a_file_and_heading)
{
    for (const fs::path& page : pages())
        for (const std::string& broken : broken_links(page))
            BOOST_ERROR(broken);
}

// docs/tutorial.md, followed as a reader follows it, in an empty folder: each file it shows
// (a code block right after a line ending in its name in backticks and a colon) written, each
// command (a line of a `sh` block starting with "$ ") run, with `impact` and `c++` (the
// build's compiler) on the PATH; "cd DIR" changes the folder the next commands run in. Each
// command must exit with 0, and print the lines shown after it, in that order ("..." stands
// for lines left out). Then every path under output/ the page names in backticks exists:
// among them the LaTeX fragment, the kernel's header and verification.md.
// Each line a page shows after a command is among what the command printed, in that order
// (`...` stands for lines left out).
void expect_shown(const std::vector<std::string>& shown, const std::string& output, const std::string& command,
                  const std::string& page)
{
    const std::vector<std::string> printed = lines_of(output);
    auto next = printed.begin();
    for (const std::string& line : shown) {
        if (line == "...")
            continue;
        next = std::find(next, printed.end(), line);
        BOOST_TEST_REQUIRE((next != printed.end()), command << " did not print, where " << page << " shows it:\n"
                                                            << line << "\nIt printed:\n"
                                                            << output);
        ++next;
    }
}

// The README's example (Eq. 8) shows what Impact prints and writes: each line of the block
// after "`impact derive inelastic_line` derives it and prints" is printed, in order (`...`
// stands for lines left out), and the LaTeX line after "`impact latex inelastic_line`" is a
// line of the committed fragment (which test_cli_output holds to a fresh regeneration).
std::vector<std::string> block_after(const std::vector<std::string>& page, const std::string& opening)
{
    auto at = std::find_if(page.begin(), page.end(),
                           [&](const std::string& line) { return line.rfind(opening, 0) == 0; });
    BOOST_TEST_REQUIRE((at != page.end()), "the README has no line starting " << opening);
    at = std::find_if(at, page.end(), is_fence);
    BOOST_TEST_REQUIRE((at != page.end()), "no code block after " << opening);
    std::vector<std::string> block;
    for (++at; at != page.end() && !is_fence(*at); ++at)
        block.push_back(*at);
    return block;
}

BOOST_AUTO_TEST_CASE(the_readme_s_example_is_what_impact_prints_and_writes)
{
    const std::vector<std::string> readme = lines_of(read_text(source / "README.md"));
    const std::vector<std::string> shown = block_after(readme, "`impact derive inelastic_line` derives it");
    const auto r = run_command("cd '" + source.string() + "' && '" + fs::absolute(IMPACT_BINARY).string() +
                               "' derive inelastic_line");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    expect_shown(shown, r.output, "impact derive inelastic_line", "the README");

    const std::vector<std::string> latex = block_after(readme, "is derived. `impact latex inelastic_line`");
    BOOST_TEST_REQUIRE(latex.size() == 1u);
    std::vector<std::string> fragment = lines_of(read_text(source / "output" / "latex" / "inelastic_line.tex"));
    for (std::string& line : fragment)
        line.erase(0, line.find_first_not_of(' '));
    BOOST_TEST((std::find(fragment.begin(), fragment.end(), latex.front()) != fragment.end()),
               "output/latex/inelastic_line.tex has no line " << latex.front());
}

BOOST_AUTO_TEST_CASE(the_tutorial_runs_from_an_empty_folder)
{
    const std::string text = read_text(source / "docs" / "tutorial.md");
    const std::vector<std::string> page = lines_of(text);
    temporary_folder scratch("impact-test-docs-tutorial");
    const fs::path bin = scratch.root / "bin";
    fs::create_directories(bin);
    fs::create_symlink(fs::absolute(IMPACT_BINARY), bin / "impact");
    fs::create_symlink(IMPACT_CXX, bin / "c++");
    const fs::path start = scratch.root / "reader";
    fs::create_directories(start);
    fs::path here = start;

    std::vector<std::string> written;
    int commands = 0;
    bool compiled = false;
    std::string before;  // the last line of text before a block
    for (std::size_t i = 0; i < page.size(); ++i) {
        if (!is_fence(page[i])) {
            if (page[i].find_first_not_of(' ') != std::string::npos)
                before = page[i];
            continue;
        }
        const std::string language = page[i].substr(3);
        std::string body;
        std::vector<std::string> block;
        for (++i; i < page.size() && !is_fence(page[i]); ++i) {
            block.push_back(page[i]);
            body += page[i] + "\n";
        }
        // A file: the line before the block ends with `NAME`:
        std::string name;
        if (before.size() > 2 && before.compare(before.size() - 2, 2, "`:") == 0) {
            const auto open = before.rfind('`', before.size() - 3);
            if (open != std::string::npos)
                name = before.substr(open + 1, before.size() - 3 - open);
        }
        before.clear();
        if (language != "sh") {
            if (!name.empty()) {
                write_text(here / name, body);
                written.push_back(name);
            }
            continue;
        }
        std::vector<std::pair<std::string, std::vector<std::string>>> shown;  // each command and its output
        for (const std::string& line : block) {
            if (line.rfind("$ ", 0) == 0)
                shown.push_back({line.substr(2), {}});
            else if (!shown.empty())
                shown.back().second.push_back(line);
        }
        for (const auto& [command, expected] : shown) {
            ++commands;
            if (command.rfind("cd ", 0) == 0) {
                here = here / command.substr(3);
                BOOST_TEST_REQUIRE(fs::is_directory(here), "$ " << command << ": no such folder");
                continue;
            }
            if (command.rfind("c++ ", 0) == 0 && command.find(".cpp") != std::string::npos)
                compiled = true;
            const auto r =
                run_command("cd '" + here.string() + "' && PATH='" + bin.string() + "':\"$PATH\" " + command);
            BOOST_TEST_REQUIRE(r.exited, "$ " << command << " was killed");
            BOOST_TEST_REQUIRE(r.status == 0, "$ " << command << " exited with " << r.status << ":\n" << r.output);
            expect_shown(expected, r.output, "$ " + command, "the tutorial");
        }
    }
    BOOST_TEST(commands > 0);
    BOOST_TEST(std::count_if(written.begin(), written.end(),
                             [](const std::string& f) { return fs::path(f).extension() == ".toml"; }) >= 1);
    BOOST_TEST(std::count_if(written.begin(), written.end(),
                             [](const std::string& f) { return fs::path(f).extension() == ".cpp"; }) >= 1,
               "the tutorial shows no program that calls its kernel");
    BOOST_TEST(compiled, "the tutorial compiles no program with c++");

    // The files it says appear: every `output/...` path it names.
    std::set<std::string> named;
    for (auto at = text.find("`output/"); at != std::string::npos; at = text.find("`output/", at + 1)) {
        const auto close = text.find('`', at + 1);
        if (close != std::string::npos)
            named.insert(text.substr(at + 1, close - at - 1));
    }
    bool latex = false, header = false, verification = false;
    for (const std::string& path : named) {
        BOOST_TEST(fs::exists(here / path), path << " is named by the tutorial but was not written");
        latex = latex || (path.rfind("output/latex/", 0) == 0 && fs::path(path).extension() == ".tex");
        header = header || (path.rfind("output/kernels/impact/", 0) == 0 && fs::path(path).extension() == ".hpp");
        verification = verification || path == "output/verification.md";
    }
    BOOST_TEST(latex, "the tutorial names no LaTeX fragment under output/latex/");
    BOOST_TEST(header, "the tutorial names no kernel header under output/kernels/impact/");
    BOOST_TEST(verification, "the tutorial does not name output/verification.md");
}

BOOST_AUTO_TEST_SUITE_END()
