// Writes the kernel headers into the build tree, before `impact` is built, and the sources
// of the Python module's bindings beside them (emit/python.h).
//
// `impact` itself is compiled against the generated kernels (its figures and
// `impact simulate` run them), so the build cannot use it to generate them: this
// small program does what `impact kernels` does, with the same pipeline functions.
//
//     impact_kernelgen <derivations folder> <output folder>
#include "emit/cxx.h"
#include "emit/python.h"
#include "engine/library/library.h"
#include "pipeline/output_folder.h"
#include "pipeline/workers.h"
#include "verify/choice.h"

#include <fmt/format.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

// Whether `folder` holds exactly `files` (and the marker that lists them), byte for byte.
bool holds_already(const std::filesystem::path& folder, const impact::pipeline::file_set& files)
{
    const auto same = [&](const std::filesystem::path& path, const std::string& text) {
        std::ifstream in(path, std::ios::binary);
        return in && std::string(std::istreambuf_iterator<char>(in), {}) == text;
    };
    for (const auto& [name, text] : files)
        if (!same(folder / name, text))
            return false;
    return same(folder / impact::pipeline::marker_name, impact::pipeline::marker_text(files));
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        fmt::print(stderr, "usage: impact_kernelgen <derivations folder> <output folder>\n");
        return 2;
    }
    try {
        // Every core, as `impact regenerate` uses them: the derivations that do not use one
        // another, then the kernels' measurements, in worker processes. Alone, the 3D rough
        // spheres took half of this program's 70 s, with the build's other core idle, since
        // what follows in the build waits for the kernels.
        const unsigned jobs = impact::pipeline::default_jobs();
        const impact::engine::task_runner runner = impact::pipeline::worker_runner(jobs);
        const impact::engine::library lib =
            impact::engine::derive_all(impact::engine::read_directory(argv[1]), "", {nullptr, runner, {}});
        if (!lib.all_hold()) {
            for (const std::string& id : lib.order)
                for (const impact::engine::check_result* c : lib.derived.at(id).all_checks())
                    if (!c->outcome.holds())
                        fmt::print(stderr, "impact_kernelgen: {}: check '{}' failed\n", id, c->name);
            fmt::print(stderr, "impact_kernelgen: no kernels written (run `impact derive <id>` for the proofs)\n");
            return 1;
        }
        // The build tree's folder of generated kernels is the build's own: forced, since a
        // build folder made before Impact marked its output holds unmarked headers. Headers
        // that come out as they were are left as they were, their times too, so that a change
        // to Impact that leaves the kernels alone recompiles nothing that includes them.
        const std::filesystem::path folder = std::filesystem::absolute(argv[2]).lexically_normal();
        impact::pipeline::file_set files = impact::emit::kernel_files(lib, impact::verify::plan_kernels(lib, nullptr, {}, runner));
        // The Python module's sources beside them (python/, built by the target `python`).
        files.merge(impact::emit::python_binding_files(lib));
        if (!holds_already(folder, files))
            impact::pipeline::replace_folder(folder, files, /*force=*/true);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "{}\n", e.what());
        return 2;
    }
}
