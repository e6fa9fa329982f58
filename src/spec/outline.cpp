#include "spec/outline.h"

#include "spec/table_reader.h"

#include <fmt/format.h>

#include <map>
#include <sstream>

namespace impact::spec {

using detail::trimmed;

std::optional<std::size_t> paper_outline::position(const std::string& place) const
{
    const std::string wanted = trimmed(place);
    for (std::size_t i = 0; i < places.size(); ++i)
        if (places[i].value == wanted)
            return i;
    return std::nullopt;
}

paper_outline parse_paper_outline(const std::string& contents, const std::string& file)
{
    paper_outline outline;
    outline.file = file;
    std::map<std::string, std::uint32_t> first_line;
    // A byte order mark is not part of the first place.
    std::istringstream in(contents.rfind("\xEF\xBB\xBF", 0) == 0 ? contents.substr(3) : contents);
    std::string line;
    for (std::uint32_t number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        const std::string place = trimmed(line);
        if (place.empty() || place.front() == '#')
            continue;
        const std::size_t begin = line.find_first_not_of(" \t");
        const source_location where{file, number, static_cast<std::uint32_t>(begin + 1)};
        const auto [seen, inserted] = first_line.emplace(place, number);
        if (!inserted)
            throw error(where, fmt::format("the place '{}' is listed twice (first at line {}): each place of the "
                                           "paper has one position in its order",
                                           place, seen->second));
        outline.places.push_back({place, where});
    }
    if (outline.places.empty())
        throw error({file, 0, 0}, "lists no place of the paper (a place per line, in the order the paper prints "
                                  "them; a line starting with # is a comment)");
    return outline;
}

std::optional<paper_outline> read_paper_outline(const std::filesystem::path& folder)
{
    const std::filesystem::path path = folder / paper_outline_name;
    const std::string name = path.generic_string();
    std::error_code failed;
    const std::filesystem::file_status status = std::filesystem::status(path, failed);
    if (status.type() == std::filesystem::file_type::not_found)
        return std::nullopt;
    if (failed)
        throw error({name, 0, 0}, "cannot read the paper's order of places: " + failed.message());
    if (status.type() != std::filesystem::file_type::regular)
        throw error({name, 0, 0}, "not a file: the paper's order of places is read from a text file of this name");
    return parse_paper_outline(read_input_file(name), name);
}

} // namespace impact::spec
