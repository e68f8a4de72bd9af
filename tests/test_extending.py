"""The open extension points (issue 54 item 4, docs/extending.md): a user's own solver
backend, friction-coefficient model and tooth compliance model, registered from outside
the package, each run a default analysis.

"A default analysis" is ``run_analysis`` of the default case with every default but the
discretisation (4 rolls per cycle, 8 segments per curve: the smallest the options accept
give the same stages, a tenth of the time) and one torque, without the root stress (its
FE coefficients are not the subject).

Independent references, one per extension point:

* solver — the toolkit's exact ``active_set`` on the same analysis: the user's solver
  below is an exact active-set method of its own (three sets: open, loaded, at the force
  limit; LU of the KKT system), so both reach the same contact sets and agree to
  round-off;
* friction model — the bundled ``constant`` model (Coleman's μ = 0.05): a user's model that
  returns 0.05 everywhere gives the same efficiency, exactly (the same arithmetic);
* compliance model — the bundled ``shell`` model: a user's model that returns the shell's
  matrices gives the same LTCA bit for bit; one that halves the structural part (stiffer
  teeth) about halves the loaded transmission error's structural part.

Plug-ins are checked through importlib.metadata with a distribution written to a temporary
directory: its three entry points are found by name, in this process and by ``ltca run``.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from contact.ltca import LTCAOptions
from contact.ltca.compliance_models import (
    available_compliance_models,
    register_compliance_model,
    shell_assembler,
    unregister_compliance_model,
)
from contact.pipeline import run_analysis
from contact.qp import available_solvers
from contact.qp.solvers import RawResult, register_backend, unregister_backend
from friction.coefficient import (
    available_friction_models,
    friction_coefficient,
    register_friction_model,
    unregister_friction_model,
)
from friction.operating import OperatingConditions
from geometry.core.caches import clear_caches
from geometry.core.errors import InputError, ModelUnavailableError

ROOT = Path(__file__).resolve().parents[1]
SMALL = {"rolls_per_cycle": 4, "segments": 8}
TORQUE = 250.0

#: [1] relative tolerance for "the same model reached through another name": the arithmetic
#: is the same, but a registered or entry-point model is called through another path whose
#: floating-point sums may be ordered differently (CI measured 1.8e-15 on the efficiency);
#: 1e-12 is ~4500 ulps, six orders below the smallest physical difference these tests
#: guard (another friction model moves the efficiency by ~1e-3, another compliance the TE
#: by ~1e-2)
SAME_MODEL_RTOL = 1e-12


def _same(actual, desired) -> None:
    """Two results of the same model through two names agree to :data:`SAME_MODEL_RTOL`."""
    np.testing.assert_allclose(actual, desired, rtol=SAME_MODEL_RTOL, atol=0.0)



def _analysis(options: LTCAOptions | None = None, operating: OperatingConditions | None = None):
    return run_analysis(None, TORQUE, options=options or LTCAOptions(**SMALL),
                        operating=operating, root_stress=False)


@pytest.fixture(scope="module")
def reference():
    """The default analysis with the bundled choices, the friction model ``constant``."""
    return _analysis(operating=OperatingConditions(friction_model="constant"))


# --------------------------------------------------------------------------- the user's code
def user_active_set(problem):
    """A user's exact solver of the contact QP: an active-set method on three sets (open,
    loaded, at the force limit), one swap per step (the most violated condition), the KKT
    system of the loaded set solved by LU. Returns (F [N], Θ [rad])."""
    C, s, R, T = problem.compliance, problem.separation, problem.moment_arm, problem.torque
    n = s.size
    upper = np.asarray(problem.upper_bound, float)
    tol = 1e-10 * problem.scale.length
    state = np.ones(n, int)  # 0 open, 1 loaded, 2 at its limit
    for _ in range(20 * n):
        loaded, at_limit = np.flatnonzero(state == 1), state == 2
        F = np.where(at_limit, upper, 0.0)
        if loaded.size == 0:
            state[np.argmin(s)] = 1
            continue
        K = np.zeros((loaded.size + 1, loaded.size + 1))
        K[:-1, :-1] = C[np.ix_(loaded, loaded)]
        K[:-1, -1] = -R[loaded]
        K[-1, :-1] = R[loaded]
        rhs = np.append(-s[loaded] - C[loaded] @ F, T - R @ F)
        x = np.linalg.solve(K, rhs)
        F[loaded], theta = x[:-1], x[-1]
        if F[loaded].min() < 0.0:
            state[loaded[np.argmin(F[loaded])]] = 0
            continue
        over = F[loaded] - upper[loaded]
        if over.max() > 0.0:
            state[loaded[np.argmax(over)]] = 2
            continue
        gap = C @ F + s - R * theta
        wrong = np.where(state == 0, -gap, np.where(at_limit, gap, 0.0))
        if wrong.max() <= tol:
            return F, float(theta)
        state[np.argmax(wrong)] = 1
    return RawResult(None, None, False, "no convergence", 0.0, 0.0)


def coleman(*, hertz_pressure):
    """A user's friction model: Coleman's constant μ = 0.05 [1] (as the bundled
    ``constant``), written as a function of the segments' Hertz pressure [MPa]."""
    return np.full(np.shape(hertz_pressure), 0.05)


