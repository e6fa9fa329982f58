// Inputs for measuring a kernel's accuracy, drawn where collisions are hard to compute.
//
// Uniform draws miss the inputs that break naive formulas, so each sample is drawn in
// one of several regimes: ordinary values; masses up to 10^±12 apart; ε within 10^-12
// of 0 or of 1; nearly grazing contacts (the relative velocity almost perpendicular to
// the line of centres); nearly head-on hits (one positive input tiny next to another);
// nearly equal velocities. Every sample is a collision that happens: a pair drawn
// separating has its velocities reversed, and a sample the kernel's guards refuse is
// drawn again. The draws are seeded, so a run is repeatable.
#pragma once

#include "engine/derive.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace impact::verify {

struct sample {
    std::string regime;          ///< which hard region it was drawn from
    std::vector<double> inputs;  ///< one value per input symbol of the kernel, in order
};

/// Whether the kernel computes its outputs at these inputs (its guards' conditions hold).
using admission = std::function<bool(const std::vector<double>& inputs)>;

/// `count` samples for `k`, from the seed; where `admitted` is given, each one it admits
/// (a sample it refuses, e.g. a sphere moving away from a wall, is drawn again in its
/// regime, in up to 64 draws, and left out when all 64 are refused, so that fewer samples
/// are measured): the accuracy is the kernel's where it computes.
std::vector<sample> draw_samples(const engine::kernel& k, std::size_t count, std::uint64_t seed,
                                 const admission& admitted = {});

} // namespace impact::verify
