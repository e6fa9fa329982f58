// The `impact` command end to end: output/ reproduced, exit codes, and bad input
// reported with file and line while output/ stays as it was.
#define BOOST_TEST_MODULE test_cli
#include <boost/test/unit_test.hpp>

#include "support.h"

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <clocale>
#include <cstdio>
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

using impact::testing::run_result;
using impact::testing::snapshot;

run_result run(const std::string& arguments)
{
    return impact::testing::run_impact(arguments);
}

const fs::path source_dir = IMPACT_SOURCE_DIR;

// Which of the project's derivation files a scratch folder holds: all; all but the 3D rough
// spheres' (rough_space.toml, whose proofs take longer than the rest of the folder's: for
// what does not compare with the committed output/); none.
enum class files { all, smooth_spheres, none };

// A scratch folder with a copy of derivations/ (or part of it) and an output/ holding a
// marker file.
struct scratch {
    fs::path root;
    explicit scratch(files which = files::all)
    {
        root = fs::temp_directory_path() /
               ("impact-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++));
        fs::remove_all(root);
        impact::testing::previous_output(root / "output");
        impact::testing::copy_derivations(root / "derivations", [which](const std::string& name) {
            return which == files::all || (which == files::smooth_spheres && impact::testing::smooth_spheres(name));
        });
    }
    ~scratch() { fs::remove_all(root); }
    static int& counter()
    {
        static int n = 0;
        return n;
    }
    void write(const std::string& name, const std::string& text) const
    {
        std::ofstream(root / "derivations" / name) << text;
    }
    run_result regenerate(const std::string& arguments = "") const
    {
        return run("regenerate --derivations " + (root / "derivations").string() + " --output " +
                   (root / "output").string() + arguments);
    }
};

const std::string valid_prefix = "id = \"bad\"\ntitle = \"a bad derivation\"\n"
                                 "[[symbol]]\nname = \"x\"\n"
                                 "[[symbol]]\nname = \"y\"\n";

void expect_refused(const std::string& text, const std::string& where, const std::string& what)
{
    // Beside the paper's smooth spheres, all derived first (zz_bad.toml comes last); the rough
    // spheres' files took half a minute more, and nothing here depends on them.
    const scratch s(files::smooth_spheres);
    s.write("zz_bad.toml", text);
    const auto before = snapshot(s.root / "output");
    const run_result r = s.regenerate();
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.output.find("zz_bad.toml:" + where) != std::string::npos, r.output);
    BOOST_TEST(r.output.find(": error: ") != std::string::npos, r.output);
    BOOST_TEST(r.output.find(what) != std::string::npos, r.output);
    BOOST_TEST((snapshot(s.root / "output") == before));
}

// `impact regenerate --no-cache` of the scratch folder's derivations/ into its output/, run
// under a German locale (0,5 for 0.5, another collation) and a time zone 13:45 ahead of UTC
// (a POSIX rule, needing no time-zone database), started two folders down with relative
// paths; `arguments` added. The committed output/ is written in the C locale and UTC.
run_result regenerate_elsewhere(const scratch& s, const std::string& arguments)
{
    BOOST_TEST_REQUIRE(std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr,
                       "the locale de_DE.UTF-8 is not installed (scripts/setup.sh generates it)");
    std::setlocale(LC_ALL, "C");
    fs::remove_all(s.root / "output");
    fs::create_directories(s.root / "elsewhere" / "deeper");
    return impact::testing::run_command(
        "cd '" + (s.root / "elsewhere" / "deeper").string() + "' && LC_ALL=de_DE.UTF-8 LANG=de_DE.UTF-8 "
        "TZ=XYZ-13:45 " + IMPACT_BINARY + " regenerate --no-cache" + arguments +
        " --derivations ../../derivations --output ../../output");
}

} // namespace

