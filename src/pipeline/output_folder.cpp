#include "pipeline/output_folder.h"

#include "spec/error.h"

#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <vector>

#ifndef IMPACT_VERSION
#error "IMPACT_VERSION is set by CMakeLists.txt"
#endif

namespace impact::pipeline {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& path, const std::string& what)
{
    throw error({path.string(), 0, 0}, what);
}

// Filesystem failures become errors naming the path, printed on one line like bad input.
template <class Action>
void on_disk(const fs::path& path, const std::string& what, Action action)
{
    try {
        action();
    } catch (const fs::filesystem_error& e) {
        refuse(path, fmt::format("cannot {}: {}", what, e.code().message()));
    }
}

// Writes `contents` to `path` (its folder exists), naming the reason when the disk refuses:
// a full disk, a file-size limit or a read-only folder is an error, never a partial success.
void write_new_file(const fs::path& path, const std::string& contents, const fs::path& named)
{
    errno = 0;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (out)
        out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    if (out)
        out.close();
    if (!out) {
        const int reason = errno;
        std::error_code ignored;
        fs::remove(path, ignored);
        refuse(named, reason ? fmt::format("cannot write the file: {}", std::strerror(reason)) : "cannot write the file");
    }
}

void write_new_file(const fs::path& path, const std::string& contents)
{
    write_new_file(path, contents, path);
}

void create_folders(const fs::path& folder)
{
    on_disk(folder, "create the folder", [&] { fs::create_directories(folder); });
}

bool present(const fs::path& path)
{
    std::error_code ignored;
    return fs::exists(fs::symlink_status(path, ignored));
}

bool is_folder(const fs::path& path)
{
    std::error_code ignored;
    return fs::is_directory(fs::symlink_status(path, ignored));
}

bool is_regular(const fs::path& path)
{
    std::error_code ignored;
    return fs::is_regular_file(fs::symlink_status(path, ignored));
}

// The paths a folder's marker lists, or nothing when the folder has no marker.
std::optional<std::set<std::string>> listed_in(const fs::path& folder)
{
    const fs::path marker = folder / marker_name;
    if (!is_regular(marker))
        return std::nullopt;
    std::ifstream in(marker, std::ios::binary);
    if (!in)
        refuse(marker, "cannot read Impact's marker file");
    std::set<std::string> listed;
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line.front() != '#')
            listed.insert(line);
    return listed;
}

// What a folder holds, without following links: every file, link or other non-folder, and
// every empty folder, as paths relative to it; the marker is not counted.
struct contents {
    std::vector<std::string> files;
    std::vector<std::string> empty_folders;
    bool empty() const { return files.empty() && empty_folders.empty(); }
};

contents contents_of(const fs::path& folder)
{
    contents held;
    if (!is_folder(folder))
        return held;
    on_disk(folder, "read the folder", [&] {
        for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
            const std::string relative = entry.path().lexically_relative(folder).generic_string();
            if (entry.symlink_status().type() != fs::file_type::directory)
                held.files.push_back(relative);
            else if (fs::is_empty(entry.path()))
                held.empty_folders.push_back(relative);
        }
    });
    held.files.erase(std::remove(held.files.begin(), held.files.end(), std::string(marker_name)), held.files.end());
    std::sort(held.files.begin(), held.files.end());
    std::sort(held.empty_folders.begin(), held.empty_folders.end());
    return held;
}

fs::path normalised(const fs::path& folder);

// A folder without a marker of its own inside one Impact wrote (`out/latex` of `impact
// regenerate --output out`): the paths under it that the nearest marker above lists, as
// paths relative to it; nothing when no folder above holds a marker.
std::optional<std::set<std::string>> listed_above(const fs::path& folder)
{
    const fs::path path = normalised(folder);
    for (fs::path above = path.parent_path();; above = above.parent_path()) {
        if (const std::optional<std::set<std::string>> listed = listed_in(above)) {
            const std::string prefix = path.lexically_relative(above).generic_string() + "/";
            std::set<std::string> under;
            for (const std::string& entry : *listed)
                if (entry.size() > prefix.size() && entry.compare(0, prefix.size(), prefix) == 0)
                    under.insert(entry.substr(prefix.size()));
            return under;
        }
        if (above == above.parent_path())
            return std::nullopt;
    }
}

