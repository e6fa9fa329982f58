#!/usr/bin/env bash
# `impact regenerate --no-cache` (cold) with --jobs 1 and --jobs 2, run in turn ROUNDS
# times so that a change in the machine's load falls on both alike: a benchmark, not a
# test (never run by CTest). For each number of jobs: the median wall time of the whole
# regeneration and of the choice of kernel forms (from --timings), and the median CPU
# time (user + system, Impact and every process it waited for: workers, pdflatex).
# With N, a folder of N derivation files (the paper's ten and variants, as
# scale_regenerate.sh makes them) instead of derivations/.
# Usage: jobs_regenerate.sh IMPACT [ROUNDS [N]]   (default: 5 rounds, derivations/)
set -euo pipefail
impact=$(realpath "${1:?usage: jobs_regenerate.sh path/to/impact [ROUNDS [N]]}")
rounds=${2:-5}
n=${3:-}
here=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

derivations="$here/derivations"
if [ -n "$n" ]; then
  derivations="$scratch/d"
  mkdir -p "$derivations"
  originals=("$here"/derivations/*.toml)
  cp "${originals[@]}" "$derivations"
  for ((i = 0; i < n - ${#originals[@]}; ++i)); do
    file=${originals[i % ${#originals[@]}]}
    k=$((i / ${#originals[@]} + 1))
    awk -v k="$k" '
      /^id = "/ { sub(/"$/, "_v" k "\""); print; next }
      /^\[\[kernel\]\]/ { in_kernel = 1; print; next }
      /^\[/ { in_kernel = 0 }
      in_kernel && /^name = "/ { sub(/"$/, "_v" k "\""); in_kernel = 0 }
      { print }' "$file" > "$derivations/$(basename "$file" .toml)_v$k.toml"
  done
fi

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
echo "impact regenerate --no-cache, --jobs 1 and 2 in turn, $rounds rounds, $(ls "$derivations"/*.toml | wc -l) files;" \
  "$(nproc) cores, $cpu, load average at the start $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 0; r < rounds; ++r)); do
  for jobs in 1 2; do
    /usr/bin/time -f '%e %U %S' -o "$scratch/time" "$impact" regenerate --quiet --timings --no-cache --jobs "$jobs" \
      --derivations "$derivations" --output "$scratch/out$jobs" > "$scratch/last" 2>&1 ||
      { cat "$scratch/last" >&2; exit 1; }
    read -r wall user sys < "$scratch/time"
    kernels=$(grep -m1 'kernel forms chosen' "$scratch/last" | awk '{ print $2 }')
    echo "$wall" >> "$scratch/wall$jobs"
    echo "$kernels" >> "$scratch/kernels$jobs"
    echo "$user + $sys" | bc >> "$scratch/cpu$jobs"
  done
  diff -r "$scratch/out1" "$scratch/out2" > /dev/null || { echo "--jobs 2 wrote other bytes than --jobs 1"; exit 1; }
done
printf '%4s %8s %10s %8s   %s\n' jobs wall_s kernels_s cpu_s "(medians; each run's wall time)"
for jobs in 1 2; do
  printf '%4d %8.2f %10.2f %8.2f   %s\n' "$jobs" "$(median < "$scratch/wall$jobs")" "$(median < "$scratch/kernels$jobs")" \
    "$(median < "$scratch/cpu$jobs")" "$(tr '\n' ' ' < "$scratch/wall$jobs")"
done
echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
