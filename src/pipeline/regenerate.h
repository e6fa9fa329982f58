// Regeneration: every stage in order, from the derivation files to output/.
//
// `regenerate` replaces the output folder only after every derivation has been
// derived with all its checks holding and every file has been written to a fresh
// folder beside it (`<output>.impact-new`); a failure leaves the previous output as it
// was, and a run that was killed is put right by the next one.
#pragma once

#include "cache/store.h"
#include "engine/library/library.h"
#include "pipeline/output_folder.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace impact::pipeline {

using engine::library;

/// Wall time of each stage of a regeneration, in seconds, in the order they ran.
using stage_times = std::vector<std::pair<std::string, double>>;

/// The files for a derived library: derivations.json, latex/<id>.tex, kernels/impact/*.hpp.
file_set generate(const library& lib, stage_times* stages = nullptr);

/// How the kernels' forms are chosen: the cache to take choices from and keep them in
/// (or none), and how many kernels are measured at once, each in a worker process of
/// its own (src/pipeline/workers.h; 1: one after another, in this process).
struct kernel_options {
    cache::store* store = nullptr;
    unsigned jobs = 1;
};

/// Only the kernel headers (kernels/impact/*.hpp), for building against them; `missed`,
/// when given, receives the outputs that miss their accuracy bounds (verify::missed_bounds).
file_set generate_kernels(const library& lib, std::vector<std::string>* missed = nullptr,
                          const kernel_options& how = {});

/// The cache as the engine keeps derivations in it (engine::derivation_store), each keyed
/// by Impact's executable and what it is derived from; with no store, none kept.
engine::derivation_store derivations_kept(cache::store* store);

/// One line for each check that failed: `file:line:column: error: check failed: id: name: residual r`.
std::vector<std::string> failed_checks(const library& lib);

struct regeneration {
    bool all_hold = false;            ///< false: some check failed and nothing was replaced
    std::size_t files = 0;
    std::vector<std::string> failures; ///< as `failed_checks` gives them
    stage_times stages;
    write_report written;             ///< the user's files kept beside the output, or moved aside
    std::optional<std::filesystem::path> cache;    ///< the cache folder used, if any
    std::map<std::string, cache::counts> cache_counts;  ///< by kind of entry
};

struct regenerate_options {
    bool force = false;                               ///< write into a folder Impact does not own
    std::optional<std::filesystem::path> cache;       ///< the cache folder (src/cache/store.h), or none
    std::uintmax_t cache_size = cache::default_limit; ///< the cache trimmed to this many bytes
    bool progress = false;                            ///< a progress line on standard error
    unsigned jobs = 1;                                ///< derivations, Z3's problems, kernels' forms, worked on at once
};

/// One line a kind of cache entry: `kernel choice: 12 reused, 0 computed (0 damaged)`.
std::vector<std::string> cache_summary(const regeneration& r);
std::vector<std::string> cache_summary(const std::optional<std::filesystem::path>& folder,
                                       const std::map<std::string, cache::counts>& counts);

/// Derives everything in `derivations` and, when every check holds, replaces what Impact
/// wrote in `output` with the generated files, the figures and the report, keeping every other
/// file there (src/pipeline/output_folder.h). Bad input throws `impact::error` before
/// anything is written, and so does an output folder Impact may not write into (a folder
/// Impact does not own is written into only with `force`).
regeneration regenerate(const std::filesystem::path& derivations, const std::filesystem::path& output,
                        bool force = false);

/// The same, with a cache: each derivation (by its file and those it uses), Z3's answers,
/// the choice of kernel forms and the PDFs are taken from it when what they depend on is
/// unchanged, and computed and kept in it otherwise (the files written are the same bytes
/// either way). The report is compiled beside the choice of kernel forms, and with `jobs`
/// above 1 the derivations that do not use one another are derived, Z3's problems run
/// (pipeline/z3_workers.h), and the kernels' forms chosen, in worker processes, that many
/// at once (the output the same bytes). A cache folder that is
/// a file, or holds what is not Impact's, throws `impact::error` before anything is derived
/// or written.
regeneration regenerate(const std::filesystem::path& derivations, const std::filesystem::path& output,
                        const regenerate_options& options);

} // namespace impact::pipeline