// A folder's contents split into Impact's files (listed in the marker, and regular files
// still), Impact's files of folders inside with markers of their own (another command's
// output, `impact latex -o out/latex/x.tex` in `out`), and everything else, which is the
// user's. A folder with no marker of its own is Impact's when a marker above lists files in
// it (`inherited`): those are Impact's.
struct ownership {
    bool marked = false;
    bool inherited = false;
    std::set<std::string> impacts;
    std::vector<std::string> nested;
    std::vector<std::string> users_files;
    std::vector<std::string> users_empty_folders;
};

ownership ownership_of(const fs::path& folder)
{
    ownership o;
    std::optional<std::set<std::string>> listed = listed_in(folder);
    o.marked = listed.has_value();
    if (!listed) {
        listed = listed_above(folder);
        o.inherited = listed && !listed->empty();
    }
    const contents held = contents_of(folder);
    // The markers of folders inside, and what each lists, are Impact's.
    std::set<std::string> nested;
    for (const std::string& file : held.files) {
        const fs::path path(file);
        if (path.filename() != marker_name || !is_regular(folder / file))
            continue;
        nested.insert(file);
        if (const std::optional<std::set<std::string>> inner = listed_in(folder / path.parent_path()))
            for (const std::string& entry : *inner)
                nested.insert((path.parent_path() / entry).generic_string());
    }
    for (const std::string& file : held.files) {
        if (listed && listed->count(file) && is_regular(folder / file))
            o.impacts.insert(file);
        else if (nested.count(file) && is_regular(folder / file))
            o.nested.push_back(file);
        else
            o.users_files.push_back(file);
    }
    o.users_empty_folders = held.empty_folders;
    return o;
}

// Every folder the files need, as paths relative to the folder written into.
std::set<std::string> folders_needed(const file_set& files)
{
    std::set<std::string> folders;
    for (const auto& [relative, contents] : files)
        for (fs::path p = fs::path(relative).parent_path(); !p.empty(); p = p.parent_path())
            folders.insert(p.generic_string());
    return folders;
}

// The part of `taken` (a user's path) that is in the way of `files`: `taken` itself when
// Impact writes a file there or, for a file, needs a folder there; or the folder above it
// that Impact writes as a file.
std::optional<std::string> in_the_way(const std::string& taken, bool is_empty_folder, const file_set& files,
                                      const std::set<std::string>& folders)
{
    if (files.count(taken) || (!is_empty_folder && folders.count(taken)))
        return taken;
    for (fs::path p = fs::path(taken).parent_path(); !p.empty(); p = p.parent_path())
        if (files.count(p.generic_string()))
            return p.generic_string();
    return std::nullopt;
}

// Where a user's path in the way goes: `<path>.orig`, or `.orig2`, `.orig3`, ... when taken.
std::string aside_name(const fs::path& folder, const std::string& path, const file_set& files,
                       const std::set<std::string>& folders, const std::set<std::string>& chosen)
{
    for (int n = 1;; ++n) {
        const std::string candidate = path + ".orig" + (n == 1 ? "" : std::to_string(n));
        if (!present(folder / candidate) && !files.count(candidate) && !folders.count(candidate) &&
            !chosen.count(candidate))
            return candidate;
    }
}

// Whether `path` is a regular file holding exactly `contents`: compared a block at a time,
// so that the whole output compared (a warm regeneration) allocates nothing large.
bool holds(const fs::path& path, const std::string& contents)
{
    if (!is_regular(path))
        return false;
    std::error_code ignored;
    if (fs::file_size(path, ignored) != contents.size())
        return false;
    std::ifstream in(path, std::ios::binary);
    std::vector<char> block(1 << 16);
    for (std::size_t at = 0; at < contents.size(); at += block.size()) {
        const std::size_t n = std::min(block.size(), contents.size() - at);
        if (!in.read(block.data(), static_cast<std::streamsize>(n)) || contents.compare(at, n, block.data(), n) != 0)
            return false;
    }
    return true;
}

