#!/usr/bin/env bash
# The hostile-input sweep of tests/test_kernels_hostile.cpp, long: 2 000 000 pairs per type
# (float, double, long double) and kernel (collide in 2D and 3D with its batch, collide_line,
# energy_loss, scatter_angle) where CI runs 20 000. Not a test: run by hand, e.g. before a
# release or after a change to the guards; it prints what each sweep saw (statuses, pairs on
# a boundary of the classification, resolved pairs beyond 16 ulps of the closed form) and
# fails if an invariant fails. 18 minutes for the vectorised build on two shared cores.
# Usage: sweep_kernels_long.sh TEST_BINARY [PAIRS]   (e.g. build/tests/test_kernels_hostile_vectorised)
set -euo pipefail
binary=${1:?usage: sweep_kernels_long.sh path/to/test_kernels_hostile [pairs]}
pairs=${2:-2000000}
echo "sweep_kernels_long: $pairs pairs per type and kernel, $(basename "$binary")"
IMPACT_SWEEP_PAIRS=$pairs "$binary" --run_test='a_randomized_sweep*' --log_level=message
