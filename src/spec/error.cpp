#include "spec/error.h"

#include <algorithm>

namespace impact {

// An error is printed on one line: GiNaC's messages, for one, carry line breaks.
std::string single_line(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n' && text[i] != '\r') {
            out += text[i++];
            continue;
        }
        const std::size_t end = std::min(text.find_first_not_of(" \t\r\n", i), text.size());
        const std::string run = text.substr(i, end - i);
        if (run.find_first_of("\r\n") == std::string::npos)
            out += run;
        else if (!out.empty() && end < text.size())
            out += ' ';
        i = end;
    }
    return out;
}

std::string to_string(const source_location& where)
{
    std::string text = where.file.empty() ? std::string("<input>") : where.file;
    if (where.line > 0) {
        text += ':' + std::to_string(where.line);
        if (where.column > 0)
            text += ':' + std::to_string(where.column);
    }
    return text;
}

error::error(source_location where, const std::string& what)
    : std::runtime_error(single_line(to_string(where) + ": error: " + what)),
      where_(std::move(where)), message_(single_line(what))
{
}

} // namespace impact
