#include "spec/outline.h"

#include <fmt/format.h>

#include <cerrno>
#include <fstream>
#include <map>
#include <sstream>

namespace impact::spec {

namespace {

// The file's size limit, as a derivation file's.
constexpr std::uintmax_t max_outline_bytes = 1 << 20;

std::string trimmed(const std::string& s)
{
    const std::size_t begin = s.find_first_not_of(" \t");
    if (begin == std::string::npos)
        return "";
    return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

} // namespace

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
    const std::uintmax_t size = std::filesystem::file_size(path, failed);
    if (!failed && size > max_outline_bytes)
        throw error({name, 0, 0}, fmt::format("file is {} bytes, larger than the limit of {} bytes", size,
                                              max_outline_bytes));
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw error({name, 0, 0}, "cannot open the file: " + std::error_code(errno, std::generic_category()).message());
    std::ostringstream contents;
    contents << in.rdbuf();
    return parse_paper_outline(contents.str(), name);
}

} // namespace impact::spec
