// What the converter of Impact's LaTeX (html_tex.cpp) and its numbering of labels
// (html_labels.cpp) share: scanning TeX source. Internal to report.
#pragma once

#include "report/html_tex.h"

#include <string>
#include <vector>

namespace impact::report::html::detail {

/// Whether `s` has `prefix` at `at`.
bool starts(const std::string& s, std::size_t at, const char* prefix);

/// The index just past the group `{...}` opening at `open` (braces balanced, \{ and \} skipped);
/// npos when it is not closed.
std::size_t group_end(const std::string& s, std::size_t open);

/// `text` split at each `separator` ("\\\\" or "&") outside braces, math and environments
/// (a `cases` or `pmatrix` inside a row keeps its own rows and columns).
std::vector<std::string> split_top(const std::string& text, const std::string& separator);

/// `s` without the white space around it.
std::string trimmed(const std::string& s);

/// Removes every `command{...}` from `row`, returning the first one's argument.
std::string take_command(std::string& row, const std::string& command);

/// A heading's HTML as plain text: without its markup, each formula's placeholder as the
/// formula's TeX, a no-break space as a space, the entities decoded.
std::string plain_text(const std::string& html, const std::vector<formula>& formulas);

} // namespace impact::report::html::detail
