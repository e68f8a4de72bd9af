"""The FE-compliance LTCA (``LTCAOptions(compliance="fe")``), issue 35 item 4.

References, none taken from the code under test:

* the FE influence coefficients themselves: interpolated to the load grid's own nodes the
  compliance must be the stored coefficients (bilinear hats are one-hot there);
* Maxwell–Betti: the FE flank compliance between loads on one tooth is symmetric (the
  load and the response are the same functional), after the interpolation to the LTCA's
  segments too (both sides take the same weights);
* the contact conditions the QP's solution must satisfy (seed Eq. 3.12–3.14), recomputed
  here from the final problems: F ≥ 0, gaps Y = C F + s − R Θ ≥ 0, F·Y = 0, Rᵀ F = T;
* the shell model (contact.compliance, its own tests) on the single-tooth load cases of
  tests/test_fe_tooth.py, within the bands stated there (slow: the default FE model).

The CI tests run the small LTCA of tests/test_root_stress.py (one mesh cycle of 4 rolls,
8 segments per curve, one torque: ~4 s) on the coarse FE model of tests/test_fe_tooth.py
(11 000–14 000 unknowns, 3–7 s per member with SuperLU, built once in this module).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.compliance.fe import (
    CACHE_ENV,
    FEOptions,
    build_influence_model,
    cache_key,
    cache_path,
    influence_dataset,
    locate_flank_points,
)
from contact.compliance.fe.cache import write_cache_entry
from contact.compliance.fe.contact_compliance import (
    fe_mesh_compliance_many,
    fe_pair_model,
    interpolated_compliance,
    segment_weights,
)
from contact.compliance.mesh import ContactSegments, pair_compliance_model
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.compliance_models import available_compliance_models
from contact.ltca.options import json_options
from contact.ltca.root_stress import _roll_rotations
from contact.utca.easeoff import ease_off
from geometry.core.errors import InputError
from geometry.pair.assembly import case_transforms

#: the coarse model of the CI tests (as tests/test_fe_tooth.py, tests/test_root_stress.py)
COARSE = FEOptions(face_divisions=4, across_divisions=2, flank_divisions=3, slot_divisions=1,
                   rim_divisions=2, fillet_divisions=2, load_nu=5, load_nv=4)
#: a small LTCA: one mesh cycle, 4 rolls, 8 segments per curve
SMALL = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8)
MEMBERS = ("pinion", "gear")


@functools.cache
def _analysis(name: str | None = None):
    case = resolve_case(name)
    eo = ease_off(case)
    return case, eo, loaded_tca(case, [250.0], easeoff=eo, options=SMALL)


@functools.cache
def _coefficients(member: str):
    case, eo, _ = _analysis()
    flank = eo.pinion_flank if member == "pinion" else eo.gear_flank
    model = build_influence_model(case, member, flank, COARSE, solver="superlu")
    return influence_dataset(model, case, progress=False)


def _segments(lt, eo, roll: int, pair: int | None = None) -> ContactSegments:
    """The LTCA's segments of one roll (one pair, or all) with a contact point, as
    ContactSegments (straight: ends ± L/2 along the contact tangent)."""
    sel = lt.isel(roll=roll)
    p = sel["contact_point"].transpose("pair", "segment", "xyz").values
    length = sel["segment_length"].transpose("pair", "segment").values
    ok = np.isfinite(p).all(axis=-1) & (np.nan_to_num(length) > 0)
    pairs = np.broadcast_to(lt["pair"].values[:, None], ok.shape)
    if pair is not None:
        ok &= pairs == pair
    mid = p[ok]
    t = sel["contact_tangent"].transpose("pair", "segment", "xyz").values[ok]
    L = length[ok]
    rp, rg = _roll_rotations(eo, lt["roll"].values)
    return ContactSegments(
        mid, np.stack([mid - 0.5 * L[:, None] * t, mid + 0.5 * L[:, None] * t], axis=1),
        sel["contact_normal"].transpose("pair", "segment", "xyz").values[ok], L,
        sel["equivalent_radius"].transpose("pair", "segment").values[ok], pairs[ok], L,
        float(rp[roll]), float(rg[roll]))


@pytest.mark.parametrize("member", MEMBERS)
def test_interpolation_is_the_coefficients_at_the_grid_nodes(member):
    """Loads and responses at the load grid's own nodes (``flank_position``, on the
    reference tooth and turned one pitch onto each neighbour) take one-hot hat weights:
    the interpolated compliance must be the stored coefficients G[a, tooth, b], for both
    the mid-surface and the flank compliance (1e-12 of the largest: the hat weights are
    exact to round-off at a node, the located fractions to ~1e-13)."""
    coef = _coefficients(member)
    pos = coef["flank_position"].values.reshape(-1, 3)
    pitch = float(coef.attrs["pitch"])
    c, s = np.cos(pitch), np.sin(pitch)
    turn = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    pts = np.concatenate([pos, pos @ turn.T])  # tooth 0, then its neighbour
    fp = locate_flank_points(coef, pts)
    nl = pos.shape[0]
    for variable, name in (("centreline", "centreline_compliance"), ("flank", "compliance")):
        got = interpolated_compliance(coef, fp.weights, fp.tooth, variable)
        g = coef[name].transpose("load_u", "load_v", "tooth", "u", "v").values
        d = int(fp.tooth[nl] - fp.tooth[0])
        want_self = g[:, :, list(coef["tooth"].values).index(0)].reshape(nl, nl).T
        want_next = g[:, :, list(coef["tooth"].values).index(d)].reshape(nl, nl).T
        scale = np.abs(want_self).max()
        np.testing.assert_allclose(got[:nl, :nl], want_self, atol=1e-12 * scale, rtol=0)
        # response on the neighbour (rows nl:) under loads on tooth 0 (columns :nl)
        np.testing.assert_allclose(got[nl:, :nl], want_next, atol=1e-12 * scale, rtol=0)


@pytest.mark.parametrize("member", MEMBERS)
def test_fe_compliance_is_symmetric_after_interpolation(member):
    """Maxwell–Betti at the LTCA's segments of every roll (all pairs with a contact point,
    Simpson line loads over each segment): the flank compliance between segments on one
    tooth is symmetric to 1e-8 of its largest entry (measured ~1e-13: the load and the
    response are the same functional, and both sides take the same weights). Between
    teeth the finite sector's coefficients are not (the neighbours' loads are read from
    the middle tooth's, docs/fe.md), nor is the mid-surface compliance (load on the
    flank, response on the mid-surface: the flank's Poisson thickening under bending is in
    one and not the other): the LTCA's total C is exactly symmetric (½(G + Gᵀ)) and its
    reported asymmetry is that of the raw mid-surface matrices (0.08–0.3 measured here;
    bounded to catch a wrong pairing of loads and responses, which gives O(1))."""
    case, eo, lt = _analysis()
    coef = _coefficients(member)
    teeth = pair_compliance_model(case)
    model = fe_pair_model(case, {"pinion": eo.pinion_flank, "gear": eo.gear_flank}, None,
                          teeth, coefficients={m: _coefficients(m) for m in MEMBERS})
    for j in range(lt.sizes["roll"]):
        seg = _segments(lt, eo, j)
        t = np.asarray(case_transforms(case, seg.pinion_rotation, seg.gear_rotation)[
            MEMBERS.index(member)])
        rot, shift = t[:3, :3], t[:3, 3]
        w, k, _ = segment_weights(coef, (seg.midpoints - shift) @ rot,
                                  (seg.ends - shift) @ rot, limit=3.0)
        c = interpolated_compliance(coef, w, k, "flank")
        same = k[:, None] == k[None, :]
        scale = np.abs(c).max()
        assert np.all(np.abs(c - c.T)[same] <= 1e-8 * scale)
        (total, info), = fe_mesh_compliance_many(case, [seg], model)
        np.testing.assert_array_equal(total, total.T)
        assert 0.0 < info["asymmetry"] < 0.5  # centreline: measured 0.08–0.3


def test_fe_ltca_satisfies_the_contact_conditions(tmp_path, monkeypatch):
    """The FE-compliance LTCA (coarse model, read from a fresh cache under its key, never
    rebuilt) solves the same contact problem: recomputed from every final problem and
    its solution, F ≥ 0, the gaps Y = C F + s − R Θ ≥ −1e-9 of the largest |s|, the
    complementarity F·Y ≤ 1e-7 of (largest F)(largest |s|) per segment, equilibrium Rᵀ F = T
    to 1e-9 (the certification tolerance of contact.qp is 1e-7, relative); the dataset's
    own residuals within the certification tolerance, every roll found; C symmetric with
    positive diagonal; the options recorded in the file. Its LTE differs from the shell's
    (> 1 %: the models differ, docs/fe.md) — the switch reaches the analysis."""
    case, eo, lt_shell = _analysis()
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    for member in MEMBERS:
        ds = _coefficients(member)
        key = cache_key(case.member(member), ds.attrs["flank"], COARSE)
        write_cache_entry(ds, cache_path(key), key)

    def no_build(*args, **kwargs):
        raise AssertionError("rebuilt instead of read from the cache")

    monkeypatch.setattr("contact.compliance.fe.influence.build_influence_model", no_build)
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8, compliance="fe", fe=COARSE)
    problems = []
    lt = loaded_tca(case, [250.0], easeoff=eo, options=opts, roll_problems=problems)
    assert lt["found"].values.all()
    for name in ("residual_primal", "residual_dual", "residual_complementarity",
                 "residual_equilibrium"):
        assert np.nanmax(lt[name].values) <= 1e-7, name
    assert len(problems) == lt.sizes["roll"]
    for rp in problems:
        p, sol = rp.problem, rp.solution
        C = np.asarray(p.compliance)
        np.testing.assert_array_equal(C, C.T)
        assert np.all(np.diag(C) > 0)
        F, s, R = sol.force, np.asarray(p.separation), np.asarray(p.moment_arm)
        Y = C @ F + s - R * sol.rotation
        scale = np.abs(s).max()
        assert F.min() >= -1e-9 * F.max()
        assert Y.min() >= -1e-9 * scale
        assert np.max(np.abs(F * Y)) <= 1e-7 * F.max() * scale
        assert abs(R @ F - p.torque) <= 1e-9 * p.torque
    assert '"compliance": "fe"' in lt.attrs["options"]
    assert lt.attrs["options"].count('"face_divisions": 4') == 1
    # the cache files are read once per process: a second model shares the datasets
    flanks = {"pinion": eo.pinion_flank, "gear": eo.gear_flank}
    teeth = pair_compliance_model(case)
    first = fe_pair_model(case, flanks, COARSE, teeth)
    again = fe_pair_model(case, flanks, COARSE, teeth)
    assert all(first.coefficients[m] is again.coefficients[m] for m in MEMBERS)
    change = abs(float(lt["lte_mean"][0]) / float(lt_shell["lte_mean"][0]) - 1.0)
    assert change > 0.01


def test_shell_options_text_is_unchanged():
    """The default (shell) analysis writes the options text it wrote before the FE
    compliance existed (no ``compliance``/``fe`` keys: the golden file guards every other
    byte), and an FE analysis names its model; the bundled models are the one registry's
    (contact.ltca.compliance_models, which the pool, the options and the CLI all read)."""
    text = json_options(LTCAOptions())
    assert '"compliance"' not in text and '"fe"' not in text
    assert '"compliance": "fe"' in json_options(LTCAOptions(compliance="fe"))
    assert available_compliance_models()[:2] == ("shell", "fe")


def test_bad_input_is_refused_naming_the_field():
    """An unknown compliance model, FE options with the shell model (unused), FE options
    of another material than the analysis', and FE options that are not FEOptions are
    refused naming the field; ``ltca run --compliance`` takes the registry's names."""
    with pytest.raises(InputError, match="compliance"):
        LTCAOptions(compliance="beam")
    with pytest.raises(InputError, match="fe: FE options are used only"):
        LTCAOptions(fe=COARSE)
    with pytest.raises(InputError, match="fe: the FE model's material"):
        LTCAOptions(compliance="fe", fe=FEOptions(youngs_modulus=200_000.0))
    with pytest.raises(InputError, match="fe: must be"):
        LTCAOptions(compliance="fe", fe={"teeth": 3})
    from contact.cli import build_parser
    from contact.commands.run import ltca_options

    args = build_parser().parse_args(["run", "--compliance", "fe"])
    assert ltca_options(args).compliance == "fe"
    assert ltca_options(build_parser().parse_args(["run"])).compliance == "shell"
    with pytest.raises(SystemExit):
        build_parser().parse_args(["run", "--compliance", "beam"])


