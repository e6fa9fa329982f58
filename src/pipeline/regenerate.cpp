#include "pipeline/regenerate.h"

#include "cache/store.h"
#include "emit/cxx.h"
#include "emit/errata.h"
#include "emit/json.h"
#include "emit/latex.h"
#include "emit/verification.h"
#include "pipeline/progress.h"
#include "pipeline/workers.h"
#include "pipeline/z3_workers.h"
#include "report/html.h"
#include "report/pdf.h"
#include "report/report.h"
#include "spec/outline.h"
#include "verify/choice.h"
#include "verify/proofs.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <locale>

namespace impact::pipeline {
namespace fs = std::filesystem;

using cache::packed;
using cache::unpacked;

namespace {

// Records the wall time between laps, when asked to.
class stopwatch {
public:
    explicit stopwatch(stage_times* times) : times_(times), start_(std::chrono::steady_clock::now()) {}
    void lap(const std::string& stage)
    {
        const auto now = std::chrono::steady_clock::now();
        if (times_)
            times_->emplace_back(stage, std::chrono::duration<double>(now - start_).count());
        start_ = now;
    }

private:
    stage_times* times_;
    std::chrono::steady_clock::time_point start_;
};

// The key of a whole regeneration: Impact's executable, the TeX installation, and each
// derivation file's name (with its folder's, which the generated files name) and meaningful
// content. A comment changes nothing Impact writes (no file it writes names a line of a
// derivation file), so a regeneration after one is the one before it. None when a file is
// not TOML: deriving reports it.
std::optional<std::string> output_key(const fs::path& derivations, const std::optional<spec::paper_outline>& outline)
{
    if (!fs::is_directory(derivations))
        return std::nullopt;
    std::string key = "a regeneration of output/\n" + cache::program_fingerprint() + "\n" +
                      report::tex_installation() + "\n";
    for (const fs::path& path : engine::derivation_files(derivations)) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        const std::optional<std::string> content = spec::meaningful_content(text.str());
        if (!in || !content)
            return std::nullopt;
        key += fmt::format("{} {}\n{}\n", engine::folder_and_file_name(path), content->size(), *content);
    }
    // The paper's order of places orders the errata: its places, not its comments.
    if (outline) {
        key += spec::paper_outline_name;
        for (const spec::text& place : outline->places)
            key += fmt::format("\n{} {}", place.value.size(), place.value);
        key += "\n";
    }
    return key;
}

} // namespace

engine::derivation_store derivations_kept(cache::store* store)
{
    if (!store)
        return {};
    // Keyed by the executable too: another build of Impact may prove otherwise.
    const auto full = [](const std::string& key) { return cache::program_fingerprint() + "\n" + key; };
    return {[store, full](const std::string& key) { return store->get("derivation", full(key)); },
            [store, full](const std::string& key, const std::string& text) { store->put("derivation", full(key), text); },
            [store](const std::string&) { store->unusable("derivation"); }};
}

namespace {

// What the report's process sends back: the PDFs, the seconds it took, and the cache
// entries it found and made (its time in microseconds, then a line per kind of entry, its
// counts before its name, which may hold spaces, then the packed files).
struct report_result {
    file_set files;
    std::map<std::string, cache::counts> used;
    double seconds = 0;
    double web_seconds = 0;   ///< of `seconds`, the web pages'

    std::string text() const
    {
        std::string out = fmt::format("{} {}\n{}\n", std::llround(seconds * 1e6), std::llround(web_seconds * 1e6),
                                      used.size());
        for (const auto& [kind, c] : used)
            out += fmt::format("{} {} {} {} {}\n", c.hits, c.misses, c.rejected, c.unusable, kind);
        return out + packed(files);
    }

    static report_result read(const std::string& text)
    {
        report_result r;
        std::istringstream in(text);
        in.imbue(std::locale::classic());
        long long microseconds = 0, web = 0;
        std::size_t kinds = 0;
        in >> microseconds >> web >> kinds;
        r.seconds = static_cast<double>(microseconds) * 1e-6;
        r.web_seconds = static_cast<double>(web) * 1e-6;
        in.get();   // the end of the line
        for (std::size_t i = 0; i < kinds; ++i) {
            std::string kind;
            cache::counts c;
            in >> c.hits >> c.misses >> c.rejected >> c.unusable;
            in.get();   // the space before the name
            std::getline(in, kind);
            r.used[kind] = c;
        }
        std::optional<file_set> files = unpacked(text.substr(in ? static_cast<std::size_t>(in.tellg()) : text.size()));
        if (!in || !files)
            throw std::runtime_error("the report's process sent back a result that is not whole");
        r.files = std::move(*files);
        return r;
    }
};

// Counts by kind made between `before` and `after`.
std::map<std::string, cache::counts> counts_since(const std::map<std::string, cache::counts>& before,
                                                  const std::map<std::string, cache::counts>& after)
{
    std::map<std::string, cache::counts> made;
    for (const auto& [kind, c] : after) {
        const auto was = before.find(kind);
        const cache::counts b = was == before.end() ? cache::counts{} : was->second;
        if (c.hits != b.hits || c.misses != b.misses || c.rejected != b.rejected || c.unusable != b.unusable)
            made[kind] = {c.hits - b.hits, c.misses - b.misses, c.rejected - b.rejected, c.unusable - b.unusable};
    }
    return made;
}

} // namespace

