// Nothing a user has is lost, end to end through the `impact` binary: every folder Impact
// writes into is missing, empty or marked as Impact's own (`.impact-output`); anything else
// is refused with exit 2 and a message naming the path, or, with --force, written into while
// every file Impact did not write is kept (moved aside to `<name>.orig` when in the way).
// Read-only folders, full disks and file-size limits are errors that leave the output whole.
//
// Each test asserts the exit status, the message, and that what was there before is
// unchanged (every file's bytes, every link, every folder).
#define BOOST_TEST_MODULE test_output_safety
#include <boost/test/unit_test.hpp>

#include "support.h"

#include "pipeline/output_folder.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using impact::testing::everything_under;
using impact::testing::lines_of;
using impact::testing::run_result;

// A derivation that holds (y = 2*x) and writes latex/<id>.tex and kernels/impact/<id>.hpp.
std::string good(const std::string& id)
{
    return "id = \"" + id + "\"\ntitle = \"a good derivation\"\n"
           "[[symbol]]\nname = \"x\"\ndomain = \"positive\"\n[[symbol]]\nname = \"y\"\n"
           "[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\nbecause = \"given\"\n"
           "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n"
           "[[result]]\nname = \"y\"\ndisplay = \"2*x\"\n"
           "[[kernel]]\nname = \"" + id + "_y\"\ninputs = [\"x\"]\noutputs = [\"y = y\"]\n";
}

// A project folder of a user's: derivations/ with one derivation; `impact` runs inside it.
struct project {
    fs::path root;

