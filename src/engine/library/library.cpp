#include "engine/library/library.h"

#include "engine/store/stored.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>

namespace impact::engine {

std::vector<const engine::derivation*> library::in_order() const
{
    std::vector<const engine::derivation*> all;
    for (const std::string& id : order)
        all.push_back(&derived.at(id));
    return all;
}

bool library::all_hold() const
{
    return std::all_of(derived.begin(), derived.end(), [](const auto& entry) { return entry.second.all_hold(); });
}

std::vector<std::filesystem::path> derivation_files(const std::filesystem::path& directory)
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(directory))
        if (entry.is_regular_file() && entry.path().extension() == ".toml")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<spec::derivation> read_directory(const std::filesystem::path& directory)
{
    if (!std::filesystem::exists(directory))
        throw error({directory.string(), 0, 0}, "no such folder of derivation files; give one with --derivations "
                                                "(or, to derive one file, its path)");
    if (!std::filesystem::is_directory(directory))
        throw error({directory.string(), 0, 0}, "not a folder of derivation files");
    const std::vector<std::filesystem::path> files = derivation_files(directory);
    if (files.empty())
        throw error({directory.string(), 0, 0}, "holds no derivation files (*.toml)");
    std::vector<spec::derivation> sources;
    for (const auto& file : files)
        sources.push_back(spec::read_derivation(file.generic_string()));
    return sources;
}

library derive_folder(const std::filesystem::path& directory)
{
    library lib = derive_all(read_directory(directory));
    lib.outline = spec::read_paper_outline(directory);
    return lib;
}

namespace {

// The text a derivation is derived from: its file's path and content without comments or
// spacing (spec::meaningful_content: a comment changes nothing derived; the places it moves
// are put right as the derivation is read back, engine/store/stored.h), then the texts of those it
// uses (whose own keys are in `keys`).
std::string key_of(const spec::derivation& s, const std::map<std::string, std::string>& keys)
{
    const std::string content = spec::meaningful_content(s.contents).value_or(s.contents);
    std::string key = fmt::format("{} {}\n{}{}\n", s.file.size(), content.size(), s.file, content);
    for (const spec::use& u : s.uses) {
        const std::string& used = keys.at(u.derivation.value);
        key += fmt::format("uses {}\n{}", used.size(), used);
    }
    return key;
}

// Derives one file here. Each derivation has a cache of proofs of its own, so that what it
// proves, and so what it writes, is the same whether those it uses were derived or kept,
// here or in a worker.
derivation derive_here(const spec::derivation& s, const derived_by_id& done)
{
    proof_cache run;
    return derive(s, done, run);
}

// In rounds: those whose uses are all derived, each taken from the store or, when there are
// several, derived as the runner's tasks (each sending back its text, engine/store/stored.h).
void derive_in_rounds(const std::vector<const spec::derivation*>& order, library& lib,
                      const std::function<bool(const spec::derivation&)>& take,
                      const std::function<void(const spec::derivation&)>& add_here,
                      const std::function<void(const spec::derivation&, const std::string&)>& keep,
                      const task_runner& runner, const std::function<void(std::size_t)>& told)
{
    std::vector<const spec::derivation*> waiting = order;
    while (!waiting.empty()) {
        std::vector<const spec::derivation*> ready, later;
        for (const spec::derivation* s : waiting) {
            const bool uses_done = std::all_of(s->uses.begin(), s->uses.end(), [&](const spec::use& u) {
                return lib.derived.count(u.derivation.value) != 0;
            });
            (uses_done ? ready : later).push_back(s);
        }
        waiting = std::move(later);
        std::vector<const spec::derivation*> to_derive;
        for (const spec::derivation* s : ready)
            if (!take(*s))
                to_derive.push_back(s);
        if (to_derive.size() < 2) {
            for (const spec::derivation* s : to_derive)
                add_here(*s);
            continue;
        }
        std::vector<text_task> tasks;
        for (const spec::derivation* s : to_derive)
            tasks.push_back({fmt::format("derivation '{}'", s->id.value), s->id.where,
                             [s, &lib] {
                                 return stored_derivation(derive_here(*s, lib.derived), lib.derived).value_or("");
                             },
                             s->contents.size(), "deriving it", "derive it"});
        std::size_t finished = 0;
        const std::vector<std::string> texts = runner(tasks, [&] { told(++finished); });
        for (std::size_t i = 0; i < to_derive.size(); ++i) {
            const spec::derivation& s = *to_derive[i];
            // A derivation that cannot be kept as text comes back empty: derived here.
            std::optional<derivation> d =
                texts[i].empty() ? std::nullopt : restored_derivation(texts[i], s, lib.derived);
            if (!d) {
                add_here(s);
                continue;
            }
            keep(s, texts[i]);
            lib.derived.emplace(s.id.value, std::move(*d));
        }
    }
}

} // namespace