file_set generate_kernels(const library& lib, std::vector<std::string>* missed, const kernel_options& how)
{
    const std::vector<verify::kernel_plan> plans = verify::plan_kernels(lib, how.store, {}, worker_runner(how.jobs));
    if (missed)
        *missed = verify::missed_bounds(plans);
    return emit::kernel_files(lib, plans);
}

namespace {

// The LaTeX fragments, derivations.json and errata.md; with `z3`, proofs/<id>.smt2 and
// each proven check's answer from Z3 in derivations.json.
void add_documents(const library& lib, file_set& files, const verify::proof_checks* z3 = nullptr)
{
    // A derivation whose results the printers cannot write (the imaginary unit, a constant
    // such as Pi) is reported at its file, before the files that gather every derivation:
    // the first, in order, whose JSON or LaTeX fragment cannot be printed (its JSON first).
    // derivations.json is printed once, for all of them; a derivation's JSON is printed
    // alone only when something failed, to find the one at fault.
    const std::vector<const engine::derivation*> all = lib.in_order();
    const auto at_fault = [](const engine::derivation& d, const std::exception& e) {
        return error({d.source.file, 0, 0}, fmt::format("cannot print what derivation '{}' derives: {}", d.id(), e.what()));
    };
    // Each of the first `count` derivations' JSON alone: the first that fails, at its file.
    const auto json_alone = [&](std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            try {
                emit::derivations_json({all[i]});
            } catch (const error&) {
                throw;
            } catch (const std::exception& e) {
                throw at_fault(*all[i], e);
            }
        }
    };
    for (std::size_t i = 0; i < all.size(); ++i) {
        try {
            files["latex/" + emit::latex_fragment_name(*all[i])] = emit::latex_fragment(*all[i], &lib.derived);
        } catch (const error&) {
            json_alone(i + 1);
            throw;
        } catch (const std::exception& e) {
            json_alone(i + 1);
            throw at_fault(*all[i], e);
        }
    }
    try {
        files["derivations.json"] = emit::derivations_json(all, z3);
    } catch (const std::exception&) {
        json_alone(all.size());
        throw;
    }
    if (z3)
        for (const verify::derivation_proofs& d : z3->derivations)
            files["proofs/" + d.id + ".smt2"] = verify::smt2_file(d);
    files["errata.md"] = emit::errata_markdown(lib.in_order(), lib.outline ? &*lib.outline : nullptr);
}

// The kernel headers and verification.md, the choice of forms taken from `store` where it
// can be; the outputs that miss their bounds.
std::vector<std::string> add_kernels(const library& lib, file_set& files, stopwatch& clock, const kernel_options& how,
                                     progress* shown, const verify::proof_checks* z3 = nullptr,
                                     std::map<std::string, std::string>* web_kernels = nullptr)
{
    const char* task = "kernel forms";
    const std::vector<verify::kernel_plan> plans = verify::plan_kernels(
        lib, how.store,
        [&](std::size_t done, std::size_t total) {
            if (shown)
                shown->say(task, fmt::format("choosing kernel forms: {} of {} kernels", done, total));
        },
        worker_runner(how.jobs));
    if (shown)
        shown->done(task);
    clock.lap(how.jobs > 1 ? fmt::format("kernel forms chosen by measurement (numeric, up to {} worker processes)",
                                         how.jobs)
                           : std::string("kernel forms chosen by measurement (numeric)"));
    for (auto& [path, contents] : emit::kernel_files(lib, plans))
        files[path] = std::move(contents);
    clock.lap("kernel sources");
    std::vector<const verify::kernel_plan*> all;
    for (const verify::kernel_plan& p : plans)
        all.push_back(&p);
    files["verification.md"] = emit::verification_markdown(all, engine::source_folder(lib.in_order()),
                                                               emit::of_the_paper(lib.in_order()), z3);
    if (web_kernels)
        *web_kernels = emit::verification_html(lib.in_order(), all);
    clock.lap("verification report (numeric)");
    return verify::missed_bounds(plans);
}

} // namespace

