"""The friction study (issue 34): its designs, one point, the Dask runner and resume.

Each study test solves 2×2×2 = 8 smooth-film conditions (Rq 0.1–0.15 µm at 25 °C, λ > 10)
on a 64-node grid: ≈ 0.1 s each on one core, so a whole design costs about a second in
this process; the LocalCluster test adds the cluster's start (a few seconds) — cheap
enough for CI.
"""

from __future__ import annotations

import numpy as np
import pytest

import contact.study.friction_study as fstudy
from contact.study.friction_study import run_friction_study
from contact.study.store import ResultStore
from friction.study.design import (
    DESIGN_BOX_TEXT,
    DESIGN_INPUTS,
    GEAR_CONTACT_RANGE,
    GEAR_FLANK_RANGE,
    TABLE_5_1,
    TABLE_5_1_RANGE,
    check_design,
    design_box_of,
    factorial_design,
    inside_box,
    space_filling_design,
)
from friction.study.points import RESULT_VARIABLES, SolveSettings, solve_design_point
from geometry.core.errors import InputError

SETTINGS = SolveSettings(nodes=64)


def _design_2x2x2() -> dict[str, np.ndarray]:
    levels = {**{k: (v[0],) for k, v in TABLE_5_1.items()},
              "hertz_pressure": (500.0, 1000.0), "entraining_velocity": (5.0, 10.0),
              "slide_to_roll": (0.2, 0.6), "radius": (20.0,), "temperature": (25.0,),
              "roughness_1": (0.1,), "roughness_2": (0.15,)}
    return factorial_design(levels)


def _serial(design) -> list:
    n = design["hertz_pressure"].size
    return [solve_design_point(SETTINGS, i, {k: float(design[k][i]) for k in DESIGN_INPUTS})
            for i in range(n)]


def _assert_equals_serial(ds, serial) -> None:
    assert ds.sizes["point"] == len(serial)
    assert (ds["status"].values == [s.status for s in serial]).all()
    for name in RESULT_VARIABLES:
        if name == "solve_time":
            continue
        # the same function on the same inputs: equal to round-off of another process
        np.testing.assert_allclose(ds[name].values, [s.values[name] for s in serial],
                                   rtol=1e-12, atol=0, err_msg=name)


# ----------------------------------------------------------------------------- designs
def test_factorial_design_is_the_seeds_31500_conditions():
    """Table 5.1's levels with unordered roughness pairs: 2100 × 15 = 31,500, the seed's
    count (§5.2.3); every level appears, Rq₁ ≤ Rq₂."""
    d = factorial_design()
    assert d["hertz_pressure"].size == 31_500
    for name, levels in TABLE_5_1.items():
        assert set(np.unique(d[name])) == set(levels), name
    assert np.all(d["roughness_1"] <= d["roughness_2"])
    assert factorial_design(unordered_roughness=False)["radius"].size == 52_500


def test_space_filling_design_is_seeded_inside_the_box_and_continues():
    a = space_filling_design(64, seed=5)
    b = space_filling_design(64, seed=5)
    for k in DESIGN_INPUTS:
        np.testing.assert_array_equal(a[k], b[k])
        lo, hi, _ = TABLE_5_1_RANGE[k]
        assert a[k].min() >= lo and a[k].max() <= hi
    # skip=32 continues the sequence: the last 32 points of the 64-point design
    tail = space_filling_design(32, seed=5, skip=32)
    np.testing.assert_array_equal(tail["radius"], a["radius"][32:])
    # Latin hypercube: each of the n strata of every input holds one point
    lhs = space_filling_design(20, method="lhs", seed=3)
    strata = np.floor((lhs["temperature"] - 25.0) / 75.0 * 20).astype(int)
    assert sorted(strata) == list(range(20))


@pytest.mark.parametrize("method", ["sobol", "lhs"])
def test_design_outside_a_box_fills_the_shell(method):
    """``exclude``: every point inside the outer box and outside the excluded one, n of
    them, the same for the same seed; the Sobol shell is the sequence's points outside
    the excluded box, in order (the points inside are passed over, not moved)."""
    a = space_filling_design(40, method=method, seed=4, box=GEAR_FLANK_RANGE,
                             exclude=GEAR_CONTACT_RANGE)
    b = space_filling_design(40, method=method, seed=4, box=GEAR_FLANK_RANGE,
                             exclude=GEAR_CONTACT_RANGE)
    assert a["radius"].size == 40
    assert not inside_box(a, GEAR_CONTACT_RANGE).any()
    assert inside_box(a, GEAR_FLANK_RANGE).all()
    for k in DESIGN_INPUTS:
        np.testing.assert_array_equal(a[k], b[k])
    if method == "sobol":
        whole = space_filling_design(40, seed=4, box=GEAR_FLANK_RANGE)
        out = ~inside_box(whole, GEAR_CONTACT_RANGE)
        k = int(out.sum())
        np.testing.assert_array_equal(a["radius"][:k], whole["radius"][out])
    with pytest.raises(InputError, match=r"^exclude: leaves 0 of"):
        space_filling_design(4, method=method, box=GEAR_CONTACT_RANGE,
                             exclude=GEAR_FLANK_RANGE)


