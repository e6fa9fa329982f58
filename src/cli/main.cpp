// The `impact` command: argument parsing and nothing else.
//
// Exit status: 0 when everything holds, 1 when a check failed, 2 on bad input
// (a derivation file that cannot be read, with file, line and what is wrong).
#include "cache/store.h"
#include "emit/json.h"
#include "emit/latex.h"
#include "emit/python.h"
#include "emit/terminal.h"
#include "engine/library/library.h"
#include "pipeline/output_folder.h"
#include "pipeline/regenerate.h"
#include "pipeline/workers.h"
#include "simulate/command.h"
#include "simulate/simulate.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using namespace impact;

constexpr int exit_failed_check = 1;
constexpr int exit_bad_input = 2;

struct options {
    std::string derivations;   ///< empty: derivations/, or the folder of the file given
    std::string output = "output";
    std::string name;
    std::string file;
    bool timings = false;
    bool force = false;
    std::string cache;         ///< empty: cache::default_folder()
    bool no_cache = false;
    std::string cache_size;    ///< empty: $IMPACT_CACHE_SIZE, or cache::default_limit
    unsigned jobs = 0;         ///< 0: pipeline::default_jobs()
    bool quiet = false;
    bool json = false;         ///< derive: JSON instead of text
    bool python = false;       ///< kernels: the Python module's sources too
};

// The cache folder and its size limit as the options and the environment give them;
// no folder with --no-cache. A size that is not one is refused before anything is done.
std::optional<fs::path> cache_folder(const options& o)
{
    if (o.no_cache)
        return std::nullopt;
    return o.cache.empty() ? cache::default_folder() : fs::path(o.cache);
}

std::uintmax_t cache_limit(const options& o)
{
    const char* from_environment = std::getenv("IMPACT_CACHE_SIZE");
    const bool given = !o.cache_size.empty();
    if (!given && (!from_environment || !*from_environment))
        return cache::default_limit;
    const std::string text = given ? o.cache_size : std::string(from_environment);
    if (const auto size = cache::parse_size(text))
        return *size;
    throw std::runtime_error(fmt::format("{} '{}' is not a size: give a number of bytes, or one with K, M, G or T "
                                         "(powers of 1024), e.g. 512M or 2G",
                                         given ? "--cache-size" : "IMPACT_CACHE_SIZE", text));
}

unsigned jobs_of(const options& o)
{
    return o.jobs == 0 ? pipeline::default_jobs() : o.jobs;
}

// What a write kept of the user's, and what it moved out of the way.
void print_kept(const pipeline::write_report& report, const fs::path& folder)
{
    if (!report.kept.empty())
        fmt::print("impact: kept {} {} Impact did not write in {}: {}\n", report.kept.size(),
                   report.kept.size() == 1 ? "path" : "paths", folder.string(), fmt::join(report.kept, ", "));
    for (const std::string& moved : report.moved_aside)
        fmt::print("impact: moved aside, in {}: {}\n", folder.string(), moved);
}

// The cache the options name, opened (a folder that is not Impact's cache is refused), or none.
std::unique_ptr<cache::store> open_cache(const options& o)
{
    const std::uintmax_t limit = cache_limit(o);
    if (const std::optional<fs::path> folder = cache_folder(o))
        return std::make_unique<cache::store>(*folder, limit);
    return nullptr;
}

// Derives one derivation and those it uses, each taken from the cache when its file and
// uses are unchanged.
engine::library derive_one(const options& o)
{
    const std::unique_ptr<cache::store> store = open_cache(o);
    // Its neighbours' errors do not stop it, unless it uses them.
    const engine::folder_read folder = engine::read_directory_for_one(o.derivations);
    const engine::derivation_store kept = pipeline::derivations_kept(store.get());
    engine::library lib = engine::derive_one_of(folder, o.name, {&kept});
    if (store)
        store->trim();
    return lib;
}

int run_regenerate(const options& o)
{
    pipeline::regenerate_options how;
    how.force = o.force;
    how.cache = cache_folder(o);
    how.cache_size = cache_limit(o);
    how.jobs = jobs_of(o);
    how.progress = !o.quiet && ::isatty(STDERR_FILENO);
    const pipeline::regeneration r = pipeline::regenerate(o.derivations, o.output, how);
    if (!r.all_hold) {
        for (const std::string& failure : r.failures)
            fmt::print(stderr, "{}\n", failure);
        fmt::print(stderr, "impact: {} left unchanged\n", o.output);
        return exit_failed_check;
    }
    print_kept(r.written, o.output);
    fmt::print("impact: wrote {} files to {}\n", r.files, o.output);
    if (o.timings)
        for (const auto& [stage, seconds] : r.stages)
            fmt::print("impact: {:8.3f} s  {}\n", seconds, stage);
    if (o.timings)
        for (const std::string& line : pipeline::cache_summary(r))
            fmt::print("impact: {}\n", line);
    return 0;
}

