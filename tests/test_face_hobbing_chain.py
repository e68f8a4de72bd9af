"""The whole chain on the seed's face-hobbed pairs: synthesised case → UTCA → LTCA → efficiency.

The cases are the synthesised FH pairs of the seed (``ltca synthesize`` of
``cases/basic/kolivand2009_fh_12x41.toml``, ``..._table54_A_fh.toml``, ``..._B_fh.toml``):
Table 4.3 (12×41, offset 45 mm) and Table 5.4 designs A and B (offsets 15 and 30 mm).
The checks are those the face-milled chain passes (tests/test_ltca.py,
tests/test_ltca_discretisation.py, tests/test_efficiency.py, tests/test_cli.py), on these
pairs and at reduced resolution:

* identities re-checked from the stored results at every roll position (torque
  equilibrium, F ≥ 0, no load where the gap stays open, contact flags);
* every registered solver backend gives the same LTE;
* the LTE and the peak pressure converge as the segments and the roll positions double;
* physics against the seed: the LTE mean grows with torque nearly linearly; the
  efficiency of A and B in the seed's band with B (larger offset) below A (seed §5.3)
  is tests/test_efficiency.py::test_table_5_4_designs_efficiency_and_offset_effect, on
  the runs the identities are checked on here;
* ``ltca run`` of an FH case file (the Table 4.3 pair with the measured-like deviations
  of seed §4.5.2), and the deviation raising the unloaded TE (seed Table 4.4).

The helpers (``_case``, ``_easeoff``, ``_transitions``, ``_run``) take any bundled case
by name and cache their results for the test session; tests/test_efficiency.py reuses
them.
"""

from __future__ import annotations

import contextlib
import dataclasses
import io
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from ltca_identities import assert_equilibrium_and_complementarity, solver_params

from contact.cli import main
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.transmission_error import transmission_error_summary
from contact.utca import transitions
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.core.io import read_netcdf
from geometry.pair.assembly import Misalignment

ROOT = Path(__file__).resolve().parents[1]
FH_CASES = ("kolivand2009_fh_12x41", "kolivand2009_table54_A_fh", "kolivand2009_table54_B_fh")
#: the torques of ``ltca run`` (seed Table 3.1), used on the Table 4.3 pair
RUN_TORQUES = (50.0, 250.0, 500.0)


@cache
def _case(name: str):
    # a path, not a bundled name: the installed package data may be another checkout's;
    # aligned, as the identities and estimates here mean (the face-milled default case's
    # [operating] table carries the seed's Table 3.1 misalignment; the FH cases none)
    case = load_case(ROOT / "cases" / f"{name}.toml")
    return dataclasses.replace(case, misalignment=Misalignment())


@cache
def _easeoff(name: str):
    return ease_off(_case(name))


@cache
def _transitions(name: str) -> tuple[float, float]:
    # loaded_tca's own M1, M2 (contact.utca.transitions), found once per case: two thirds
    # of a small LTCA's time (the pipeline hands the UTCA's to it the same way)
    return tuple(float(m) for m in transitions(_easeoff(name)))


@cache
def _run(name: str, torques=(500.0,), rolls: int = 6, segments: int = 12,
         solver: str = "active_set"):
    """LTCA over one mesh cycle of a bundled case (cached: the same call is computed once
    per test session)."""
    opts = LTCAOptions(cycles=1, rolls_per_cycle=rolls, segments=segments, solver=solver)
    return loaded_tca(_case(name), list(torques), options=opts, easeoff=_easeoff(name),
                      transitions=_transitions(name))


#: the run the identities are checked on, per case, as ``_run``'s (torques, rolls, segments):
#: each is reused — the Table 4.3 pair's at the ``ltca run`` resolution and torques by
#: the linearity test and as the refinement's base, A's and B's at 500 N·m by
#: tests/test_efficiency.py's Table 5.4 test
CHECKED = {
    "kolivand2009_fh_12x41": (RUN_TORQUES, 20, 24),
    "kolivand2009_table54_A_fh": ((500.0,), 6, 12),
    "kolivand2009_table54_B_fh": ((500.0,), 6, 12),
}