def test_design_box_read_back_from_the_study_files():
    """``ltca friction-fit --box auto``: the box each committed study was designed in is read
    back from its ``design_box`` attribute (one table of the texts the command writes); the
    flank shell, which also names the gear box it lies outside, is the flank box."""
    from friction.kolivand2009 import DATA_DIR
    from geometry.core.io import read_netcdf

    expect = {"": "gear", "_heldout": "gear", "_flank": "gear_flank", "_edge": "gear_edge"}
    for suffix, name in expect.items():
        st = read_netcdf(DATA_DIR / f"friction_study_75W90{suffix}.nc", tree=False)
        assert design_box_of(st.attrs["design_box"]) == name, suffix
    for name, text in DESIGN_BOX_TEXT.items():
        assert design_box_of(text) == name


@pytest.mark.parametrize(("call", "match"), [
    (lambda: space_filling_design(0), r"^n: must be"),
    (lambda: space_filling_design(8, method="halton"), r"^method: must be one of"),
    (lambda: space_filling_design(8, method="lhs", skip=2), r"^skip: only the Sobol"),
    (lambda: check_design({"radius": [1.0]}), r"^design: inputs must be"),
    (lambda: check_design({**{k: [1.0] for k in DESIGN_INPUTS}, "hertz_pressure": [-1.0]}),
     r"^hertz_pressure: must be in \(0, 6000\] \[MPa\], got -1"),
    (lambda: check_design({**{k: [0.5] for k in DESIGN_INPUTS}, "slide_to_roll": [3.0]}),
     r"^slide_to_roll: must be in \[-2, 2\]"),
    (lambda: check_design({**{k: [0.5] for k in DESIGN_INPUTS}, "roughness_2": [np.nan]}),
     r"^roughness_2: must be finite"),
    (lambda: SolveSettings(nodes=8), r"^nodes: must be"),
])
def test_bad_input_named(call, match):
    with pytest.raises(InputError, match=match):
        call()


def test_refused_point_is_a_failed_point_not_a_crash():
    """An unknown oil is refused when the settings are made, before any work (issue 55); a
    point the solver refuses (here a temperature outside the oil's data) is a row with
    status input_refused and the reason."""
    with pytest.raises(InputError, match=r"^lubricant: no lubricant named or at"):
        SolveSettings(lubricant="no-such-oil")
    out = solve_design_point(SolveSettings(), 3,
                             {**{k: 0.5 for k in DESIGN_INPUTS}, "hertz_pressure": 800.0,
                              "radius": 20.0, "entraining_velocity": 5.0,
                              "temperature": 200.0})
    assert out.status == 2 and out.index == 3
    assert out.reason.startswith("InputError: temperature")
    assert np.isnan(out.values["friction_coefficient"])


# ----------------------------------------------------------------------------- engine
def test_2x2x2_design_synchronous_equals_serial_solver_calls():
    design = _design_2x2x2()
    ds = run_friction_study(design, SETTINGS, scheduler="synchronous",
                            design_attrs={"method": "factorial"})
    _assert_equals_serial(ds, _serial(design))
    assert (ds["status"].values == 0).all()
    assert ds.attrs["solver_nodes"] == 64 and ds.attrs["design_method"] == "factorial"
    assert ds.attrs["points_converged"] == 8 and ds.attrs["wall_time"] > 0
    for name in ("friction_coefficient", "hertz_pressure", "status"):
        assert "long_name" in ds[name].attrs and "units" in ds[name].attrs


def test_2x2x2_design_on_a_local_cluster_equals_serial_solver_calls():
    distributed = pytest.importorskip("distributed")
    design = _design_2x2x2()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        ds = run_friction_study(design, SETTINGS, scheduler=client)
    _assert_equals_serial(ds, _serial(design))


