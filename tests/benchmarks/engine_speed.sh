#!/usr/bin/env bash
# The engine's own speed beside SymPy's (issue 61): a benchmark, not a test (no CTest, no
# time gates anything). In one invocation, one after the other on the same machine state:
# `impact derive --no-cache --timings derivations/rough_space.toml` RUNS times (default 3) and
# tests/benchmarks/sympy_rough_space.py once (SymPy solving rough_space's equations and proving
# its momentum, angular-momentum and energy checks). Prints the medians, their ratio, the date,
# the commit and the machine (CPU, its vector ISA, cores, load average).
# Usage: engine_speed.sh IMPACT [RUNS] [SYMPY_TIMEOUT_SECONDS]
# Exit status: non-zero when Impact fails; SymPy running out of time is reported, not a failure.
set -euo pipefail
impact=${1:?usage: engine_speed.sh path/to/impact [runs] [sympy timeout in seconds]}
runs=${2:-3}
sympy_timeout=${3:-600}
here=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
now() { date +%s.%N; }
cpu_of_children() { awk '{ print $16 + $17 }' /proc/$$/stat; }  # ticks: user+sys, waited-for children
ticks=$(getconf CLK_TCK)

cpu=$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo)
isa=$(grep -m1 -owE 'avx512f|avx2|asimd|sve' /proc/cpuinfo | sort -u | paste -sd' ' || true)
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "commit:  $(git -C "$here" rev-parse --short HEAD)$(git -C "$here" diff --quiet HEAD -- src derivations || echo ' (with local changes)')"
echo "machine: ${cpu:-unknown CPU}, ISA ${isa:-none of avx2/avx512f/asimd}, $(nproc) cores"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) before the runs"

for ((i = 1; i <= runs; ++i)); do
  t0=$(now); c0=$(cpu_of_children)
  if ! "$impact" derive --no-cache --timings "$here/derivations/rough_space.toml" > "$scratch/impact_$i.txt" 2> "$scratch/impact_$i.err"; then
    echo "engine_speed.sh: impact derive rough_space failed (run $i):" >&2
    tail -20 "$scratch/impact_$i.err" >&2
    exit 1
  fi
  t1=$(now); c1=$(cpu_of_children)
  wall=$(echo "$t1 - $t0" | bc -l)
  cpu_s=$(echo "($c1 - $c0) / $ticks" | bc -l)
  in_all=$(awk '/deriving .rough_space. in all/ { print $2 }' "$scratch/impact_$i.txt")
  printf 'impact run %d: %7.2f s wall (the process), %7.2f s CPU, %7.2f s deriving rough_space (its --timings)\n' \
    "$i" "$wall" "$cpu_s" "${in_all:-0}"
  echo "$wall" >> "$scratch/impact_wall"; echo "$cpu_s" >> "$scratch/impact_cpu"
done
echo "impact's slowest parts (last run):"
grep '^impact: ' "$scratch/impact_$runs.txt" | sed 's/^impact: /  /'

echo "sympy (time limit ${sympy_timeout} s):"
sympy_status=0
python3 "$here/tests/benchmarks/sympy_rough_space.py" --timeout "$sympy_timeout" > "$scratch/sympy.txt" || sympy_status=$?
sed 's/^/  /' "$scratch/sympy.txt"
sympy_total=$(awk '/^sympy: .* total/ { print $2, $5; exit }' "$scratch/sympy.txt")
sympy_wall=${sympy_total% *}; sympy_cpu=${sympy_total#* }

impact_wall=$(median < "$scratch/impact_wall"); impact_cpu=$(median < "$scratch/impact_cpu")
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the runs"
printf 'impact derive rough_space (103 checks, and the derivations it uses): median of %d: %.2f s wall, %.2f s CPU\n' \
  "$runs" "$impact_wall" "$impact_cpu"
if [ "$sympy_status" -eq 0 ] && [ -n "${sympy_wall:-}" ]; then
  printf 'sympy (the solve, momentum, angular momentum and energy checks): %.2f s wall, %.2f s CPU\n' "$sympy_wall" "$sympy_cpu"
  printf 'sympy / impact: %.1f (wall), %.1f (CPU)\n' "$(echo "$sympy_wall / $impact_wall" | bc -l)" "$(echo "$sympy_cpu / $impact_cpu" | bc -l)"
elif [ -n "${sympy_wall:-}" ]; then
  printf 'sympy: did not finish within %s s (%.2f s CPU by then); sympy / impact > %.1f (wall), > %.1f (CPU)\n' "$sympy_timeout" "$sympy_cpu" \
    "$(echo "$sympy_wall / $impact_wall" | bc -l)" "$(echo "$sympy_cpu / $impact_cpu" | bc -l)"
else
  echo "sympy: failed (exit status $sympy_status), no figure"
fi
