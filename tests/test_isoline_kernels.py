"""The compiled iso-line kernels (contact.utca.isoline_numba) against the NumPy path.

The kernels repeat, point by point, the steps of the NumPy reference
(:class:`contact.utca.fields.EaseOffFields` and the contact curves' end search) on the
splines in piecewise-polynomial form (:mod:`contact.utca.piecewise`), so the references
here are independent implementations:

- the piecewise-polynomial splines and their partial derivatives against SciPy's FITPACK
  (``RectBivariateSpline.ev``, the de Boor–Cox recurrence), on random places inside, on
  and beyond the knots;
- the contact curves' places, ε and UTE of a real ease-off, and a study point's summaries,
  computed with ``kernels="numpy"`` and ``kernels="numba"``.

Tolerance: the polynomial form and FITPACK's recurrence are two round-off paths to the
same spline; measured ≤ 1e-15 of the spline's scale apart (16 terms, a few units in the
last place each), taken as 1e-13 (``SPLINE_RTOL``). The iterations stop at |ΔQ| < 1e-13
rad, so the places agree to that over the slope of Q (``PLACE_TOL``), and a study
point's summaries to the 5×5 guard's 1e-9.
"""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import RectBivariateSpline

from contact.utca import piecewise
from contact.utca.fields import EaseOffFields, kernels_module
from geometry.core import kernels as kernels_core
from geometry.core.errors import InputError

numba_kernels = pytest.importorskip("contact.utca.isoline_numba",
                                    reason="numba (the 'fast' extra) is not installed")

ROOT = Path(__file__).resolve().parents[1]
SPLINE_RTOL = 1e-13
# places solved on either spline: Newton stops at |ΔQ| < 1e-13 rad, and |∂Q/∂v| ≥ 0.0057
# rad per unit of v on the valid nodes of the cases here (least: ISO sample 2 at its
# extreme mounting; median 0.6–0.8), so two iterates can stop ≤ 1.8e-11 apart
PLACE_TOL = 2e-11


def _random_spline(seed=3):
    rng = np.random.default_rng(seed)
    u = np.sort(np.r_[0.0, rng.random(39), 1.0])  # uneven lengthwise nodes
    v = np.linspace(-0.1, 1.1, 21)
    return RectBivariateSpline(u, v, rng.standard_normal((41, 21))), u, v, rng


@pytest.mark.parametrize("order", [(0, 0), (1, 0), (0, 1), (1, 1), (2, 0), (0, 2)])
def test_spline_kernel_is_fitpack(order):
    """The piecewise-polynomial form's values and partial derivatives at 20,000 places, a
    tenth of them on nodes and a fifth beyond the grid (FITPACK clamps them to its ends),
    as ``RectBivariateSpline.ev`` of each of two splines on the same knots."""
    s, u, v, rng = _random_spline()
    s2 = RectBivariateSpline(u, v, rng.standard_normal((41, 21)) * 1e3 + 5.0)
    x = rng.uniform(-0.2, 1.2, 20_000)
    y = rng.uniform(-0.3, 1.3, 20_000)
    x[:1000] = u[rng.integers(0, u.size, 1000)]
    y[1000:2000] = v[rng.integers(0, v.size, 1000)]
    base = piecewise.from_splines([s, s2], numba_kernels)
    # the compiled sums and NumPy's (the same terms in another order)
    ref = piecewise.from_splines([s, s2]).coefficients
    scale = np.abs(ref).max(axis=(0, 1), keepdims=True)  # per spline and power
    assert np.max(np.abs(base.coefficients - ref) / scale) < SPLINE_RTOL
    pp = piecewise.derivative(base, *order)
    got = numba_kernels.ev(pp.bx, pp.by, pp.coefficients, x, y)
    assert got.shape == (x.size, 2)
    for k, spline in enumerate((s, s2)):
        want = spline.ev(x, y, dx=order[0], dy=order[1])
        scale = np.max(np.abs(want))
        np.testing.assert_allclose(got[:, k], want, rtol=SPLINE_RTOL,
                                   atol=SPLINE_RTOL * scale)