def scaled_shell(factor):
    """A user's compliance model: the shell model's structural compliance times
    ``factor`` (Weber's term and depths as the shell's)."""

    def prepare(case, easeoff, options):
        shell = shell_assembler(case, easeoff, options)

        def assemble(batch):
            out = []
            for total, info in shell(batch):
                structural = total - info["weber"]
                out.append((factor * structural + info["weber"], info))
            return out

        return assemble

    prepare.__name__ = f"shell_times_{factor:g}"
    return prepare


# --------------------------------------------------------------------------- solvers
def test_a_registered_backend_runs_a_default_analysis(reference):
    backend = register_backend("user_active_set", user_active_set, family="active-set")
    try:
        assert "user_active_set" in available_solvers()
        tree = _analysis(LTCAOptions(**SMALL, solver="user_active_set"),
                         OperatingConditions(friction_model="constant"))
    finally:
        unregister_backend("user_active_set")
    assert backend.name == "user_active_set"
    assert "user_active_set" not in available_solvers()
    lt, ref = tree["ltca"], reference["ltca"]
    assert tree.attrs["solver"] == lt.attrs["solver"] == "user_active_set"
    assert bool(lt["found"].all())
    # two exact methods on the same KKT systems: round-off (measured 1e-13 µrad, 6e-15 of
    # the largest force)
    np.testing.assert_allclose(lt["transmission_error"], ref["transmission_error"], rtol=0,
                               atol=1e-9)
    f_max = float(ref["force"].max())
    np.testing.assert_allclose(lt["force"].fillna(0), ref["force"].fillna(0), rtol=0,
                               atol=1e-10 * f_max)


def test_a_solve_function_stands_where_a_solver_name_does(reference):
    """No registration: the function itself as ``LTCAOptions.solver``, recorded by name."""
    tree = _analysis(LTCAOptions(**SMALL, solver=user_active_set),
                     OperatingConditions(friction_model="constant"))
    assert tree["ltca"].attrs["solver"] == "user_active_set"
    assert '"solver": "user_active_set"' in tree["ltca"].attrs["options"]
    np.testing.assert_allclose(tree["ltca"]["transmission_error"],
                               reference["ltca"]["transmission_error"], rtol=0, atol=1e-9)