# ------------------------------------------------------------------ against the shell model
def _tip_peaks(name: str, member: str, options: FEOptions | None = None) -> np.ndarray:
    """Shell/FE ratio of the tip-line deflection peak under unit loads at (0.5, 0.53) and
    (0.5, 0.72) of the working flank (the single-tooth load cases of tests/test_fe_tooth.py),
    both read through the LTCA's assembly: the FE path's mid-surface compliance
    (interpolated from the default model's coefficients) and the shell path's shell plus
    Sainsot foundation, at the same generated flank points."""
    from contact.compliance.tooth import (
        member_compliance,
        member_foundation,
        shell_coordinates,
        shell_tooth_from_case,
    )
    from geometry.machine.flank import flank_at

    case = resolve_case(name)
    eo = ease_off(case)
    flank = eo.pinion_flank if member == "pinion" else eo.gear_flank
    teeth = pair_compliance_model(case)
    model = fe_pair_model(case, {"pinion": eo.pinion_flank, "gear": eo.gear_flank},
                          options, teeth)
    coef = model.coefficients[member]
    gu = coef["u"].values
    pos = coef["flank_position"].transpose("u", "v", ...).values  # (nu, nv, 3)
    # the loads: on the flank at (0.5, 0.53), (0.5, 0.72), from the grid's spline
    i = int(np.argmin(np.abs(gu - 0.5)))
    from scipy.interpolate import CubicSpline

    col = CubicSpline(coef["v"].values, pos[i], axis=0)
    loads = col(np.array([0.53, 0.72]))
    tip = pos[:, -1]
    pts = np.concatenate([loads, tip])
    fp = locate_flank_points(coef, pts)
    fe = interpolated_compliance(coef, fp.weights, fp.tooth, "centreline")
    rho = np.hypot(pts[:, 0], pts[:, 1])
    generated = flank_at(case, member, flank, pts[:, 2], rho)
    nrm = generated.normal  # turned from the generated point onto the FE flank's tooth
    phi = np.arctan2(pts[:, 1], pts[:, 0]) - np.arctan2(generated.position[:, 1],
                                                         generated.position[:, 0])
    c, s = np.cos(phi), np.sin(phi)
    nrm = np.stack([c * nrm[:, 0] - s * nrm[:, 1], s * nrm[:, 0] + c * nrm[:, 1], nrm[:, 2]],
                   axis=1)
    data = shell_tooth_from_case(case, member)
    sh = member_compliance(data, pts, nrm)
    sh = sh + member_foundation(data, shell_coordinates(data, pts, nrm))
    return np.array([sh[2:, a].max() / fe[2:, a].max() for a in range(2)])


