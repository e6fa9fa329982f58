#!/usr/bin/env python3
"""SymPy doing the work of `impact derive derivations/rough_space.toml` that issue 61 compares:
a benchmark, not a test (tests/benchmarks/engine_speed.sh runs it beside Impact).

It reads the derivation files themselves (tomllib, Python >= 3.11), so that SymPy works on the
same equations, written once:

- derivations/rough_sticking.toml: its [[given]] equations (impulse_M_n, impulse_m_n,
  impulse_M_t, impulse_m_t, spin_M, spin_m, restitution_normal, restitution_tangential), the
  eight linear equations its [[step]] solves for its eight unknowns, solved by sympy.solve.
  rough_space takes J_n from there ([[use]] results = ["J_n = J_n"]), as Impact does: Impact
  derives rough_sticking in the same run;
- derivations/rough_space.toml: every [[symbol]]'s definition (d, n, W, g, g_n, g_t, s_n,
  G_t, D_t, m_r, m_t) substituted, then its [[step]]s in order, each in its two cases (sticking
  and sliding, the cases of J_tx, J_ty, J_tz, J_t). Those steps are definitions (define = ...,
  as = ...), not equations: Impact substitutes them and so does this script;
- the checks of rough_space.toml named in CHECKS, proven in each case as Impact proves them:
  lhs - rhs brought to zero by SymPy's own normalisation, the cheapest first: expand(); then
  together() and expand() of the numerator; then simplify(). A check is reported proven in a
  case only when one of them gives exactly 0.

What SymPy is not asked to do and Impact does (say so when comparing the two): Impact also
proves that the cases cover every value, that no divisor vanishes (d, G_t, M + m, D_t, ...) and
every other of the file's 103 checks (rotation covariance, the fixed spheres' limits, the
smooth limit, the friction cone, continuity where the cases meet), derives the files
rough_space uses, and writes the kernel. energy_never_gained is an inequality that needs the
case's condition and the symbols' bounds (eps <= 1, |b| <= 1, q <= 2/3, mu >= 0): SymPy has
no prover for polynomial inequalities under such conditions, so the script simplifies the
difference and asks SymPy's assumptions whether it is <= 0, and reports the check not proven
when they cannot say.

Usage: sympy_rough_space.py [--timeout SECONDS] [--derivations FOLDER]
Prints one line per check and case, the time of the solve and of each proof (wall and CPU),
and the total; `sympy: ... total` is the line engine_speed.sh reads. Exit status 0 when it
ran to the end (whatever SymPy could or could not prove), 2 when the time limit stopped it.
"""

import argparse
import os
import signal
import sys
import time

try:
    import tomllib
except ImportError:  # Python < 3.11
    sys.exit("sympy_rough_space.py: needs Python >= 3.11 (tomllib) to read the derivation files")

try:
    import sympy as sp
    from sympy.parsing.sympy_parser import convert_xor, parse_expr, standard_transformations
except ImportError:
    sys.exit("sympy_rough_space.py: needs SymPy (Debian: apt-get install python3-sympy; scripts/setup.sh installs it)")

# The checks of rough_space.toml the issue names: momentum, angular momentum about the contact
# point, and energy (its change as an identity, the tangential work in it, and its sign).
CHECKS = [
    "momentum_conserved_x",
    "momentum_conserved_y",
    "momentum_conserved_z",
    "angular_momentum_about_the_contact_point_x",
    "angular_momentum_about_the_contact_point_y",
    "angular_momentum_about_the_contact_point_z",
    "energy_change",
    "tangential_work",
    "energy_never_gained",
]


class OutOfTime(Exception):
    pass


def on_alarm(signum, frame):
    raise OutOfTime()


class Clock:
    """The time limit of the whole run, and the wall and CPU time of each part."""

    def __init__(self, limit):
        self.limit = limit
        self.start_wall = time.perf_counter()
        self.start_cpu = time.process_time()
        signal.signal(signal.SIGALRM, on_alarm)

    def left(self):
        return self.limit - (time.perf_counter() - self.start_wall)

    def run(self, work):
        """(result, wall, cpu); result is OutOfTime when the limit came first."""
        left = self.left()
        wall0, cpu0 = time.perf_counter(), time.process_time()
        if left <= 0:
            return OutOfTime(), 0.0, 0.0
        signal.setitimer(signal.ITIMER_REAL, left)
        try:
            result = work()
        except OutOfTime as e:
            result = e
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
        return result, time.perf_counter() - wall0, time.process_time() - cpu0


