// Inputs for measuring a kernel's accuracy, drawn where collisions are hard to compute.
//
// Uniform draws miss the inputs that break naive formulas, so each sample is drawn in
// one of several regimes, taking turns, each named by what it does to the kernel at hand:
// ordinary values; the positive inputs (masses, radii) over 12 decades instead of 4; each
// input of an interval (ε, β, q) near each end (10^-12 to 10^-1 of its width from it), one at a time; where the
// kernel has a line of approach (two bodies' centres, or a guard on a body's velocity
// towards a wall, v . N < 0), nearly grazing hits (the relative velocity almost across it)
// and nearly head-on ones (almost along it); with two velocities, nearly equal ones; and
// the regimes its file declares (`[[kernel.regime]]`: an input set so that a ratio of two
// quantities spans decades, or so that a case boundary is within a hair). Every sample is
// a collision that happens: a pair drawn separating has its velocities reversed, and a
// sample the kernel's guards refuse is drawn again. The draws are seeded, so a run is
// repeatable.
#pragma once

#include "engine/derivation/derivation.h"
#include "engine/expr/order.h"

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
                                 const engine::term_order& order, const admission& admitted = {});

/// The names of the regimes `k`'s samples are drawn in, in the order they take turns.
std::vector<std::string> regime_names(const engine::kernel& k, const engine::term_order& order);

} // namespace impact::verify