@pytest.mark.slow
@pytest.mark.parametrize("name, member, band", [
    ("kolivand2009_fm_11x41_reference", "gear", (0.8, 1.2)),
    ("kolivand2009_fh_12x41", "gear", (0.8, 1.2)),
    ("kolivand2009_fh_12x41", "pinion", (0.75, 1.2)),
    ("kolivand2009_fm_11x41_reference", "pinion", (0.4, 0.75)),
])
def test_fe_path_against_the_shell_on_single_tooth_loads(name, member, band):
    """The FE path's compliance (the default FE model's mid-surface compliance,
    interpolated as the LTCA does) against the shell path's (shell + Sainsot foundation)
    on the single-tooth load cases of tests/test_fe_tooth.py: the shell's stated accuracy
    is 15 % against FE of the tooth clamped at the root cone (tests/test_compliance_tooth.py);
    with the fillets and rim the Sainsot term models, the bands add 5 % (0.8–1.2), the
    face-milled generated pinion outside them for the reason docs/fe.md gives (its slots
    reach 2–3 mm under the blank's root cone): the bands of tests/test_fe_tooth.py, which
    this reproduces through the interpolation (measured: see docs/fe.md). The default
    FE model: ~30–60 s per member the first time (PARDISO), then read from the cache."""
    ratio = _tip_peaks(name, member)
    assert np.all((ratio > band[0]) & (ratio < band[1])), ratio