def test_piecewise_form_rejects_what_it_cannot_represent():
    """An order beyond the degree, splines on different knots, no splines: ValueErrors
    that name the argument."""
    s, u, v, rng = _random_spline()
    pp = piecewise.from_splines([s])
    assert pp.coefficients.shape == (u.size - 1 - 2, v.size - 1 - 2, 1, 4, 4)
    with pytest.raises(ValueError, match="nux, nuy"):
        piecewise.derivative(pp, 4, 0)
    other = RectBivariateSpline(u, np.linspace(-0.1, 1.1, 23), rng.random((41, 23)))
    with pytest.raises(ValueError, match="same knots"):
        piecewise.from_splines([s, other])
    with pytest.raises(ValueError, match="at least one"):
        piecewise.from_splines([])


@pytest.fixture(scope="module")
def easeoff():
    from contact.utca.easeoff import ease_off
    from geometry.case import load_case

    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41_reference.toml")
    # misaligned off the mounting: the curves end on the tip, the blank margin and the toe
    mis = dataclasses.replace(case.misalignment, delta_E=case.misalignment.delta_E - 0.12,
                              delta_P=case.misalignment.delta_P - 0.08)
    return ease_off(dataclasses.replace(case, misalignment=mis))


def test_contact_curves_agree(easeoff):
    """The places, ε and UTE of 80 iso-lines over two mesh cycles (curve ends inside the
    region, on its boundary and at jumps of the measure; short curves), both paths."""
    from contact.utca import CURVE_SPACINGS, transitions
    from contact.utca.contact_curves import _seed_places

    eo = easeoff
    m1, _ = transitions(eo)
    t = m1 + np.linspace(-1.5, 0.5, 80) * eo.pitch
    frac = CURVE_SPACINGS["cosine"](17)
    got = _seed_places(EaseOffFields(eo, kernels="numba"), t, frac)
    want = _seed_places(EaseOffFields(eo, kernels="numpy"), t, frac)
    assert np.isfinite(want.ute).sum() >= 40  # not vacuous: most targets have a curve
    for name in ("u", "v", "ease_off_angle", "ute", "contact_u", "contact_v"):
        a, b = getattr(got, name), getattr(want, name)
        np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b), err_msg=name)
        np.testing.assert_allclose(a, b, rtol=PLACE_TOL, atol=PLACE_TOL, err_msg=name)
    np.testing.assert_array_equal(got.index, want.index)


@pytest.mark.parametrize("name, d_e, d_p", [
    ("kolivand2009_fh_12x41_reference", 0.2, -0.2),
    ("iso23509_sample2_fm", -0.2, 0.2),
    ("kolivand2009_fm_11x41_reference", 0.2, -0.2)])
def test_second_order_curves_agree(name, d_e, d_p):
    """The whole contact-curve evaluation (coarse runs, short curves, ends, samples,
    lowest point; first and second order) of 301 iso-lines over eight pitches, on a
    face-hobbed pair and on ISO sample 2 at extreme mountings, both paths."""
    from contact.catalogue import resolve_case
    from contact.study.points import misalignment_of
    from contact.utca import CURVE_SPACINGS
    from contact.utca.contact_curves import _curves_second_order
    from contact.utca.easeoff import ease_off

    case = resolve_case(name)
    m0 = case.misalignment
    mis = misalignment_of(m0, {"delta_E": m0.delta_E + d_e, "delta_P": m0.delta_P + d_p})
    eo = ease_off(dataclasses.replace(case, misalignment=mis))
    fk, fn = EaseOffFields(eo, kernels="numba"), EaseOffFields(eo, kernels="numpy")
    t = float(np.nanmedian(eo.roll_angle)) + np.linspace(-4.0, 4.0, 301) * eo.pitch
    frac = CURVE_SPACINGS["cosine"](41)
    got, want = _curves_second_order(fk, t, frac), _curves_second_order(fn, t, frac)
    assert 60 <= np.isfinite(want.ute).sum() < t.size  # curves, and targets without one
    for field in ("u", "v", "ease_off_angle", "ute", "shift", "contact_u", "contact_v",
                  "position", "normal"):
        a, b = getattr(got, field), getattr(want, field)
        np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b), err_msg=field)
        np.testing.assert_allclose(a, b, rtol=PLACE_TOL, atol=PLACE_TOL, err_msg=field)
    np.testing.assert_array_equal(got.index, want.index)


