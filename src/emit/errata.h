// Errata emitter: every printed equation and claim of the paper with its verdict,
// as `output/errata.md`.
#pragma once

#include "engine/derive.h"

#include <string>
#include <vector>

namespace impact::emit {

/// The errata table in Markdown.
std::string errata_markdown(const std::vector<const engine::derivation*>& derivations);

} // namespace impact::emit