library derive_all(const std::vector<spec::derivation>& sources, const std::string& only, const deriving& how)
{
    const derivation_store* const kept = how.kept;
    std::map<std::string, const spec::derivation*> by_id;
    // Two files of one id: an error when the id is derived (every id, without `only`).
    std::map<std::string, const spec::derivation*> twice;
    for (const spec::derivation& s : sources) {
        const auto [it, inserted] = by_id.emplace(s.id.value, &s);
        if (!inserted && !twice.count(s.id.value))
            twice.emplace(s.id.value, &s);
    }
    const auto once = [&](const std::string& id) {
        if (const auto again = twice.find(id); again != twice.end())
            throw error(again->second->id.where,
                        fmt::format("derivation id '{}' is also used by {}", id, by_id.at(id)->file));
    };
    if (only.empty())
        for (const spec::derivation& s : sources)
            once(s.id.value);

    // Depth-first over [[use]]: each derivation after those it uses; a derivation met
    // again while still on the path is a cycle.
    std::vector<const spec::derivation*> order;
    std::set<std::string> placed, on_path;
    std::function<void(const spec::derivation&)> visit = [&](const spec::derivation& s) {
        if (placed.count(s.id.value))
            return;
        once(s.id.value);
        on_path.insert(s.id.value);
        for (const spec::use& u : s.uses) {
            const auto used = by_id.find(u.derivation.value);
            if (used == by_id.end())
                throw error(u.derivation.where,
                            fmt::format("uses derivation '{}', which does not exist", u.derivation.value));
            if (on_path.count(u.derivation.value))
                throw error(u.derivation.where,
                            fmt::format("derivation '{}' uses '{}', which uses it in turn (a cycle)", s.id.value,
                                        u.derivation.value));
            visit(*used->second);
        }
        on_path.erase(s.id.value);
        placed.insert(s.id.value);
        order.push_back(&s);
    };
    if (!only.empty()) {
        const auto found = by_id.find(only);
        if (found == by_id.end())
            throw error({}, fmt::format("no derivation with id '{}'", only));
        visit(*found->second);
    } else {
        for (const spec::derivation& s : sources)
            visit(s);
    }

    std::map<std::string, std::string> keys;
    for (const spec::derivation* s : order)
        keys[s->id.value] = key_of(*s, keys);
    library lib;
    // Those derived, and those a round's workers have finished (`more`): never fewer than
    // told before (a round's texts are read back after all its workers are done).
    std::size_t shown = 0;
    const auto told = [&](std::size_t more = 0) {
        shown = std::max(shown, lib.derived.size() + more);
        if (how.progress)
            how.progress(shown, order.size());
    };
    const auto keep = [&](const spec::derivation& s, const std::string& text) {
        if (kept && kept->keep && !text.empty())
            kept->keep(keys.at(s.id.value), text);
    };
    // From `kept`, or nothing.
    const auto take = [&](const spec::derivation& s) -> bool {
        if (!kept || !kept->find)
            return false;
        const std::optional<std::string> text = kept->find(keys.at(s.id.value));
        std::optional<derivation> found = text ? restored_derivation(*text, s, lib.derived) : std::nullopt;
        if (found) {
            lib.derived.emplace(s.id.value, std::move(*found));
            told();
        } else if (text && kept->unusable) {
            kept->unusable(keys.at(s.id.value));
        }
        return found.has_value();
    };
    const auto add_here = [&](const spec::derivation& s) {
        derivation d = derive_here(s, lib.derived);
        if (kept && kept->keep)
            keep(s, stored_derivation(d, lib.derived).value_or(""));
        lib.derived.emplace(s.id.value, std::move(d));
        told();
    };
    // One after another in the order: a bad file throws as soon as it is met.
    const auto each_in_order = [&] {
        for (const spec::derivation* s : order)
            if (!lib.derived.count(s->id.value) && !take(*s))
                add_here(*s);
    };

    if (!how.runner) {
        each_in_order();
    } else {
        try {
            derive_in_rounds(order, lib, take, add_here, keep, how.runner, told);
        } catch (...) {
            // A file is bad input, or a worker died: what is left is derived here, one after
            // another in the order, which throws what a run without workers throws (the
            // first bad file's error); when nothing does, the worker's death is reported.
            each_in_order();
            throw;
        }
    }
    for (const spec::derivation* s : order)
        lib.order.push_back(s->id.value);
    return lib;
}

