#!/usr/bin/env bash
# How the time of `impact regenerate` grows with the number of derivation files, cold
# (an empty cache) and warm: a benchmark, not a test (never run by CTest).
#
# For each size N, a folder holds the paper's derivations plus N - 10 variants (copies
# of them under another id, with their kernels renamed, so that each variant's kernels
# are measured like new ones). Then, each with its own empty cache:
#   cold     the first regeneration;
#   warm     again, nothing changed;
#   comment  after a comment is added to one derivation file;
#   change   after one variant's title and one of its kernels' names change: only that
#            derivation, that kernel's choice and the report should be computed again (the
#            cache lines say).
# Each size is measured with each number of worker processes in JOBS (default "1 2":
# `--jobs 1`, the files derived and the kernels' forms chosen one after another in Impact's
# process, and `--jobs 2`, two at once in worker processes), each with its own empty cache;
# the columns kernels_s and derive_s are the cold run's choice of kernel forms and its
# derivations, from --timings.
# A variant's kernels draw the samples of the kernel they copy (samples are seeded by a
# kernel's inputs and outputs, not its name), so every variant is measured and verified
# like its original, and a folder of any size regenerates.
# Usage: [JOBS="1 2"] scale_regenerate.sh IMPACT [N ...]   (default sizes: 12 50 100 200 300)
set -euo pipefail
impact=$(realpath "${1:?usage: scale_regenerate.sh path/to/impact [N ...]}")
shift
sizes=("$@")
[ $# -eq 0 ] && sizes=(12 50 100 200 300)
here=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

originals=("$here"/derivations/*.toml)

# A copy of derivation file $1 as variant $2: id, file name and kernel names suffixed.
variant() {
  local file=$1 k=$2 base
  base=$(basename "$file" .toml)
  awk -v k="$k" '
    /^id = "/ { sub(/"$/, "_v" k "\""); print; next }
    /^\[\[kernel\]\]/ { in_kernel = 1; print; next }
    /^\[/ { in_kernel = 0 }
    in_kernel && /^name = "/ { sub(/"$/, "_v" k "\""); in_kernel = 0 }
    { print }' "$file" > "$3/${base}_v$k.toml"
}

# Seconds taken by a regeneration, its cache lines kept in $scratch/last.
timed() {
  local start end
  start=$(date +%s.%N)
  "$impact" regenerate --quiet --timings "$@" > "$scratch/last" 2>&1 || { cat "$scratch/last" >&2; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

jobs_list=(${JOBS:-1 2})
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
isa=$(grep -m1 '^flags' /proc/cpuinfo | grep -o -w -E 'avx512f|avx2|fma|sse4_2' | sort -u | tr '\n' ' ')
echo "impact regenerate, cold and warm; $(nproc) cores, $cpu ($isa), load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%6s %4s %9s %9s %8s %9s %7s %10s %7s %9s %7s  %s\n' files jobs cold_s kernels_s derive_s warm_s warm/c \
  comment_s com/c change_s chg/c "cache after the change"
# The seconds --timings gave a stage in the last run.
stage() { { grep -m1 "$1" "$scratch/last" || echo 'impact: 0'; } | awk '{ print $2 }'; }
for n in "${sizes[@]}"; do
  for jobs in "${jobs_list[@]}"; do
    d="$scratch/d$n-j$jobs"
    rm -rf "$d"
    mkdir -p "$d"
    cp "${originals[@]}" "$d"
    for ((i = 0; i < n - ${#originals[@]}; ++i)); do
      variant "${originals[i % ${#originals[@]}]}" "$((i / ${#originals[@]} + 1))" "$d"
    done
    files=$(ls "$d"/*.toml | wc -l)
    args=(--jobs "$jobs" --derivations "$d" --output "$scratch/out$n-j$jobs" --cache "$scratch/cache$n-j$jobs")
    cold=$(timed "${args[@]}")
    kernels=$(stage 'kernel forms chosen')
    derive=$(stage 'derivations with their checks')
    warm=$(timed "${args[@]}")
    echo "# a comment added by the benchmark" >> "$d/eq08_inelastic_line.toml"
    comment=$(timed "${args[@]}")
    changed=$(grep -l '^\[\[kernel\]\]' "$d"/*_v1.toml 2>/dev/null | head -1 || true)
    # Without variants, a file of the folder that nothing uses (eq08, which most use, would have
    # them derived again too).
    if [ -z "$changed" ]; then changed="$d/eq14_scatter_angle.toml"; fi
    sed -i -e 's/^title = "\(.*\)"/title = "\1, changed"/' "$changed"
    awk '/^\[\[kernel\]\]/ { k = 1 } k && /^name = "/ { sub(/"$/, "_changed\""); k = 0 } { print }' "$changed" > "$scratch/t" &&
      mv "$scratch/t" "$changed"
    change=$(timed "${args[@]}")
    cache=$(grep -E 'cache: (derivation|PDF|kernel choice):' "$scratch/last" | sed 's/^impact: cache: //; s/ (0 damaged, computed again)//; s/ (0 damaged, \([0-9]* found but not usable\), computed again)/ (\1)/' |
      tr '\n' ';' | sed 's/;$//; s/;/; /g')
    printf '%6d %4d %9.2f %9.2f %8.2f %9.2f %7.3f %10.2f %7.3f %9.2f %7.3f  %s\n' "$files" "$jobs" "$cold" "$kernels" \
      "$derive" "$warm" "$(echo "$warm / $cold" | bc -l)" "$comment" "$(echo "$comment / $cold" | bc -l)" "$change" \
      "$(echo "$change / $cold" | bc -l)" "$cache"
    # The outputs of every number of jobs are the same bytes.
    if [ "$jobs" != "${jobs_list[0]}" ]; then
      diff -r "$scratch/out$n-j${jobs_list[0]}" "$scratch/out$n-j$jobs" > /dev/null ||
        { echo "the output with --jobs $jobs differs from --jobs ${jobs_list[0]}"; exit 1; }
    fi
  done
done
