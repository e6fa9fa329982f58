#!/usr/bin/env bash
# Times a full regeneration (every derivation with its checks, LaTeX fragments,
# kernels, derivations.json and errata.md) as the `impact` command does it, over
# repeated runs: a benchmark, not a test. Usage: time_regenerate.sh IMPACT [RUNS]
set -euo pipefail
impact=${1:?usage: time_regenerate.sh path/to/impact [runs]}
runs=${2:-21}
here=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

times=()
for ((i = 0; i < runs; ++i)); do
  start=$(date +%s%N)
  "$impact" regenerate --derivations "$here/derivations" --output "$scratch/output" > /dev/null
  end=$(date +%s%N)
  times+=($(( (end - start) / 1000 )))
done
sorted=($(printf '%s\n' "${times[@]}" | sort -n))
median=${sorted[$(( runs / 2 ))]}
awk -v runs="$runs" -v lo="${sorted[0]}" -v mid="$median" -v hi="${sorted[$(( runs - 1 ))]}" \
    -v n="$(ls "$here"/derivations/*.toml | wc -l)" -v cores="$(nproc)" 'BEGIN {
  printf "regenerate: %d runs, wall time min %.3f s, median %.3f s, max %.3f s (%d derivations, %d cores)\n",
         runs, lo / 1e6, mid / 1e6, hi / 1e6, n, cores }'
