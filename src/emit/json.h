// JSON emitter: every derivation's results, checks and paper checks in one
// machine-readable file, `output/derivations.json`.
#pragma once

#include "engine/derivation/derivation.h"
#include "verify/proofs.h"

#include <string>
#include <vector>

namespace impact::emit {

/// The whole library as JSON text (two-space indent, trailing newline); with `z3`, each
/// proven check's answer from Z3 (its field "z3").
std::string derivations_json(const std::vector<const engine::derivation*>& derivations,
                             const verify::proof_checks* z3 = nullptr);

/// One derivation as JSON, as `impact derive --json` prints it (docs/cli.md): the object
/// derivations_json gives it, without Z3's answers, and the LaTeX of each result's displayed
/// form ("latex") and of each check's claim (each check's "latex").
std::string derivation_json_with_latex(const engine::derivation& d);

} // namespace impact::emit