def test_backend_registration_refuses_bad_input():
    with pytest.raises(InputError, match="name: 'active_set' is the toolkit's reference"):
        register_backend("active_set", user_active_set)
    with pytest.raises(InputError, match="name: must be a non-empty name without spaces"):
        register_backend("my solver", user_active_set)
    with pytest.raises(InputError, match="solve: must be callable"):
        register_backend("x", 3)
    with pytest.raises(InputError, match=r"solve: parameter\(s\) \['tolerance'\]"):
        register_backend("x", lambda problem, *, tolerance: None)
    with pytest.raises(InputError, match="takes \\*args"):
        register_backend("x", lambda problem, *args: None)
    with pytest.raises(InputError, match="name: a solver 'osqp' is registered already"):
        register_backend("osqp", user_active_set)
    with pytest.raises(InputError, match="was not registered"):
        unregister_backend("osqp")


# --------------------------------------------------------------------------- friction models
def test_a_registered_friction_model_runs_a_default_analysis(reference):
    register_friction_model("user_coleman", coleman, source="Coleman (1975)")
    try:
        assert "user_coleman" in available_friction_models()
        tree = _analysis(operating=OperatingConditions(friction_model="user_coleman"))
    finally:
        unregister_friction_model("user_coleman")
    fr, ref = tree["friction"], reference["friction"]
    assert fr.attrs["friction_model"] == "user_coleman"
    assert 'friction_model = "user_coleman"' in tree.attrs["inputs"]
    _same(fr["efficiency"], ref["efficiency"])
    _same(fr["friction_coefficient"], ref["friction_coefficient"])


def test_a_model_function_stands_where_a_friction_model_name_does(reference):
    tree = _analysis(operating=OperatingConditions(friction_model=coleman))
    assert tree["friction"].attrs["friction_model"] == "coleman"
    _same(tree["friction"]["efficiency"],
                                  reference["friction"]["efficiency"])
    assert friction_coefficient(coleman, hertz_pressure=[900.0, 1200.0],
                                slide_to_roll=0.3) == pytest.approx([0.05, 0.05])


def test_friction_registration_checks_as_the_bundled_models_are():
    """The same checks as the bundled models pass at import: keyword inputs, required
    ones from the vocabulary, a validity function on the model's inputs."""
    with pytest.raises(InputError, match=r"requires \['pressure'\], which are not inputs"):
        register_friction_model("x", lambda *, pressure: 0.05)
    with pytest.raises(InputError, match=r"takes \*\*kw; name its inputs"):
        register_friction_model("x", lambda **kw: 0.05)
    with pytest.raises(InputError, match="positional-only"):
        register_friction_model("x", lambda hertz_pressure, /: 0.05)
    with pytest.raises(InputError, match="name: 'xu2007' is a bundled friction model"):
        register_friction_model("xu2007", coleman)
    with pytest.raises(InputError, match="name: 'kolivand2009_table_5_3' is a bundled"):
        register_friction_model("kolivand2009_table_5_3", coleman)
    with pytest.raises(InputError, match=r"validity: .* requires \['radius'\]"):
        register_friction_model("x", coleman, validity=lambda *, radius: radius > 0)
    with pytest.raises(InputError, match=r"^friction_model: function: "):
        OperatingConditions(friction_model=lambda *, pressure: 0.05)
    register_friction_model("user_twice", coleman)
    try:
        with pytest.raises(InputError, match="registered already; pass replace=True"):
            register_friction_model("user_twice", coleman)
        register_friction_model("user_twice", coleman, replace=True)
    finally:
        unregister_friction_model("user_twice")
    with pytest.raises(ModelUnavailableError, match="unknown friction model 'user_twice'"):
        OperatingConditions(friction_model="user_twice")


# --------------------------------------------------------------------------- compliance models
def test_a_registered_compliance_model_runs_a_default_analysis(reference):
    register_compliance_model("user_shell", scaled_shell(1.0), description="the shell, again")
    try:
        assert "user_shell" in available_compliance_models()
        tree = _analysis(LTCAOptions(**SMALL, compliance="user_shell"),
                         OperatingConditions(friction_model="constant"))
    finally:
        unregister_compliance_model("user_shell")
    lt, ref = tree["ltca"], reference["ltca"]
    assert '"compliance": "user_shell"' in lt.attrs["options"]
    _same(lt["transmission_error"], ref["transmission_error"])
    _same(lt["force"], ref["force"])


