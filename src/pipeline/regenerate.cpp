#include "pipeline/regenerate.h"

#include "emit/cxx.h"
#include "emit/errata.h"
#include "emit/json.h"
#include "emit/latex.h"
#include "verify/report.h"

#include <fmt/format.h>

#include <chrono>

namespace impact::pipeline {
namespace fs = std::filesystem;

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

// Every kernel's plan (its forms chosen by measurement), derivation by derivation.
std::vector<emit::kernel_plan> plan_kernels(const library& lib)
{
    std::vector<emit::kernel_plan> plans;
    for (const engine::derivation* d : lib.in_order()) {
        const engine::term_order order = engine::declaration_order(d->symbols);
        for (const engine::kernel& k : d->kernels)
            plans.push_back(emit::plan_kernel(k, order));
    }
    return plans;
}

file_set kernel_files(const library& lib, const std::vector<emit::kernel_plan>& plans)
{
    file_set files;
    std::vector<const engine::derivation*> with_kernels;
    std::vector<const emit::kernel_plan*> all;
    std::size_t next = 0;
    for (const engine::derivation* d : lib.in_order()) {
        if (d->kernels.empty())
            continue;
        with_kernels.push_back(d);
        std::vector<const emit::kernel_plan*> own;
        for (std::size_t i = 0; i < d->kernels.size(); ++i)
            own.push_back(&plans[next++]);
        all.insert(all.end(), own.begin(), own.end());
        files["kernels/impact/" + emit::kernel_header_name(*d)] = emit::kernel_header(*d, own);
    }
    files["kernels/impact/common.hpp"] = emit::common_header(all);
    files["kernels/impact/impact.hpp"] = emit::umbrella_header(with_kernels);
    return files;
}

} // namespace

file_set generate_kernels(const library& lib)
{
    return kernel_files(lib, plan_kernels(lib));
}

file_set generate(const library& lib, stage_times* stages)
{
    stopwatch clock(stages);
    file_set files;
    // A derivation whose results the printers cannot write (the imaginary unit, a constant
    // such as Pi) is reported at its file, before the files that gather every derivation.
    for (const engine::derivation* d : lib.in_order()) {
        try {
            emit::derivations_json({d});
            files["latex/" + emit::latex_fragment_name(*d)] = emit::latex_fragment(*d);
        } catch (const error&) {
            throw;
        } catch (const std::exception& e) {
            throw error({d->source.file, 0, 0}, fmt::format("cannot print what derivation '{}' derives: {}",
                                                            d->id(), e.what()));
        }
    }
    files["derivations.json"] = emit::derivations_json(lib.in_order());
    files["errata.md"] = emit::errata_markdown(lib.in_order());
    clock.lap("LaTeX fragments, derivations.json, errata.md");
    const std::vector<emit::kernel_plan> plans = plan_kernels(lib);
    clock.lap("kernel forms chosen by measurement (numeric)");
    for (auto& [path, contents] : kernel_files(lib, plans))
        files[path] = std::move(contents);
    clock.lap("kernel sources");
    std::vector<const emit::kernel_plan*> all;
    for (const emit::kernel_plan& p : plans)
        all.push_back(&p);
    files["verification.md"] = verify::verification_markdown(all);
    clock.lap("verification report (numeric)");
    return files;
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

regeneration regenerate(const fs::path& derivations, const fs::path& output, const more_files& more, bool force)
{
    // The output folder is checked before anything is derived, so that a refusal comes at once.
    const fs::path target = checked_folder(output, derivations);
    recover_interrupted(target);
    check_writable(target, {}, force);

    regeneration result;
    stopwatch clock(&result.stages);
    const library lib = derive_all(read_directory(derivations));
    clock.lap("derivations with their checks");
    result.failures = failed_checks(lib);
    result.all_hold = result.failures.empty();
    if (!result.all_hold)
        return result;

    file_set files = generate(lib, &result.stages);
    clock.lap("");
    result.stages.pop_back();
    if (more)
        for (auto& [path, contents] : more(lib, files))
            files[path] = std::move(contents);
    clock.lap("figures and report");
    result.files = files.size();
    result.written = replace_folder(target, files, force);
    return result;
}

} // namespace impact::pipeline
