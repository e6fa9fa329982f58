#include "spec/outline.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <sstream>

namespace impact::spec {

std::optional<std::size_t> paper_outline::position(const std::string& place) const
{
    for (std::size_t i = 0; i < places.size(); ++i)
        if (places[i].value == place)
            return i;
    return std::nullopt;
}

paper_outline parse_paper_outline(const std::string& contents, const std::string& file)
{
    paper_outline outline;
    outline.file = file;
    std::map<std::string, std::uint32_t> first_line;
    std::istringstream in(contents);
    std::string line;
    for (std::uint32_t number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        const std::size_t begin = line.find_first_not_of(" \t");
        if (begin == std::string::npos || line[begin] == '#')
            continue;
        const std::size_t end = line.find_last_not_of(" \t");
        const std::string place = line.substr(begin, end - begin + 1);
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
                                  "them; # starts a comment)");
    return outline;
}

std::optional<paper_outline> read_paper_outline(const std::filesystem::path& folder)
{
    const std::filesystem::path path = folder / paper_outline_name;
    std::error_code ignored;
    if (!std::filesystem::exists(path, ignored))
        return std::nullopt;
    const std::string name = path.generic_string();
    if (!std::filesystem::is_regular_file(path, ignored))
        throw error({name, 0, 0}, "not a file: the paper's order of places is read from a text file of this name");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw error({name, 0, 0}, "cannot open the file");
    std::ostringstream contents;
    contents << in.rdbuf();
    return parse_paper_outline(contents.str(), name);
}

} // namespace impact::spec