#: the coarse model with the default model's load grid (21 × 11): a hat as narrow as the
#: default's, rows near the single-tooth loads' heights 0.53 and 0.72 (on the 5 × 4 grid
#: a load's hat spans a quarter of the face, which lowers the FE's peak deflection under
#: it: shell/FE 1.32 on a 9 × 11 grid, 1.21 on this one); the grid costs solves only
COARSE_GRID = dataclasses.replace(COARSE, load_nu=21, load_nv=11)
FACE_HOBBED = "kolivand2009_fh_12x41"


@pytest.fixture(scope="module")
def coarse_cache(tmp_path_factory):
    """A cache directory for this module's coarse FE models, in the environment while
    its tests run (each model built once, then read by every analysis)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv(CACHE_ENV, str(tmp_path_factory.mktemp("fe-cache")))
        yield


def test_fe_against_the_shell_on_a_coarse_model(coarse_cache):
    """The CI version of the shell/FE comparison (docs/fe.md, the seed's Fig. 3.4/3.7) on
    the face-hobbed pair, with the coarse FE model (the default's 21 × 11 load grid),
    within the bands the slow tests and the docs justify, widened by the coarse model's
    own offset from the default one, measured:

    * the gear's mid-surface compliance under the single-tooth loads at mid face, heights
      0.53 and 0.72, through the LTCA's interpolation (as the slow test below): shell +
      Sainsot foundation / FE within 0.8–1.3 — the shell's stated 15 % against FE clamped
      at the root cone plus 5 % for the fillets and the rim (the slow test's 0.8–1.2),
      the upper side × 1.08 for the coarse mesh, stiffer than the default one under these
      loads (shell/FE 1.21/1.20 here against 1.12/1.10 with the default model);
    * the LTE mean of the small LTCA at 250 N·m, FE / shell within 0.90–1.03: with the
      default FE model and LTCA, FE −5 … +1 % over 50–500 N·m and Fig. 3.7's
      misalignments (docs/fe.md: the rim's coupling of the teeth takes back the FE's
      stiffer teeth), and the coarse model 2 % under the default one at every torque
      (small LTCA: 0.936/0.960/0.985 against 0.955/0.980/1.005 at 50/250/500 N·m).

    ~15–30 s: both members' coarse coefficients (built once into the module's cache) and
    two small LTCAs."""
    ratio = _tip_peaks(FACE_HOBBED, "gear", COARSE_GRID)
    assert np.all((ratio > 0.8) & (ratio < 1.3)), ratio
    case, eo, shell = _analysis(FACE_HOBBED)
    fe = loaded_tca(case, [250.0], easeoff=eo, options=dataclasses.replace(
        SMALL, compliance="fe", fe=COARSE_GRID))
    assert fe["found"].values.all()
    lte = float(fe["lte_mean"][0]) / float(shell["lte_mean"][0])
    assert 0.90 < lte < 1.03, lte


def test_the_hypoid_example_takes_the_default_load_grid(coarse_cache):
    """The hypoid example's gear flank is generated only from v = 0.093 up near the heel
    (its straight slot bottoms lie above the root cone there): the default load grid
    follows it (its lowest row at v₀ + 0.01, influence.load_v_limits; the other members
    keep the ease-off grid's 0.05), so ``--compliance fe`` and the root stress run
    without FE options — here the FE-compliance LTCA with its root stress on the coarse
    model: every roll found, both members' peak root stress positive. The ease-off
    grid's limits given explicitly are refused naming ``load_v_limits`` before any
    mesh is solved. ~15 s."""
    from contact.compliance.fe import influence_coefficients
    from contact.pipeline import run_analysis

    name = "hypoid_iso23509_s2"
    opts = dataclasses.replace(SMALL, compliance="fe", fe=COARSE)
    tree = run_analysis(name, [250.0], options=opts, root_stress=True, operating=False,
                        geometry=False, mesh_interface=False)
    lt = tree["ltca"].to_dataset()
    assert lt["found"].values.all()
    assert np.all(lt["root_stress_max"].values > 0)
    case = resolve_case(name)
    low = {m: float(influence_coefficients(case, m, options=COARSE, progress=False)["v"][0])
           for m in MEMBERS}
    assert low["pinion"] == 0.05
    assert 0.093 < low["gear"] < 0.105, low
    with pytest.raises(InputError, match="load_v_limits"):
        build_influence_model(case, "gear", "drive", dataclasses.replace(
            COARSE, load_v_limits=(0.05, 1.0)), solver="superlu")


@pytest.mark.slow
def test_every_bundled_case_runs_the_fe_compliance_and_root_stress(coarse_cache):
    """``--compliance fe`` with the root stress and no FE options on every bundled case
    (the small LTCA at 250 N·m, the coarse FE model; the default model differs only in
    its divisions): every roll found, both members' peak root stress positive and
    finite. 1–3 min (the coarse coefficients of every design)."""
    from contact.catalogue import bundled_cases
    from contact.pipeline import run_analysis

    opts = dataclasses.replace(SMALL, compliance="fe", fe=COARSE)
    for file in bundled_cases():
        tree = run_analysis(file.removesuffix(".toml"), [250.0], options=opts,
                            root_stress=True, operating=False, geometry=False,
                            mesh_interface=False)
        lt = tree["ltca"].to_dataset()
        assert lt["found"].values.all(), file
        peak = lt["root_stress_max"].values
        assert np.all(np.isfinite(peak) & (peak > 0)), (file, peak)


# ------------------------------------------------------------------ root stress in studies
def _coarse_cache(tmp_path, monkeypatch):
    """The coarse models of this module in a fresh cache under their keys; building any
    other model fails the test."""
    case = resolve_case(None)
    tmp_path.mkdir(parents=True, exist_ok=True)
    monkeypatch.setenv(CACHE_ENV, str(tmp_path))
    keys = []
    for member in MEMBERS:
        ds = _coefficients(member)
        key = cache_key(case.member(member), ds.attrs["flank"], COARSE)
        write_cache_entry(ds, cache_path(key), key)
        keys.append(key)

    def no_build(*args, **kwargs):
        raise AssertionError("rebuilt instead of read from the cache")

    monkeypatch.setattr("contact.compliance.fe.influence.build_influence_model", no_build)
    return case, keys


def test_fe_ltca_root_stress_takes_the_compliance_model(tmp_path, monkeypatch):
    """``run_analysis(root_stress=True)`` with the FE compliance superposes the fillet
    stress of the same FE model the compliance came from (``options.fe``), not the default
    one: only the coarse coefficients are in the cache and none may be built. ~5 s (the
    small LTCA once)."""
    from contact.pipeline import run_analysis

    _, keys = _coarse_cache(tmp_path / "cache", monkeypatch)
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=8, compliance="fe", fe=COARSE)
    tree = run_analysis(None, [250.0], options=opts, root_stress=True, operating=False,
                        geometry=False, mesh_interface=False)
    lt = tree["ltca"].to_dataset()
    assert lt["root_stress"].attrs["fe_cache_keys"].split() == keys
    assert np.all(lt["root_stress_max"].values > 0)


def test_studies_take_root_stress(tmp_path, monkeypatch):
    """``StudyRun(root_stress=...)`` reaches every point of a sweep and of a tolerance
    analysis: a one-point sweep's ``root_stress_max`` (point dims, torque, member) equals
    the single analysis' at the same mounting (same inputs: rtol 1e-9, the order of sums);
    ``sample`` hands the same switch to its points; ``ltca sweep``/``tolerance
    --root-stress`` set it (the default, issue 53; ``--no-root-stress`` leaves it out),
    ``--compliance`` the LTCA's model; a bad value is refused naming the field. ~10 s: the
    small LTCA twice on the coarse FE model."""
    import argparse

    from contact.cli import build_parser
    from contact.commands.study import _prepare
    from contact.pipeline import run_analysis
    from contact.study import StudyRun, sample, sweep

    case, _ = _coarse_cache(tmp_path / "cache", monkeypatch)
    de = case.misalignment.delta_E
    grid = sweep(case, delta_E=[de], torque=250.0,
                 run=StudyRun(options=SMALL, root_stress=COARSE, scheduler="synchronous"))
    assert grid["root_stress_max"].dims == ("delta_E", "torque", "member")
    single = run_analysis(case, [250.0], options=SMALL, root_stress=COARSE, operating=False,
                          geometry=False, mesh_interface=False)["ltca"]
    np.testing.assert_allclose(grid["root_stress_max"].isel(delta_E=0).values,
                               single["root_stress_max"].values, rtol=1e-9)
    seen = []

    def capture(shared, points, **kw):
        seen.append(shared.root_stress)
        raise RuntimeError("captured")

    monkeypatch.setattr("contact.study.monte_carlo.run_points", capture)
    import scipy.stats

    with pytest.raises(RuntimeError, match="captured"):
        sample(case, {"delta_E": scipy.stats.norm(de, 0.01)}, 2,
               run=StudyRun(options=SMALL, root_stress=COARSE))
    assert seen == [COARSE]
    with pytest.raises(InputError, match="root_stress"):
        StudyRun(root_stress="yes")
    parser = build_parser()
    for cmd in (["sweep", "--dE", "0"], ["tolerance", "--dE", "normal:0:0.05"]):
        args = parser.parse_args([*cmd, "--root-stress", "--compliance", "fe", "-o",
                                  str(tmp_path / f"{cmd[0]}.nc")])
        _, run = _prepare(args)
        assert run.root_stress is True and run.options.compliance == "fe"
        args = parser.parse_args([*cmd, "-o", str(tmp_path / f"{cmd[0]}.nc")])
        _, run = _prepare(args)
        assert run.root_stress is True and run.options.compliance == "shell"  # on by default
        args = parser.parse_args([*cmd, "--no-root-stress", "-o", str(tmp_path / f"{cmd[0]}.nc")])
        _, run = _prepare(args)
        assert run.root_stress is False
    assert isinstance(args, argparse.Namespace)