def symbol_of(entry):
    """A SymPy symbol with what SymPy can hold of the file's domain: its sign. Upper bounds
    (q <= 2/3, eps <= 1, |b| <= 1) have no place in SymPy's assumptions."""
    domain = entry.get("domain", "").replace(" ", "")
    if domain == "positive" or domain.startswith("(0,"):
        return sp.Symbol(entry["name"], positive=True)
    if domain == "nonnegative" or domain.startswith("[0,"):
        return sp.Symbol(entry["name"], nonnegative=True)
    return sp.Symbol(entry["name"], real=True)


class Derivation:
    """A derivation file's symbols and expressions, read as SymPy."""

    def __init__(self, path):
        with open(path, "rb") as f:
            self.toml = tomllib.load(f)
        self.path = path
        self.symbols = {e["name"]: symbol_of(e) for e in self.toml.get("symbol", [])}
        self.names = dict(self.symbols)
        self.names["sqrt"] = sp.sqrt

    def parse(self, text):
        # Impact writes powers with ^; every name is the file's symbol (none of SymPy's E, I, S...).
        return parse_expr(text, local_dict=self.names, transformations=standard_transformations + (convert_xor,))

    def definitions(self):
        """Each defined symbol in terms of the undefined ones, as Impact substitutes them."""
        raw = {e["name"]: self.parse(e["definition"]) for e in self.toml.get("symbol", []) if "definition" in e}
        resolved = {}

        def resolve(name):
            if name not in resolved:
                expr = raw[name]
                inner = {s: resolve(s.name) for s in expr.free_symbols if s.name in raw}
                resolved[name] = expr.xreplace(inner)
            return resolved[name]

        for name in raw:
            resolve(name)
        return {self.symbols[n]: v for n, v in resolved.items()}

    def check(self, name):
        for c in self.toml.get("check", []):
            if c["name"] == name:
                return c
        sys.exit(f"sympy_rough_space.py: {self.path} has no check named {name}")


def equation_sides(text):
    for relation in ("<=", ">=", "="):
        if relation in text:
            lhs, rhs = text.split(relation, 1)
            return lhs, relation, rhs
    raise ValueError(f"no relation in {text!r}")


def solve_rough_sticking(sticking):
    """rough_sticking.toml's [[step]] solve: its given equations for its unknowns."""
    step = next(s for s in sticking.toml["step"] if "solve" in s)
    given = {g["name"]: g["equation"] for g in sticking.toml["given"]}
    equations = []
    for name in step["solve"]:
        lhs, _, rhs = equation_sides(given[name])
        equations.append(sp.Eq(sticking.parse(lhs), sticking.parse(rhs)))
    unknowns = [sticking.symbols[n] for n in step["for"]]
    solutions = sp.solve(equations, unknowns, dict=True)
    if len(solutions) != 1:
        raise RuntimeError(f"rough_sticking: sympy.solve gave {len(solutions)} solutions")
    return solutions[0]


def derive_cases(space, j_n):
    """rough_space's steps in order, in each case of the tangential impulse: a map from each
    symbol to its value in the symbols that have none. Returns (case names, maps)."""
    base = space.definitions()
    base[space.symbols["J_n"]] = j_n.xreplace(base)
    names = []
    maps = []
    for case in (0, 1):
        values = dict(base)
        for step in space.toml["step"]:
            if "cases" in step:
                chosen = step["cases"][case]
                text = chosen["as"]
                if case >= len(names):
                    names.append("sticking" if "<=" in chosen["when"] else "sliding")
            else:
                text = step["as"]
            values[space.symbols[step["define"]]] = space.parse(text).xreplace(values)
        maps.append(values)
    return names, maps


def reduce_to_zero(expr):
    """The first of SymPy's normalisations, cheapest first, that gives exactly 0, or None
    (and what simplify left)."""
    if sp.expand(expr) == 0:
        return "expand", None
    numerator, _ = sp.fraction(sp.together(expr))
    if sp.expand(numerator) == 0:
        return "together+expand", None
    left = sp.simplify(expr)
    if left == 0:
        return "simplify", None
    return None, left


