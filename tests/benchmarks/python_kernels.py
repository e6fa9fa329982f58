"""The benchmark of docs/python.md (target benchmark_python), side by side in one run:

- impact.collide in 3D, float64, on 4 million pairs in the batch layout (each vector's
  components contiguous, np.asfortranarray), against the C++ batch loop collide_batch on
  collide_batch_arrays (tests/benchmarks/python_batch.cpp, built with the module's flags);
- impact.collide_line on 4 million pairs against Eq. 8 written in NumPy array operations;
- how far the kernel's results are from that NumPy formula, in ulps of the velocity scale
  (max(|v_M|, |v_m|) of the pair) for v_M' and v_m', of the impulse scale
  (M m / (M + m) (|v_M| + |v_m|)) for J, over the pairs the kernel answers (status ok).

Each time is the best of five runs on the same inputs. Usage:
python_kernels.py PYTHON_BATCH_PROGRAM [FLAGS]
"""
import os
import platform
import subprocess
import sys
import time

import numpy as np

import impact

PAIRS = 4_000_000
RUNS = 5


def best(f):
    times = []
    for _ in range(RUNS):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def cpu():
    try:
        with open("/proc/cpuinfo") as info:
            lines = info.read().splitlines()
    except OSError:
        return platform.processor(), ""
    name = next((l.split(":", 1)[1].strip() for l in lines if l.startswith("model name")), "?")
    flags = next((l.split(":", 1)[1].split() for l in lines if l.startswith("flags")), [])
    isa = [f for f in ("sse4_2", "avx", "avx2", "fma", "avx512f") if f in flags]
    return name, " ".join(isa)


def eq8_numpy(M, m, v_M, v_m, eps):
    # Eq. 8 as the derivation displays it.
    s = M + m
    d = v_M - v_m
    p = M * v_M + m * v_m
    return (p - m * eps * d) / s, (p + M * eps * d) / s, M * m * (1 + eps) * d / s


def ulps(a, b, scale):
    return float(np.max(np.abs(a - b) / np.spacing(scale))) if a.size else 0.0


def main():
    program = sys.argv[1]
    flags = sys.argv[2] if len(sys.argv) > 2 else "?"
    name, isa = cpu()
    print(f"machine: {name}, {os.cpu_count()} cores, ISA {isa}; load {os.getloadavg()[0]:.1f}")
    print(f"Python {platform.python_version()}, NumPy {np.__version__}; C++ flags: {flags}")
    print(f"{PAIRS} pairs, float64, best of {RUNS}")

    rng = np.random.default_rng(1)
    M, m = rng.uniform(0.5, 2.0, PAIRS), rng.uniform(0.5, 2.0, PAIRS)
    eps = rng.uniform(0.0, 1.0, PAIRS)
    C_M, C_m, v_M3, v_m3 = (np.asfortranarray(rng.normal(size=(PAIRS, 3))) for _ in range(4))
    python = best(lambda: impact.collide(M, m, C_M, C_m, v_M3, v_m3, eps))
    cxx = float(subprocess.run([program, str(PAIRS), str(RUNS)], check=True, capture_output=True,
                               text=True).stdout.split()[0])
    print(f"impact.collide 3D (batch layout): {python * 1e3:7.1f} ms; C++ collide_batch: {cxx * 1e3:7.1f} ms; "
          f"throughput {cxx / python:.2f}x the C++ loop's (issue 62: >= 0.8x)")

    v_M, v_m = rng.uniform(-1.0, 1.0, PAIRS), rng.uniform(-1.0, 1.0, PAIRS)
    kernel = best(lambda: impact.collide_line(M, m, v_M, v_m, eps))
    formula = best(lambda: eq8_numpy(M, m, v_M, v_m, eps))
    print(f"impact.collide_line: {kernel * 1e3:7.1f} ms; Eq. 8 in NumPy: {formula * 1e3:7.1f} ms; "
          f"{formula / kernel:.2f}x faster (issue 62: >= 3x)")

    r = impact.collide_line(M, m, v_M, v_m, eps)
    ok = r.status == impact.status.ok
    f = eq8_numpy(M[ok], m[ok], v_M[ok], v_m[ok], eps[ok])
    velocity = np.maximum(np.abs(v_M[ok]), np.abs(v_m[ok]))
    impulse = M[ok] * m[ok] / (M[ok] + m[ok]) * (np.abs(v_M[ok]) + np.abs(v_m[ok]))
    far = max(ulps(r.v_M[ok], f[0], velocity), ulps(r.v_m[ok], f[1], velocity), ulps(r.J[ok], f[2], impulse))
    print(f"kernel against the NumPy formula on {np.count_nonzero(ok)} pairs answered: at most {far:.2f} ulps "
          f"of the velocity (impulse) scale (issue 62: <= 4)")


if __name__ == "__main__":
    main()