@pytest.mark.parametrize("name", FH_CASES)
def test_equilibrium_and_complementarity_at_every_roll(name):
    """As tests/test_ltca.py on the face-milled pair, from the stored forces, arms and
    separations: Σ F R = T_g to 1e-9 relative (the exact solver reaches round-off), F ≥ 0,
    F = 0 wherever the gap stays open (s > R Θ: C ≥ 0 entrywise), contact flags exactly
    where F > 0, the solver's own residuals < 1e-9 — at every roll position and torque."""
    ds = _run(name, *CHECKED[name])
    case = _case(name)
    assert case.pair.method == "FH"
    assert_equilibrium_and_complementarity(ds, case)
    # more than one pair shares the load somewhere in the cycle (a hypoid's contact ratio)
    assert int(ds["pairs_in_contact"].max()) >= 2


@pytest.mark.parametrize("solver", solver_params())
def test_every_solver_gives_the_same_lte(solver):
    """Every registered backend on the Table 4.3 pair (200 N·m, 4 rolls, 10 segments):
    LTE within 0.01 µrad of our exact solver — ten times the Weber iteration's stopping
    tolerance (1e-3 µrad), as for the face-milled pair — and the peak pressure within
    0.1 %. Measured: ≤ 1.2e-6 µrad (cvxpy:PIQP), every other ≤ 6e-8."""
    ref = _run("kolivand2009_fh_12x41", (200.0,), 4, 10)
    ds = _run("kolivand2009_fh_12x41", (200.0,), 4, 10, solver)
    assert ds["found"].all(), ds["status"].values
    np.testing.assert_allclose(ds["transmission_error"], ref["transmission_error"], atol=0.01)
    assert float(ds["pressure_max"].max()) == pytest.approx(
        float(ref["pressure_max"].max()), rel=1e-3
    )


def test_refinement_converges():
    """The face-milled bounds (tests/test_ltca_discretisation.py) on the Table 4.3 pair at
    50/250/500 N·m, from the ``ltca run`` discretisation (20 rolls, 24 segments):
    doubling the segments changes the LTE by < 0.5 µrad and the peak pressure (the edge
    peak, 2.8–5.4 GPa, and the flank peak apart) by < 2 % (measured 0.11 µrad, 0.04 % and
    0.5 %); doubling the rolls leaves the shared rolls unchanged (1e-9 µrad: the same
    problems) and moves the cycle's mean and peak-to-peak LTE by < 0.5 µrad (measured
    0.003 and 0.11) and the peak pressure by < 2 % (measured 0.08 %)."""
    name = "kolivand2009_fh_12x41"
    a = _run(name, RUN_TORQUES, 20, 24)
    b = _run(name, RUN_TORQUES, 20, 48)
    c = _run(name, RUN_TORQUES, 40, 24)
    assert bool(b["found"].all() & c["found"].all())
    assert np.abs(a["transmission_error"] - b["transmission_error"]).max().item() < 0.5
    for var in ("pressure_max_flank", "pressure_max_edge"):
        assert np.all(np.abs(b[var].values / a[var].values - 1) < 0.02), var
        assert np.all(np.abs(c[var].values / a[var].values - 1) < 0.02), var
    shared = c["transmission_error"].isel(roll=slice(0, None, 2))
    np.testing.assert_allclose(shared.values, a["transmission_error"].values, rtol=0,
                               atol=1e-9)
    for var in ("lte_mean", "lte_peak_to_peak"):
        assert np.all(np.abs(c[var].values - a[var].values) < 0.5), var


def test_lte_mean_grows_nearly_linearly_with_torque():
    """LTE mean of the Table 4.3 pair at 50/250/500 N·m (the ``ltca run`` resolution;
    measured 91.8/264.3/414.8 µrad). Criterion, the face-milled one of tests/test_ltca.py:
    monotone, and a straight line explains ≥ 98 % of the variance (measured 98.9 %).
    Beyond it, the ratio of the increments per N·m (250–500 against 50–250; measured
    0.86 → 0.60 µrad/(N·m), ratio 0.70): below 1, because the pair stiffens as its
    contact spreads over the ease-off (the loaded length of the contact lines grows:
    checked), and above 0.6: a power law T^n gives 1 for n = 1, 0.71 for n = 2/3 (Hertz's
    point contact) and 0.60 for n = 1/2, so the LTE must grow faster than the square root
    of the torque. Over 50–500 N·m it grows about like T^0.64: "nearly linear" in the
    fit's sense only, as concave as the default face-milled case (ratio 0.79), whereas
    the seed's Fig. 3.6 for its 11×41 pair (about 110/290/600 µrad) is convex (1.38)."""
    ds = _run("kolivand2009_fh_12x41", RUN_TORQUES, 20, 24)
    T = np.asarray(RUN_TORQUES)
    mean = ds["lte_mean"].values
    assert np.all(np.diff(mean) > 0)
    fit = np.polyval(np.polyfit(T, mean, 1), T)
    assert 1.0 - np.var(mean - fit) / np.var(mean) >= 0.98
    slope = np.diff(mean) / np.diff(T)
    assert 0.6 < slope[1] / slope[0] < 1.0
    loaded = ((ds["contact"] > 0) * ds["segment_length"]).sum(("roll", "pair", "segment"))
    assert np.all(np.diff(loaded.values) > 0)