file_set generate(const library& lib, stage_times* stages)
{
    stopwatch clock(stages);
    file_set files;
    add_documents(lib, files);
    clock.lap("LaTeX fragments, derivations.json, errata.md");
    add_kernels(lib, files, clock, {}, nullptr);
    return files;
}

std::vector<std::string> cache_summary(const regeneration& r)
{
    return cache_summary(r.cache, r.cache_counts);
}

std::vector<std::string> cache_summary(const std::optional<fs::path>& folder,
                                       const std::map<std::string, cache::counts>& counts)
{
    std::vector<std::string> lines;
    if (!folder)
        return {"cache: none (--no-cache)"};
    lines.push_back("cache: " + folder->string());
    for (const auto& [kind, c] : counts) {
        std::string line = fmt::format("cache: {}: {} reused, {} computed ({} damaged", kind, c.hits, c.misses, c.rejected);
        if (c.unusable > 0)
            line += fmt::format(", {} found but not usable", c.unusable);
        lines.push_back(line + ", computed again)");
    }
    return lines;
}

std::vector<std::string> failed_checks(const library& lib)
{
    std::vector<std::string> failures;
    for (const engine::derivation* d : lib.in_order())
        for (const engine::check_result* c : d->all_checks())
            if (!c->outcome.holds())
                failures.push_back(single_line(fmt::format("{}: error: check failed: {}: {}: residual {}",
                                                           to_string(c->where), d->id(), c->name,
                                                           d->symbols.text(c->outcome.residual))));
    return failures;
}

regeneration regenerate(const fs::path& derivations, const fs::path& output, bool force)
{
    regenerate_options options;
    options.force = force;
    return regenerate(derivations, output, options);
}

