// Writing what Impact generates: derivations.json, LaTeX fragments, kernel headers.
//
// `regenerate` replaces the output folder only after every derivation has been
// derived with all its checks holding and every file has been written to a fresh
// folder beside it; a failure leaves the previous output as it was.
#pragma once

#include "pipeline/library.h"

#include <filesystem>
#include <map>
#include <string>

namespace impact::pipeline {

/// Every generated file, by path relative to the output folder.
using file_set = std::map<std::string, std::string>;

/// The files for a derived library: derivations.json, latex/<id>.tex, kernels/impact/*.hpp.
file_set generate(const library& lib);

/// Only the kernel headers (kernels/impact/*.hpp), for building against them.
file_set generate_kernels(const library& lib);

/// Writes `files` into `directory` (created if needed).
void write_files(const file_set& files, const std::filesystem::path& directory);

struct regeneration {
    bool all_hold = false;            ///< false: some check failed and nothing was replaced
    std::size_t files = 0;
    std::vector<std::string> failures; ///< "id: check" for each failed check
};

/// Derives everything in `derivations` and, when every check holds, replaces `output`
/// with the generated files. Bad input throws `impact::error` before anything is written.
regeneration regenerate(const std::filesystem::path& derivations, const std::filesystem::path& output);

} // namespace impact::pipeline