BOOST_AUTO_TEST_CASE(regeneration_reproduces_the_committed_output_byte_for_byte_under_another_locale_time_zone_and_folder)
{
    // Without a cache: everything computed, as from a fresh clone (test_cache shows a
    // regeneration from a cache writes the same bytes). The committed output/ is written
    // in the C locale and UTC from the project's folder; this regeneration runs under a
    // German locale, which writes 0,5 for 0.5 and sorts differently, and a time zone 13:45
    // ahead of UTC (a POSIX rule, needing no time-zone database), which moves any date
    // printed, started two folders down with relative paths: the same bytes. (CTest runs
    // this case alone, as test_cli_output: it takes most of test_cli's time.)
    const scratch s;
    const run_result r = regenerate_elsewhere(s, "");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    const auto fresh = snapshot(s.root / "output");
    const auto committed = snapshot(source_dir / "output");
    for (const auto& [name, bytes] : committed) {
        const auto found = fresh.find(name);
        BOOST_TEST((found != fresh.end()), "output/" + name + " is no longer generated");
        if (found != fresh.end())
            BOOST_TEST((found->second == bytes), "output/" + name + " differs from a fresh regeneration");
    }
    for (const auto& [name, bytes] : fresh)
        BOOST_TEST(committed.count(name) == 1u, "output/" + name + " is generated but not committed");
}

// The sanitized build's stand-in for the case above (.ci/run: test_cli_subset, which names it;
// it is disabled otherwise, the case above covering it): a third of the project's files, chosen
// so that every stage runs on them, regenerated without a cache under the same locale, time
// zone and folder. Every file of theirs that the project's output/ holds too is the same:
// each derivation's LaTeX fragment and Z3 problems, the kernels they emit, the figures. Only
// what gathers the whole folder (the report and its web pages, derivations.json, errata.md,
// verification.md, the kernels' shared headers) differs, and is not compared. The files: the elastic and
// inelastic collisions on a line and in a plane, whose results the paper prints (its errata
// reconciled); a wall (a derivation that uses another's results, kernel with a fixed
// partner); the billiard transfer and scatter angle (acos, limits, a figure); rough spheres
// sticking and in the plane (cases by the friction cone, square roots, a kernel by cases).
BOOST_AUTO_TEST_CASE(a_representative_subset_regenerates_as_committed_under_another_locale_time_zone_and_folder,
                     *boost::unit_test::disabled())
{
    const std::set<std::string> chosen = {
        "eq03_elastic_line.toml", "eq04_elastic_plane.toml", "eq08_inelastic_line.toml",
        "eq09_inelastic_plane.toml", "wall_plane.toml", "eq12_billiard_transfer.toml",
        "eq14_scatter_angle.toml", "rough_sticking.toml", "rough_plane.toml"};
    const std::set<std::string> whole_folder = {
        ".impact-output", "derivations.json", "errata.md", "verification.md", "report.tex",
        "report.pdf", "kernels/impact/impact.hpp", "kernels/impact/common.hpp"};
    const scratch s(files::none);
    for (const std::string& name : chosen)
        fs::copy_file(source_dir / "derivations" / name, s.root / "derivations" / name);
    const run_result r = regenerate_elsewhere(s, " --jobs 2");
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    const auto fresh = snapshot(s.root / "output");
    const auto committed = snapshot(source_dir / "output");
    int compared = 0, fragments = 0;
    for (const auto& [name, bytes] : fresh) {
        // The web pages too: each numbers its sections, links its neighbours and lists the
        // folder's contents (their style sheets, fonts and figures are compared).
        const bool page = name.rfind("html/", 0) == 0 && name.size() > 5 && name.compare(name.size() - 5, 5, ".html") == 0;
        if (whole_folder.count(name) != 0 || page)
            continue;
        const auto found = committed.find(name);
        BOOST_TEST((found != committed.end()), "output/" + name + " is generated from a part of derivations/ but not from the whole");
        if (found == committed.end())
            continue;
        BOOST_TEST((found->second == bytes), "output/" + name + " differs from the committed one");
        ++compared;
        fragments += name.rfind("latex/", 0) == 0;
    }
    // A fragment per derivation: 9 files, 9 derivations (each file's id).
    BOOST_TEST(fragments == 9);
    BOOST_TEST(compared >= 30, compared << " files compared");
}

BOOST_AUTO_TEST_CASE(regenerating_twice_gives_identical_files)
{
    const scratch s(files::smooth_spheres);
    BOOST_TEST_REQUIRE(s.regenerate().status == 0);
    const auto first = snapshot(s.root / "output");
    BOOST_TEST_REQUIRE(s.regenerate().status == 0);
    BOOST_TEST((snapshot(s.root / "output") == first));
    BOOST_TEST(first.count("previous.txt") == 0u);  // the old output was replaced, not merged into
}

