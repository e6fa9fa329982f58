// The paper's outline: the places of its printed lines and claims in the order it prints
// them, read from `paper_order.txt` beside the derivation files. The errata lists its rows
// in this order, as a referee would, rather than derivation by derivation.
#pragma once

#include "spec/derivation.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impact::spec {

/// The places of the paper, in print order, each as the `paper` fields of the derivation
/// files name it ("Eq. 8, right, line 1", "Sec. III C, after Eq. 14, 5th sentence").
struct paper_outline {
    std::string file;
    std::vector<text> places;

    /// The position of `place` (spaces around it ignored) in print order; none when the
    /// outline does not list it.
    std::optional<std::size_t> position(const std::string& place) const;
};

/// The name of the outline's file in a folder of derivation files.
inline constexpr const char* paper_outline_name = "paper_order.txt";

/// Reads an outline from text, `file` naming it in messages: a place per line, blank lines
/// and lines starting with `#` (after any spaces) skipped, spaces around a place and a byte
/// order mark ignored. A place listed twice is an error at its second line; an outline
/// with no place, an error at the file. Throws `impact::error`.
paper_outline parse_paper_outline(const std::string& contents, const std::string& file);

/// The outline of a folder of derivation files (`paper_order.txt`), none when it has no
/// such file. Throws `impact::error` when it is not a file, cannot be read, is larger than
/// a megabyte or is malformed.
std::optional<paper_outline> read_paper_outline(const std::filesystem::path& folder);

} // namespace impact::spec