def prove_identity(claim, values, space):
    lhs, relation, rhs = equation_sides(claim)
    assert relation == "="
    difference = (space.parse(lhs) - space.parse(rhs)).xreplace(values)
    how, left = reduce_to_zero(difference)
    if how:
        return True, f"lhs - rhs reduced to 0 by {how}"
    return False, f"lhs - rhs not reduced to 0 (simplify leaves {sp.count_ops(left)} operations)"


def try_inequality(claim, values, space):
    lhs, relation, rhs = equation_sides(claim)
    assert relation == "<="
    difference = (space.parse(lhs) - space.parse(rhs)).xreplace(values)
    simplified = sp.simplify(difference)
    if simplified.is_nonpositive:
        return True, "lhs - rhs simplified, and SymPy's assumptions decide it is <= 0"
    return False, (f"NOT PROVEN: SymPy has no prover for this inequality under the case's condition and "
                   f"the bounds eps <= 1, |b| <= 1, q <= 2/3; lhs - rhs simplified to {sp.count_ops(simplified)} "
                   f"operations, whose sign SymPy's assumptions leave open ({simplified.is_nonpositive})")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--timeout", type=float, default=600, help="seconds for the whole run (default 600)")
    parser.add_argument("--derivations", default=os.path.join(here, "..", "..", "derivations"),
                        help="folder of rough_space.toml and rough_sticking.toml")
    args = parser.parse_args()

    clock = Clock(args.timeout)
    print(f"sympy {sp.__version__}, Python {sys.version.split()[0]}, time limit {args.timeout:g} s")
    space = Derivation(os.path.join(args.derivations, "rough_space.toml"))
    sticking = Derivation(os.path.join(args.derivations, "rough_sticking.toml"))
    unfinished = []
    unproven = []

    def solve():
        j_n = solve_rough_sticking(sticking)[sticking.symbols["J_n"]]
        # rough_sticking's symbols named as rough_space's (v_Mn, v_mn, M, m, eps: defined there too).
        j_n = j_n.xreplace({s: space.symbols[s.name] for s in j_n.free_symbols})
        return derive_cases(space, j_n)

    solved, wall, cpu = clock.run(solve)
    solve_wall, solve_cpu = wall, cpu
    if isinstance(solved, OutOfTime):
        print(f"sympy: {wall:8.3f} s wall {cpu:8.3f} s CPU  solve: DID NOT FINISH within the time limit")
        print(f"sympy: did not finish: the solve and every proof (time limit {args.timeout:g} s)")
        print(f"sympy: {wall:8.3f} s wall {cpu:8.3f} s CPU  total (stopped by the time limit)")
        return 2
    case_names, maps = solved
    print(f"sympy: {wall:8.3f} s wall {cpu:8.3f} s CPU  solve: rough_sticking's 8 equations by sympy.solve, "
          f"rough_space's {len(space.toml['step'])} steps in {len(maps)} cases ({', '.join(case_names)})")

    proofs_wall = proofs_cpu = 0.0
    for name in CHECKS:
        claim = space.check(name)["claim"]
        for case_name, values in zip(case_names, maps):
            if "<=" in claim:
                outcome, wall, cpu = clock.run(lambda: try_inequality(claim, values, space))
            else:
                outcome, wall, cpu = clock.run(lambda: prove_identity(claim, values, space))
            proofs_wall += wall
            proofs_cpu += cpu
            if isinstance(outcome, OutOfTime):
                verdict = "DID NOT FINISH within the time limit"
                unfinished.append(f"{name} ({case_name})")
            else:
                proven, verdict = outcome
                verdict = ("proven: " if proven else "") + verdict
                if not proven:
                    unproven.append(f"{name} ({case_name})")
            print(f"sympy: {wall:8.3f} s wall {cpu:8.3f} s CPU  {name}, {case_name}: {verdict}")
            sys.stdout.flush()

    print(f"sympy: {proofs_wall:8.3f} s wall {proofs_cpu:8.3f} s CPU  the proofs")
    if unproven:
        print(f"sympy: not proven: {', '.join(unproven)}")
    if unfinished:
        print(f"sympy: did not finish (time limit {args.timeout:g} s): {', '.join(unfinished)}")
    total_wall, total_cpu = solve_wall + proofs_wall, solve_cpu + proofs_cpu
    stopped = " (stopped by the time limit)" if unfinished else ""
    print(f"sympy: {total_wall:8.3f} s wall {total_cpu:8.3f} s CPU  total{stopped}")
    return 2 if unfinished else 0


if __name__ == "__main__":
    sys.exit(main())
