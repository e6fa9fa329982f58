// A cache of results by the content of what they were computed from.
//
// The expensive stages (the numeric choice of kernel forms, the figures' and the
// report's PDFs) ask the store for a result by a key, the text of everything the
// result depends on; the store names the entry by the SHA-256 of that text and keeps
// the result's length and SHA-256 beside it. An entry that does not match them (a disk
// or a user damaged it, a run was killed while writing it) is rejected and the result
// computed again: an entry is never trusted because of its name alone.
//
// The folder holds `CACHEDIR.TAG` (the Cache Directory Tagging standard, naming Impact)
// and entries `<64 hex digits>.entry`, nothing else. Entries are written to a temporary
// file beside their place and renamed into it, so that two regenerations sharing the
// folder each see a whole entry or none. The store removes only files of those names,
// and it refuses a folder holding anything else (it may be the user's) or a file.
// Beyond the size limit the entries used longest ago are removed (`trim`).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace impact::cache {

/// Where Impact keeps its cache when not told: `$XDG_CACHE_HOME/impact`, or
/// `~/.cache/impact` when XDG_CACHE_HOME is unset or not absolute.
std::filesystem::path default_folder();

/// The running executable's identity: its linker build ID (a hash of the whole linked
/// program), or the SHA-256 of the executable's file when it was linked without one. Part
/// of every key whose result Impact's own code computes, so that a rebuilt Impact never
/// reuses what an older one measured.
const std::string& program_fingerprint();

/// How often each kind of entry was found, computed, or rejected as damaged.
struct counts {
    std::size_t hits = 0;
    std::size_t misses = 0;    ///< computed (including those rejected and unusable)
    std::size_t rejected = 0;  ///< present but damaged: wrong length, hash or header
    std::size_t unusable = 0;  ///< whole, but its reader could not use it (`store::unusable`)
};

/// The size the cache is kept under by default, in bytes.
inline constexpr std::uintmax_t default_limit = 256ull << 20;

/// A size as `--cache-size` and IMPACT_CACHE_SIZE give it: a whole number of bytes, or
/// one followed by K, M, G or T (powers of 1024, either case, `B` or `iB` allowed after),
/// e.g. `512M`, `2G`, `1048576`; nothing when `text` is not one (or is too large).
std::optional<std::uintmax_t> parse_size(const std::string& text);

/// Files (path → contents) as one text for an entry, and back: for each file, its path's and
/// contents' lengths, then both. Nothing when the text is not such a one.
std::string packed(const std::map<std::string, std::string>& files);
std::optional<std::map<std::string, std::string>> unpacked(const std::string& text);

class store {
public:
    /// Opens the cache folder, creating it when missing. Throws `impact::error` naming
    /// `folder` when it is a file, or a folder holding a file or folder that is not
    /// Impact's cache (nothing in it is touched then).
    explicit store(std::filesystem::path folder, std::uintmax_t limit = default_limit);

    /// The result stored for `kind` and `key`, or nothing (missing or damaged).
    std::optional<std::string> get(const std::string& kind, const std::string& key);

    /// Stores `value` for `kind` and `key`. A failure to write (a full or read-only disk)
    /// is not an error: the result is only not kept.
    void put(const std::string& kind, const std::string& key, const std::string& value);

    /// An entry `get` gave for `kind` was whole but of no use to its reader (a derivation
    /// whose file moved in a way its places cannot follow): counted as computed again, not
    /// as reused.
    void unusable(const std::string& kind);

    /// Removes the entries used longest ago until the cache is under its limit, and
    /// temporary files a killed run left over an hour ago.
    void trim();

    /// Counts by kind, for `--timings`.
    std::map<std::string, counts> statistics() const;

    /// Adds `more` to the counts of `kind`: those of a process that used the same folder
    /// on this one's behalf (the report's, pipeline::beside).
    void add_counts(const std::string& kind, const counts& more);

    const std::filesystem::path& folder() const { return folder_; }

    /// The file an entry for `kind` and `key` is kept in (for tests that damage one).
    std::filesystem::path entry_path(const std::string& kind, const std::string& key) const;

private:
    std::filesystem::path folder_;
    std::uintmax_t limit_;
    mutable std::mutex mutex_;
    std::map<std::string, counts> counts_;
};

/// True when `name` is a file name the store writes (an entry or a temporary file).
bool is_store_file_name(const std::string& name);

} // namespace impact::cache