def test_field_queries_agree(easeoff):
    """newton_v, measure and solve_columns on their own: places on, inside and beyond
    the grid, NaN places, targets the iso-lines miss."""
    eo = easeoff
    fk, fn = EaseOffFields(eo, kernels="numba"), EaseOffFields(eo, kernels="numpy")
    rng = np.random.default_rng(7)
    u = rng.uniform(-0.05, 1.05, 3000)
    v = rng.uniform(-0.05, 1.05, 3000)
    v[::17] = np.nan
    np.testing.assert_allclose(fk.measure(u, v), fn.measure(u, v), rtol=SPLINE_RTOL,
                               atol=SPLINE_RTOL)
    q = fn.q.ev(np.clip(u, 0, 1), np.clip(np.nan_to_num(v, nan=0.5), 0, 1))
    t = q + rng.normal(0.0, 0.002, q.size)
    start = np.full(u.size, 0.5)
    a, b = fk.newton_v(u, t, start.copy()), fn.newton_v(u, t, start.copy())
    np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b))
    assert np.isfinite(b).sum() > 1000
    np.testing.assert_allclose(a, b, rtol=PLACE_TOL, atol=PLACE_TOL)
    uc = np.linspace(0.0, 1.0, 81)
    tc = np.linspace(np.nanmin(q) - 0.01, np.nanmax(q) + 0.01, 60)
    a, b = fk.solve_columns(uc, tc), fn.solve_columns(uc, tc)
    np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b))
    assert np.isfinite(b).any() and not np.isfinite(b).all()
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("order", [(0, 0), (1, 0), (0, 1), (2, 0)])
def test_field_values_share_the_basis(easeoff, order):
    """EaseOffFields.values: ten fields on one basis per place (compiled) against each
    field's own ``RectBivariateSpline.ev`` (the NumPy path), at places inside and beyond
    the grid, in the shape of the places; an unknown name is an InputError."""
    fk, fn = EaseOffFields(easeoff, kernels="numba"), EaseOffFields(easeoff, kernels="numpy")
    rng = np.random.default_rng(11)
    u = rng.uniform(-0.05, 1.05, (40, 50))
    v = rng.uniform(-0.05, 1.05, (40, 50))
    names = ("q", "eps", "arm", "pos", "nrm", "margin")
    got = fk.values(names, u, v, *order)
    want = fn.values(names, u, v, *order)
    assert got.shape == want.shape == (40, 50, 10)
    splines = [fn.q, fn.eps, fn.arm, *fn.pos, *fn.nrm, fn.margin]
    value = fn.values(names, u, v)
    # the round-off of a derivative is the values' (a few units in the last place of
    # their scale) over the grid step to the derivative's order
    step = 1.0 / (np.min(np.diff(fn.u)) ** order[0] * np.min(np.diff(fn.v)) ** order[1])
    for k, spline in enumerate(splines):
        np.testing.assert_array_equal(want[..., k], spline.ev(u, v, *order))
        scale = max(np.max(np.abs(want[..., k])), np.max(np.abs(value[..., k])) * step)
        np.testing.assert_allclose(got[..., k], want[..., k], rtol=SPLINE_RTOL,
                                   atol=SPLINE_RTOL * scale)
    with pytest.raises(InputError, match="names: must be among"):
        fk.values(("q", "curvature"), u, v)


