#!/usr/bin/env bash
# Times regeneration, stage by stage, over repeated runs: a benchmark, not a test.
# The figure the project is held to is the symbolic part: every derivation with its
# checks, the LaTeX fragments, derivations.json, errata.md and the kernel sources
# (not the numeric choice of kernel forms and verification, not the figures and PDF), each
# run cold (--no-cache): the cache would give the whole output at once from the second run.
# Usage: time_regenerate.sh IMPACT [RUNS]
set -euo pipefail
impact=${1:?usage: time_regenerate.sh path/to/impact [runs]}
runs=${2:-11}
here=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

for ((i = 0; i < runs; ++i)); do
  "$impact" regenerate --no-cache --timings --derivations "$here/derivations" --output "$scratch/output" |
    awk -v run="$i" '/^impact: +[0-9.]+ s/ { sub(/^impact: +/, ""); seconds = $1; $1 = ""; $2 = "";
                      sub(/^ +/, ""); print run "\t" seconds "\t" $0 }'
done > "$scratch/times"

awk -F'\t' -v runs="$runs" -v cores="$(nproc)" -v n="$(ls "$here"/derivations/*.toml | wc -l)" '
  { stage[$3] = stage[$3] " " $2; order[$3] = order[$3] ? order[$3] : ++stages; names[order[$3]] = $3
    if ($3 ~ /^derivations with|^LaTeX|^kernel sources/) symbolic[$1] += $2 }
  function median(list,   a, k, i, j, t) {
    k = split(list, a, " ")
    for (i = 1; i <= k; ++i) for (j = i + 1; j <= k; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return a[int((k + 1) / 2)] }
  END {
    printf "regenerate, median of %d runs (%d derivations, %d cores):\n", runs, n, cores
    for (i = 1; i <= stages; ++i) printf "  %8.3f s  %s\n", median(stage[names[i]]), names[i]
    list = ""; for (r in symbolic) list = list " " symbolic[r]
    printf "symbolic part (derivations, checks, LaTeX, JSON, errata, kernel sources): median %.3f s\n", median(list)
  }' "$scratch/times"
