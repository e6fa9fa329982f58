// Where Impact writes, and how it keeps what it did not write.
//
// Every folder Impact writes into holds a marker, `.impact-output`, that lists the files
// Impact wrote there. A folder is Impact's to write into when it is missing, empty, or
// holds the marker; any other folder is refused unless the user forces it. Whatever
// happens, only files the marker lists (regular files at those paths) are ever replaced
// or removed: every other file, folder or link in the folder is kept where it is. A folder
// inside one Impact wrote (`out/latex` of `--output out`) is Impact's too, its files those
// the marker above lists; files another command wrote in a folder inside, under a marker
// of their own (`impact latex -o out/latex/x.tex`), are Impact's: kept, never called the user's.
//
// A file Impact is about to write whose path is taken by something Impact did not write
// (or a folder Impact needs where a user's file is) is "in the way": refused, or, when
// forced, moved aside to `<name>.orig` (`<name>.orig2`, ... when that is taken too).
//
// Paths Impact never writes into, forced or not: a symbolic link, a file where a folder is
// meant, the root, a folder holding the derivations or the current folder, anything inside
// the derivations folder, inside a `.git` folder, or inside the `src/` or `tests/` beside the
// derivations folder.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace impact::pipeline {

/// Every generated file, by path relative to the folder it is written into.
using file_set = std::map<std::string, std::string>;

/// The marker's name, in every folder Impact writes into.
inline constexpr const char* marker_name = ".impact-output";

/// The marker's text listing `files` (sorted, one path a line, after a header naming Impact's version).
std::string marker_text(const file_set& files);

/// What a write kept of the user's and what it moved aside, as paths relative to the folder.
struct write_report {
    std::vector<std::string> kept;         ///< files Impact did not write, kept where they are
    std::vector<std::string> moved_aside;  ///< "a -> a.orig": files that were in the way (forced only)
};

/// How a folder is written: replaced as a whole (`replace_folder`), or files added beside
/// what it holds (`add_to_folder`). Only a folder replaced may not hold the derivations or
/// the current folder.
enum class writing { replacing, beside };

/// `folder` made absolute, or refused (throws `impact::error` naming `folder` as given) when
/// it is a path Impact never writes into (above). `derivations` is the folder of derivation files.
std::filesystem::path checked_folder(const std::filesystem::path& folder, const std::filesystem::path& derivations,
                                     writing how = writing::replacing);

/// Refuses (throws) unless Impact may write into `folder`: missing, empty, or holding the
/// marker, or `force`; and unless nothing is in the way of `files` there, or `force`.
/// Writes nothing; both writers below call it first.
void check_writable(const std::filesystem::path& folder, const file_set& files, bool force);

/// Replaces what Impact wrote in `folder` by `files`, keeping every other file. The new
/// folder is written whole beside it (`<folder>.impact-new`) and swapped in with two renames,
/// so that the previous output stays whole until it is replaced; a run killed part-way is
/// put right by `recover_interrupted`.
///
/// `stop_at`, for tests only (the `impact` command passes none), is a seam for faults: it
/// is called with "writing" once half the files are written, and with "swapping" once the
/// previous folder is moved aside and before the new one is moved in, so that a test can
/// kill the process at each point and show that nothing is lost.
write_report replace_folder(const std::filesystem::path& folder, const file_set& files, bool force,
                            void (*stop_at)(const char* point) = nullptr);

/// Writes `files` into `folder` beside what is there, replacing only files of the same
/// paths that Impact wrote; each file is written beside its place and renamed over it.
write_report add_to_folder(const std::filesystem::path& folder, const file_set& files, bool force);

/// Puts right what an interrupted `replace_folder` left: restores the previous folder from
/// `<folder>.impact-old` when `folder` is missing, and removes the leftover `.impact-new` and
/// `.impact-old` when they are Impact's (hold the marker, or nothing); refuses otherwise.
void recover_interrupted(const std::filesystem::path& folder);

} // namespace impact::pipeline