@pytest.fixture(scope="module")
def measured_run(tmp_path_factory):
    """``ltca run cases/kolivand2009_fh_12x41_measured.toml`` at 200 N·m (the seed's §4.5.2
    torque), 6 rolls and 10 segments per curve, efficiency at 1500 rpm; the printed text
    and the netCDF file. Without the root stress (``--no-root-stress``): no test here reads
    it, and it is an FE build of both members of this case (~19 s of CPU, no other test's);
    the FE models of the face-hobbed pair are tested in tests/test_fe_tooth.py and
    tests/test_fe_ltca.py."""
    out = tmp_path_factory.mktemp("fh_run") / "fh.nc"
    case = ROOT / "cases" / "kolivand2009_fh_12x41_measured.toml"
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        code = main(["run", str(case), "--torque", "200", "--rolls-per-cycle", "6",
                     "--segments", "10", "--no-root-stress", "--no-progress", "-o",
                     str(out)])
    return code, text.getvalue(), read_netcdf(out, tree=True)


def test_ltca_run_of_a_face_hobbed_case_file(measured_run):
    """The command line on an FH case file: exit 0, the summary and the theoretical/deviated
    TE table printed, every roll position certified in both runs, the efficiency stage
    within the seed's 96–99.5 % band widened to 92 % (measured 93.3 % on the deviated
    surfaces: at Rq 0.8 µm and 90 °C the flanks run at λ ≈ 0.15, where the asperities
    carry most of the load at μ_b 0.1 — tests/test_efficiency.py's module docstring)."""
    code, text, tree = measured_run
    assert code == 0
    assert "case kolivand2009_fh_12x41_measured" in text
    assert "theoretical" in text and "deviated" in text
    assert {"easeoff", "utca", "ltca", "friction", "theoretical"} <= set(tree.children)
    assert bool(tree["ltca"]["found"].all()) and bool(tree["theoretical/ltca"]["found"].all())
    eff = tree["friction"]["efficiency_mean"].values
    assert np.all((eff > 0.92) & (eff < 0.995))


def test_global_deviation_raises_the_unloaded_te(measured_run):
    """Seed §4.5.2, Table 4.4: with the measured global deviations the UTE peak-to-peak
    and first harmonic "almost doubled" (36.9 → 61.5 and 15.1 → 28.9 µrad) and the LTE
    p-p at 200 N·m rose (23.9 → 29.8). Required: UTE p-p and 1st harmonic at least 1.5
    times the theoretical (the seed's ratios 1.67 and 1.91, less a margin for a deviation
    that is measured-*like*, not the seed's); LTE p-p larger. Measured here (30 UTCA rolls;
    LTCA 6 rolls per cycle): UTE p-p 12.7 → 100.1, 1st 4.1 → 41.8 µrad; LTE p-p 17.5 →
    39.1 µrad (at 20 rolls 17.6 → 40.0, benchmarks/fh_table_4_4.py) — our deviation, both
    flanks' profile slopes adding up at the pinion tip, raises them far more than the
    seed's."""
    _, _, tree = measured_run
    ute = {}
    for name, group in (("theoretical", "theoretical/utca"), ("deviated", "utca")):
        ut = tree[group].to_dataset()
        ute[name] = transmission_error_summary(
            ut["roll"].values, ut["unloaded_transmission_error"].values,
            float(ut.attrs["mesh_period"]))
    assert ute["deviated"]["peak_to_peak"] > 1.5 * ute["theoretical"]["peak_to_peak"]
    assert ute["deviated"]["harmonics"][0] > 1.5 * ute["theoretical"]["harmonics"][0]
    lte_dev = float(tree["ltca"]["lte_peak_to_peak"][0])
    lte_th = float(tree["theoretical/ltca"]["lte_peak_to_peak"][0])
    assert lte_dev > lte_th