// A check that failed, said on standard error too (file, line, what it came to), as
// `regenerate` says it: a script that reads only the exit status and standard error, or a
// reader of a long listing, sees which.
int failures_said(const engine::library& lib, const engine::derivation& d)
{
    if (d.all_hold())
        return 0;
    for (const std::string& failure : pipeline::failed_checks(lib))
        fmt::print(stderr, "{}\n", failure);
    return exit_failed_check;
}

// The parts of a derivation that took longest, longest first, and the rest summed: where a
// physicist editing the file waits.
void print_timings(const engine::derivation& d)
{
    if (d.timings.empty()) {
        fmt::print("impact: '{}' was taken from the cache, nothing derived; --no-cache times each part\n", d.id());
        return;
    }
    std::vector<std::pair<std::string, double>> parts = d.timings;
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    double total = 0;
    for (const auto& part : parts)
        total += part.second;
    constexpr std::size_t shown = 12;
    for (std::size_t i = 0; i < parts.size() && i < shown; ++i)
        fmt::print("impact: {:8.3f} s  {}\n", parts[i].second, parts[i].first);
    if (parts.size() > shown) {
        double rest = 0;
        for (std::size_t i = shown; i < parts.size(); ++i)
            rest += parts[i].second;
        fmt::print("impact: {:8.3f} s  the other {} parts\n", rest, parts.size() - shown);
    }
    fmt::print("impact: {:8.3f} s  deriving '{}' in all (wall time)\n", total, d.id());
}

int run_derive(const options& o)
{
    const engine::library lib = derive_one(o);
    const engine::derivation& d = lib.derived.at(lib.order.back());
    if (o.json) {
        fmt::print("{}", emit::derivation_json_with_latex(d));
        return failures_said(lib, d);
    }
    fmt::print("{}", emit::terminal_text(d));
    if (o.timings)
        print_timings(d);
    return failures_said(lib, d);
}

int run_latex(const options& o)
{
    const fs::path file = o.file;
    fs::path folder;
    if (!file.empty()) {
        if (!file.has_filename() || fs::is_directory(file))
            throw error({o.file, 0, 0}, "is a folder; give the file to write (e.g. -o folder/fragment.tex)");
        folder = pipeline::checked_folder(file.parent_path().empty() ? "." : file.parent_path(), o.derivations,
                                          pipeline::writing::beside);
        pipeline::check_writable(folder, {{file.filename().string(), ""}}, o.force);
    }
    const engine::library lib = derive_one(o);
    const engine::derivation& d = lib.derived.at(lib.order.back());
    const std::string fragment = emit::latex_fragment(d, &lib.derived);
    if (file.empty())
        fmt::print("{}", fragment);
    else
        print_kept(pipeline::add_to_folder(folder, {{file.filename().string(), fragment}}, o.force), folder);
    return failures_said(lib, d);
}

int run_kernels(const options& o)
{
    const fs::path folder = pipeline::checked_folder(o.output, o.derivations, pipeline::writing::beside);
    pipeline::check_writable(folder, {}, o.force);
    const std::optional<fs::path> cache_at = cache_folder(o);
    const std::unique_ptr<cache::store> store = open_cache(o);
    const engine::derivation_store kept = pipeline::derivations_kept(store.get());
    const unsigned jobs = jobs_of(o);
    const engine::library lib = engine::derive_all(
        engine::read_directory(o.derivations), "",
        {&kept, pipeline::worker_runner(jobs)});
    if (!lib.all_hold()) {
        for (const std::string& failure : pipeline::failed_checks(lib))
            fmt::print(stderr, "{}\n", failure);
        fmt::print(stderr, "impact: no kernels written\n");
        return exit_failed_check;
    }
    std::vector<std::string> missed;
    pipeline::kernel_options how;
    how.store = store.get();
    how.jobs = jobs;
    pipeline::file_set files = pipeline::generate_kernels(lib, &missed, how);
    if (!missed.empty()) {
        for (const std::string& m : missed)
            fmt::print(stderr, "{}\n", m);
        fmt::print(stderr, "impact: no kernels written\n");
        return exit_failed_check;
    }
    const std::size_t headers = files.size();
    // The Python module's sources beside them (python/*.cpp, docs/python.md).
    if (o.python)
        files.merge(emit::python_binding_files(lib));
    print_kept(pipeline::add_to_folder(folder, files, o.force), folder);
    fmt::print("impact: wrote {} kernel headers to {}\n", headers, o.output);
    if (store)
        store->trim();
    if (o.timings)
        for (const std::string& line : pipeline::cache_summary(cache_at, store ? store->statistics()
                                                                                : std::map<std::string, cache::counts>{}))
            fmt::print("impact: {}\n", line);
    return 0;
}