def test_a_study_point_is_the_same_on_both_paths(monkeypatch):
    """A study point's 21 summaries (LTE, pattern, pressures, efficiency) with either
    path, within the 5×5 guard's 1e-9 (tests/test_sweep_guard.py)."""
    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs
    from geometry.core.caches import clear_caches

    case = resolve_case("kolivand2009_fm_11x41_reference")
    shared = StudyInputs(case=case, torque=(250.0,),
                         options=LTCAOptions(rolls_per_cycle=8, segments=8))
    point = {"delta_E": case.misalignment.delta_E - 0.12,
             "delta_P": case.misalignment.delta_P - 0.08}
    out = {}
    for kernels in ("numpy", "numba"):
        monkeypatch.setenv("LTCA_KERNELS", kernels)
        clear_caches()  # each path computes its own ease-off and unloaded cycle (memoised)
        out[kernels] = analyse_point(shared, 0, point)
    a, b = out["numba"], out["numpy"]
    assert a.status == b.status == 0
    assert set(a.summary) == set(b.summary) and len(a.summary) >= 20
    for name in a.summary:
        x, y = np.asarray(a.summary[name], float), np.asarray(b.summary[name], float)
        np.testing.assert_allclose(x, y, rtol=1e-9, atol=1e-9 * np.nanmax(np.abs(y),
                                                                          initial=1.0),
                                   err_msg=name)


def test_kernels_choice(monkeypatch):
    """The names, the environment variable, and the errors that name the field."""
    monkeypatch.delenv("LTCA_KERNELS", raising=False)
    assert kernels_module() is numba_kernels  # installed: the default
    # auto: numba where its cache holds the kernels for this machine
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: True)
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})  # a new process's first choice
    assert kernels_module("auto") is numba_kernels
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: False)
    assert kernels_module("auto") is numba_kernels  # decided once per process: kept
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})
    assert kernels_module("auto") is None  # not compiled yet: one analysis does not pay
    monkeypatch.setenv("LTCA_KERNELS", "auto")
    assert kernels_module() is None
    assert kernels_module("numba") is numba_kernels  # asked for: compiled on first use
    monkeypatch.setenv("LTCA_KERNELS", "numba")
    assert kernels_module() is numba_kernels
    monkeypatch.delenv("LTCA_KERNELS")
    assert kernels_module("numpy") is None
    monkeypatch.setenv("LTCA_KERNELS", "numpy")
    assert kernels_module() is None
    monkeypatch.setenv("LTCA_KERNELS", "fortran")
    with pytest.raises(InputError, match="LTCA_KERNELS: must be one of numpy, numba"):
        kernels_module()
    with pytest.raises(InputError, match="kernels: must be one of"):
        kernels_module("cuda")
    monkeypatch.setattr(kernels_core, "compiled_module", lambda name: None)
    with pytest.raises(InputError, match=r"kernels: 'numba' needs numba installed"):
        kernels_module("numba")
    monkeypatch.delenv("LTCA_KERNELS")
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})
    assert kernels_module() is None  # not installed: the NumPy path, silently