BOOST_AUTO_TEST_CASE(invalid_toml_names_file_and_line_and_leaves_output_untouched)
{
    expect_refused(valid_prefix + "[[given]\nname = \"g\"\n", "7:", "invalid TOML");
}

BOOST_AUTO_TEST_CASE(an_undeclared_symbol_names_file_and_line_and_leaves_output_untouched)
{
    expect_refused(valid_prefix + "[[given]]\nname = \"g\"\nequation = \"y = 2*w\"\nbecause = \"b\"\n"
                                  "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n",
                   "9:", "undeclared symbol 'w'");
}

BOOST_AUTO_TEST_CASE(an_expression_that_does_not_parse_names_file_and_line_and_leaves_output_untouched)
{
    expect_refused(valid_prefix + "[[given]]\nname = \"g\"\nequation = \"y = (2*x\"\nbecause = \"b\"\n"
                                  "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n",
                   "9:", "does not parse");
}

BOOST_AUTO_TEST_CASE(a_failed_check_exits_one_and_leaves_output_untouched)
{
    const scratch s(files::none);  // the failing file alone: nothing else needs deriving
    s.write("zz_bad.toml", valid_prefix + "[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\nbecause = \"b\"\n"
                                          "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"
                                          "[[check]]\nname = \"wrong\"\nclaim = \"y = 3*x\"\n");
    const auto before = snapshot(s.root / "output");
    const run_result r = s.regenerate();
    BOOST_TEST(r.status == 1);
    BOOST_TEST(r.output.find("check failed: bad: wrong") != std::string::npos, r.output);
    BOOST_TEST((snapshot(s.root / "output") == before));
}

BOOST_AUTO_TEST_CASE(derive_and_latex_say_a_failed_check_on_standard_error)
{
    // y = 2x, claimed 3x: derive lists it among the checks on standard output, and says it
    // on standard error as regenerate does (file, line of the claim, what it came to).
    const scratch s(files::none);
    s.write("zz_bad.toml", valid_prefix + "[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\nbecause = \"b\"\n"
                                          "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"
                                          "[[check]]\nname = \"wrong\"\nclaim = \"y = 3*x\"\n");
    const std::string file = (s.root / "derivations" / "zz_bad.toml").string();
    for (const char* command : {" derive ", " latex "}) {
        // Standard error alone (run_command adds 2>&1 after the group).
        const run_result said = impact::testing::run_command("{ " + std::string(IMPACT_BINARY) + command + file +
                                                             " 2>&1 >/dev/null; }");
        BOOST_TEST(said.status == 1, command);
        BOOST_TEST(said.output == file + ":18:9: error: check failed: bad: wrong: residual -x\n", command + said.output);
    }
    const run_result listed = run("derive " + file);
    BOOST_TEST(listed.output.find("failed             wrong: y = 3*x") != std::string::npos, listed.output);
}