    project()
    {
        static int counter = 0;
        root = fs::temp_directory_path() /
               ("impact-output-safety-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(root);
        fs::create_directories(root / "derivations");
        write("derivations/a.toml", good("first"));
    }
    ~project() { fs::remove_all(root); }

    void write(const std::string& relative, const std::string& bytes) const
    {
        fs::create_directories((root / relative).parent_path());
        std::ofstream(root / relative, std::ios::binary) << bytes;
    }

    std::string read(const std::string& relative) const
    {
        std::ifstream in(root / relative, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        return bytes.str();
    }

    bool has(const std::string& relative) const
    {
        std::error_code ignored;
        return fs::exists(fs::symlink_status(root / relative, ignored));
    }

    run_result impact(const std::string& arguments, const std::string& before = "") const
    {
        return impact::testing::run_command("cd '" + root.string() + "' && " + before + " exec " + IMPACT_BINARY +
                                            " " + arguments);
    }

    std::map<std::string, std::string> all() const { return everything_under(root); }
};

// A user's folder: a thesis, notes in a subfolder, a link and an empty folder.
void users_folder(const project& p, const std::string& folder)
{
    p.write(folder + "/thesis.tex", "\\documentclass{article}\n% my thesis\n");
    p.write(folder + "/notes/ideas.md", "rough spheres next\n");
    fs::create_directories(p.root / folder / "empty");
    fs::create_symlink("thesis.tex", p.root / folder / "link.tex");
}

// Runs `arguments` and expects exit 2 with exactly `message`, and nothing in the project changed.
void expect_refused(const project& p, const std::string& arguments, const std::string& message,
                    const std::string& before = "")
{
    const auto then = p.all();
    const run_result r = p.impact(arguments, before);
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(lines_of(r.output) == std::vector<std::string>{message}, boost::test_tools::per_element());
    BOOST_TEST((p.all() == then), "the project changed");
}

// Whether this machine lets a test mount file systems of its own (a user and mount
// namespace, as `unshare -rm` makes): read-only folders and full disks need it, since the
// tests may run as root, whom file permissions do not stop.
bool can_mount()
{
    return impact::testing::run_command("unshare -rm sh -c 'mount -t tmpfs -o size=64k tmpfs /tmp' 2>&1").status == 0;
}

// Where `killed_at` kills the process, through `replace_folder`'s seam for faults.
const char* kill_point = "";
void kill_here(const char* point)
{
    if (std::strcmp(point, kill_point) == 0)
        std::raise(SIGKILL);
}

// Replaces `folder` with `files` (forced) in a child process that is killed with SIGKILL at
// `point`, as a crash or a power cut would stop it; true when it was killed there.
bool killed_at(const char* point, const fs::path& folder, const impact::pipeline::file_set& files)
{
    const pid_t child = fork();
    BOOST_TEST_REQUIRE(child >= 0);
    if (child == 0) {
        kill_point = point;
        try {
            impact::pipeline::replace_folder(folder, files, /*force=*/true, kill_here);
        } catch (...) {
        }
        _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

} // namespace

BOOST_AUTO_TEST_SUITE(folders_impact_does_not_own)

BOOST_AUTO_TEST_CASE(an_output_that_is_a_users_file_is_refused)
{
    project p;
    p.write("results", "a user's file\n");
    expect_refused(p, "regenerate --output results", "results: error: refusing to write here: it is a file, not a folder");
    expect_refused(p, "kernels --output results", "results: error: refusing to write here: it is a file, not a folder");
}

BOOST_AUTO_TEST_CASE(a_folder_impact_did_not_write_is_refused_and_left_as_it_was)
{
    project p;
    users_folder(p, "docs");
    const std::string why = "docs: error: refusing to write into this folder: Impact did not write what it holds "
                            "(link.tex, notes/ideas.md, thesis.tex and 1 more); give a new or empty folder, or "
                            "--force to write into it and keep its files";
    expect_refused(p, "regenerate --output docs", why);
    expect_refused(p, "kernels --output docs", why);
    expect_refused(p, "simulate --output docs", why);
    expect_refused(p, "latex first -o docs/first.tex", why);
}

BOOST_AUTO_TEST_CASE(forced_every_file_impact_did_not_write_is_kept_and_one_in_the_way_moved_aside)
{
    project p;
    users_folder(p, "docs");
    p.write("docs/errata.md", "my own list of errata\n");   // Impact writes errata.md
    const auto users = everything_under(p.root / "docs");

    const run_result r = p.impact("regenerate --output docs --force");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(r.output.find("impact: kept 4 paths Impact did not write in docs: empty/, link.tex, notes/ideas.md, "
                             "thesis.tex") != std::string::npos,
               r.output);
    BOOST_TEST(r.output.find("impact: moved aside, in docs: errata.md -> errata.md.orig") != std::string::npos, r.output);
    auto after = everything_under(p.root / "docs");
    for (const auto& [path, bytes] : users)
        if (path != "errata.md")
            BOOST_TEST((after[path] == bytes), path + " was not kept as it was");
    BOOST_TEST(after["errata.md.orig"] == "my own list of errata\n");
    BOOST_TEST(after["errata.md"].find("my own") == std::string::npos);
    BOOST_TEST(p.has("docs/kernels/impact/first_y.hpp"));
    // The marker lists Impact's files, and none of the user's.
    const std::string marker = after[".impact-output"];
    BOOST_TEST(marker.find("\nkernels/impact/first_y.hpp\n") != std::string::npos, marker);
    for (const char* users_file : {"thesis.tex", "errata.md.orig", "notes/ideas.md", "link.tex"})
        BOOST_TEST(marker.find(std::string("\n") + users_file + "\n") == std::string::npos, marker);

    // Now the folder is Impact's: written again without --force, the user's files stay.
    p.write("derivations/a.toml", good("renamed"));
    const run_result again = p.impact("regenerate --output docs");
    BOOST_TEST_REQUIRE(again.status == 0, again.output);
    after = everything_under(p.root / "docs");
    for (const auto& [path, bytes] : users)
        if (path != "errata.md")
            BOOST_TEST((after[path] == bytes), path + " was not kept as it was");
    BOOST_TEST(after["errata.md.orig"] == "my own list of errata\n");
    BOOST_TEST(!p.has("docs/kernels/impact/first_y.hpp"));   // Impact's own, no longer written
    BOOST_TEST(p.has("docs/kernels/impact/renamed_y.hpp"));
}

BOOST_AUTO_TEST_CASE(forced_files_holding_what_impact_writes_are_taken_over_not_moved_aside)
{
    // Headers written before Impact marked its folders: the same bytes, no marker.
    project p;
    BOOST_TEST_REQUIRE(p.impact("kernels --output marked").status == 0);
    fs::create_directories(p.root / "unmarked");
    fs::copy(p.root / "marked" / "kernels", p.root / "unmarked" / "kernels", fs::copy_options::recursive);
    p.write("unmarked/kernels/impact/first_y.hpp", "// a user's edit\n");
    const run_result r = p.impact("kernels --output unmarked --force");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(lines_of(r.output) ==
                   (std::vector<std::string>{"impact: moved aside, in unmarked: kernels/impact/first_y.hpp -> "
                                             "kernels/impact/first_y.hpp.orig",
                                             "impact: wrote 3 kernel headers to unmarked"}),
               boost::test_tools::per_element());
    BOOST_TEST((everything_under(p.root / "unmarked/kernels") ==
                [&] {
                    auto expected = everything_under(p.root / "marked/kernels");
                    expected["impact/first_y.hpp.orig"] = "// a user's edit\n";
                    return expected;
                }()));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(impacts_own_folders)

BOOST_AUTO_TEST_CASE(files_a_user_adds_to_impacts_output_are_kept_and_a_file_in_the_way_is_refused)
{
    project p;
    BOOST_TEST_REQUIRE(p.impact("regenerate").status == 0);
    p.write("output/my_notes.md", "what I make of Eq. 8\n");
    p.write("output/latex/second.tex", "my own second derivation\n");

    // A second derivation would write latex/second.tex, where the user's file is.
    p.write("derivations/b.toml", good("second"));
    expect_refused(p, "regenerate",
                   "output/latex/second.tex: error: in the way: Impact writes a file here, and this is not "
                   "Impact's; move it away, or --force to keep it as latex/second.tex.orig");

    const run_result forced = p.impact("regenerate --force");
    BOOST_TEST_REQUIRE(forced.status == 0, forced.output);
    BOOST_TEST(p.read("output/my_notes.md") == "what I make of Eq. 8\n");
    BOOST_TEST(p.read("output/latex/second.tex.orig") == "my own second derivation\n");
    BOOST_TEST(p.read("output/latex/second.tex").find("my own") == std::string::npos);
    BOOST_TEST(forced.output.find("impact: kept 1 path Impact did not write in output: my_notes.md") !=
                   std::string::npos,
               forced.output);
}

BOOST_AUTO_TEST_CASE(latex_kernels_and_simulate_replace_only_their_own_files)
{
    project p;
    users_folder(p, "paper");
    p.write("paper/first.tex", "my own typesetting of the result\n");

    // A user's file of the name asked for is in the way, even when forced into the folder.
    const run_result forced = p.impact("latex first -o paper/first.tex --force");
    BOOST_TEST_REQUIRE(forced.status == 0, forced.output);
    BOOST_TEST(p.read("paper/first.tex.orig") == "my own typesetting of the result\n");
    BOOST_TEST(p.read("paper/first.tex").find("\\begin{align") != std::string::npos, p.read("paper/first.tex"));
    BOOST_TEST(p.read("paper/thesis.tex") == "\\documentclass{article}\n% my thesis\n");

    // The folder holds the marker now: the fragment is Impact's and is replaced without --force;
    // the user's files beside it are not Impact's, and a name that is the user's is refused.
    const auto before = everything_under(p.root / "paper");
    BOOST_TEST(p.impact("latex first -o paper/first.tex").status == 0);
    BOOST_TEST((everything_under(p.root / "paper") == before));
    expect_refused(p, "latex first -o paper/thesis.tex",
                   "paper/thesis.tex: error: in the way: Impact writes a file here, and this is not Impact's; move "
                   "it away, or --force to keep it as thesis.tex.orig");
    // A folder given as the file: said of the folder, not of the folder it is in.
    expect_refused(p, "latex first -o paper", "paper: error: is a folder; give the file to write (e.g. -o "
                                              "folder/fragment.tex)");

    // Kernels and simulations go beside them, and take nothing away.
    BOOST_TEST(p.impact("kernels --output paper").status == 0);
    BOOST_TEST(p.impact("simulate --output paper").status == 0);
    BOOST_TEST(p.has("paper/kernels/impact/first_y.hpp"));
    BOOST_TEST(p.has("paper/billiard.dat"));
    const auto after = everything_under(p.root / "paper");
    for (const auto& [path, bytes] : before)
        if (path != ".impact-output")
            BOOST_TEST((after.at(path) == bytes), path);

    // By default `impact simulate` writes into a folder of its own, not the current folder.
    BOOST_TEST(p.impact("simulate").status == 0);
    BOOST_TEST(p.has("simulations/billiard.dat"));
    BOOST_TEST(p.has("simulations/.impact-output"));
}

BOOST_AUTO_TEST_CASE(a_leftover_beside_the_output_that_is_not_impacts_is_refused)
{
    project p;
    p.write("output.impact-new/mine.txt", "a user's folder that happens to have this name\n");
    expect_refused(p, "regenerate",
                   "output.impact-new: error: in the way: Impact uses this name while it replaces output, and this "
                   "is not what it left there; move it away");
}

// Written again with the same bytes, a file of Impact's is the same file (linked into the new
// folder, its time kept); a file whose bytes changed is a new file, so that a link a user made
// to the old one keeps the old bytes.
BOOST_AUTO_TEST_CASE(a_file_written_again_unchanged_is_kept_as_it_was_and_a_changed_one_is_new)
{
    project p;
    const fs::path folder = p.root / "output";
    impact::pipeline::replace_folder(folder, {{"same.txt", "same\n"}, {"sub/changes.txt", "old\n"}}, false);
    const auto an_hour_ago = fs::last_write_time(folder / "same.txt") - std::chrono::hours(1);
    fs::last_write_time(folder / "same.txt", an_hour_ago);
    fs::create_hard_link(folder / "sub/changes.txt", p.root / "my_copy.txt");
    struct stat same_before {}, changes_before {};
    BOOST_TEST_REQUIRE(::stat((folder / "same.txt").c_str(), &same_before) == 0);
    BOOST_TEST_REQUIRE(::stat((folder / "sub/changes.txt").c_str(), &changes_before) == 0);

    impact::pipeline::replace_folder(folder, {{"same.txt", "same\n"}, {"sub/changes.txt", "new\n"}}, false);
    struct stat same_after {}, changes_after {};
    BOOST_TEST_REQUIRE(::stat((folder / "same.txt").c_str(), &same_after) == 0);
    BOOST_TEST_REQUIRE(::stat((folder / "sub/changes.txt").c_str(), &changes_after) == 0);
    BOOST_TEST(same_after.st_ino == same_before.st_ino);
    BOOST_TEST((fs::last_write_time(folder / "same.txt") == an_hour_ago));
    BOOST_TEST(same_after.st_nlink == 1u);   // the old folder's name for it is gone
    BOOST_TEST(changes_after.st_ino != changes_before.st_ino);
    BOOST_TEST(p.read("output/sub/changes.txt") == "new\n");
    BOOST_TEST(p.read("my_copy.txt") == "old\n");
    BOOST_TEST(p.read("output/same.txt") == "same\n");
    BOOST_TEST(!p.has("output.impact-old"));
    BOOST_TEST(!p.has("output.impact-new"));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(runs_killed_part_way)

// A user's folder forced into, and the run killed while writing the new folder beside it:
// the folder is as it was, and the next run tidies up what was left.
BOOST_AUTO_TEST_CASE(a_run_killed_while_writing_leaves_the_folder_as_it_was_and_the_next_run_tidies_up)
{
    project p;
    users_folder(p, "output");
    const auto before = everything_under(p.root / "output");
    const impact::pipeline::file_set files = {{"a.txt", "a\n"}, {"b.txt", "b\n"}, {"c/d.txt", "d\n"}};
    BOOST_TEST_REQUIRE(killed_at("writing", p.root / "output", files));
    BOOST_TEST((everything_under(p.root / "output") == before));
    BOOST_TEST_REQUIRE(p.has("output.impact-new"));   // the half-written folder it left

    const run_result next = p.impact("regenerate --force");
    BOOST_TEST(next.status == 0, next.output);
    BOOST_TEST(!p.has("output.impact-new"));
    BOOST_TEST(p.has("output/kernels/impact/first_y.hpp"));
    const auto after = everything_under(p.root / "output");
    for (const auto& [path, bytes] : before)
        BOOST_TEST((after.at(path) == bytes), path);
}

// Killed between the two renames: the previous folder is only `output.impact-old`. The next
// run puts it back, even one that then fails on bad input; every user's file is there.
BOOST_AUTO_TEST_CASE(a_run_killed_between_the_renames_is_restored_by_the_next_run_even_a_failing_one)
{
    project p;
    users_folder(p, "output");
    const auto before = everything_under(p.root / "output");
    BOOST_TEST_REQUIRE(killed_at("swapping", p.root / "output", {{"a.txt", "a\n"}}));
    BOOST_TEST_REQUIRE(!p.has("output"));              // moved aside ...
    BOOST_TEST_REQUIRE(p.has("output.impact-old"));    // ... here, when the process died

    p.write("derivations/b.toml", "");
    const run_result next = p.impact("regenerate");
    BOOST_TEST(next.status == 2, next.output);
    BOOST_TEST(next.output.find("derivations/b.toml: error: file is empty") == 0u, next.output);
    auto after = everything_under(p.root / "output");
    after.erase(".impact-output");   // the forced run marked the folder as it moved it aside
    BOOST_TEST((after == before));
    BOOST_TEST(!p.has("output.impact-old"));
    BOOST_TEST(!p.has("output.impact-new"));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(paths_impact_never_writes)

BOOST_AUTO_TEST_CASE(a_symbolic_link_is_refused_and_what_it_points_to_is_untouched)
{
    project p;
    users_folder(p, "elsewhere");
    fs::create_symlink(p.root / "elsewhere", p.root / "output");
    expect_refused(p, "regenerate --force",
                   "output: error: refusing to write through a symbolic link (to " + (p.root / "elsewhere").string() +
                       "); give the folder itself");
}

BOOST_AUTO_TEST_CASE(the_derivations_sources_tests_and_git_folders_are_refused)
{
    project p;
    for (const char* folder : {"src", "tests", ".git/objects"})
        fs::create_directories(p.root / folder);
    expect_refused(p, "regenerate --force --output derivations/out",
                   "derivations/out: error: refusing to write inside the derivations folder");
    expect_refused(p, "latex first --force -o derivations/first.tex",
                   "derivations: error: refusing to write inside the derivations folder");
    expect_refused(p, "regenerate --force --output src/generated",
                   "src/generated: error: refusing to write inside " + (p.root / "src").string() +
                       ": it holds sources, not output");
    expect_refused(p, "kernels --force --output tests",
                   "tests: error: refusing to write inside " + (p.root / "tests").string() +
                       ": it holds sources, not output");
    expect_refused(p, "simulate --force --output .git/objects",
                   ".git/objects: error: refusing to write inside a .git folder");
    expect_refused(p, "regenerate --force --output .",
                   ".: error: refusing to replace this folder: it holds the derivations or the current folder");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(disks_that_refuse)

BOOST_AUTO_TEST_CASE(a_read_only_folder_is_an_error_and_the_output_survives)
{
    BOOST_TEST_REQUIRE(can_mount(), "this machine does not let a test mount a read-only folder (unshare -rm)");
    project p;
    BOOST_TEST_REQUIRE(p.impact("regenerate").status == 0);
    p.write("derivations/b.toml", good("second"));
    // The project mounted read-only over itself, in a namespace of the command's own.
    const std::string read_only = "unshare -rm sh -c 'mount --bind \"$PWD\" \"$PWD\" && "
                                  "mount -o remount,bind,ro \"$PWD\" && cd \"$PWD\" && exec \"$0\" \"$@\"' ";
    const auto before = p.all();
    const run_result r = impact::testing::run_command("cd '" + p.root.string() + "' && " + read_only + IMPACT_BINARY +
                                                      " regenerate");
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(lines_of(r.output) == std::vector<std::string>{"output.impact-new: error: cannot create the folder: "
                                                              "Read-only file system"},
               boost::test_tools::per_element());
    BOOST_TEST((p.all() == before));
}

BOOST_AUTO_TEST_CASE(a_full_disk_is_an_error_and_the_output_survives)
{
    BOOST_TEST_REQUIRE(can_mount(), "this machine does not let a test mount a small disk (unshare -rm)");
    project p;
    BOOST_TEST_REQUIRE(p.impact("regenerate").status == 0);
    // A disk a little larger than the previous output (its files in 4 KiB pages, as a tmpfs
    // holds them), holding it. The derivation is retitled, so the new output's report, pages
    // and fragment differ (about 100 KiB): written beside the old one, they cannot fit. The
    // files that did not change are linked, not written, and need no room. What the disk holds
    // after is copied out.
    std::uintmax_t pages = 0;
    for (const auto& entry : fs::recursive_directory_iterator(p.root / "output"))
        if (entry.is_regular_file())
            pages += (entry.file_size() + 4095) / 4096;
    const std::uintmax_t disk_kib = (pages + 8) * 4;
    {
        std::string retitled = good("first");
        const std::size_t title = retitled.find("a good derivation");
        BOOST_TEST_REQUIRE(title != std::string::npos);
        retitled.replace(title, 17, "a good derivation, retitled");
        p.write("derivations/a.toml", retitled);
    }
    fs::create_directories(p.root / "disk");
    const std::string script =
        "mount -t tmpfs -o size=" + std::to_string(disk_kib) + "k tmpfs disk && cp -a output disk/ && "
        "(cd disk && " + std::string(IMPACT_BINARY) + " regenerate --derivations ../derivations; "
        "echo \"exit $?\") > result.txt 2>&1; cp -a disk/. after/";
    fs::create_directories(p.root / "after");
    const run_result r = impact::testing::run_command("cd '" + p.root.string() + "' && unshare -rm sh -c '" +
                                                      script + "'");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    const std::vector<std::string> result = lines_of(p.read("result.txt"));
    BOOST_TEST_REQUIRE(result.size() == 2u, p.read("result.txt"));
    BOOST_TEST(result[0].find("output.impact-new/") == 0u, result[0]);
    BOOST_TEST(result[0].find(": error: cannot write the file: No space left on device") != std::string::npos, result[0]);
    BOOST_TEST(result[1] == "exit 2");
    BOOST_TEST((everything_under(p.root / "after/output") == everything_under(p.root / "output")));
    BOOST_TEST(!fs::exists(p.root / "after/output.impact-new"));
}

BOOST_AUTO_TEST_CASE(a_file_size_limit_is_an_error_and_the_folder_keeps_what_it_had)
{
    project p;
    BOOST_TEST_REQUIRE(p.impact("kernels --output headers").status == 0);
    p.write("derivations/b.toml", good("second"));
    const auto before = p.all();
    // 2 blocks of 512 bytes: common.hpp, the largest header (over 1 KiB), cannot be written.
    // (Not `regenerate`: pdflatex, which it runs, stops at the limit first.)
    const run_result r = p.impact("kernels --output headers", "ulimit -f 2 &&");
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(lines_of(r.output) == std::vector<std::string>{"headers/kernels/impact/common.hpp: error: cannot write "
                                                              "the file: File too large"},
               boost::test_tools::per_element());
    // The headers written are whole (new or old), none is cut short, and no scratch file is left.
    const auto after = p.all();
    for (const auto& [path, bytes] : after)
        BOOST_TEST((path.find(".impact-writing") == std::string::npos), path);
    BOOST_TEST((after.at("headers/kernels/impact/common.hpp") == before.at("headers/kernels/impact/common.hpp")));
}

BOOST_AUTO_TEST_CASE(standard_output_that_cannot_be_written_is_an_error)
{
    project p;
    const run_result r =
        impact::testing::run_command("cd '" + p.root.string() + "' && { " + IMPACT_BINARY + " latex first > /dev/full; }");
    BOOST_TEST(r.status == 2, r.output);
    BOOST_TEST(lines_of(r.output) ==
                   std::vector<std::string>{"impact: error: cannot write to standard output: No space left on device"},
               boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(folders_inside_impacts_output)

BOOST_AUTO_TEST_CASE(files_impact_wrote_in_a_folder_inside_its_output_are_never_called_the_users)
{
    project p;
    BOOST_TEST_REQUIRE(p.impact("regenerate").status == 0);

    // output/latex is Impact's (output's marker lists its files): written into without --force.
    const run_result fragment = p.impact("latex first -o output/latex/mine.tex");
    BOOST_TEST(fragment.status == 0, fragment.output);
    BOOST_TEST(fragment.output == "", fragment.output);
    const run_result kernels = p.impact("kernels --output output/latex");
    BOOST_TEST(kernels.status == 0, kernels.output);
    BOOST_TEST(lines_of(kernels.output) == std::vector<std::string>{"impact: wrote 3 kernel headers to output/latex"},
               boost::test_tools::per_element());
    const run_result simulated = p.impact("simulate --output output/latex/simulations");
    BOOST_TEST(simulated.status == 0, simulated.output);
    BOOST_TEST(simulated.output.find("did not write") == std::string::npos, simulated.output);

    // Regenerated, output keeps what the other commands wrote inside it, and says nothing of
    // them: they are Impact's. A file of the user's beside them is said to be kept.
    p.write("output/latex/notes.md", "what I make of it\n");
    const run_result again = p.impact("regenerate");
    BOOST_TEST_REQUIRE(again.status == 0, again.output);
    BOOST_TEST(lines_of(again.output) ==
                   (std::vector<std::string>{"impact: kept 1 path Impact did not write in output: latex/notes.md",
                                             "impact: wrote 34 files to output"}),   // proofs/<id>.smt2 among them
                   // and html/: index.html, the derivation's page, impact.css, KaTeX's style
                   // sheet and its 20 fonts
               boost::test_tools::per_element());
    BOOST_TEST(p.read("output/latex/mine.tex").find("\\subsection{a good derivation}") != std::string::npos);
    BOOST_TEST(p.has("output/latex/kernels/impact/first_y.hpp"));
    BOOST_TEST(p.has("output/latex/simulations/billiard.dat"));
    BOOST_TEST(p.read("output/latex/notes.md") == "what I make of it\n");
}

BOOST_AUTO_TEST_CASE(a_folder_holding_only_what_another_command_wrote_is_impacts)
{
    // `impact latex -o out/latex/x.tex` made out/; regenerating into out is not refused as a
    // folder of the user's.
    project p;
    BOOST_TEST_REQUIRE(p.impact("latex first -o out/latex/x.tex").status == 0);
    const run_result r = p.impact("regenerate --output out");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(lines_of(r.output) == std::vector<std::string>{"impact: wrote 34 files to out"},
               boost::test_tools::per_element());
    BOOST_TEST(p.has("out/latex/x.tex"));
    BOOST_TEST(p.has("out/latex/first.tex"));
}

BOOST_AUTO_TEST_SUITE_END()
