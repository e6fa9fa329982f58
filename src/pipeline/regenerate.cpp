#include "pipeline/regenerate.h"

#include "emit/cxx.h"
#include "emit/errata.h"
#include "emit/json.h"
#include "emit/latex.h"

#include <fmt/format.h>

#include <fstream>

namespace impact::pipeline {
namespace fs = std::filesystem;

file_set generate_kernels(const library& lib)
{
    file_set files;
    std::vector<const engine::derivation*> with_kernels;
    for (const engine::derivation* d : lib.in_order()) {
        if (d->kernels.empty())
            continue;
        with_kernels.push_back(d);
        files["kernels/impact/" + emit::kernel_header_name(*d)] = emit::kernel_header(*d);
    }
    files["kernels/impact/impact.hpp"] = emit::umbrella_header(with_kernels);
    return files;
}

file_set generate(const library& lib)
{
    file_set files = generate_kernels(lib);
    files["derivations.json"] = emit::derivations_json(lib.in_order());
    files["errata.md"] = emit::errata_markdown(lib.in_order());
    for (const engine::derivation* d : lib.in_order())
        files["latex/" + emit::latex_fragment_name(*d)] = emit::latex_fragment(*d);
    return files;
}

void write_files(const file_set& files, const fs::path& directory)
{
    for (const auto& [relative, contents] : files) {
        const fs::path path = directory / relative;
        fs::create_directories(path.parent_path());
        std::ofstream out(path, std::ios::binary);
        out << contents;
        if (!out.good())
            throw error({path.string(), 0, 0}, "cannot write the file");
    }
}

regeneration regenerate(const fs::path& derivations, const fs::path& output)
{
    const library lib = derive_all(read_directory(derivations));
    regeneration result;
    for (const engine::derivation* d : lib.in_order())
        for (const engine::check_result* c : d->all_checks())
            if (!c->outcome.holds())
                result.failures.push_back(fmt::format("{}: {}", d->id(), c->name));
    result.all_hold = result.failures.empty();
    if (!result.all_hold)
        return result;

    const file_set files = generate(lib);
    result.files = files.size();

    // Write beside the output folder, then swap: the old output survives any failure
    // before the swap.
    const fs::path target = fs::absolute(output).lexically_normal();
    const fs::path fresh = target.parent_path() / (target.filename().string() + ".impact-new");
    const fs::path old = target.parent_path() / (target.filename().string() + ".impact-old");
    fs::remove_all(fresh);
    fs::remove_all(old);
    write_files(files, fresh);
    if (fs::exists(target))
        fs::rename(target, old);
    fs::rename(fresh, target);
    fs::remove_all(old);
    return result;
}

} // namespace impact::pipeline