def test_a_preparation_stands_where_a_compliance_model_name_does(reference):
    """The shell's structural compliance times 0.5 and times 0 (rigid teeth, Weber's term
    alone), each as the preparation function itself: the mean LTE falls with the factor,
    and its structural part (over the rigid teeth') about halves at 0.5 — exactly half
    for one loaded segment, off by the load sharing's change elsewhere (measured 0.53 on
    this case; the band 0.4–0.65 allows that, not a model that ignores the factor)."""
    lte = {}
    for factor in (0.5, 0.0):
        tree = _analysis(LTCAOptions(**SMALL, compliance=scaled_shell(factor)),
                         OperatingConditions(friction_model="constant"))
        assert f'"compliance": "shell_times_{factor:g}"' in tree["ltca"].attrs["options"]
        lte[factor] = float(tree["ltca"]["lte_mean"][0])
    lte[1.0] = float(reference["ltca"]["lte_mean"][0])
    assert lte[0.0] < lte[0.5] < lte[1.0]
    assert 0.4 < (lte[0.5] - lte[0.0]) / (lte[1.0] - lte[0.0]) < 0.65


def test_compliance_registration_refuses_bad_input():
    with pytest.raises(InputError, match="name: 'fe' is a bundled compliance model"):
        register_compliance_model("fe", scaled_shell(1.0))
    with pytest.raises(InputError, match="must take 3 positional argument"):
        register_compliance_model("x", lambda case, easeoff: None)
    with pytest.raises(InputError, match=r"^compliance: unknown compliance model 'beam'"):
        LTCAOptions(compliance="beam")
    with pytest.raises(InputError, match="compliance: model 'broken' gave no"):
        _analysis(LTCAOptions(**SMALL, compliance=_broken))


def _broken(case, easeoff, options):
    def assemble(batch):
        return [(np.eye(seg.size), {}) for seg in batch]

    return assemble


_broken.__name__ = "broken"


# --------------------------------------------------------------------------- in a study
def test_a_study_takes_the_functions_and_records_their_names(tmp_path, reference):
    """A one-point sweep (in this process) with the user's solver, compliance preparation
    and friction function: the point is the default analysis' and the study's file names
    them (a function's name, not its object, goes into the netCDF attributes)."""
    from contact.catalogue import resolve_case
    from contact.study import StudyRun, sweep
    from geometry.core.io import read_netcdf, write_netcdf

    case = resolve_case(None)
    run = StudyRun(options=LTCAOptions(**SMALL, solver=user_active_set,
                                       compliance=scaled_shell(1.0)),
                   operating=OperatingConditions(friction_model=coleman),
                   scheduler="synchronous", root_stress=False)
    grid = sweep(case, delta_E=[float(case.misalignment.delta_E)], torque=TORQUE,
                 pinion_speed=1500.0, run=run)
    assert (grid["status"].values == 0).all()
    # the point is the default analysis: LTE to round-off (exact solvers, the same shell
    # matrices), the efficiency of μ = 0.05 as the bundled constant model's, to round-off
    # (the same sums over segments and rolls; the plug-in's μ passes through the plug-in
    # checks as a copy, which may change the order of a sum's last bit: 1e-16 measured)
    assert float(grid["lte_mean"].squeeze()) == pytest.approx(
        float(reference["ltca"]["lte_mean"][0]), rel=1e-12)
    assert float(grid["efficiency"].squeeze()) == pytest.approx(
        float(reference["friction"]["efficiency_mean"][0]), rel=1e-12)
    back = read_netcdf(write_netcdf(grid, tmp_path / "sweep.nc"))
    assert back.attrs["solver"] == "user_active_set"


