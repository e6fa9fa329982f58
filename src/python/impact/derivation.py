"""A derivation from Python (docs/python.md): ``impact.derive(path_or_id)`` runs the command
``impact derive --json`` (docs/cli.md) and returns what it derived and proved as a
``Derivation``, typeset in a notebook. The command is the one this package was built or
installed with (``_executable.py``), or the one the environment variable IMPACT_EXECUTABLE
names.
"""

import json
import os
import re
import subprocess

__all__ = ["derive", "Derivation", "DerivationError", "Expression", "Check", "Solution"]


class DerivationError(Exception):
    """A mistake in a derivation file: ``.file``, ``.line``, ``.column`` (None where the
    command gives none) and ``.message``, the command line's own words."""

    def __init__(self, message, file=None, line=None, column=None):
        super().__init__(message)
        self.message, self.file, self.line, self.column = message, file, line, column


class Expression:
    """A result: ``str()`` in Impact's syntax, ``.latex`` as the report typesets it."""

    def __init__(self, text, latex):
        self.text, self.latex = text, latex

    def __str__(self):
        return self.text

    def __repr__(self):
        return f"Expression({self.text!r})"

    def _repr_latex_(self):
        return f"${self.latex}$"


class Check:
    """A check: ``.name``, ``.status`` (proven, sampled, failed, ...), ``.claim``, ``.proof``
    (how it was proven, in words) and ``.latex`` (its claim typeset)."""

    def __init__(self, j):
        self.name, self.status = j["name"], j["status"]
        self.claim = j.get("claim", j.get("continuity", ""))
        self.proof = "; ".join([j.get("method", "")] + j.get("proof", [])).strip("; ")
        self.latex = j.get("latex", "")
        self.data = j

    def __repr__(self):
        return f"Check({self.name!r}, {self.status!r})"


class Solution:
    """A solution of a step whose equations are not linear: ``.values`` (unknown -> value),
    ``.kept`` and, for one rejected, ``.why``."""

    def __init__(self, j):
        self.data = j
        self.values = j.get("values", {})
        self.fate = j.get("status", "kept")
        self.kept = self.fate == "kept"
        self.why = j.get("why", "")

    def __repr__(self):
        return f"Solution({self.values!r}, {self.fate!r})"


class Derivation:
    """What ``impact derive`` derived: ``.id``, ``.title``, ``.file``, ``.paper``,
    ``.results`` (name -> Expression), ``.checks`` (list of Check), ``.solutions`` (list of
    Solution, kept and rejected) and ``.data``, the command's JSON."""

    def __init__(self, j):
        self.data = j
        self.id, self.title, self.file, self.paper = j["id"], j["title"], j["file"], j.get("paper", "")
        self.results = {name: Expression(text, j.get("latex", {}).get(name, text))
                        for name, text in j["results"].items()}
        self.checks = [Check(c) for c in j["checks"]]
        self.solutions = [Solution(s) for s in j.get("solutions", [])]

    def __repr__(self):
        return f"Derivation({self.id!r}: {len(self.results)} results, {len(self.checks)} checks)"

    def _repr_latex_(self):
        rows = " \\\\\n".join(f"\\text{{{name.replace('_', chr(92) + '_')}}} &= {e.latex}"
                              for name, e in self.results.items())
        return f"$$\\begin{{aligned}}\n{rows}\n\\end{{aligned}}$$"

    def _repr_markdown_(self):
        lines = [f"**{self.title}**" + (f" ({self.paper})" if self.paper else ""), ""]
        lines += [f"- `{name}` = ${e.latex}$" for name, e in self.results.items()]
        lines += ["", "| check | status | how |", "| --- | --- | --- |"]
        lines += [f"| {c.name} | {c.status} | {c.proof.replace('|', '/')} |" for c in self.checks]
        return "\n".join(lines)


def executable():
    """The ``impact`` command: $IMPACT_EXECUTABLE, else the one the package was built with."""
    if os.environ.get("IMPACT_EXECUTABLE"):
        return os.environ["IMPACT_EXECUTABLE"]
    try:
        from ._executable import IMPACT_EXECUTABLE
    except ImportError:
        IMPACT_EXECUTABLE = "impact"
    return IMPACT_EXECUTABLE


_WHERE = re.compile(r"^(?P<file>.*?):(?P<line>\d+)(?::(?P<column>\d+))?: error: (?P<message>.*)$")


def derive(path_or_id, derivations=None):
    """Derives the file (or the derivation of that id in ``derivations``, by default the
    project's derivations/ folder) and returns its Derivation. A mistake in the file raises
    DerivationError; a check that fails is a result, with its status."""
    command = [executable(), "derive", "--json", os.fspath(path_or_id)]
    if derivations is not None:
        command += ["--derivations", os.fspath(derivations)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.stdout.strip():
        return Derivation(json.loads(done.stdout))
    message = done.stderr.strip() or f"impact derive exited with status {done.returncode}"
    first = message.splitlines()[0]
    where = _WHERE.match(first)
    if where:
        line = int(where["line"])
        column = int(where["column"]) if where["column"] else None
        raise DerivationError(first, where["file"], line, column)
    raise DerivationError(first)
