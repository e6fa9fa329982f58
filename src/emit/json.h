// JSON emitter: every derivation's results, checks and paper checks in one
// machine-readable file, `output/derivations.json`.
#pragma once

#include "engine/derivation/derivation.h"

#include <string>
#include <vector>

namespace impact::emit {

/// The whole library as JSON text (two-space indent, trailing newline).
std::string derivations_json(const std::vector<const engine::derivation*>& derivations);

} // namespace impact::emit
