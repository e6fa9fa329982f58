// Errata emitter: every printed equation and claim of the paper with its verdict,
// as `output/errata.md`.
#pragma once

#include "engine/derive.h"

#include <string>
#include <vector>

namespace impact::emit {

/// The errata table in Markdown.
std::string errata_markdown(const std::vector<const engine::derivation*>& derivations);

/// How many printed lines and claims of the paper `derivations` compare: the distinct
/// places (`paper`) their comparisons name. A place is one printed line of a displayed
/// equation ("Eq. 12, line 2"), an equation or a sentence of the text ("Sec. III C,
/// after Eq. 14, 5th sentence"), a footnote; several comparisons may name one place (a
/// vector's components, two claims of one sentence). How many the paper prints is not
/// known here: tests/test_paper_lines.cpp lists them, typed from the paper.
std::size_t compared_places(const std::vector<const engine::derivation*>& derivations);

} // namespace impact::emit
