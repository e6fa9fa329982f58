"""impact.derive (docs/python.md): a derivation file written here, derived by the command
`impact derive --json`; its results, checks and solutions, and the errors of a bad file."""
import pytest

import impact

FALL = '''id = "fall"
title = "A ball dropped from rest"

[[symbol]]
name = "m"
domain = "positive"
dimension = "mass"
meaning = "mass of the ball"

[[symbol]]
name = "g"
domain = "positive"
dimension = "acceleration"
meaning = "acceleration of gravity"

[[symbol]]
name = "h"
domain = "positive"
dimension = "length"
meaning = "height of the fall"

[[symbol]]
name = "v"
domain = "positive"
dimension = "length/time"
meaning = "speed at the ground"

[[given]]
name = "energy"
equation = "m*v^2/2 = m*g*h"
because = "the potential energy becomes kinetic"

[[step]]
solve = ["energy"]
for = ["v"]
because = "v appears squared: two roots, and v is positive"

[[result]]
name = "v"

[[check]]
name = "faster_from_higher"
claim = "v^2 = 2*g*h"
because = "Torricelli"
'''


@pytest.fixture
def fall(tmp_path):
    path = tmp_path / "fall.toml"
    path.write_text(FALL)
    return path


def test_results_checks_and_solutions(fall):
    d = impact.derive(fall)
    assert d.id == "fall"
    # v = sqrt(2 g h), typed here: the positive root.
    assert str(d.results["v"]).replace(" ", "") in ("sqrt(2)*sqrt(g)*sqrt(h)", "sqrt(2)*sqrt(h)*sqrt(g)",
                                                    "sqrt(2*g*h)", "sqrt(2)*sqrt(g*h)")
    assert "\\sqrt" in d.results["v"].latex
    check = next(c for c in d.checks if c.name == "faster_from_higher")
    assert check.status == "proven"
    assert check.proof
    kept = [s for s in d.solutions if s.kept]
    rejected = [s for s in d.solutions if not s.kept]
    assert len(kept) == 1 and len(rejected) == 1
    assert rejected[0].values["v"].startswith("-")
    assert "faster_from_higher" in d._repr_markdown_()
    assert d._repr_latex_().startswith("$$")


def test_a_mistake_names_file_line_and_column(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(FALL.replace('equation = "m*v^2/2 = m*g*h"', 'equation = "m*v^2/2 = m*g*"'))
    with pytest.raises(impact.DerivationError) as raised:
        impact.derive(path)
    e = raised.value
    assert e.file.endswith("bad.toml")
    # The equation is on line 33 of the file (counted in FALL above).
    assert e.line == FALL.splitlines().index('equation = "m*v^2/2 = m*g*h"') + 1
    assert e.column is not None
    assert "error" in e.message


def test_the_command_is_overridden_by_the_environment(fall, monkeypatch):
    monkeypatch.setenv("IMPACT_EXECUTABLE", "/nonexistent/impact")
    with pytest.raises(FileNotFoundError):
        impact.derive(fall)