regeneration regenerate(const fs::path& derivations, const fs::path& output, const regenerate_options& options)
{
    // The output and cache folders are checked before anything is derived, so that a
    // refusal comes at once.
    const fs::path target = checked_folder(output, derivations);
    recover_interrupted(target);
    check_writable(target, {}, options.force);
    std::optional<cache::store> store;
    if (options.cache)
        store.emplace(*options.cache, options.cache_size);
    progress shown(options.progress);

    regeneration result;
    result.cache = options.cache;
    const auto start = std::chrono::steady_clock::now();
    stopwatch clock(&result.stages);
    // Nothing that changes what Impact writes: the output of the last regeneration of
    // these files (the cache checks the entry's length and SHA-256).
    // The paper's order of places, read once, before anything is derived: for the cache's
    // key and for the errata.
    const std::optional<spec::paper_outline> outline = spec::read_paper_outline(derivations);
    const std::optional<std::string> key = store ? output_key(derivations, outline) : std::nullopt;
    if (key)
        if (const std::optional<std::string> entry = store->get("output", *key))
            if (const std::optional<file_set> cached = unpacked(*entry)) {
                clock.lap("the whole output, from the cache (no derivation file changed but for comments)");
                result.all_hold = true;
                result.files = cached->size();
                result.written = replace_folder(target, *cached, options.force);
                store->trim();
                result.cache_counts = store->statistics();
                result.stages.emplace_back(
                    "total (wall time)",
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
                return result;
            }
    shown.say("derivations", "deriving and proving");
    const engine::derivation_store kept = derivations_kept(store ? &*store : nullptr);
    const auto told = [&shown](std::size_t done, std::size_t all) {
        shown.say("derivations", fmt::format("deriving and proving: {} of {} files", done, all));
    };
    library lib = engine::derive_all(engine::read_directory(derivations), "", {&kept, worker_runner(options.jobs), told});
    lib.outline = outline;
    shown.done("derivations");
    clock.lap("derivations with their checks");
    result.failures = failed_checks(lib);
    result.all_hold = result.failures.empty();
    if (!result.all_hold)
        return result;
    // Every proof re-checked by Z3, each answer kept in the cache by its problem's text. A
    // proof Z3 refutes fails the regeneration as a failed check does, with Z3's model.
    shown.say("z3", "re-checking the proofs with Z3");
    const verify::proof_checks z3 = verify::check_proofs(
        lib.in_order(), lib.derived, store ? &*store : nullptr,
        [&shown](std::size_t done, std::size_t all) {
            shown.say("z3", fmt::format("re-checking the proofs with Z3: {} of {} problems", done, all));
        },
        z3_runner_for(options.jobs));
    shown.done("z3");
    clock.lap(fmt::format("proofs re-checked by Z3 ({} problems, {} run, {:.1f} s in Z3{})", z3.problems, z3.run,
                          z3.seconds,
                          options.jobs > 1 ? fmt::format(", up to {} worker processes", options.jobs)
                                           : std::string(", in a worker process")));
    result.failures = z3.refuted();
    result.all_hold = result.failures.empty();
    if (!result.all_hold)
        return result;

    file_set files;
    add_documents(lib, files, &z3);
    clock.lap("LaTeX fragments, derivations.json, errata.md");
    // The report's sources print GiNaC expressions, so they are made here; compiling them
    // runs pdflatex and nothing of GiNaC's (which is not thread-safe), beside the choice
    // of kernel forms on this thread.
    file_set report_files = report::report_sources(lib, &z3);
    file_set sources = report_files;
    for (const auto& [path, contents] : files)
        if (path.rfind("latex/", 0) == 0 || path == "derivations.json")
            sources[path] = contents;
    clock.lap("figures' tables, report.tex");
    // Compiled in a process beside this one (workers.h says why not a thread), which sends
    // back the PDFs, its time and its use of the cache.
    cache::store* const shared = store ? &*store : nullptr;
    engine::text_task compile;
    compile.what = "the report";
    compile.where = {"output/report.pdf", 0, 0};
    compile.doing = "compiling it";
    compile.instead = "compile it";
    compile.run = [&] {
        const auto began = std::chrono::steady_clock::now();
        const std::map<std::string, cache::counts> before = shared ? shared->statistics() : std::map<std::string, cache::counts>{};
        report::compile_options compiling;
        compiling.store = shared;
        file_set made = report::compile_report(sources, compiling);
        // The web pages, from the same sources and the figures' PDFs (report/html.h).
        const auto web_began = std::chrono::steady_clock::now();
        file_set with_pdfs = sources;
        for (const auto& [path, contents] : made)
            with_pdfs[path] = contents;
        for (auto& [path, contents] : report::html_site(with_pdfs, shared))
            made[path] = std::move(contents);
        const auto done = std::chrono::steady_clock::now();
        return report_result{made, shared ? counts_since(before, shared->statistics()) : std::map<std::string, cache::counts>{},
                             std::chrono::duration<double>(done - began).count(),
                             std::chrono::duration<double>(done - web_began).count()}
            .text();
    };
    beside report_process(std::move(compile));
    shown.say("report", "compiling the figures and the report");
    std::map<std::string, std::string> web_kernels;
    const std::vector<std::string> missed =
        add_kernels(lib, files, clock, kernel_options{shared, options.jobs}, &shown, &z3, &web_kernels);
    const report_result compiled = report_result::read(report_process.get());
    shown.done("report");
    for (auto& [path, contents] : report_files)
        files[path] = std::move(contents);
    for (const auto& [path, contents] : compiled.files)
        files[path] = contents;
    // Each derivation's page gets its kernels and their accuracy, measured beside the pages.
    for (auto& [path, contents] : files) {
        if (path.rfind("html/", 0) != 0)
            continue;
        const std::size_t marker = contents.find(report::html_kernels_marker);
        if (marker == std::string::npos)
            continue;
        // index.html takes the kernels' summary (the entry named "").
        const std::string id = path == "html/index.html" ? "" : path.substr(5, path.size() - 10);
        const auto section = web_kernels.find(id);
        contents.replace(marker, std::char_traits<char>::length(report::html_kernels_marker),
                         section == web_kernels.end() ? "" : section->second);
    }
    if (store)
        for (const auto& [kind, more] : compiled.used)
            store->add_counts(kind, more);
    const double report_seconds = compiled.seconds;
    clock.lap("waiting for the figures and report");
    result.stages.emplace_back("figures, report PDFs and web pages (beside the kernel forms)", report_seconds);
    result.stages.emplace_back("  of which the web pages (html/)", compiled.web_seconds);
    // A kernel that misses its accuracy bound fails the regeneration like a failed check.
    if (!missed.empty()) {
        result.failures = missed;
        result.all_hold = false;
        return result;
    }
    result.files = files.size();
    result.written = replace_folder(target, files, options.force);
    if (store) {
        if (key)
            store->put("output", *key, packed(files));
        store->trim();
        result.cache_counts = store->statistics();
    }
    result.stages.emplace_back("total (wall time)",
                               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return result;
}

} // namespace impact::pipeline