def test_killed_study_resumes_with_the_missing_points_only(tmp_path, monkeypatch):
    """Killed while its third point runs (two chunks of one point on disk), the same study
    started again solves only the other six; the result equals an uninterrupted run; the
    parts of another design are refused."""
    design = _design_2x2x2()
    out = tmp_path / "fs.nc"
    calls: list[int] = []
    real = fstudy.solve_design_point

    def counting(settings, index, point):
        calls.append(index)
        if len(calls) == 3 and not getattr(counting, "resumed", False):
            raise KeyboardInterrupt
        return real(settings, index, point)

    monkeypatch.setattr(fstudy, "solve_design_point", counting)
    with pytest.raises(KeyboardInterrupt):
        run_friction_study(design, SETTINGS, output=out, scheduler="synchronous",
                           chunk_size=1)
    assert len(list(ResultStore.parts_dir(out).glob("chunk-*.nc"))) == 2
    calls.clear()
    counting.resumed = True
    resumed = run_friction_study(design, SETTINGS, output=out, scheduler="synchronous",
                                 chunk_size=1)
    assert sorted(calls) == [2, 3, 4, 5, 6, 7]
    assert resumed.attrs["points_resumed"] == 2
    _assert_equals_serial(resumed, _serial(design))
    other = {**design, "temperature": design["temperature"] + 10.0}
    with pytest.raises(InputError, match="different study"):
        run_friction_study(other, SETTINGS, output=out, scheduler="synchronous")


# ----------------------------------------------------------------------------- commands
def test_friction_study_and_fit_commands(tmp_path, monkeypatch, capsys):
    """``ltca friction-study`` (4 Sobol conditions, 64 nodes, this process: ~1 s) writes
    the study file with its provenance; ``ltca friction-fit`` fits the committed study and
    writes a coefficient file the model reads (two training files; ~3 s)."""
    from contact.cli import main
    from friction.kolivand2009 import DATA_DIR, load_kolivand2009_fit
    from geometry.core.io import read_netcdf

    monkeypatch.chdir(tmp_path)
    assert main(["friction-study", "-n", "4", "--nodes", "64", "--scheduler", "synchronous",
                 "-o", "fs.nc", "--no-progress"]) == 0
    assert "4 conditions" in capsys.readouterr().out
    ds = read_netcdf(tmp_path / "fs.nc", tree=False)
    assert ds.sizes["point"] == 4 and ds.attrs["design_method"] == "sobol"
    assert ds.attrs["solver_nodes"] == 64 and "solver_commit" in ds.attrs
    assert not ResultStore.parts_dir(tmp_path / "fs.nc").exists()
    # the Sobol design and its --skip 1024 continuation, as the bundled fit was made
    assert main(["friction-fit", str(DATA_DIR / "friction_study_75W90.nc"),
                 str(DATA_DIR / "friction_study_75W90_skip1024.nc"), "--held-out",
                 str(DATA_DIR / "friction_study_75W90_heldout.nc"), "-o", "k.toml"]) == 0
    assert "held out" in capsys.readouterr().out
    fit = load_kolivand2009_fit(tmp_path / "k.toml")
    # the bundled file is this fit of the committed data (coefficients to 1e-4: the
    # optimum is flat along some directions, tests/test_kolivand2009.py compares μ to 1e-6)
    np.testing.assert_allclose(np.asarray(fit.coefficients),
                               np.asarray(load_kolivand2009_fit("75W90").coefficients),
                               rtol=1e-4, atol=1e-6)
    assert main(["friction-fit", str(DATA_DIR / "friction_study_75W90.nc"), "-o", "k.txt"]) != 0
    assert "must end in .toml" in capsys.readouterr().err


def test_realisations_are_averaged():
    """realisations=2 stores the mean of the two profile pairs' solutions (seeds 1, 2 and
    3, 4) and their spread — each solved here on its own (64 nodes, λ ≈ 5: ~0.2 s)."""
    point = {"hertz_pressure": 800.0, "radius": 20.0, "entraining_velocity": 5.0,
             "slide_to_roll": 0.3, "temperature": 25.0, "roughness_1": 0.3,
             "roughness_2": 0.4}
    both = solve_design_point(SolveSettings(nodes=64, realisations=2), 0, point)
    one = solve_design_point(SolveSettings(nodes=64, profile_seeds=(1, 2)), 0, point)
    two = solve_design_point(SolveSettings(nodes=64, profile_seeds=(3, 4)), 0, point)
    assert (both.status, one.status, two.status) == (0, 0, 0)
    assert both.values["realisations_converged"] == 2
    mus = [one.values["friction_coefficient"], two.values["friction_coefficient"]]
    assert mus[0] != mus[1]  # the realisations differ
    assert both.values["friction_coefficient"] == pytest.approx(np.mean(mus), rel=1e-12)
    assert both.values["friction_coefficient_spread"] == pytest.approx(np.std(mus), rel=1e-9)
    assert one.values["friction_coefficient_spread"] == 0.0


