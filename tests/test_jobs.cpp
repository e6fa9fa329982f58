// Kernels' forms chosen in worker processes (`--jobs`, src/pipeline/workers.h): texts
// collected in the tasks' order whichever worker finishes first, a task's error thrown
// at its place (the first in the tasks' order), a worker that dies named as such; end to
// end, a regeneration with two jobs writes the bytes of one with one, and a failure under
// two jobs (a derivation, a kernel in its worker, a worker killed) is reported as under one
// with the output folder left as it was; `impact kernels` takes its choices from the
// cache; a number of jobs below one is refused; on a terminal, and there only, a progress
// line says what a long stage is doing. The report, compiled in a process beside
// (pipeline::beside): its text, its error, how it died, and no process left behind.
#define BOOST_TEST_MODULE test_jobs
#include <boost/test/unit_test.hpp>

#include "cache/sha256.h"
#include "pipeline/workers.h"
#include "spec/error.h"

#include "support.h"

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace impact;
using impact::testing::lines_of;
using impact::testing::run_result;
using impact::testing::snapshot;

namespace {

// A folder of its own under the system's temporary folder, holding derivations/ and an
// output/ from an earlier run; `impact` runs inside it, so that messages name
// `derivations/<file>` as a user sees them.
struct scratch : impact::testing::temporary_folder {
    scratch() : temporary_folder("impact-test-jobs")
    {
        fs::create_directories(root / "derivations");
        impact::testing::previous_output(root / "output");
    }

    void write(const std::string& relative, const std::string& bytes) const
    {
        std::ofstream(root / relative, std::ios::binary) << bytes;
    }
    // One of the project's derivation files, copied into derivations/.
    void copy(const std::string& name) const
    {
        fs::copy_file(fs::path(IMPACT_SOURCE_DIR) / "derivations" / name, root / "derivations" / name);
    }
    // The derivations of the paper's smooth spheres (every file but the rough spheres'),
    // with the paper's order of places: a dozen kernels, for two workers to share, at
    // half the cost of the whole folder (the rough spheres' proofs take minutes under the
    // sanitizers).
    void copy_smooth_spheres() const
    {
        impact::testing::copy_derivations(root / "derivations", impact::testing::smooth_spheres);
    }
    run_result impact(const std::string& arguments) const
    {
        return impact::testing::run_command("cd '" + root.string() + "' && XDG_CACHE_HOME='" + (root / "xdg").string() +
                                            "' exec " + IMPACT_BINARY + " " + arguments);
    }
};

// Every file under `root` by relative path, with the SHA-256 of its bytes.
std::map<std::string, std::string> hashes(const fs::path& root)
{
    std::map<std::string, std::string> found;
    for (const auto& [path, bytes] : snapshot(root))
        found[path] = cache::sha256_hex(bytes);
    return found;
}

engine::text_task task(const std::string& what, std::function<std::string()> run)
{
    return {what, {"derivations/d.toml", 7, 3}, std::move(run), 0, "choosing its forms", "choose them"};
}

bool said(const std::string& text, const std::string& pattern)
{
    return std::regex_search(text, std::regex(pattern));
}

std::string what_is_thrown(const std::vector<engine::text_task>& tasks, unsigned jobs)
{
    try {
        pipeline::run_in_workers(tasks, jobs);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "nothing thrown";
}

// Runs `command` with a terminal for its standard input, output and error (a pseudo-
// terminal), as a user at one runs it; everything it printed.
run_result on_a_terminal(const std::string& command)
{
    int terminal = -1;
    const pid_t pid = ::forkpty(&terminal, nullptr, nullptr, nullptr);
    BOOST_REQUIRE(pid >= 0);
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    run_result r;
    std::string got;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(terminal, buffer, sizeof buffer);
        if (n > 0)
            got.append(buffer, static_cast<std::size_t>(n));
        else if (n < 0 && errno == EINTR)
            continue;
        else
            break;  // EIO: the command's side of the terminal is closed
    }
    ::close(terminal);
    // The terminal ends each line with \r\n: as the command wrote it, \n.
    r.output = std::regex_replace(got, std::regex("\r\n"), "\n");
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    r.exited = WIFEXITED(status);
    r.status = r.exited ? WEXITSTATUS(status) : -1;
    return r;
}

// A Pi-computing kernel on line 21, column 8 (tests/test_bad_input.cpp has its message).
const std::string circle = "id = \"p\"\ntitle = \"a circle\"\n[[symbol]]\nname = \"r\"\ndomain = \"positive\"\n"
                           "[[symbol]]\nname = \"A\"\n[[given]]\nname = \"g\"\nequation = \"A = Pi*r^2\"\n"
                           "because = \"a disc\"\n[[step]]\nsolve = [\"g\"]\nfor = [\"A\"]\n[[result]]\nname = \"A\"\n"
                           "[[check]]\nname = \"positive\"\nclaim = \"A > 0\"\n"
                           "[[kernel]]\nname = \"area\"\ninputs = [\"r\"]\noutputs = [\"A = A\", \"w = asinh(r)\"]\n";

} // namespace