PLUGIN = '''
"""A plug-in of hypoid-ltca: a solver, a friction model and a compliance model."""
import numpy as np

from contact.ltca.compliance_models import shell_assembler
from contact.qp.solvers import get_backend


def solve(problem, *, accuracy="high"):
    return get_backend("active_set").solve(problem, accuracy=accuracy)


def mu(*, hertz_pressure):
    return np.full(np.shape(hertz_pressure), 0.05)


def shell(case, easeoff, options):
    return shell_assembler(case, easeoff, options)
'''


@pytest.fixture
def plugin(tmp_path, monkeypatch):
    """A distribution ``hypoid-ltca-plugin`` on sys.path advertising one entry in each of
    the three groups; the registries' plug-in memos emptied before and after."""
    (tmp_path / "hypoid_ltca_plugin.py").write_text(PLUGIN)
    info = tmp_path / "hypoid_ltca_plugin-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: hypoid-ltca-plugin\n"
                                   "Version: 1.0\n")
    (info / "entry_points.txt").write_text(textwrap.dedent("""\
        [hypoid_ltca.solvers]
        plugin_solver = hypoid_ltca_plugin:solve

        [hypoid_ltca.friction_models]
        plugin_mu = hypoid_ltca_plugin:mu

        [hypoid_ltca.compliance_models]
        plugin_shell = hypoid_ltca_plugin:shell
        """))
    monkeypatch.syspath_prepend(str(tmp_path))
    clear_caches()
    yield tmp_path
    monkeypatch.undo()
    sys.modules.pop("hypoid_ltca_plugin", None)
    clear_caches()


def test_plugins_are_found_through_their_entry_points(plugin, reference):
    assert "plugin_solver" in available_solvers()
    assert "plugin_mu" in available_friction_models()
    assert "plugin_shell" in available_compliance_models()
    tree = _analysis(LTCAOptions(**SMALL, solver="plugin_solver", compliance="plugin_shell"),
                     OperatingConditions(friction_model="plugin_mu"))
    assert tree.attrs["solver"] == "plugin_solver"
    assert tree["friction"].attrs["friction_model"] == "plugin_mu"
    _same(tree["friction"]["efficiency"],
                                  reference["friction"]["efficiency"])


def test_ltca_run_finds_the_plugins(plugin, tmp_path):
    """The command line takes the plug-ins' names (it registers nothing itself)."""
    out = tmp_path / "r.nc"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(plugin), str(ROOT)])}
    run = subprocess.run(
        [sys.executable, "-m", "contact", "run", "--torque", str(TORQUE), "--rolls-per-cycle",
         "4", "--segments", "8", "--no-root-stress", "--no-progress", "--solver",
         "plugin_solver", "--friction-model", "plugin_mu", "--compliance", "plugin_shell",
         "-o", str(out)], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    import xarray as xr

    with xr.open_datatree(out) as tree:
        assert tree.attrs["solver"] == "plugin_solver"
        assert tree["friction"].attrs["friction_model"] == "plugin_mu"
        assert '"compliance": "plugin_shell"' in tree["ltca"].attrs["options"]


def test_the_page_examples_run():
    """docs/extending.md's Python examples (a backend, a friction model, a compliance model
    and a load-capacity rating method registered, used and removed) run as printed, each in
    a namespace of its own."""
    import re

    page = (ROOT / "docs" / "extending.md").read_text(encoding="utf-8")
    examples = re.findall(r"```python\n(.*?)```", page, flags=re.S)
    assert len(examples) == 4
    for i, code in enumerate(examples):
        exec(compile(code, f"docs/extending.md example {i + 1}", "exec"), {})
    assert "projected_gradient" not in available_solvers()
    assert "stiffer_teeth" not in available_compliance_models()
    from contact import available_rating_methods

    assert "mean_point_forces" not in available_rating_methods()
