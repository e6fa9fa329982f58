"""The benchmark of docs/python.md (target benchmark_python), side by side in one run:

- impact.collide in 3D, float64, on 4 million pairs in the batch layout (each vector's
  components contiguous, np.asfortranarray), against the C++ batch loop collide_batch on
  collide_batch_arrays (tests/benchmarks/python_batch.cpp, built with the module's flags), which
  updates the velocities in place: the call in place (out= the velocities' own arrays) on
  arrays laid out as the C++ loop's are (impact.batch_arrays) and on arrays of np.empty, and
  the call as it allocates its outputs; each run in place on the velocities afresh, their copy
  not timed, as the C++ side does;
- impact.collide_line on 4 million pairs against Eq. 8 written in NumPy array operations: the
  call in place on impact.batch_arrays, into outputs of np.empty made once (out=), and
  allocating its outputs;
- how far the kernel's results are from that NumPy formula, in ulps of the velocity scale
  (the pair's largest velocity, before or after) for v_M' and v_m', of |J| for J, over the
  pairs the kernel answers (status ok); and each from the formula in long double.

Each time is the best of fifteen runs on the same inputs, five at a time, taken in turns with
the time it is compared with. Usage:
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


def best(f, before=None):
    times = []
    for _ in range(RUNS):
        if before:
            before()
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
    spacing = np.spacing(scale.astype(np.float64))
    return float(np.max(np.abs(a.astype(np.longdouble) - b) / spacing)) if a.size else 0.0


def main():
    program = sys.argv[1]
    flags = sys.argv[2] if len(sys.argv) > 2 else "?"
    name, isa = cpu()
    print(f"machine: {name}, {os.cpu_count()} cores, ISA {isa}; load {os.getloadavg()[0]:.1f}")
    print(f"Python {platform.python_version()}, NumPy {np.__version__}; C++ flags: {flags}")
    print(f"{PAIRS} pairs, float64, best of {3 * RUNS} (in turns)")

    rng = np.random.default_rng(1)
    M, m = rng.uniform(0.5, 2.0, PAIRS), rng.uniform(0.5, 2.0, PAIRS)
    eps = rng.uniform(0.0, 1.0, PAIRS)
    C_M, C_m, v_M3, v_m3 = (np.asfortranarray(rng.normal(size=(PAIRS, 3))) for _ in range(4))
    # In place on the batch layout: the arrays as C++'s collide_batch_arrays lays them out.
    b = impact.batch_arrays(impact.collide, PAIRS, dimension=3)
    for name, values in (("M", M), ("m", m), ("C_M", C_M), ("C_m", C_m), ("eps", eps)):
        np.copyto(getattr(b, name), values)
    # In place on arrays of np.empty (aligned to 16 bytes, each at one offset in its pages).
    w_M3, w_m3 = np.empty_like(v_M3, order="F"), np.empty_like(v_m3, order="F")
    statuses = np.empty(PAIRS, np.int64)

    def afresh3():
        for w, v in ((b.v_M, v_M3), (b.v_m, v_m3), (w_M3, v_M3), (w_m3, v_m3)):
            np.copyto(w, v)

    # Taken in turns, so that a change of the machine's load falls on both.
    laid_out, plain, fresh, cxx = (float("inf"),) * 4
    for _ in range(3):
        laid_out = min(laid_out, best(lambda: impact.collide(*b.inputs, out=b.out), afresh3))
        plain = min(plain, best(lambda: impact.collide(M, m, C_M, C_m, w_M3, w_m3, eps, out=(w_M3, w_m3, statuses)),
                                afresh3))
        fresh = min(fresh, best(lambda: impact.collide(M, m, C_M, C_m, v_M3, v_m3, eps)))
        cxx = min(cxx, float(subprocess.run([program, str(PAIRS), str(RUNS)], check=True, capture_output=True,
                                            text=True).stdout.split()[0]))
    print(f"C++ collide_batch, in place:                     {cxx * 1e3:7.1f} ms")
    print(f"impact.collide 3D, in place on batch_arrays:     {laid_out * 1e3:7.1f} ms: "
          f"throughput {cxx / laid_out:.2f}x the C++ loop's (issue 62: >= 0.8x)")
    print(f"impact.collide 3D, in place on np.empty arrays:  {plain * 1e3:7.1f} ms: {cxx / plain:.2f}x")
    print(f"impact.collide 3D, allocating its outputs:       {fresh * 1e3:7.1f} ms: {cxx / fresh:.2f}x")

    v_M, v_m = rng.uniform(-1.0, 1.0, PAIRS), rng.uniform(-1.0, 1.0, PAIRS)
    line = impact.batch_arrays(impact.collide_line, PAIRS)
    for name, values in (("M", M), ("m", m), ("eps", eps)):
        np.copyto(getattr(line, name), values)
    o_M, o_m, J = np.empty(PAIRS), np.empty(PAIRS), np.empty(PAIRS)

    def afresh():
        np.copyto(line.v_M, v_M)
        np.copyto(line.v_m, v_m)

    laid_out, given, fresh, formula = (float("inf"),) * 4
    for _ in range(3):
        laid_out = min(laid_out, best(lambda: impact.collide_line(*line.inputs, out=line.out), afresh))
        given = min(given, best(lambda: impact.collide_line(M, m, v_M, v_m, eps, out=(o_M, o_m, J, statuses))))
        fresh = min(fresh, best(lambda: impact.collide_line(M, m, v_M, v_m, eps)))
        formula = min(formula, best(lambda: eq8_numpy(M, m, v_M, v_m, eps)))
    print(f"Eq. 8 in NumPy:                                  {formula * 1e3:7.1f} ms")
    print(f"impact.collide_line, in place on batch_arrays:   {laid_out * 1e3:7.1f} ms: "
          f"{formula / laid_out:.2f}x faster (issue 62: >= 3x)")
    print(f"impact.collide_line, into np.empty arrays (out=): {given * 1e3:6.1f} ms: {formula / given:.2f}x faster")
    print(f"impact.collide_line, allocating its outputs:     {fresh * 1e3:7.1f} ms: {formula / fresh:.2f}x faster")

    # The kernel's results against the formula's, and each against the formula in long double
    # (64 bits of mantissa: the exact value to within 2^-11 ulp here), so that the figure says
    # whose rounding it is.
    r = impact.collide_line(M, m, v_M, v_m, eps)
    ok = r.status == impact.status.ok
    inputs = (M[ok], m[ok], v_M[ok], v_m[ok], eps[ok])
    f = eq8_numpy(*inputs)
    exact = eq8_numpy(*(x.astype(np.longdouble) for x in inputs))
    kernel_results = (r.v_M[ok], r.v_m[ok], r.J[ok])
    velocity = np.maximum.reduce([np.abs(x) for x in (v_M[ok], v_m[ok], r.v_M[ok], r.v_m[ok])])
    impulse = np.abs(r.J[ok])
    print(f"on the {np.count_nonzero(ok)} pairs the kernel answers (status ok), the largest difference in ulps of")
    print("the pair's velocity scale (its largest velocity, before or after; for J, of |J|):")
    worst = 0.0
    for name, k, formula, e, scale in zip(("v_M", "v_m", "J"), kernel_results, f, exact,
                                          (velocity, velocity, impulse)):
        apart = ulps(k, formula, scale)
        worst = max(worst, apart) if name != "J" else worst
        print(f"  {name:4} kernel - NumPy {apart:5.2f}; kernel - exact {ulps(k, e, scale):5.2f}; "
              f"NumPy - exact {ulps(formula, e, scale):5.2f}")
    print(f"velocities: at most {worst:.2f} ulps apart (issue 62: <= 4)")


if __name__ == "__main__":
    main()
