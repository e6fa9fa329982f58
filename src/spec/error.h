// Errors that point at a place in a derivation file.
//
// Every stage of Impact reports bad input by throwing `impact::error`: it carries
// the file, line and column of the offending text so that `main` can print one
// clear line (`file:line:column: error: what`) and exit non-zero.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace impact {

/// A position in a derivation file; line and column count from 1, 0 means unknown.
struct source_location {
    std::string file;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
};

/// Formats a location as `file:line:column` (omitting the parts that are unknown).
std::string to_string(const source_location& where);

/// `text` on one line: each run of white space holding a line break becomes one space.
std::string single_line(const std::string& text);

/// Bad input, with the place it was found. The message is kept to one line.
class error : public std::runtime_error {
public:
    error(source_location where, const std::string& what);

    const source_location& where() const noexcept { return where_; }
    /// The message without the location.
    const std::string& message() const noexcept { return message_; }

private:
    source_location where_;
    std::string message_;
};

} // namespace impact