BOOST_AUTO_TEST_CASE(derive_json_prints_results_checks_and_their_latex)
{
    // y = 2x, claimed 2x: `derive --json` (what impact.derive reads) gives the result in
    // Impact's syntax and typeset, the check proven with its claim typeset.
    const scratch s(files::none);
    s.write("zz_json.toml", valid_prefix + "[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\nbecause = \"b\"\n"
                                           "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n"
                                           "[[check]]\nname = \"twice\"\nclaim = \"y = 2*x\"\n");
    const run_result r = impact::testing::run_command(std::string(IMPACT_BINARY) + " derive --json " +
                                                      (s.root / "derivations" / "zz_json.toml").string() +
                                                      " 2>/dev/null");
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.front() == '{', r.output);
    BOOST_TEST(r.output.find("\"results\": {\n    \"y\": \"2*x\"\n  }") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("\"latex\": {\n    \"y\": \"2 x\"\n  }") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("\"name\": \"twice\",\n      \"status\": \"proven\"") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_CASE(derive_json_words_the_checks_a_define_by_cases_makes)
{
    // The block pushed on a rough floor: f defined by cases, a continuity check. Those two
    // checks are stated in words, not as a relation; `derive --json` stopped on them
    // ("ex::lhs(): not a relation") for every rough collision of the paper.
    const std::string file = (source_dir / "tests" / "examples" / "pushed_block.toml").string();
    const run_result r =
        impact::testing::run_command(std::string(IMPACT_BINARY) + " derive --no-cache --json " + file + " 2>/dev/null");
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.find("\"latex\": \"the cases of $f$ cover every value\"") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("\"latex\": \"$f$ is continuous where its cases meet\"") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_CASE(derive_given_a_folder_says_so)
{
    // `impact derive mine` said "derivations: error: no such folder", of another folder.
    const std::string folder = (source_dir / "tests" / "examples").string();
    for (const char* command : {"derive ", "latex "}) {
        const run_result r = run(command + folder);
        BOOST_TEST(r.status == 2, r.output);
        BOOST_TEST(r.output == folder + ": error: is a folder; give one derivation: its file (mine/spring.toml), "
                                        "or its id with the folder (spring --derivations mine)\n",
                   r.output);
    }
}

BOOST_AUTO_TEST_CASE(derive_prints_eq8_results_and_proven_checks)
{
    const run_result r = run("derive inelastic_line --derivations " + (source_dir / "derivations").string());
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.find("v_M_after = (M*v_M+m*v_m-m*eps*(v_M-v_m))/(M+m)") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("J = M*m*(1+eps)*(v_M-v_m)/(M+m)") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("proven             momentum_conserved") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("proven             restitution_law_holds") != std::string::npos, r.output);
    BOOST_TEST(r.output.find("proven             elastic_limit_M") != std::string::npos, r.output);
}

// Where a physicist editing a file waits: each part's time, the slowest first, and the whole.
BOOST_AUTO_TEST_CASE(derive_with_timings_lists_its_slowest_parts_and_says_when_nothing_was_derived)
{
    const std::filesystem::path cache = std::filesystem::temp_directory_path() / "impact_test_derive_timings";
    std::filesystem::remove_all(cache);
    const std::string folder = " --derivations " + (source_dir / "derivations").string();
    const run_result cold = run("derive inelastic_line --timings --no-cache" + folder);
    BOOST_TEST(cold.status == 0, cold.output);
    // Its twelve slowest parts, each a part of the file (a step by its line, a check, a claim of
    // the paper's, a kernel), slowest first; then the rest (inelastic_line has 20 checks and
    // more than 20 claims), then the whole.
    std::vector<double> seconds;
    const std::regex part("impact: +([0-9]+\\.[0-9]{3}) s  (check [a-z_A-Z0-9]+|step [0-9]+ \\(line [0-9]+\\)|"
                          "kernel [a-z_]+|paper claim [a-z_A-Z0-9]+|results|quantities, definitions and given "
                          "equations|the paper's values compared)\n");
    for (std::sregex_iterator it(cold.output.begin(), cold.output.end(), part), end; it != end; ++it)
        seconds.push_back(std::stod((*it)[1]));
    BOOST_TEST(seconds.size() == 12u, cold.output);
    BOOST_TEST(std::is_sorted(seconds.rbegin(), seconds.rend()), cold.output);
    BOOST_TEST(std::regex_search(cold.output, std::regex("\nimpact: +[0-9]+\\.[0-9]{3} s  the other [1-9][0-9]* parts\n")),
               cold.output);
    BOOST_TEST(cold.output.find(" s  deriving 'inelastic_line' in all (wall time)\n") != std::string::npos, cold.output);
    // Derived once into the cache, then taken from it: nothing was timed, and it says so.
    BOOST_TEST(run("derive inelastic_line --cache " + cache.string() + folder).status == 0);
    const run_result warm = run("derive inelastic_line --timings --cache " + cache.string() + folder);
    BOOST_TEST(warm.status == 0, warm.output);
    BOOST_TEST(warm.output.find("impact: 'inelastic_line' was taken from the cache, nothing derived") != std::string::npos,
               warm.output);
    std::filesystem::remove_all(cache);
}

BOOST_AUTO_TEST_CASE(every_subcommand_has_help)
{
    for (const char* command : {"", "regenerate ", "derive ", "latex ", "kernels ", "list "}) {
        const run_result r = run(std::string(command) + "--help");
        BOOST_TEST(r.status == 0, command);
        BOOST_TEST((r.output.find("--derivations") != std::string::npos || std::string(command).empty()), command);
    }
}

BOOST_AUTO_TEST_CASE(a_derivation_file_is_derived_from_any_folder)
{
    // Run from the root folder, where there is no derivations/: the file's own folder
    // holds the derivations it uses (Eq. 11 uses Eq. 8's results).
    const fs::path file = source_dir / "derivations" / "eq11_energy_loss.toml";
    const run_result r = impact::testing::run_command("cd / && exec " + std::string(IMPACT_BINARY) + " derive " +
                                                      file.string() + " 2>&1");
    BOOST_TEST(r.status == 0, r.output);
    BOOST_TEST(r.output.rfind("energy_loss: ", 0) == 0, r.output);
    const run_result missing = impact::testing::run_command("cd / && exec " + std::string(IMPACT_BINARY) +
                                                            " derive energy_loss 2>&1");
    BOOST_TEST(missing.status == 2);
    BOOST_TEST(missing.output == "derivations: error: no such folder of derivation files; give one with "
                                 "--derivations (or, to derive one file, its path)\n");
    // A path to a derivation file that is not there is that file's error, for derive and latex.
    for (const char* command : {" derive ", " latex "}) {
        const run_result typo = impact::testing::run_command("cd / && exec " + std::string(IMPACT_BINARY) + command +
                                                             (source_dir / "derivations" / "eq11_energy_los.toml").string() +
                                                             " 2>&1");
        BOOST_TEST(typo.status == 2);
        BOOST_TEST(typo.output == (source_dir / "derivations" / "eq11_energy_los.toml").string() +
                                      ": error: no such derivation file\n",
                   typo.output);
    }
}

BOOST_AUTO_TEST_CASE(a_folder_without_derivation_files_is_an_error)
{
    const fs::path empty = fs::temp_directory_path() / ("impact-empty-" + std::to_string(::getpid()));
    fs::create_directories(empty);
    const run_result r = run("list --derivations " + empty.string());
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.output == empty.string() + ": error: holds no derivation files (*.toml)\n");
    fs::remove_all(empty);
}