// The user's paths in the way of `files`, each with the name it moves aside to. A file that
// holds byte for byte what Impact writes in its place is not in the way: nothing is lost;
// nor is a file of a folder inside that Impact wrote (`nested`), which Impact replaces.
std::map<std::string, std::string> plan_asides(const fs::path& folder, const ownership& o, const file_set& files)
{
    const std::set<std::string> folders = folders_needed(files);
    std::map<std::string, std::string> asides;
    std::set<std::string> chosen;
    auto consider = [&](const std::string& taken, bool is_empty_folder, bool impacts = false) {
        const std::optional<std::string> way = in_the_way(taken, is_empty_folder, files, folders);
        if (way && *way == taken && files.count(taken) && (impacts || holds(folder / taken, files.at(taken))))
            return;
        if (way && !asides.count(*way)) {
            asides[*way] = aside_name(folder, *way, files, folders, chosen);
            chosen.insert(asides[*way]);
        }
    };
    for (const std::string& file : o.users_files)
        consider(file, false);
    for (const std::string& empty : o.users_empty_folders)
        consider(empty, true);
    for (const std::string& file : o.nested)
        consider(file, false, true);
    return asides;
}

// `path` with its part `from` (itself or a folder above it) renamed `to`.
std::string renamed(const std::string& path, const std::string& from, const std::string& to)
{
    if (path == from)
        return to;
    if (path.size() > from.size() && path.compare(0, from.size(), from) == 0 && path[from.size()] == '/')
        return to + path.substr(from.size());
    return path;
}

std::string moved_to(const std::string& path, const std::map<std::string, std::string>& asides)
{
    for (const auto& [from, to] : asides) {
        const std::string moved = renamed(path, from, to);
        if (moved != path)
            return moved;
    }
    return path;
}

// "a, b, c and 4 more"
std::string some_of(const std::vector<std::string>& paths)
{
    std::string text;
    const std::size_t shown = std::min<std::size_t>(paths.size(), 3);
    for (std::size_t i = 0; i < shown; ++i)
        text += (i == 0 ? "" : ", ") + paths[i];
    if (paths.size() > shown)
        text += fmt::format(" and {} more", paths.size() - shown);
    return text;
}

// A name for a file being written in `folder`, taken by nothing there.
fs::path scratch_name(const fs::path& folder)
{
    for (int n = 0;; ++n) {
        const fs::path candidate = folder / fmt::format(".impact-writing-{}-{}", ::getpid(), n);
        if (!present(candidate))
            return candidate;
    }
}

// Writes `contents` to `path` by writing it beside and renaming it over: a reader sees the
// old file or the new one, never a part.
void replace_file(const fs::path& path, const std::string& contents)
{
    const fs::path scratch = scratch_name(path.parent_path());
    write_new_file(scratch, contents, path);
    on_disk(path, "replace the file", [&] { fs::rename(scratch, path); });
}

// Puts a link to (or a copy of) the user's `from` at `to`: the original stays where it is
// until the folder holding it is swapped out, so the user's file exists throughout.
void keep(const fs::path& from, const fs::path& to)
{
    create_folders(to.parent_path());
    on_disk(from, "keep this file in the new output", [&] {
        std::error_code linked;
        if (fs::is_symlink(fs::symlink_status(from))) {
            fs::copy_symlink(from, to);
            return;
        }
        fs::create_hard_link(from, to, linked);
        if (linked)
            fs::copy_file(from, to);   // another file system's rules, or not a regular file: throws
    });
}

// `out/`, `./out` and `out` all name the folder `out`, absolutely.
fs::path normalised(const fs::path& folder)
{
    fs::path path = fs::absolute(folder).lexically_normal();
    return path.has_filename() ? path : path.parent_path();
}

// Whether `path` is `folder` or inside it.
bool inside(const fs::path& path, const fs::path& folder)
{
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

fs::path fresh_of(const fs::path& folder) { return folder.string() + ".impact-new"; }
fs::path old_of(const fs::path& folder) { return folder.string() + ".impact-old"; }

// A leftover of an interrupted replacement is Impact's when it holds the marker or nothing.
void remove_leftover(const fs::path& leftover, const fs::path& folder)
{
    if (!present(leftover))
        return;
    bool empty = false;
    on_disk(leftover, "read the folder", [&] { empty = is_folder(leftover) && fs::is_empty(leftover); });
    if (!empty && !(is_folder(leftover) && listed_in(leftover)))
        refuse(leftover, fmt::format("in the way: Impact uses this name while it replaces {}, and this is not "
                                     "what it left there; move it away",
                                     folder.filename().string()));
    on_disk(leftover, "remove what an interrupted run left", [&] { fs::remove_all(leftover); });
}

} // namespace

