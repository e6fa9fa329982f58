// Writes the kernel headers into the build tree, before `impact` is built.
//
// `impact` itself is compiled against the generated kernels (its figures and
// `impact simulate` run them), so the build cannot use it to generate them: this
// small program does what `impact kernels` does, with the same pipeline functions.
//
//     impact_kernelgen <derivations folder> <output folder>
#include "emit/cxx.h"
#include "engine/library.h"
#include "pipeline/output_folder.h"
#include "verify/choice.h"

#include <fmt/format.h>

#include <exception>
#include <filesystem>

int main(int argc, char** argv)
{
    if (argc != 3) {
        fmt::print(stderr, "usage: impact_kernelgen <derivations folder> <output folder>\n");
        return 2;
    }
    try {
        const impact::engine::library lib =
            impact::engine::derive_all(impact::engine::read_directory(argv[1]));
        if (!lib.all_hold()) {
            for (const std::string& id : lib.order)
                for (const impact::engine::check_result* c : lib.derived.at(id).all_checks())
                    if (!c->outcome.holds())
                        fmt::print(stderr, "impact_kernelgen: {}: check '{}' failed\n", id, c->name);
            fmt::print(stderr, "impact_kernelgen: no kernels written (run `impact derive <id>` for the proofs)\n");
            return 1;
        }
        // The build tree's folder of generated kernels is the build's own: forced, since a
        // build folder made before Impact marked its output holds unmarked headers.
        impact::pipeline::replace_folder(std::filesystem::absolute(argv[2]).lexically_normal(),
                                         impact::emit::kernel_files(lib, impact::verify::plan_kernels(lib)), /*force=*/true);
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "{}\n", e.what());
        return 2;
    }
}