BOOST_AUTO_TEST_CASE(an_unknown_derivation_is_an_error)
{
    const run_result r = run("derive no_such_thing --derivations " + (source_dir / "derivations").string());
    BOOST_TEST(r.status == 2);
    BOOST_TEST(r.output.find("no_such_thing: error: no derivation has this id or file (impact list shows the ids)") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_CASE(a_file_is_derived_whatever_errors_its_unused_neighbours_hold)
{
    // one.toml beside a file that is not TOML and one with an unknown field: derived. A
    // file that uses the broken one gets that file's own error, file and line.
    const scratch s(files::none);
    const std::string one = "id = \"one\"\ntitle = \"one\"\n[[symbol]]\nname = \"x\"\ndomain = \"(0, Pi/2)\"\n"
                            "[[symbol]]\nname = \"y\"\n[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\n"
                            "because = \"b\"\n[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n[[result]]\nname = \"y\"\n";
    s.write("one.toml", one);
    s.write("not_toml.toml", "id = \"not_toml\"\ntitle = \n");
    s.write("unknown_field.toml", "id = \"unknown_field\"\ntitle = \"u\"\n[[symbol]]\nname = \"a\"\n"
                                  "[[result]]\nname = \"a\"\nbogus = 1\n");
    const fs::path folder = s.root / "derivations";
    for (const char* command : {"derive ", "latex "}) {
        const run_result r = run(command + (folder / "one.toml").string());
        BOOST_TEST(r.status == 0, command + r.output);
        BOOST_TEST(r.output.find("not_toml") == std::string::npos, r.output);
    }
    BOOST_TEST(run("derive one --derivations " + folder.string()).status == 0);
    // The broken file itself, by its path or its id, is its error.
    const run_result itself = run("derive " + (folder / "unknown_field.toml").string());
    BOOST_TEST(itself.status == 2);
    BOOST_TEST(itself.output == (folder / "unknown_field.toml").string() +
                                    ":7:1: error: unknown field 'bogus' in [[result]]\n",
               itself.output);
    BOOST_TEST(run("derive unknown_field --derivations " + folder.string()).output == itself.output);
    // Used by one.toml: the used file's error.
    s.write("one.toml", one + "[[use]]\nderivation = \"unknown_field\"\nresults = [\"b = a\"]\n");
    const run_result using_it = run("derive " + (folder / "one.toml").string());
    BOOST_TEST(using_it.status == 2);
    BOOST_TEST(using_it.output == itself.output, using_it.output);
}
