#include "engine/library.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
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

library derive_all(const std::vector<spec::derivation>& sources, const std::string& only)
{
    std::map<std::string, const spec::derivation*> by_id;
    for (const spec::derivation& s : sources) {
        const auto [it, inserted] = by_id.emplace(s.id.value, &s);
        if (!inserted)
            throw error(s.id.where, fmt::format("derivation id '{}' is also used by {}", s.id.value, it->second->file));
    }

    // Depth-first over [[use]]: each derivation after those it uses; a derivation met
    // again while still on the path is a cycle.
    library lib;
    // One cache for the run: a derivation meets again the polynomials of those it uses.
    proof_cache run;
    std::set<std::string> on_path;
    std::function<void(const spec::derivation&)> visit = [&](const spec::derivation& s) {
        if (lib.derived.count(s.id.value))
            return;
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
        lib.derived.emplace(s.id.value, engine::derive(s, lib.derived, run));
        lib.order.push_back(s.id.value);
    };

    if (!only.empty()) {
        const auto found = by_id.find(only);
        if (found == by_id.end())
            throw error({}, fmt::format("no derivation with id '{}'", only));
        visit(*found->second);
        return lib;
    }
    for (const spec::derivation& s : sources)
        visit(s);
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

} // namespace impact::engine
