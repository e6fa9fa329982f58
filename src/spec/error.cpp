#include "spec/error.h"

namespace impact {

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
    : std::runtime_error(to_string(where) + ": error: " + what),
      where_(std::move(where)), message_(what)
{
}

} // namespace impact
