"""A plug-in that raises or returns what its contract refuses, at call time (issue 64
item 2): one sentence naming the plug-in and what it returned, never a traceback from deep
inside NumPy (``matmul … size 3 is different from 106``) — for the contact solver, the
friction model and the compliance model alike (docs/extending.md).
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from contact.cli import main
from contact.ltca import LTCAOptions
from contact.ltca.compliance_models import (
    ComplianceModelError,
    register_compliance_model,
    shell_assembler,
    unregister_compliance_model,
)
from contact.qp import solve_contact
from contact.qp.benchmark_problems import hertz_cylinder_problem
from contact.qp.solvers import SOLVERS_EXTRA, register_backend, unregister_backend
from friction.coefficient import (
    MU_CAP,
    MU_MAX,
    FrictionModelRangeWarning,
    friction_coefficient,
    register_friction_model,
    unregister_friction_model,
)
from geometry.core.errors import LTCAError, PluginError

RAW = re.compile(r"Traceback|matmul|broadcast|Errno")


@pytest.fixture
def problem():
    return hertz_cylinder_problem(20).problem


# --------------------------------------------------------------------------- solvers
@pytest.mark.parametrize(("returned", "pattern"), [
    (lambda n: (np.ones(3), 0.0),
     r"^solver 'bad' returned forces of shape \(3,\) \(float64\) for a problem of (\d+) "
     r"segments; a solver returns F \[N\] of shape \(\1,\)"),
    (lambda n: "converged",
     r"^solver 'bad' returned str 'converged'; a solver returns a RawResult or \(force"),
    (lambda n: (np.ones(n), np.ones(2)),
     r"^solver 'bad' returned force array\(\[1\., .*… and rotation array\(\[1\., 1\.\]\); a "
     r"solver returns F \[N\], one number per segment, and one rotation"),
    (lambda n: ([[1.0], [1.0, 2.0]], 0.0), r"^solver 'bad' returned force \[\[1\.0\]"),
])
def test_a_solver_returning_the_wrong_shape_is_named(problem, returned, pattern):
    register_backend("bad", lambda p: returned(p.size), replace=True)
    try:
        with pytest.raises(PluginError, match=pattern) as info:
            solve_contact(problem, "bad")
    finally:
        unregister_backend("bad")
    assert "\n" not in str(info.value)


def test_a_solver_that_raises_is_a_failed_solve_naming_it(problem):
    """Raising is how a backend says it failed: an uncertified solution whose status
    names the backend (the analysis then fails, tests/test_failed_analysis.py)."""
    def diverges(p):
        raise FloatingPointError("ADMM diverged")

    register_backend("diverges", diverges, replace=True)
    try:
        sol = solve_contact(problem, "diverges")
    finally:
        unregister_backend("diverges")
    assert not sol.found
    assert sol.status == "failed: backend 'diverges' raised FloatingPointError: ADMM diverged"


def test_a_stop_inside_a_backend_is_not_a_failed_solve(problem):
    """A SIGTERM (the CLI's Terminated, a KeyboardInterrupt) or Ctrl-C that lands inside
    a compiled kernel reaches the caller as numba's ``SystemError`` chained to it: the
    solve raises the interrupt itself instead of reporting an unfound solution, which let
    `ltca synthesize` run to its end after SIGTERM (Round 25, docs/own_gear_set.md). A
    plain failure is still a failed solve (the test above)."""
    def stopped(p):
        try:
            raise KeyboardInterrupt("signal 15")
        except KeyboardInterrupt as stop:
            raise SystemError("CPUDispatcher(...) returned a result with an exception "
                              "set") from stop

    register_backend("stopped", stopped, replace=True)
    try:
        with pytest.raises(KeyboardInterrupt, match="signal 15"):
            solve_contact(problem, "stopped")
    finally:
        unregister_backend("stopped")


def test_ltca_run_with_a_solver_of_the_wrong_shape_is_one_line(tmp_path, capsys):
    register_backend("three_forces", lambda p: (np.ones(3), 0.0), replace=True)
    try:
        code = main(["run", "--solver", "three_forces", "--rolls-per-cycle", "4",
                     "--segments", "8", "--torque", "250", "--no-rating", "--no-root-stress",
                     "--no-progress",
                     "-o", str(tmp_path / "r.nc")])
    finally:
        unregister_backend("three_forces")
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1, err
    assert re.match(r"ltca run: error: solver 'three_forces' returned forces of shape "
                    r"\(3,\) \(float64\) for a problem of \d+ segments", err), err
    assert not RAW.search(err)
    assert not (tmp_path / "r.nc").exists()


# --------------------------------------------------------------------------- friction
def _boom(*, slide_to_roll):
    raise ZeroDivisionError("division by zero")


@pytest.mark.parametrize(("function", "pattern"), [
    (_boom, r"^friction model 'mu' raised ZeroDivisionError computing μ: division by zero"),
    (lambda *, slide_to_roll: np.array([0.05, 0.06, 0.07]),
     r"^friction model 'mu' returned ndarray of shape \(3,\) .* for inputs of shape \(2,\); "
     r"a model returns μ \[1\] as a number or an array of the inputs' shape"),
    (lambda *, slide_to_roll: -0.2 * np.ones_like(slide_to_roll),
     r"^friction model 'mu' returned a negative μ \(least -0\.2\); a sliding friction "
     r"coefficient is >= 0"),
    (lambda *, slide_to_roll: np.full_like(slide_to_roll, np.nan),
     r"^friction model 'mu' returned a non-finite μ \(2 of 2 values\)"),
    (lambda *, slide_to_roll: "low",
     r"^friction model 'mu' returned str 'low' for inputs of shape \(2,\)"),
    # issue 71 (plugin83): μ = 5 went into the efficiency (-120.51 %) and S_B (0.0405)
    (lambda *, slide_to_roll: 5.0 * np.ones_like(slide_to_roll),
     r"^friction model 'mu' returned friction_coefficient μ = 5 at 2 of 2 point\(s\); "
     r"accepted 0 <= μ <= 1 "),
    (lambda *, slide_to_roll: np.array([0.05, 1.2]),
     r"^friction model 'mu' returned friction_coefficient μ = 1\.2 at 1 of 2 point\(s\)"),
    (lambda *, slide_to_roll: np.array([0.05, np.inf]),
     r"^friction model 'mu' returned a non-finite μ \(1 of 2 values\)"),
    (lambda *, slide_to_roll: np.ones((2, 1)) * 0.05,
     r"^friction model 'mu' returned ndarray of shape \(2, 1\) .* for inputs of shape \(2,\)"),
])
def test_a_friction_model_failing_at_call_time_is_named(function, pattern):
    register_friction_model("mu", function, replace=True)
    try:
        with pytest.raises(PluginError, match=pattern) as info:
            friction_coefficient("mu", slide_to_roll=np.array([0.1, 0.3]))
    finally:
        unregister_friction_model("mu")
    assert "\n" not in str(info.value)


def test_a_good_friction_model_still_broadcasts():
    """The checks refuse what the contract refuses, nothing more: a scalar μ for array
    inputs broadcasts to their shape, as before."""
    register_friction_model("flat", lambda *, slide_to_roll, value=0.04: value,
                            replace=True)
    try:
        mu = friction_coefficient("flat", slide_to_roll=np.array([0.1, 0.2, 0.3]))
    finally:
        unregister_friction_model("flat")
    np.testing.assert_array_equal(mu, [0.04, 0.04, 0.04])


@pytest.mark.parametrize("top", [0.31, 0.6, 1.0])
def test_a_friction_coefficient_above_lubricated_steel_is_warned_not_refused(top):
    """Between :data:`MU_CAP` (0.3: no lubricated steel gear contact; boundary friction is
    0.1-0.15) and :data:`MU_MAX` (1: above dry steel on steel, ~0.8 static) μ is that of a
    dry contact: kept as returned — the exact values, no clipping — with a
    FrictionModelRangeWarning naming the model and the count, which the efficiency stage
    records in ``model_range_warnings``."""
    register_friction_model("mu", lambda *, slide_to_roll: np.array([0.05, top]),
                            replace=True)
    try:
        with pytest.warns(FrictionModelRangeWarning,
                          match=rf"^mu: friction_coefficient μ up to {top:g} above 0\.3 at "
                                r"1 of 2 point\(s\)"):
            mu = friction_coefficient("mu", slide_to_roll=np.array([0.1, 0.3]))
    finally:
        unregister_friction_model("mu")
    np.testing.assert_array_equal(mu, [0.05, top])


def test_the_bounds_hold_the_bundled_models_as_before():
    """The bounds are those of the bundled models: ``constant`` accepts its value up to 1
    (its own range, now :data:`MU_MAX`), and the regressions clip at :data:`MU_CAP`, so a
    bundled model is never refused by the new bound; at 0.3 exactly, no warning."""
    assert MU_MAX == 1.0 and MU_CAP == 0.3
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert friction_coefficient("constant", value=0.3) == 0.3
    with pytest.warns(FrictionModelRangeWarning, match=r"^constant: friction_coefficient μ"):
        assert friction_coefficient("constant", value=1.0) == 1.0


def test_ltca_run_with_a_friction_coefficient_of_five_is_one_line(tmp_path, capsys):
    """Before plugin83 this run printed an efficiency of -120.51 % and a scuffing safety S_B
    of 0.0405 and wrote its file (exit 0)."""
    register_friction_model("mu5", lambda *, slide_to_roll: 5.0 * np.ones_like(slide_to_roll),
                            replace=True)
    try:
        code = main(["run", "--friction-model", "mu5", "--rolls-per-cycle", "4",
                     "--segments", "8", "--torque", "250", "--no-rating", "--no-root-stress",
                     "--no-progress", "-o", str(tmp_path / "r.nc")])
    finally:
        unregister_friction_model("mu5")
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert re.fullmatch(r"ltca run: error: friction model 'mu5' returned friction_coefficient "
                        r"μ = 5 at \d+ of \d+ point\(s\); accepted 0 <= μ <= 1 .*", err), err
    assert not (tmp_path / "r.nc").exists()


def test_ltca_run_with_a_friction_model_that_raises_is_one_line(tmp_path, capsys):
    register_friction_model("boom", _boom, replace=True)
    try:
        code = main(["run", "--friction-model", "boom", "--rolls-per-cycle", "4",
                     "--segments", "8", "--torque", "250", "--no-rating", "--no-root-stress",
                     "--no-progress",
                     "-o", str(tmp_path / "r.nc")])
    finally:
        unregister_friction_model("boom")
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert err == ("ltca run: error: friction model 'boom' raised ZeroDivisionError "
                   "computing μ: division by zero (docs/extending.md)")


# --------------------------------------------------------------------------- compliance
def _raises_in_prepare(case, easeoff, options):
    raise MemoryError("no room for the stiffness matrix")


def _raises_in_assembler(case, easeoff, options):
    def assemble(batch):
        raise IndexError("list index out of range")
    return assemble


def _negative_diagonal(case, easeoff, options):
    shell = shell_assembler(case, easeoff, options)

    def assemble(batch):
        return [(-c, info) for c, info in shell(batch)]
    return assemble


@pytest.mark.parametrize(("prepare", "pattern"), [
    (_raises_in_prepare, r"^compliance: model 'teeth' raised MemoryError in prepare: no room "
                         r"for the stiffness matrix"),
    (_raises_in_assembler, r"^compliance: model 'teeth' raised IndexError in its assembler: "
                           r"list index out of range"),
    (lambda case, easeoff, options: 42,
     r"^compliance: model 'teeth' prepare returned int 42, not an assembler"),
    (_negative_diagonal, r"^compliance: model 'teeth' gave a compliance with a diagonal "
                         r"entry <= 0"),
])
def test_a_compliance_model_failing_at_call_time_is_named(prepare, pattern):
    from contact.pipeline import run_analysis

    register_compliance_model("teeth", prepare, replace=True)
    try:
        with pytest.raises(ComplianceModelError, match=pattern) as info:
            run_analysis(None, 250.0, options=LTCAOptions(rolls_per_cycle=4, segments=8,
                                                          compliance="teeth"),
                         operating=False, geometry=False, mesh_interface=False)
    finally:
        unregister_compliance_model("teeth")
    assert isinstance(info.value, PluginError) and isinstance(info.value, LTCAError)
    assert "\n" not in str(info.value)


# --------------------------------------------------------------------------- install hints
def test_install_hints_serve_a_clone_and_an_installed_package(monkeypatch):
    """``pip install 'hypoid-ltca[solvers]'`` installs the release from PyPI; in a clone
    the extra of the clone is ``pip install '.[solvers]'``: both are printed."""
    from contact.qp import solvers

    assert SOLVERS_EXTRA == ("pip install 'hypoid-ltca[solvers]', from a clone: pip install "
                             "'.[solvers]'")
    monkeypatch.setitem(solvers.KNOWN_BACKENDS, "nosuchqp", "nosuchqp-dist")
    with pytest.raises(LTCAError) as info:
        solvers.get_backend("nosuchqp")
    assert "pip install 'hypoid-ltca[solvers]'" in str(info.value)
    assert "from a clone: pip install '.[solvers]'" in str(info.value)