std::string marker_text(const file_set& files)
{
    std::string text = fmt::format("# Written by Impact {}. The files listed are Impact's: it replaces or removes\n"
                                   "# them when it writes here again. Files not listed are not Impact's; it keeps them.\n",
                                   IMPACT_VERSION);
    for (const auto& [relative, contents] : files)
        text += relative + '\n';
    return text;
}

fs::path checked_folder(const fs::path& folder, const fs::path& derivations, writing how)
{
    if (folder.empty())
        refuse(folder, "no folder given to write into");
    // Kept as the user wrote it (relative stays relative), for messages; compared absolutely.
    fs::path given = folder.lexically_normal();
    if (!given.has_filename() && given.has_parent_path() && given != given.root_path())
        given = given.parent_path();
    const fs::path target = normalised(folder);
    std::error_code ignored;
    const fs::file_status status = fs::symlink_status(target, ignored);
    if (fs::is_symlink(status))
        refuse(folder, fmt::format("refusing to write through a symbolic link (to {}); give the folder itself",
                                   fs::read_symlink(target, ignored).string()));
    if (fs::exists(status) && !fs::is_directory(status))
        refuse(folder, "refusing to write here: it is a file, not a folder");

    const fs::path sources = fs::weakly_canonical(fs::absolute(derivations));
    const fs::path project = sources.parent_path();
    for (const fs::path& path : {target, fs::weakly_canonical(target)}) {
        if (how == writing::replacing && (path == path.root_path() || path.filename() == ".." ||
                                          inside(sources, path) || inside(fs::current_path(), path)))
            refuse(folder, "refusing to replace this folder: it holds the derivations or the current folder");
        if (inside(path, sources))
            refuse(folder, "refusing to write inside the derivations folder");
        for (const fs::path& part : path)
            if (part == ".git")
                refuse(folder, "refusing to write inside a .git folder");
        for (const char* kept : {"src", "tests"})
            if (inside(path, project / kept))
                refuse(folder, fmt::format("refusing to write inside {}: it holds sources, not output",
                                           (project / kept).string()));
    }
    return given;
}

void check_writable(const fs::path& folder, const file_set& files, bool force)
{
    if (!present(folder))
        return;
    if (!is_folder(folder))
        refuse(folder, "refusing to write here: it is a file, not a folder");
    const ownership o = ownership_of(folder);
    if (!o.marked && !o.inherited && !(o.users_files.empty() && o.users_empty_folders.empty()) && !force) {
        std::vector<std::string> held = o.users_files;
        held.insert(held.end(), o.users_empty_folders.begin(), o.users_empty_folders.end());
        refuse(folder, fmt::format("refusing to write into this folder: Impact did not write what it holds ({}); "
                                   "give a new or empty folder, or --force to write into it and keep its files",
                                   some_of(held)));
    }
    if (force)
        return;
    const std::map<std::string, std::string> asides = plan_asides(folder, o, files);
    if (!asides.empty()) {
        const auto& [path, aside] = *asides.begin();
        refuse(folder / path, fmt::format("in the way: Impact writes {} here, and this is not Impact's; move it "
                                          "away, or --force to keep it as {}",
                                          files.count(path) ? "a file" : "a folder", aside));
    }
}

