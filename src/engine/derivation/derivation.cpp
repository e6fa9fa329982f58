#include "engine/derivation/derivation.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace impact::engine {

std::string derivation::source_name() const
{
    return folder_and_file_name(source.file);
}

std::string source_folder(const std::vector<const derivation*>& derivations)
{
    if (derivations.empty())
        return "derivations/";
    const std::string name = derivations.front()->source_name();
    const auto slash = name.find_last_of('/');
    return slash == std::string::npos ? std::string() : name.substr(0, slash + 1);
}

std::string folder_and_file_name(const std::filesystem::path& file)
{
    const std::filesystem::path folder = file.parent_path();
    std::string name = folder.filename().string();
    if (name.empty() || name == "." || name == "..") {
        // `x.toml`, `./x.toml`, `../x.toml`: the folder's name is its full path's last part.
        std::error_code failed;
        const std::filesystem::path full = std::filesystem::weakly_canonical(
            folder.empty() ? std::filesystem::current_path(failed) : folder, failed);
        name = failed ? std::string() : full.filename().string();
    }
    return name.empty() ? file.filename().string() : name + "/" + file.filename().string();
}

std::vector<GiNaC::ex> kernel::input_symbols() const
{
    std::vector<GiNaC::ex> symbols;
    for (const kernel_parameter& p : parameters)
        for (const quantity& q : p.components)
            symbols.push_back(q.symbol);
    return symbols;
}

std::string kernel_output::own_array_name(std::size_t c) const
{
    return is_array ? member + "_" + std::to_string(c) : member;
}

const quantity* kernel::find_input(const std::string& name) const
{
    for (const kernel_parameter& p : parameters)
        for (const quantity& q : p.components)
            if (q.name == name)
                return &q;
    return nullptr;
}

const kernel_parameter* kernel::find_parameter(const std::string& name) const
{
    for (const kernel_parameter& p : parameters)
        if (p.name == name)
            return &p;
    return nullptr;
}

const result* derivation::find_result(const std::string& name) const
{
    for (const result& r : results)
        if (r.name == name)
            return &r;
    return nullptr;
}

std::vector<const check_result*> derivation::all_checks() const
{
    std::vector<const check_result*> all;
    for (const step_result& s : steps)
        for (const check_result& c : s.checks)
            all.push_back(&c);
    for (const check_result& c : checks)
        all.push_back(&c);
    return all;
}

bool derivation::all_hold() const
{
    const auto checks = all_checks();
    return std::all_of(checks.begin(), checks.end(), [](const check_result* c) { return c->outcome.holds(); });
}

} // namespace impact::engine