def test_a_synthesis_compiles_only_the_kernels_that_pay(monkeypatch):
    """``ltca synthesize`` on a fresh numba cache compiles the envelope's kernels only (they
    earn their ~10 s of compiling back within one synthesis, the iso-lines', the shell's
    and the block pivoting's ~17 s do not: docs/performance.md, issue 75): ``auto`` with
    the envelope compiled, the others NumPy; numba throughout where the cache holds all
    four; a user's ``LTCA_KERNELS`` wins; the note names the geometry's compile only."""
    import argparse

    import contact.cli
    from contact.cli import build_parser

    envelope = "geometry.machine.envelope_numba"
    sub = next(a for a in build_parser()._actions
               if isinstance(a, argparse._SubParsersAction))
    assert sub.choices["synthesize"].get_default("compiled_kernels") == (envelope,)
    monkeypatch.delenv("LTCA_KERNELS", raising=False)
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})
    monkeypatch.setattr(kernels_core, "_COMPILED_ANYWAY", {})
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: False)  # a fresh cache
    kernels_core.prefer_compiled((envelope,))
    assert os.environ["LTCA_KERNELS"] == "auto"
    assert kernels_module() is None  # the iso-lines: NumPy
    assert kernels_core.kernels_module(envelope) is kernels_core.compiled_module(envelope)
    assert kernels_core.kernels_module("contact.qp.solvers.pivoting_numba") is None
    assert kernels_core.compiled_modules() == (envelope,)
    assert kernels_core.process_choice() == "numpy"  # a study's workers: NumPy
    note = contact.cli.compile_note()
    assert note is not None and "geometry's numba kernels" in note and "ltca compile" in note
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: name == envelope)
    assert contact.cli.compile_note() is None  # the envelope's cached: nothing to compile
    # every module cached: numba throughout, as for the other commands of many analyses
    monkeypatch.delenv("LTCA_KERNELS")
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})
    monkeypatch.setattr(kernels_core, "_COMPILED_ANYWAY", {})
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: True)
    kernels_core.prefer_compiled((envelope,))
    assert os.environ["LTCA_KERNELS"] == "numba"
    assert kernels_module() is numba_kernels
    assert kernels_core.compiled_modules() == kernels_core.KERNEL_MODULES
    # a user's choice wins
    monkeypatch.setenv("LTCA_KERNELS", "numpy")
    monkeypatch.setattr(kernels_core, "cache_ready", lambda name: False)
    kernels_core.prefer_compiled((envelope,))
    assert os.environ["LTCA_KERNELS"] == "numpy"
    assert kernels_core.compiled_modules() == ()


def test_auto_decides_by_an_uncached_module_first(monkeypatch):
    """``auto`` asks first about a module without a cache index file (answered without
    importing numba, ~1 s of CPU): after a synthesis on a fresh cache the envelope's
    kernels are cached and the others not, and the next ``ltca run`` must not import numba
    to learn that it runs NumPy."""
    envelope = "geometry.machine.envelope_numba"
    asked = []
    monkeypatch.setenv("LTCA_KERNELS", "auto")
    monkeypatch.setattr(kernels_core, "_AUTO_CHOICE", {})
    monkeypatch.setattr(kernels_core, "_no_index_file", lambda name: name != envelope)
    monkeypatch.setattr(kernels_core, "cache_ready",
                        lambda name: asked.append(name) or name == envelope)
    assert kernels_core.process_choice() == "numpy"
    assert asked == [kernels_core.KERNEL_MODULES[1]]


def test_kernels_that_cannot_be_cached_leave_the_numpy_path(monkeypatch, caplog):
    """numba raises RuntimeError where it finds no writable cache directory: the NumPy path
    runs, with a warning that says how to get the kernels back (not a crash on import)."""
    def no_cache(name):
        raise RuntimeError("cannot cache function '_basis': no locator available")

    kernels_core.compiled_module.cache_clear()
    monkeypatch.setattr(kernels_core.importlib, "import_module", no_cache)
    try:
        with caplog.at_level("WARNING", logger="geometry.core.kernels"):
            assert kernels_core.compiled_module("contact.utca.isoline_numba") is None
        assert "NUMBA_CACHE_DIR" in caplog.text
    finally:
        monkeypatch.undo()
        kernels_core.compiled_module.cache_clear()
    assert kernels_module("numba") is numba_kernels