std::string resolve_id(const std::vector<spec::derivation>& sources, const std::string& name)
{
    for (const spec::derivation& s : sources) {
        if (s.id.value == name)
            return s.id.value;
        std::error_code ignored;
        if (std::filesystem::equivalent(s.file, name, ignored))
            return s.id.value;
    }
    throw error({name, 0, 0}, "no derivation has this id or file (impact list shows the ids)");
}

folder_read read_directory_for_one(const std::filesystem::path& directory)
{
    // The folder itself must be one, with files in it.
    if (!std::filesystem::is_directory(directory) || derivation_files(directory).empty())
        return {read_directory(directory), {}};
    folder_read folder;
    static const std::regex id_line(R"re(^\s*id\s*=\s*"([A-Za-z][A-Za-z0-9_]*)")re");
    for (const auto& file : derivation_files(directory)) {
        try {
            folder.sources.push_back(spec::read_derivation(file.generic_string()));
        } catch (const error& e) {
            std::string id;
            std::ifstream in(file);
            for (std::string line; id.empty() && std::getline(in, line);)
                if (std::smatch m; std::regex_search(line, m, id_line))
                    id = m[1];
            folder.failures.push_back({file.generic_string(), id, e});
        }
    }
    return folder;
}

library derive_one_of(const folder_read& folder, const std::string& name, const deriving& how)
{
    std::error_code ignored;
    const auto unreadable_as = [&](const std::string& id, const std::string& file) -> const folder_read::unreadable* {
        for (const folder_read::unreadable& f : folder.failures)
            if ((!id.empty() && f.id == id) || (!file.empty() && std::filesystem::equivalent(f.file, file, ignored)))
                return &f;
        return nullptr;
    };
    // The derivation named: its own error when its file could not be read.
    std::string id;
    try {
        id = resolve_id(folder.sources, name);
    } catch (const error&) {
        if (const folder_read::unreadable* f = unreadable_as(name, name))
            throw f->what;
        throw;
    }
    // Those it uses, through their uses: the error of one whose file could not be read.
    std::map<std::string, const spec::derivation*> by_id;
    for (const spec::derivation& s : folder.sources)
        by_id.emplace(s.id.value, &s);
    std::set<std::string> seen;
    std::function<void(const spec::derivation&)> visit = [&](const spec::derivation& s) {
        if (!seen.insert(s.id.value).second)
            return;
        for (const spec::use& u : s.uses) {
            const auto used = by_id.find(u.derivation.value);
            if (used != by_id.end()) {
                visit(*used->second);
                continue;
            }
            if (const folder_read::unreadable* f = unreadable_as(u.derivation.value, ""))
                throw f->what;
            // Not found: derive_all says so, naming the files that could not be read.
            if (!folder.failures.empty()) {
                std::vector<std::string> files;
                for (const folder_read::unreadable& f : folder.failures)
                    files.push_back(f.file);
                throw error(u.derivation.where,
                            fmt::format("uses derivation '{}', which does not exist (these files could not be read: "
                                        "{})",
                                        u.derivation.value, fmt::join(files, ", ")));
            }
        }
    };
    visit(*by_id.at(id));
    return derive_all(folder.sources, id, how);
}

} // namespace impact::engine
