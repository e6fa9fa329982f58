// The derivation library: every file under derivations/, read, ordered and derived.
//
// Derivation files may use one another's results (`[[use]]`), so they are derived in
// an order where each comes after the ones it uses; a missing derivation, a cycle or
// two files with the same id is bad input.
#pragma once

#include "engine/derive/derive.h"
#include "engine/library/tasks.h"
#include "spec/derivation.h"
#include "spec/outline.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace impact::engine {

struct library {
    derived_by_id derived;            ///< by id
    std::vector<std::string> order;   ///< ids in the order they were derived
    /// The paper's places in print order (spec/outline.h), when the folder has them: the
    /// errata's order. Set by derive_folder and by the regeneration (which reads it once,
    /// for its cache's key too); none: derivation by derivation.
    std::optional<spec::paper_outline> outline;

    /// The derivations in derivation order.
    std::vector<const engine::derivation*> in_order() const;
    /// True when every check of every derivation holds.
    bool all_hold() const;
};

/// Reads every `*.toml` in `directory` (sorted by file name). Throws `impact::error`.
std::vector<spec::derivation> read_directory(const std::filesystem::path& directory);

/// The derivation files of a folder (`*.toml`, regular files), sorted by path.
std::vector<std::filesystem::path> derivation_files(const std::filesystem::path& directory);

/// Derivations kept between runs (the pipeline's cache, src/cache/store.h): `find` gives
/// the text kept for a key, if any, and `keep` keeps one. A derivation's key is the text of
/// what it is derived from: its file's path and bytes, and the keys of the derivations it
/// uses (engine/store/stored.h writes and reads the text). `unusable` is told of a text `find`
/// gave that could not be read back (the file's keys reordered, say: the same key, places
/// that cannot be followed), the derivation then derived again.
struct derivation_store {
    std::function<std::optional<std::string>(const std::string& key)> find;
    std::function<void(const std::string& key, const std::string& text)> keep;
    std::function<void(const std::string& key)> unusable;
};

/// How a library is derived: with `kept`, a derivation whose file and uses are unchanged
/// is taken from it (the same derivation), and each one derived is kept in it; with a
/// `runner`, derivations that do not use one another are derived as its tasks (in worker
/// processes), each sending back its text (engine/store/stored.h); `progress(k, n)` is told as
/// each of the n derivations is done.
struct deriving {
    const derivation_store* kept = nullptr;
    task_runner runner{};
    std::function<void(std::size_t done, std::size_t all)> progress{};
};

/// Derives `sources` in dependency order; with `only`, just that id and what it uses. The
/// library is the same however `how` derives it, and a bad file throws the same error (the
/// first bad file's in that order).
library derive_all(const std::vector<spec::derivation>& sources, const std::string& only = "",
                   const deriving& how = {});

/// Every derivation of a folder (read_directory, derive_all), with the paper's order of
/// places that the folder's `paper_order.txt` gives (spec::read_paper_outline).
library derive_folder(const std::filesystem::path& directory);

/// The id of the derivation that `name` names: an id, or the path of one of the files.
std::string resolve_id(const std::vector<spec::derivation>& sources, const std::string& name);

/// A folder read for one of its derivations: the files that read, and the errors of those
/// that did not, kept rather than thrown (with the id each declares, when its `id = "..."`
/// line can be found), so that a file the one derived does not use does not stop it.
struct folder_read {
    struct unreadable {
        std::string file;
        std::string id;   ///< as its `id = "..."` line gives it; empty when none is found
        error what;
    };
    std::vector<spec::derivation> sources;
    std::vector<unreadable> failures;
};
folder_read read_directory_for_one(const std::filesystem::path& directory);

/// Derives the derivation `name` names (an id or a file) and those it uses, from a folder
/// read by read_directory_for_one: a file that could not be read is an error only when it
/// is that derivation or one it uses (its own error, as read_directory throws it), and two
/// files of one id only when the id is one of those.
library derive_one_of(const folder_read& folder, const std::string& name, const deriving& how = {});

} // namespace impact::engine