def test_cache_ready_reads_numba_index(tmp_path, monkeypatch):
    """``cache_ready`` is True once numba's cache holds every kernel of a module for this
    machine, False in an empty cache: checked in a child process with its own
    ``NUMBA_CACHE_DIR`` (numba reads the variable at import), compiling the smallest
    module (the block pivoting's kernels and the Weber iteration's warm solve) by one call
    of each. In the empty
    cache the answer comes without importing numba (no index file of the module there:
    the cold first run's ~1 s of numba's import saved, issue 75)."""
    import subprocess
    import sys

    child = (
        "import sys\n"
        "import numpy as np\n"
        "from geometry.core import kernels\n"
        "name = 'contact.qp.solvers.pivoting_numba'\n"
        "before = kernels.cache_ready(name)\n"
        "assert 'numba' not in sys.modules\n"
        "from contact.qp.benchmark_problems import ltca_like_problem\n"
        "from contact.qp.solvers.active_set import block_pivoting\n"
        "import os; os.environ['LTCA_KERNELS'] = 'numba'\n"
        "p = ltca_like_problem(12, seed=0).problem\n"
        "assert block_pivoting(p)['converged']\n"
        "from contact.qp.problem import ProblemScale\n"
        "from contact.qp.solvers import pivoting_numba as k\n"
        "from contact.qp.solvers.active_set import pivoting_thresholds\n"
        "d = np.diagonal(p.compliance).copy()\n"
        "sc = ProblemScale(force=p.scale.force, length=p.scale.force * float(d.mean()),\n"
        "                  arm=p.scale.arm)\n"
        "k.warm_solve(p.compliance, d, p.separation, p.moment_arm, float(p.torque),\n"
        "             p.upper_bound, p.bounded, p.has_bounds, *pivoting_thresholds(sc),\n"
        "             np.ones(p.size), 1e-7, sc.force, sc.length, sc.arm, 50)\n"
        "kernels.cache_ready.cache_clear()\n"
        "print(before, kernels.cache_ready(name))\n")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path), LTCA_KERNELS="")
    out = subprocess.run([sys.executable, "-c", child], env=env, capture_output=True,
                         text=True, cwd=Path(__file__).resolve().parents[1])
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["False", "True"]


def test_commands_of_many_analyses_ask_for_the_compiled_kernels():
    """The commands that run many analyses declare it (``many_analyses``, which
    ``contact.cli.main`` answers with ``prefer_compiled``); a single analysis does not."""
    import argparse

    from contact.cli import build_parser

    sub = next(a for a in build_parser()._actions
               if isinstance(a, argparse._SubParsersAction))
    many = {"synthesize", "sweep", "tolerance", "vh-check", "optimize", "correct", "wear",
            "friction-study", "efficiency-map"}
    for name in (*many, "run", "rate", "report", "duty-cycle", "compile"):
        assert bool(sub.choices[name].get_default("many_analyses")) is (name in many), name


def test_ltca_run_as_its_own_process_takes_numpy(monkeypatch):
    """``ltca run`` as the process (the console script, ``python -m contact``: ``main()``
    without arguments) runs with ``LTCA_KERNELS=numpy`` where the user set nothing — one
    analysis never earns numba's first-use compile back, nor on a full cache its import
    and kernel loading (issue 75, compile90: docs/performance.md) — while the same
    command called from Python (``main([...])``) leaves the process's default alone (a
    test session or a script keeps one path for all its analyses), and a user's
    ``LTCA_KERNELS`` wins. The command's work is replaced by a probe."""
    import argparse
    import sys

    import contact.commands.run as run_command
    from contact.cli import build_parser, main

    sub = next(a for a in build_parser()._actions
               if isinstance(a, argparse._SubParsersAction))
    assert sub.choices["run"].get_default("one_analysis") is True
    assert not sub.choices["synthesize"].get_default("one_analysis")
    seen = []
    monkeypatch.setattr(run_command, "run",
                        lambda args: seen.append(os.environ.get("LTCA_KERNELS")) or 0)
    monkeypatch.delenv("LTCA_KERNELS", raising=False)
    assert main(["run", "-q"]) == 0
    monkeypatch.setattr(sys, "argv", ["ltca", "run", "-q"])
    assert main() == 0
    monkeypatch.setenv("LTCA_KERNELS", "numba")
    assert main() == 0
    assert seen == [None, "numpy", "numba"]