def test_combine_studies_and_refusals():
    from friction.kolivand2009 import DATA_DIR
    from friction.study.fit import RESOLVED_MODEL_SETTINGS, combine_studies, fit_kolivand2009
    from geometry.core.io import read_netcdf

    held = read_netcdf(DATA_DIR / "friction_study_75W90_heldout.nc", tree=False)
    both = combine_studies([held, held])
    assert both.sizes["point"] == 2 * held.sizes["point"]
    assert both["point"].values.tolist() == list(range(2 * held.sizes["point"]))
    assert both.attrs["wall_time"] == pytest.approx(2 * held.attrs["wall_time"])
    assert both.attrs["design_method"] == "lhs; lhs"
    more = held.copy()
    more.attrs = {**held.attrs, "solver_realisations": 2}  # the same model sampled more often
    assert combine_studies([held, more]).attrs["solver_realisations"] == "1; 2"
    # a stored study (written before issue 61, with the resolved models' settings) and a
    # new one without them combine, either first; the settings that differ still refuse
    new = held.copy()
    new.attrs = {k: v for k, v in held.attrs.items() if k not in RESOLVED_MODEL_SETTINGS}
    assert "solver_courant" in held.attrs and "solver_courant" not in new.attrs
    assert combine_studies([held, new]).sizes["point"] == 2 * held.sizes["point"]
    assert combine_studies([new, held]).sizes["point"] == 2 * held.sizes["point"]
    transient = new.copy()
    transient.attrs = {**new.attrs, "solver_mode": "transient"}
    with pytest.raises(InputError, match="solver_mode differs"):
        combine_studies([new, transient])
    other = held.copy()
    other.attrs = {**held.attrs, "solver_nodes": 1024}
    with pytest.raises(InputError, match="solver_nodes differs"):
        combine_studies([held, other])
    with pytest.raises(InputError, match="at least one"):
        combine_studies([])
    with pytest.raises(InputError, match=r"^features: unknown \['ln_X'\]"):
        fit_kolivand2009(held, features=("1", "ln_X"))
    with pytest.raises(InputError, match=r"^ridge: must be >= 0"):
        fit_kolivand2009(held, ridge=-1.0)
    with pytest.raises(InputError, match=r"^structure: must be one of"):
        fit_kolivand2009(held, structure="cubic")
    with pytest.raises(InputError, match=r"^study: not a friction study"):
        fit_kolivand2009(held.drop_vars("status"))


def test_eyring_fit_refuses_an_oil_without_traction_properties(tmp_path):
    # the 'eyring' structure's film traction needs τ₀ and Λ: an oil TOML without them is
    # refused naming them (the split structure still fits)
    from friction.kolivand2009 import DATA_DIR
    from friction.study.fit import fit_kolivand2009
    from geometry.core.io import read_netcdf

    text = (DATA_DIR / "75W90.toml").read_text(encoding="utf-8")
    keep = [line for line in text.splitlines()
            if not line.startswith(("eyring_stress", "limiting_shear_coefficient"))]
    oil = tmp_path / "bare.toml"
    oil.write_text("\n".join(keep) + "\n", encoding="utf-8")
    held = read_netcdf(DATA_DIR / "friction_study_75W90_heldout.nc", tree=False)
    held.attrs = {**held.attrs, "solver_lubricant": str(oil)}
    with pytest.raises(InputError, match=r"^lubricant: .* has no \['eyring_stress', "
                                         r"'limiting_shear_coefficient'\]"):
        fit_kolivand2009(held)
    assert fit_kolivand2009(held, structure="split").structure == "split"


def test_fit_refuses_a_boundary_friction_table(tmp_path):
    # kolivand2009 holds one μ_b and takes no temperature: an oil whose boundary_friction is
    # a table against temperature is refused by the structures that use μ_b, naming it
    # (the 'regimes' structure, without μ_b, still fits)
    from friction.kolivand2009 import DATA_DIR
    from friction.study.fit import fit_kolivand2009
    from geometry.core.io import read_netcdf

    text = (DATA_DIR / "75W90.toml").read_text(encoding="utf-8").replace(
        "boundary_friction = 0.1\n", "")
    oil = tmp_path / "table.toml"
    oil.write_text(text + "\n[boundary_friction]\ntemperature = [40.0, 120.0]\n"
                   "value = [0.1, 0.12]\nsource = \"a test\"\n", encoding="utf-8")
    held = read_netcdf(DATA_DIR / "friction_study_75W90_heldout.nc", tree=False)
    held.attrs = {**held.attrs, "solver_lubricant": str(oil)}
    for structure in ("eyring", "split"):
        with pytest.raises(InputError, match=r"^boundary_friction: .* table against "
                                             r"temperature.*'regimes'"):
            fit_kolivand2009(held, structure=structure)
    assert fit_kolivand2009(held, structure="regimes").structure == "regimes"