// Runs the scenario, writes `<output>/<name>.dat` (trajectories) and `<name>.tex` (a
// pgfplots figure reading that table), prints a summary; spheres that never touch are a
// result, not an error.
int run_simulate(const simulate::command_options& o)
{
    const simulate::scenario s = simulate::scenario_from(o);
    const fs::path folder = pipeline::checked_folder(o.output, "derivations", pipeline::writing::beside);
    const std::string dat = s.name + ".dat", tex = s.name + ".tex";
    pipeline::check_writable(folder, {{dat, ""}, {tex, ""}}, o.force);
    const simulate::trajectory path = simulate::run(s);
    const pipeline::write_report written = pipeline::add_to_folder(
        folder, {{dat, simulate::table(s, path)}, {tex, simulate::figure(s, path, dat)}}, o.force);
    fmt::print("{}", simulate::summary(s, path));
    for (const std::string& moved : written.moved_aside)
        fmt::print("moved aside, in {}: {}\n", o.output, moved);
    const fs::path given = o.output;
    fmt::print("wrote {} and {}\n", (given / dat).string(), (given / tex).string());
    return 0;
}

int run_list(const options& o)
{
    for (const spec::derivation& s : engine::read_directory(o.derivations))
        fmt::print("{:<24} {:<10} {}\n", s.id.value, s.paper ? s.paper->value : "", s.title.value);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"Impact: derives, proves and typesets the collisions of smooth spheres, and emits verified "
                 "C++ kernels."};
    app.require_subcommand(1);
    options o;
    auto add_derivations = [&](CLI::App* command) {
        command->add_option("--derivations", o.derivations,
                            "folder of derivation files (default: derivations, or the folder of the file given)");
    };

    // The cache, for every command that derives.
    auto add_cache = [&](CLI::App* command) {
        CLI::Option* cache = command->add_option(
            "--cache", o.cache, "cache folder (default: $XDG_CACHE_HOME/impact, or ~/.cache/impact)");
        command->add_flag("--no-cache", o.no_cache, "compute everything; read and write no cache")->excludes(cache);
        command->add_option("--cache-size", o.cache_size,
                            "trim the cache to this size, e.g. 512M or 2G (default: $IMPACT_CACHE_SIZE, or 256M)");
    };
    // The worker processes, for the commands that derive every file and choose kernel forms.
    auto add_jobs = [&](CLI::App* command) {
        command->add_option("-j,--jobs", o.jobs,
                            "derivations, then Z3's problems, then kernels whose forms are chosen, worked on at once, in "
                            "worker processes (default: the hardware's threads; 1: one after another, in Impact's "
                            "own process)")
            ->check(CLI::Range(1u, 4096u));
    };

    CLI::App* regenerate = app.add_subcommand("regenerate", "derive everything and rewrite the output folder");
    add_derivations(regenerate);
    regenerate->add_flag("--timings", o.timings, "print the wall time of each stage");
    const char* force_help = "write into a folder Impact does not own, keeping its files (those in the way "
                             "are renamed <name>.orig)";
    regenerate->add_flag("--force", o.force, force_help);
    regenerate->add_option("--output", o.output, "output folder, replaced only when every check holds")
        ->capture_default_str();
    add_cache(regenerate);
    add_jobs(regenerate);
    regenerate->add_flag("--quiet", o.quiet, "no progress line on the terminal");

    CLI::App* derive = app.add_subcommand("derive", "derive one derivation and print its results and checks");
    add_derivations(derive);
    derive->add_option("derivation", o.name, "id or file of the derivation")->required();
    derive->add_flag("--timings", o.timings, "print the wall time of its slowest steps, checks and kernels");
    derive->add_flag("--json", o.json, "print its results, checks and solutions as JSON (with their LaTeX)");
    add_cache(derive);

    CLI::App* latex = app.add_subcommand("latex", "print (or write) the LaTeX fragment of one derivation");
    add_derivations(latex);
    latex->add_option("derivation", o.name, "id or file of the derivation")->required();
    latex->add_option("-o,--output", o.file, "file to write instead of printing");
    latex->add_flag("--force", o.force, force_help);
    add_cache(latex);

    CLI::App* kernels = app.add_subcommand("kernels", "write the C++ kernel headers");
    add_derivations(kernels);
    kernels->add_option("--output", o.output, "folder to write kernels/impact/*.hpp into")->capture_default_str();
    kernels->add_flag("--force", o.force, force_help);
    kernels->add_flag("--timings", o.timings, "print how often the cache was used");
    kernels->add_flag("--python", o.python,
                      "write the Python module's sources too, python/*.cpp (impact_add_python_module)");
    add_cache(kernels);
    add_jobs(kernels);

    simulate::command_options sim;
    CLI::App* simulation = app.add_subcommand(
        "simulate", "move two spheres until they touch, collide them with the generated kernel (smooth, or rough with "
                    "--beta), write trajectories");
    simulation->add_option("scenario", sim.file, "scenario file (TOML); without one, Fig. 2's billiard shot");
    simulation->add_option("--output", sim.output, "folder for <name>.dat and <name>.tex")->capture_default_str();
    simulation->add_flag("--force", sim.force, force_help);
    simulation->add_option("--name", sim.name, "scenario name (names the files)");
    simulation->add_option("--eps", sim.eps, "Newton's coefficient of restitution, in [0, 1]");
    simulation->add_option("--duration", sim.duration, "time simulated");
    simulation->add_option("--mass-M", sim.mass_M, "mass of M");
    simulation->add_option("--mass-m", sim.mass_m, "mass of m");
    simulation->add_option("--radius-M", sim.radius_M, "radius of M");
    simulation->add_option("--radius-m", sim.radius_m, "radius of m");
    simulation->add_option("--position-M", sim.position_M, "centre of M at t = 0, as x,y");
    simulation->add_option("--position-m", sim.position_m, "centre of m at t = 0, as x,y");
    simulation->add_option("--velocity-M", sim.velocity_M, "velocity of M, as x,y");
    simulation->add_option("--velocity-m", sim.velocity_m, "velocity of m, as x,y");
    simulation->add_option("--spin-M", sim.spin_M, "angular velocity of M, counter-clockwise (default 0)");
    simulation->add_option("--spin-m", sim.spin_m, "angular velocity of m, counter-clockwise (default 0)");
    simulation->add_option("--q-M", sim.q_M, "M's moment of inertia over M R_M^2, in (0, 2/3] (default 0.4)");
    simulation->add_option("--q-m", sim.q_m, "m's moment of inertia over m R_m^2, in (0, 2/3] (default 0.4)");
    simulation->add_option("--beta", sim.beta,
                           "rough spheres: the tangential restitution, in [-1, 1] (-1 smooth, 1 perfectly rough)");
    simulation->add_option("--mu", sim.mu, "rough spheres: Coulomb's friction coefficient, >= 0 or inf (default inf)");

    CLI::App* list = app.add_subcommand("list", "list the derivations");
    add_derivations(list);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version are answers, printed as CLI11 prints them; a mistake is
        // one line, like every other error of Impact's, and exit status 2.
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
            return app.exit(e);
        fmt::print(stderr, "impact: error: {} (impact --help lists the commands, impact <command> --help "
                           "their options)\n",
                   single_line(e.what()));
        return exit_bad_input;
    }
    // `impact derive path/to/file.toml` reads the folder the file is in, where the
    // derivations it uses are, so that it works from any folder.
    // A name that is a path to a .toml file that is not there is a missing file, not an id.
    if (o.derivations.empty() && fs::path(o.name).extension() == ".toml" && !fs::is_regular_file(o.name)) {
        fmt::print(stderr, "{}: error: no such derivation file\n", o.name);
        return exit_bad_input;
    }
    // `impact derive mine`, a folder: one derivation of it is meant.
    if (!o.name.empty() && (derive->parsed() || latex->parsed()) && fs::is_directory(o.name)) {
        fmt::print(stderr, "{}: error: is a folder; give one derivation: its file (mine/spring.toml), or its id "
                           "with the folder (spring --derivations mine)\n",
                   o.name);
        return exit_bad_input;
    }
    if (o.derivations.empty())
        o.derivations = fs::is_regular_file(o.name) ? fs::path(o.name).parent_path().lexically_normal().string()
                                                    : std::string("derivations");
    if (o.derivations.empty())
        o.derivations = ".";
    // A file-size limit reached (`ulimit -f`) fails the write, reported like a full disk,
    // rather than killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
    int status = 0;
    try {
        if (regenerate->parsed())
            status = run_regenerate(o);
        else if (derive->parsed())
            status = run_derive(o);
        else if (latex->parsed())
            status = run_latex(o);
        else if (simulation->parsed())
            status = run_simulate(sim);
        else if (kernels->parsed())
            status = run_kernels(o);
        else
            status = run_list(o);
    } catch (const impact::error& e) {
        fmt::print(stderr, "{}\n", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {
        fmt::print(stderr, "impact: error: {}\n", single_line(e.what()));
        return exit_bad_input;
    }
    // What was printed must have arrived: a full disk or a closed pipe is an error.
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        fmt::print(stderr, "impact: error: cannot write to standard output: {}\n",
                   errno ? std::strerror(errno) : "write error");
        return exit_bad_input;
    }
    return status;
}