write_report replace_folder(const fs::path& folder, const file_set& files, bool force,
                            void (*stop_at)(const char* point))
{
    recover_interrupted(folder);
    check_writable(folder, files, force);
    const ownership o = ownership_of(folder);
    const std::map<std::string, std::string> asides = plan_asides(folder, o, files);

    write_report report;
    const fs::path fresh = fresh_of(folder);
    const fs::path old = old_of(folder);
    try {
        create_folders(fresh);
        // The marker first: a leftover `.impact-new` is then recognisably Impact's.
        write_new_file(fresh / marker_name, marker_text(files));
        std::size_t written = 0;
        for (const auto& [relative, contents] : files) {
            create_folders((fresh / relative).parent_path());
            // A file of Impact's that already holds these bytes is linked, not written again:
            // a warm regeneration copies nothing, and the file keeps its time for make and
            // its kin. Nothing ever writes into a file in place, so the link changes nothing
            // for the old folder, which goes.
            // Linked first and compared after, so that what is compared is what is kept.
            const fs::path made = fresh / relative;
            const bool impacts = o.impacts.count(relative) > 0;
            std::error_code unlinked;
            if (impacts)
                fs::create_hard_link(folder / relative, made, unlinked);
            if (!impacts || unlinked || !holds(made, contents)) {
                if (impacts && !unlinked)
                    on_disk(made, "replace a changed file", [&made] { fs::remove(made); });
                write_new_file(made, contents);
            }
            if (++written == files.size() / 2 && stop_at)
                stop_at("writing");
        }
        for (const std::string& file : o.users_files) {
            const std::string to = moved_to(file, asides);
            if (to == file && files.count(file))
                continue;   // the same bytes as Impact's file in its place (plan_asides)
            keep(folder / file, fresh / to);
            if (to == file)
                report.kept.push_back(file);
            else
                report.moved_aside.push_back(file + " -> " + to);
        }
        // Impact's files of a folder inside (another command's), where nothing new is written:
        // kept, and not said to be the user's.
        for (const std::string& file : o.nested) {
            const std::string to = moved_to(file, asides);
            if (to == file && files.count(file))
                continue;
            keep(folder / file, fresh / to);
            if (to != file)
                report.moved_aside.push_back(file + " -> " + to);
        }
        for (const std::string& empty : o.users_empty_folders) {
            const std::string to = moved_to(empty, asides);
            create_folders(fresh / to);
            if (to == empty)
                report.kept.push_back(empty + "/");
            else
                report.moved_aside.push_back(empty + "/ -> " + to + "/");
        }
        std::sort(report.kept.begin(), report.kept.end());
        if (present(folder)) {
            // A folder forced into becomes recognisably Impact's, so that a run killed
            // after the next rename can put it back and a later one can tidy it up.
            if (!o.marked)
                write_new_file(folder / marker_name, marker_text({}));
            on_disk(folder, "move the previous output aside", [&] { fs::rename(folder, old); });
        }
        if (stop_at)
            stop_at("swapping");
        on_disk(folder, "move the new output in place", [&] { fs::rename(fresh, folder); });
    } catch (...) {
        std::error_code ignored;
        if (!present(folder) && present(old))
            fs::rename(old, folder, ignored);
        fs::remove_all(fresh, ignored);
        throw;
    }
    std::error_code ignored;
    fs::remove_all(old, ignored);   // a leftover is removed by the next run
    return report;
}

write_report add_to_folder(const fs::path& folder, const file_set& files, bool force)
{
    check_writable(folder, files, force);
    create_folders(folder);
    const ownership o = ownership_of(folder);
    write_report report;
    for (const auto& aside : plan_asides(folder, o, files)) {
        const std::string& from = aside.first;
        const std::string& to = aside.second;
        on_disk(folder / from, "move this aside", [&] { fs::rename(folder / from, folder / to); });
        report.moved_aside.push_back(from + " -> " + to);
    }
    // Impact's own files where Impact now needs a folder go; so do leftovers it no longer lists.
    for (const std::string& needed : folders_needed(files))
        if (o.impacts.count(needed))
            on_disk(folder / needed, "remove a file Impact wrote", [&] { fs::remove(folder / needed); });

    // The marker lists the new files before they are written: a run killed part-way leaves
    // files that are Impact's, never files that look like a user's.
    file_set listed;
    for (const std::string& file : o.impacts)
        if (!folders_needed(files).count(file))
            listed[file];
    for (const auto& [relative, contents] : files)
        listed[relative];
    replace_file(folder / marker_name, marker_text(listed));
    for (const auto& [relative, contents] : files) {
        create_folders((folder / relative).parent_path());
        replace_file(folder / relative, contents);
    }
    return report;
}

void recover_interrupted(const fs::path& folder)
{
    const fs::path fresh = fresh_of(folder);
    const fs::path old = old_of(folder);
    // Stopped between the two renames: the previous output is `.impact-old`; put it back.
    if (!present(folder) && is_folder(old) && listed_in(old))
        on_disk(old, "restore the previous output", [&] { fs::rename(old, folder); });
    // Stopped while writing (a partial `.impact-new`) or before tidying up (`.impact-old`).
    remove_leftover(fresh, folder);
    remove_leftover(old, folder);
}

} // namespace impact::pipeline