BOOST_AUTO_TEST_SUITE(test_jobs)

BOOST_AUTO_TEST_CASE(workers_give_their_texts_in_the_tasks_order_whichever_finishes_first)
{
    const std::string here = std::to_string(::getpid());
    std::vector<engine::text_task> tasks;
    // The first sleeps longest: the workers finish in the reverse of the tasks' order.
    for (int i = 0; i < 4; ++i)
        tasks.push_back(task("task " + std::to_string(i), [i] {
            ::usleep(static_cast<useconds_t>((4 - i) * 100000));
            return "text " + std::to_string(i) + " from " + std::to_string(::getpid());
        }));
    std::size_t finished = 0;
    const std::vector<std::string> texts = pipeline::run_in_workers(tasks, 4, [&] { ++finished; });
    BOOST_TEST_REQUIRE(texts.size() == 4u);
    BOOST_TEST(finished == 4u);
    for (int i = 0; i < 4; ++i) {
        BOOST_TEST(texts[i].rfind("text " + std::to_string(i) + " from ", 0) == 0u, texts[i]);
        BOOST_TEST(texts[i] != "text " + std::to_string(i) + " from " + here, "task " << i << " ran in this process");
    }
    // A text of any bytes and length (more than a pipe holds) comes back whole.
    std::string bytes(300000, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = static_cast<char>(i * 7 % 256);
    const auto whole = pipeline::run_in_workers({task("big", [&] { return bytes; }), task("small", [] { return ""; })}, 2);
    BOOST_TEST((whole == std::vector<std::string>{bytes, ""}));
}

BOOST_AUTO_TEST_CASE(the_costliest_task_is_started_first_and_its_text_kept_in_its_place)
{
    // Each says when it started (a clock all processes share); two run at once, so the
    // third task to start waits for one of the first two to end.
    const auto started = [] {
        ::timespec now{};
        ::clock_gettime(CLOCK_MONOTONIC, &now);
        ::usleep(200000);
        return std::to_string(now.tv_sec * 1000000000LL + now.tv_nsec);
    };
    std::vector<engine::text_task> tasks = {task("cheap", started), task("cheap too", started),
                                            task("costly", started)};
    tasks[2].cost = 9;
    const std::vector<std::string> texts = pipeline::run_in_workers(tasks, 2);
    BOOST_TEST_REQUIRE(texts.size() == 3u);
    // The costly one, last in the tasks' order, started before the second.
    BOOST_TEST(std::stoll(texts[2]) < std::stoll(texts[1]));
}

BOOST_AUTO_TEST_CASE(one_job_runs_the_tasks_in_this_process_one_after_another)
{
    std::string order;
    std::vector<engine::text_task> tasks;
    for (int i = 0; i < 3; ++i)
        tasks.push_back(task("task", [i, &order] {
            order += std::to_string(i);
            return std::to_string(::getpid());
        }));
    const std::vector<std::string> texts = pipeline::run_in_workers(tasks, 1);
    BOOST_TEST(order == "012");
    for (const std::string& t : texts)
        BOOST_TEST(t == std::to_string(::getpid()));
}

BOOST_AUTO_TEST_CASE(a_tasks_error_comes_back_at_its_place_the_first_in_the_tasks_order)
{
    const auto fails_at = [](source_location where, const std::string& message, useconds_t after) {
        return [=]() -> std::string {
            ::usleep(after);
            throw error(where, message);
        };
    };
    // The second task fails late, the third at once: the second's error is the one a run
    // without workers reports.
    const std::vector<engine::text_task> tasks = {
        task("first", [] { return std::string("fine"); }),
        task("second", fails_at({"derivations/b.toml", 12, 3}, "kernel 'b': cannot be computed", 300000)),
        task("third", fails_at({"derivations/c.toml", 4, 1}, "kernel 'c': cannot be computed", 0)),
    };
    BOOST_TEST(what_is_thrown(tasks, 3) == "derivations/b.toml:12:3: error: kernel 'b': cannot be computed");
    BOOST_TEST(what_is_thrown(tasks, 2) == "derivations/b.toml:12:3: error: kernel 'b': cannot be computed");
    BOOST_TEST(what_is_thrown(tasks, 1) == "derivations/b.toml:12:3: error: kernel 'b': cannot be computed");
    try {
        pipeline::run_in_workers(tasks, 2);
    } catch (const error& e) {
        BOOST_TEST(e.where().file == "derivations/b.toml");
        BOOST_TEST(e.where().line == 12u);
        BOOST_TEST(e.where().column == 3u);
        BOOST_TEST(e.message() == "kernel 'b': cannot be computed");
    }
    // The first fails at once and the second would run for minutes: it is stopped.
    const std::vector<engine::text_task> long_after = {
        task("first", fails_at({"derivations/a.toml", 1, 1}, "kernel 'a': cannot be computed", 0)),
        task("second", [] {
            ::sleep(600);
            return std::string("too late");
        }),
    };
    BOOST_TEST(what_is_thrown(long_after, 2) == "derivations/a.toml:1:1: error: kernel 'a': cannot be computed");
    // Another exception keeps its message.
    const std::vector<engine::text_task> other = {
        task("first", [] { return std::string("fine"); }),
        task("second", []() -> std::string { throw std::runtime_error("out of memory"); }),
    };
    BOOST_TEST(what_is_thrown(other, 2) == "out of memory");
}

BOOST_AUTO_TEST_CASE(a_worker_that_dies_is_an_error_at_its_task_naming_how)
{
    const std::vector<engine::text_task> killed = {
        task("kernel 'fine'", [] { return std::string("fine"); }),
        task("kernel 'k'", []() -> std::string {
            ::raise(SIGKILL);
            return "never";
        }),
    };
    const std::string what = what_is_thrown(killed, 2);
    BOOST_TEST(what.rfind("derivations/d.toml:7:3: error: kernel 'k': the worker process choosing its forms was "
                          "killed by signal 9 (",
                          0) == 0u,
               what);
    BOOST_TEST(what.find("--jobs 1") != std::string::npos, what);
    const std::vector<engine::text_task> quit = {
        task("kernel 'fine'", [] { return std::string("fine"); }),
        task("kernel 'k'", []() -> std::string { ::_exit(7); }),
    };
    BOOST_TEST(what_is_thrown(quit, 2).rfind("derivations/d.toml:7:3: error: kernel 'k': the worker process choosing "
                                             "its forms ended (status 7) without sending its result",
                                             0) == 0u,
               what_is_thrown(quit, 2));
}

BOOST_AUTO_TEST_CASE(a_task_beside_runs_in_a_process_of_its_own_and_gives_its_text_or_why_not)
{
    // Its text, larger than a pipe holds, from another process.
    pipeline::beside big(task("the report", [] { return std::to_string(::getpid()) + " " + std::string(200000, 'x'); }));
    const std::string text = big.get();
    BOOST_TEST(text.substr(0, text.find(' ')) != std::to_string(::getpid()));
    BOOST_TEST(text.substr(text.find(' ') + 1) == std::string(200000, 'x'));
    // Its error, at its place.
    pipeline::beside failing(task("the report", []() -> std::string {
        throw error({"output/report.pdf", 0, 0}, "pdflatex stopped: Undefined control sequence");
    }));
    try {
        failing.get();
        BOOST_FAIL("nothing thrown");
    } catch (const error& e) {
        BOOST_TEST(e.where().file == "output/report.pdf");
        BOOST_TEST(e.message() == "pdflatex stopped: Undefined control sequence");
    }
    // How it died.
    pipeline::beside killed(task("the report", []() -> std::string {
        ::raise(SIGKILL);
        return "never";
    }));
    try {
        killed.get();
        BOOST_FAIL("nothing thrown");
    } catch (const error& e) {
        BOOST_TEST(e.message().rfind("the report: the process compiling it was killed by signal 9 (", 0) == 0u,
                   e.message());
    }
    // Left running when the parent stops: killed and waited for, no process left behind.
    {
        pipeline::beside forgotten(task("the report", [] {
            ::sleep(600);
            return std::string("too late");
        }));
    }
    BOOST_TEST(::waitpid(-1, nullptr, WNOHANG) == -1);
    BOOST_TEST(errno == ECHILD);
}

BOOST_AUTO_TEST_CASE(regenerating_with_two_jobs_writes_the_bytes_of_one_job)
{
    const scratch s;
    s.copy_smooth_spheres();
    const run_result one = s.impact("regenerate --no-cache --timings --jobs 1 --output one");
    BOOST_TEST_REQUIRE(one.status == 0, one.output);
    const run_result two = s.impact("regenerate --no-cache --timings --jobs 2 --output two");
    BOOST_TEST_REQUIRE(two.status == 0, two.output);
    BOOST_TEST(two.output.find("kernel forms chosen by measurement (numeric, up to 2 worker processes)") !=
                   std::string::npos,
               two.output);
    BOOST_TEST(one.output.find("worker processes") == std::string::npos, one.output);
    const auto by_one = hashes(s.root / "one");
    BOOST_TEST(by_one.size() > 20u);
    BOOST_TEST(by_one.count("kernels/impact/collide_line.hpp") == 1u);
    BOOST_TEST(by_one.count("verification.md") == 1u);
    BOOST_TEST((hashes(s.root / "two") == by_one));
}

// On a terminal, a stage taking more than a second says what it does on one line of
// standard error, rewritten in place and erased when done; with --quiet, or when standard
// error is not a terminal, nothing of it is printed. The choice of a dozen kernels' forms
// takes seconds, derived or not.
BOOST_AUTO_TEST_CASE(a_progress_line_on_a_terminal_only_and_not_with_quiet)
{
    const scratch s;
    s.copy_smooth_spheres();
    // One job: the forms' stage lasts seconds whatever the number of cores, and a kernel
    // is done (the line's count set) within its first second.
    const std::string impact =
        "cd '" + s.root.string() + "' && exec " + IMPACT_BINARY + " regenerate --no-cache --jobs 1 ";
    const run_result shown = on_a_terminal(impact + "--output shown");
    BOOST_TEST_REQUIRE(shown.status == 0, shown.output);
    BOOST_TEST(said(shown.output, "\\rimpact: choosing kernel forms: [0-9]+ of [0-9]+ kernels"), shown.output);
    // Erased at the end: what stays on the screen is what Impact prints anyway.
    const std::size_t last = shown.output.rfind('\r');
    BOOST_TEST_REQUIRE(last != std::string::npos);
    BOOST_TEST(shown.output.compare(last, 4, "\r\033[K") == 0, shown.output.substr(last));
    BOOST_TEST(said(shown.output, "impact: wrote [0-9]+ files to shown"), shown.output);

    const run_result quiet = on_a_terminal(impact + "--quiet --output quiet");
    BOOST_TEST_REQUIRE(quiet.status == 0, quiet.output);
    BOOST_TEST(quiet.output.find("choosing kernel forms") == std::string::npos, quiet.output);
    BOOST_TEST(quiet.output.find("\033[K") == std::string::npos, quiet.output);

    const run_result piped = impact::testing::run_command(impact + "--output piped");
    BOOST_TEST_REQUIRE(piped.status == 0, piped.output);
    BOOST_TEST(piped.output.find("choosing kernel forms") == std::string::npos, piped.output);
    BOOST_TEST(piped.output.find('\r') == std::string::npos, piped.output);
}

BOOST_AUTO_TEST_CASE(a_failing_derivation_under_two_jobs_is_reported_at_its_place_and_the_output_kept)
{
    const scratch s;
    s.copy("eq08_inelastic_line.toml");
    s.copy("eq11_energy_loss.toml");
    const auto before = impact::testing::everything_under(s.root / "output");
    // A display form that is not the result: a failed check, exit 1.
    s.write("derivations/bad.toml", "id = \"bad\"\ntitle = \"a bad derivation\"\n[[symbol]]\nname = \"x\"\n"
                                    "domain = \"positive\"\n[[symbol]]\nname = \"y\"\n"
                                    "[[given]]\nname = \"g\"\nequation = \"y = 2*x\"\nbecause = \"b\"\n"
                                    "[[step]]\nsolve = [\"g\"]\nfor = [\"y\"]\n"
                                    "[[result]]\nname = \"y\"\ndisplay = \"3*x\"\n");
    const run_result failed = s.impact("regenerate --no-cache --jobs 2 --derivations derivations --output output");
    BOOST_TEST(failed.status == 1, failed.output);
    BOOST_TEST(lines_of(failed.output) ==
                   (std::vector<std::string>{"derivations/bad.toml:17:11: error: check failed: bad: display form of y: "
                                             "residual x",
                                             "impact: output left unchanged"}),
               boost::test_tools::per_element());
    BOOST_TEST((impact::testing::everything_under(s.root / "output") == before));
    // Bad input: exit 2, one line at its place.
    s.write("derivations/bad.toml", "id = \"bad\"\ntitle = \"a bad derivation\"\n[[given]\nname = \"g\"\n");
    const run_result bad = s.impact("regenerate --no-cache --jobs 2 --derivations derivations --output output");
    BOOST_TEST(bad.status == 2, bad.output);
    BOOST_TEST(lines_of(bad.output).size() == 1u, bad.output);
    BOOST_TEST(bad.output.rfind("derivations/bad.toml:3:9: error: invalid TOML", 0) == 0u, bad.output);
    BOOST_TEST((impact::testing::everything_under(s.root / "output") == before));
}

BOOST_AUTO_TEST_CASE(a_kernel_that_fails_in_its_worker_is_reported_as_without_workers_and_the_output_kept)
{
    const scratch s;
    s.copy("eq08_inelastic_line.toml");
    s.write("derivations/p.toml", circle);
    const auto before = impact::testing::everything_under(s.root / "output");
    const std::string expected = "derivations/p.toml:21:8: error: kernel 'area': a kernel cannot compute asinh(r): "
                                 "asinh is not among its functions (a kernel computes with +, -, *, /, sqrt, rational "
                                 "numbers, Pi, abs, sin, cos, tan, asin, acos, atan, atan2, exp, log, sinh, cosh, tanh "
                                 "and pow; give any other constant or function as an input)";
    for (const char* jobs : {"1", "2"}) {
        const run_result r =
            s.impact(std::string("regenerate --no-cache --jobs ") + jobs + " --derivations derivations --output output");
        BOOST_TEST(r.status == 2, r.output);
        BOOST_TEST(lines_of(r.output) == std::vector<std::string>{expected}, boost::test_tools::per_element());
        BOOST_TEST((impact::testing::everything_under(s.root / "output") == before), "--jobs " << jobs);
        BOOST_TEST(!fs::exists(s.root / "output.impact-new"));
    }
}

BOOST_AUTO_TEST_CASE(a_bad_file_derived_in_a_worker_is_reported_as_without_workers_and_the_output_kept)
{
    // a.toml uses the collision on a line (eq08) and c.toml uses nothing; both are wrong
    // where they are derived (a claim naming an undeclared symbol). In file order, a comes
    // first (after eq08, which it uses): every run reports a's error alone, whether c is
    // derived beside eq08 in a worker (--jobs 2) or after a (--jobs 1), and whether eq08 is
    // derived or taken from the cache.
    const scratch s;
    s.copy("eq08_inelastic_line.toml");
    const auto bad = [](const std::string& id, const std::string& use) {
        std::string text = circle;
        text.replace(text.find("\"p\""), 3, "\"" + id + "\"");
        text.replace(text.find("A > 0"), 5, "A > B");
        text.replace(text.find("[[symbol]]"), 0, use);
        return text;
    };
    s.write("derivations/a.toml", bad("a", "[[use]]\nderivation = \"inelastic_line\"\nresults = [\"vMp = v_M_after\"]\n"
                                           "[[symbol]]\nname = \"vMp\"\n"));
    s.write("derivations/c.toml", bad("c", ""));
    const auto before = impact::testing::everything_under(s.root / "output");
    std::vector<std::string> said_by;
    for (const char* how : {"--no-cache --jobs 1", "--no-cache --jobs 2", "--cache cache --jobs 1", "--cache cache --jobs 2"}) {
        const run_result r =
            s.impact(std::string("regenerate ") + how + " --derivations derivations --output output");
        BOOST_TEST(r.status == 2, r.output);
        const std::vector<std::string> lines = lines_of(r.output);
        BOOST_TEST_REQUIRE(lines.size() == 1u, r.output);
        BOOST_TEST(said(lines[0], "^derivations/a\\.toml:[0-9]+:[0-9]+: error: .*'B'"), lines[0]);
        said_by.push_back(lines[0]);
        BOOST_TEST((impact::testing::everything_under(s.root / "output") == before), how);
        BOOST_TEST(!fs::exists(s.root / "output.impact-new"));
    }
    BOOST_TEST(said_by[0] == said_by[1]);
    BOOST_TEST(said_by[0] == said_by[2]);
    BOOST_TEST(said_by[0] == said_by[3]);
}

BOOST_AUTO_TEST_CASE(a_worker_killed_during_a_regeneration_is_reported_at_its_derivation_or_kernel_and_the_output_kept)
{
    const scratch s;
    s.copy_smooth_spheres();
    const auto before = impact::testing::everything_under(s.root / "output");
    // The first worker seen alive among Impact's children is killed: a process named impact-worker (the shells of
    // the report's pdflatex are forked from Impact too, and named impact until they run). A worker deriving a small
    // file lives a few milliseconds: it is stopped first, and killed only once it is seen stopped (state T), so
    // that one which finished meanwhile (a zombie, state Z) is passed over. The watch lasts as long as Impact
    // runs: under the sanitizers the derivations take minutes.
    const run_result r = impact::testing::run_command(
        "cd '" + s.root.string() + "' && { XDG_CACHE_HOME=xdg " + IMPACT_BINARY +
        " regenerate --no-cache --jobs 2 --derivations derivations --output output > log 2>&1 & p=$!; "
        "stopped() { for i in $(seq 100); do case \"$(cut -d' ' -f3 /proc/$1/stat 2>/dev/null)\" in "
        "T) return 0;; Z|'') return 1;; esac; sleep 0.01; done; return 1; }; "
        "while kill -0 $p 2>/dev/null; do for c in $(cat /proc/$p/task/*/children 2>/dev/null); do "
        "if [ \"$(cat /proc/$c/comm 2>/dev/null)\" = impact-worker ] && kill -STOP $c 2>/dev/null && stopped $c; "
        "then kill -KILL $c; echo killed; break 2; fi; "
        "done; "
        "sleep 0.01; done; wait $p; echo \"status $?\"; cat log; }");
    BOOST_TEST_REQUIRE(r.output.find("killed\n") == 0u, r.output);
    BOOST_TEST(r.output.find("status 2\n") != std::string::npos, r.output);
    const std::vector<std::string> lines = lines_of(r.output);
    BOOST_TEST_REQUIRE(lines.size() == 3u, r.output);
    // The first worker is deriving a file (several derive at once) or choosing a kernel's forms.
    BOOST_TEST(said(lines[2], "^derivations/[a-z0-9_]+\\.toml:[0-9]+:[0-9]+: error: (kernel|derivation) '[a-z_]+': the "
                              "worker process (choosing its forms|deriving it) was killed by signal 9 "),
               lines[2]);
    BOOST_TEST((impact::testing::everything_under(s.root / "output") == before));
    BOOST_TEST(!fs::exists(s.root / "output.impact-new"));
}

BOOST_AUTO_TEST_CASE(a_warm_impact_kernels_takes_every_choice_from_the_cache)
{
    const scratch s;
    s.copy("eq08_inelastic_line.toml");
    s.copy("eq11_energy_loss.toml");
    // Four kernels: collide_line, its fixed spheres' (M and m +infinity), energy_loss.
    const std::string cache = " --cache '" + (s.root / "cache").string() + "'";
    const run_result cold = s.impact("kernels --timings --jobs 2 --output cold" + cache);
    BOOST_TEST_REQUIRE(cold.status == 0, cold.output);
    BOOST_TEST(cold.output.find("cache: kernel choice: 0 reused, 4 computed") != std::string::npos, cold.output);
    const run_result warm = s.impact("kernels --timings --output warm" + cache);
    BOOST_TEST_REQUIRE(warm.status == 0, warm.output);
    BOOST_TEST(warm.output.find("cache: kernel choice: 4 reused, 0 computed") != std::string::npos, warm.output);
    const run_result none = s.impact("kernels --timings --no-cache --jobs 1 --output none");
    BOOST_TEST_REQUIRE(none.status == 0, none.output);
    BOOST_TEST(none.output.find("cache: none (--no-cache)") != std::string::npos, none.output);
    // Without --cache, the default folder: $XDG_CACHE_HOME/impact.
    BOOST_TEST_REQUIRE(s.impact("kernels --output default").status == 0);
    BOOST_TEST(fs::exists(s.root / "xdg" / "impact" / "CACHEDIR.TAG"));
    const auto headers = hashes(s.root / "none");
    BOOST_TEST(headers.count("kernels/impact/collide_line.hpp") == 1u);
    BOOST_TEST((hashes(s.root / "cold") == headers));
    BOOST_TEST((hashes(s.root / "warm") == headers));
    BOOST_TEST((hashes(s.root / "default") == headers));
}

BOOST_AUTO_TEST_CASE(a_number_of_jobs_below_one_is_refused_in_one_line)
{
    const scratch s;
    s.copy("eq08_inelastic_line.toml");
    const auto before = impact::testing::everything_under(s.root / "output");
    for (const char* command : {"regenerate --output output --jobs 0", "kernels --output output --jobs 0",
                                "regenerate --output output --jobs -2", "regenerate --output output --jobs two"}) {
        const run_result r = s.impact(command);
        BOOST_TEST(r.status == 2, command << ": " << r.output);
        BOOST_TEST(lines_of(r.output).size() == 1u, r.output);
        BOOST_TEST(r.output.rfind("impact: error: --jobs", 0) == 0u, r.output);
    }
    BOOST_TEST((impact::testing::everything_under(s.root / "output") == before));
    BOOST_TEST(!fs::exists(s.root / "xdg"));
}

BOOST_AUTO_TEST_SUITE_END()
