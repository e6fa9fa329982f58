#include "pipeline/regenerate.h"

#include "emit/cxx.h"
#include "emit/errata.h"
#include "emit/json.h"
#include "emit/latex.h"
#include "emit/verification.h"
#include "report/report.h"
#include "verify/choice.h"

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

} // namespace

file_set generate_kernels(const library& lib)
{
    return emit::kernel_files(lib, verify::plan_kernels(lib));
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
    const std::vector<verify::kernel_plan> plans = verify::plan_kernels(lib);
    clock.lap("kernel forms chosen by measurement (numeric)");
    for (auto& [path, contents] : emit::kernel_files(lib, plans))
        files[path] = std::move(contents);
    clock.lap("kernel sources");
    std::vector<const verify::kernel_plan*> all;
    for (const verify::kernel_plan& p : plans)
        all.push_back(&p);
    files["verification.md"] = emit::verification_markdown(all);
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

regeneration regenerate(const fs::path& derivations, const fs::path& output, bool force)
{
    // The output folder is checked before anything is derived, so that a refusal comes at once.
    const fs::path target = checked_folder(output, derivations);
    recover_interrupted(target);
    check_writable(target, {}, force);

    regeneration result;
    stopwatch clock(&result.stages);
    const library lib = engine::derive_all(engine::read_directory(derivations));
    clock.lap("derivations with their checks");
    result.failures = failed_checks(lib);
    result.all_hold = result.failures.empty();
    if (!result.all_hold)
        return result;

    file_set files = generate(lib, &result.stages);
    clock.lap("");
    result.stages.pop_back();
    for (auto& [path, contents] : report::figures_and_report(lib, files))
        files[path] = std::move(contents);
    clock.lap("figures and report");
    result.files = files.size();
    result.written = replace_folder(target, files, force);
    return result;
}

} // namespace impact::pipeline
