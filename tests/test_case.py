"""Case files, blank trimming, the flank Dataset and plots.

Published references: ISO 23509:2016 Annex F outside and root diameters at the heel and the
inner crown-to-crossing-point distances (not used to build the case files), copied below.
"""

from __future__ import annotations

import copy
import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from geometry.case import OPERATING_DEFAULTS, case_from_dict, load_case
from geometry.core.errors import InputError
from geometry.machine.flank import blank_outline, flank_dataset, flank_surface, projection_grid
from geometry.plot import plot_flanks_in_mesh, plot_projection_grid

CASES = Path(__file__).resolve().parents[1] / "cases"
S1 = CASES / "spiral_bevel_iso23509_s1.toml"
S2 = CASES / "hypoid_iso23509_s2.toml"

# ISO 23509:2016 Annex F, tables F.3 and F.6: outside diameter d_ae, root diameter d_fe at
# the heel, inner crown to crossing point t_xi [mm], with the relative tolerance that matches
# the printed precision (sample 2 values carry the 2 % tolerance of the data set)
ISO_HEEL = {
    (S1, "pinion"): dict(dae=75.324, dfe=58.102, txi=63.395, tol=0.003),
    (S1, "gear"): dict(dae=178.288, dfe=172.106, txi=22.117, tol=0.003),
    (S2, "pinion"): dict(dae=73.528, dfe=59.877, txi=54.135, tol=0.02),
    (S2, "gear"): dict(dae=171.560, dfe=166.196, txi=19.653, tol=0.02),
}


@cache
def _raw(path):
    with open(path, "rb") as fh:
        return tomllib.load(fh)


def _mutated(path, dotted, value):
    raw = copy.deepcopy(path if isinstance(path, dict) else _raw(path))
    node = raw
    keys = dotted.split(".")
    for k in keys[:-1]:
        node = node[k]
    if value is _DELETE:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value
    return raw


_DELETE = object()


def test_load_converts_degrees_once():
    """Angles are radians after loading (the file's degrees × π/180), lengths unchanged."""
    case = load_case(S2)
    raw = _raw(S2)
    assert case.pinion.blank.pitch_angle == math.radians(raw["pinion"]["blank"]["pitch_angle"])
    assert case.pair.shaft_angle == math.radians(90.0)
    assert case.gear.concave.blade.blade_angle == math.radians(
        raw["gear"]["cutter"]["concave"]["blade_angle"])
    assert case.pinion.convex.machine.tilt == math.radians(
        raw["pinion"]["machine"]["convex"]["tilt"])
    assert case.pinion.blank.face_width == raw["pinion"]["blank"]["face_width"]
    assert case.gear.process == "Formate" and case.pinion.process == "Generate"
    assert case.pinion.concave.blade.side == "outside"
    assert "pinion.machine.concave" in case.synthesised
    assert case.extra["derivation"]["gear_rotation_deg"] > 0


def _assert_close(a, b, path="case"):
    if hasattr(a, "__dataclass_fields__"):
        for name in a.__dataclass_fields__:
            _assert_close(getattr(a, name), getattr(b, name), f"{path}.{name}")
    elif isinstance(a, float):
        # degrees → rad → degrees → rad may move the last bit
        assert a == pytest.approx(b, rel=1e-14, abs=1e-300), path
    elif isinstance(a, tuple):
        assert len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b, strict=True)):
            _assert_close(x, y, f"{path}[{k}]")
    elif hasattr(a, "items"):
        assert dict(a) == dict(b), path
    else:
        assert a == b, path


@pytest.mark.parametrize("path", [S1, S2])
def test_to_toml_round_trip(path):
    """case_from_dict(tomllib.loads(case.to_toml())) reproduces the case (to the last bit of
    the degree conversion), extra tables included."""
    case = load_case(path)
    again = case_from_dict(tomllib.loads(case.to_toml()))
    _assert_close(case, again)


def test_infinite_limits_of_an_extra_table_round_trip():
    """An ``[optimize]`` table may say "no limit" with TOML's ``inf`` (e.g.
    ``max_flank_pressure = [inf, inf, 2000]``): to_toml writes it back as ``inf`` (it used
    to refuse it, failing every evaluation of an optimisation whose case carried one), and a
    NaN is still refused by name."""
    raw = tomllib.loads(S2.read_text(encoding="utf-8"))
    raw["optimize"] = {"max_flank_pressure": [math.inf, -math.inf, 2000.0]}
    case = case_from_dict(raw)
    again = case_from_dict(tomllib.loads(case.to_toml()))
    assert again.extra["optimize"]["max_flank_pressure"] == [math.inf, -math.inf, 2000.0]
    raw["optimize"] = {"max_flank_pressure": math.nan}
    with pytest.raises(InputError, match="to_toml: non-finite value nan"):
        case_from_dict(raw).to_toml()


def test_a_nan_in_a_case_names_its_key_and_table():
    """A NaN the case would write is refused naming where it is ("at [optimize]
    max_flank_pressure"; nested tables by their dotted name): ``ltca synthesize`` of the FM
    14x19 at Sigma 60 (branch unseen98) stopped on "to_toml: non-finite value nan" alone,
    which named no field of the case it was about to write."""
    raw = tomllib.loads(S2.read_text(encoding="utf-8"))
    raw["optimize"] = {"max_flank_pressure": math.nan}
    with pytest.raises(InputError, match=r"non-finite value nan at \[optimize\] "
                                         r"max_flank_pressure$"):
        case_from_dict(raw).to_toml()
    from geometry.core.toml_files import dump_toml

    with pytest.raises(InputError, match=r"at \[a\.b\] x$"):
        dump_toml({"a": {"b": {"x": [1.0, math.nan]}}})
    with pytest.raises(InputError, match=r"non-finite value nan at y$"):
        dump_toml({"y": math.nan})


@pytest.mark.parametrize("dotted, value, match", [
    ("pinion.blank.teeth", -3, r"^pinion\.blank\.teeth: must be an integer in \[3, 500\]"),
    ("pinion.blank.teeth", 13.5, r"^pinion\.blank\.teeth: must be an integer"),
    ("gear.cutter.concave.blade_angle", 60.0,
     r"^gear\.cutter\.concave\.blade_angle: must be in \[0, 45\) deg"),
    ("pinion.machine.concave.ratio_of_roll", -1,
     r"^pinion\.machine\.concave\.ratio_of_roll: must be > 0"),
    ("gear.machine.convex.ratio_of_roll", 2.0, r"^gear\.machine\.convex\.ratio_of_roll:"),
    ("gear.blank.toothcount", 3, r"^gear\.blank\.toothcount: unknown field"),
    ("pinion.blank.face_width", _DELETE, r"^pinion\.blank\.face_width: missing"),
    ("pair.gear_hand", "left", r"^pair\.gear_hand: must be the opposite"),
    ("pair.shaft_angle", "90", r"^pair\.shaft_angle: must be a number"),
    ("pair.shaft_angle", 190.0, r"^pair\.shaft_angle: must be in \(0, 180\)"),
    ("pair.drive_flank", "left", r"^pair\.drive_flank:"),
    ("pinion.blank.face_apex", 3.0, r"^pinion\.blank\.face_apex: the cone through"),
    ("gear.blank.face_width", 200.0, r"^gear\.blank\.face_width: must be in"),
    ("gear.cutter.convex.profile", "parabolic", r"^gear\.cutter\.convex\.profile:"),
    ("pinion.process", "Hob", r"^pinion\.process:"),
    ("synthesised", ["pinion.blank.nonsense"], r"^synthesised:"),
    ("gear.machine.concave.tilt", 100.0, r"^gear\.machine\.concave\.tilt: must be in"),
    ("operating.delta_Sigma", 30.0, r"^operating\.delta_Sigma: must be in \(-10, 10\) deg"),
    ("operating.torque", [50.0, -1.0], r"^operating\.torque: must be in \(0, 1e\+06\] \[N m\]"),
    ("operating.torque", [], r"^operating\.torque: must be one or more"),
    ("operating.pinion_speed", -5.0, r"^operating\.pinion_speed: must be in \(0, 50000\] \[rpm\]"),
    ("operating.temperature", -300.0,
     r"^operating\.temperature: must be in \[-40, 200\] \[degC\]"),
    ("operating.roughness", 0.0, r"^operating\.roughness: must be in \(0, 5\] \[um\]"),
    ("operating.lubricant", 75, r"^operating\.lubricant: must be a string"),
    ("operating.speed", 1500.0, r"^operating\.speed: unknown field; accepted: torque"),
    ("source", "", r"^source:"),
])
def test_bad_fields_are_named(dotted, value, match):
    """Every invalid field raises InputError whose message starts with its dotted path and
    says the accepted range."""
    with pytest.raises(InputError, match=match):
        case_from_dict(_mutated(S2, dotted, value))


def test_operating_table_round_trips_and_the_old_misalignment_table_still_loads():
    """[operating] holds torques, misalignment (ΔΣ in deg in the file, rad in Misalignment)
    and the efficiency conditions; to_toml writes it back; a case of the older layout (a
    top-level [misalignment]) loads the same; both at once is refused."""
    raw = _raw(S2)
    raw.pop("misalignment", None)
    raw["operating"] = {"torque": [100.0, 200.0], "delta_E": -0.1, "delta_Sigma": 0.05,
                        "pinion_speed": 0.0, "temperature": 60.0}
    c = case_from_dict(raw)
    assert c.operating.torque == (100.0, 200.0) and c.operating.pinion_speed == 0.0
    assert c.misalignment.delta_E == -0.1
    assert c.misalignment.delta_Sigma == pytest.approx(math.radians(0.05), rel=1e-15)
    assert c.operating.roughness == OPERATING_DEFAULTS["roughness"]
    again = case_from_dict(tomllib.loads(c.to_toml()))
    assert again.operating == c.operating and again.misalignment == c.misalignment
    old = _raw(S2)
    old.pop("operating", None)
    old["misalignment"] = {"delta_E": -0.1, "delta_Sigma": 0.05}
    assert case_from_dict(old).misalignment == c.misalignment
    both = {**old, "operating": {"delta_E": 0.1}}
    with pytest.raises(InputError, match=r"^misalignment: give the misalignment once"):
        case_from_dict(both)


def test_face_hobbing_needs_blade_groups_on_both_members():
    """FH is accepted as a method, but a pair without the cutter's blade groups cannot be
    face-hobbed: the error names the field and its range."""
    with pytest.raises(InputError, match=r"^pinion\.cutter\.blade_groups: must be an integer "
                                         r"in \[1, 50\] for a face-hobbed pair"):
        case_from_dict(_mutated(S1, "pair.method", "FH"))
    fh = _mutated(_mutated(_mutated(S1, "pair.method", "FH"), "pinion.cutter.blade_groups",
                           5), "gear.cutter.blade_groups", 0)
    with pytest.raises(InputError, match=r"^gear\.cutter\.blade_groups"):
        case_from_dict(fh)


@pytest.mark.parametrize(("dotted", "value", "match"), [
    ("pinion.cutter.blade_groups", 3, r"^pinion\.cutter\.blade_groups: must be 0 or absent "
                                      r"for a face-milled pair"),
    ("gear.cutter.blade_groups", 2.5, r"^gear\.cutter\.blade_groups: must be an integer"),
    ("gear.cutter.blade_groups", -1, r"^gear\.cutter\.blade_groups: must be an integer in "
                                     r"\[0, 50\]"),
    ("gear.cutter.blade_groups", 13, r"^gear\.cutter\.blade_groups: must share no common "
                                     r"factor with the member's teeth \(z = 39\)"),
    ("gear.cutter.cutter_radius", -5.0, r"^gear\.cutter\.cutter_radius: must be >= 0"),
    ("gear.cutter.concave.blade_offset_angle", 50.0,
     r"^gear\.cutter\.concave\.blade_offset_angle: must be in \(-45, 45\) deg"),
    ("gear.cutter.convex.hook_angle", -25.0,
     r"^gear\.cutter\.convex\.hook_angle: must be in \(-20, 20\) deg"),
    ("gear.cutter.convex.rake_angle", 31.0,
     r"^gear\.cutter\.convex\.rake_angle: must be in \(-30, 30\) deg"),
    ("pinion.cutter.concave.blade_phase", 400.0,
     r"^pinion\.cutter\.concave\.blade_phase: must be in \[-360, 360\] deg"),
    ("gear.cutter.spindle", 1.0, r"^gear\.cutter\.spindle: unknown field; accepted: concave, "
                                 r"convex, blade_groups, cutter_radius"),
    ("gear.machine.concave.indexing_ratio", -0.1,
     r"^gear\.machine\.concave\.indexing_ratio: unknown field"),
])
def test_face_hobbing_fields_are_named(dotted, value, match):
    """The face-hobbing fields are validated with the field named (bad z0: not an integer,
    out of range, sharing a factor with the teeth; placement angles out of range; the
    indexing ratio is derived, never written)."""
    raw = S1
    if "blade_groups" in dotted and value != 3:
        raw = _mutated(_mutated(S1, "pair.method", "FH"), "pinion.cutter.blade_groups", 5)
    with pytest.raises(InputError, match=match):
        case_from_dict(_mutated(raw, dotted, value))


def test_file_errors(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        load_case(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("name = 'x'\n[pair\n", encoding="utf-8")
    with pytest.raises(InputError, match="invalid TOML"):
        load_case(bad)


@pytest.mark.parametrize("key", sorted(ISO_HEEL, key=str))
def test_blank_outline_matches_iso(key):
    """Heel tip and root corners are the outside and root diameters d_ae, d_fe at the heel,
    the toe tip corner lies at the inner crown-to-crossing-point distance t_xi (ISO 23509
    Annex F; none of these were used to write the case files); the front and back cones
    are ⟂ to the pitch cone (identity)."""
    path, member = key
    ref = ISO_HEEL[key]
    bl = getattr(load_case(path), member).blank
    out = blank_outline(bl)
    c = out.corners
    assert 2 * c[1, 1, 1] == pytest.approx(ref["dae"], rel=ref["tol"])
    assert 2 * c[1, 0, 1] == pytest.approx(ref["dfe"], rel=ref["tol"])
    assert c[0, 1, 0] == pytest.approx(ref["txi"], rel=ref["tol"])
    gen = np.array([math.cos(bl.pitch_angle), math.sin(bl.pitch_angle)])
    for iu in (0, 1):
        assert (c[iu, 1] - c[iu, 0]) @ gen == pytest.approx(0.0, abs=1e-12)


def test_projection_grid_layout_and_errors():
    """u runs toe → heel along the root and face lines, v root → tip; corners of the grid
    are the outline's corners (bilinear layout, identity)."""
    bl = load_case(S1).gear.blank
    g = projection_grid(bl, 5, 4, v_limits=(0.0, 1.0))
    c = blank_outline(bl).corners
    np.testing.assert_allclose([g.axial[0, 0], g.radius[0, 0]], c[0, 0], atol=1e-12)
    np.testing.assert_allclose([g.axial[-1, -1], g.radius[-1, -1]], c[1, 1], atol=1e-12)
    with pytest.raises(InputError, match="nu"):
        projection_grid(bl, 1, 4)
    with pytest.raises(InputError, match="v_limits"):
        projection_grid(bl, 4, 4, v_limits=(0.5, 0.2))


def test_projection_fractions_invert_the_grid_layout():
    """projection_fractions inverts the bilinear layout: the grid's own places give back
    their (u, v) fractions, as do places outside the outline (u, v in [−0.5, 1.5]), to
    1e-12; with one outline per point the same (identity, round-off only)."""
    from geometry.machine.flank import projection_fractions

    bl = load_case(S1).gear.blank
    c = blank_outline(bl).corners
    g = projection_grid(bl, 9, 7, v_limits=(0.0, 1.0))
    u, v = projection_fractions(c, g.axial, g.radius)
    np.testing.assert_allclose(u, np.broadcast_to(g.u[:, None], u.shape), atol=1e-12)
    np.testing.assert_allclose(v, np.broadcast_to(g.v[None, :], v.shape), atol=1e-12)
    # beyond the outline: the bilinear layout's formula continued
    uo, vo = np.meshgrid(np.linspace(-0.5, 1.5, 9), np.linspace(-0.5, 1.5, 7), indexing="ij")
    p = ((1 - uo) * (1 - vo))[..., None] * c[0, 0] + (uo * (1 - vo))[..., None] * c[1, 0] \
        + ((1 - uo) * vo)[..., None] * c[0, 1] + (uo * vo)[..., None] * c[1, 1]
    u, v = projection_fractions(c, p[..., 0], p[..., 1])
    np.testing.assert_allclose(u, uo, atol=1e-12)
    np.testing.assert_allclose(v, vo, atol=1e-12)
    per_point = np.repeat(c[None], uo.size, axis=0)
    u2, v2 = projection_fractions(per_point, p[..., 0].ravel(), p[..., 1].ravel())
    np.testing.assert_allclose(u2, u.ravel(), atol=1e-14)
    np.testing.assert_allclose(v2, v.ravel(), atol=1e-14)


def test_flank_dataset_conventions_and_netcdf_round_trip(tmp_path):
    """The Dataset has dims (u, v, xyz), every variable and coordinate carries units and
    long_name, attributes are netCDF-safe (geometry.core.io.check_conventions), and it survives a
    netCDF write/read unchanged (xarray.testing.assert_identical)."""
    io = pytest.importorskip("geometry.core.io")
    case = load_case(S2)
    ds = flank_dataset(case, "pinion", "concave", nu=7, nv=5)
    assert dict(ds.sizes) == {"u": 7, "v": 5, "xyz": 3}
    assert ds["position"].attrs["units"] == "mm"
    assert ds["kappa1"].attrs["units"] == "1/mm"
    assert int(ds["mask"].sum()) == 35
    io.check_conventions(ds)
    loaded = case_from_dict(tomllib.loads(ds.attrs["inputs"]))
    assert loaded.name == case.name
    path = io.write_netcdf(ds, tmp_path / "flank.nc", inputs=ds.attrs["inputs"])
    back = io.without_stamps(io.read_netcdf(path), ds)
    # the writer adds attributes (history, version, ACDD); the data come back identical
    for name in list(ds.data_vars) + list(ds.coords):
        xr.testing.assert_identical(back[name], ds[name])
    for key, val in ds.attrs.items():
        assert back.attrs[key] == val


def test_plots_write_png(tmp_path):
    """Both plots write a non-trivial PNG (magic number checked)."""
    case = load_case(S2)
    surfaces = [flank_surface(case, m, f, nu=7, nv=5) for m in ("pinion", "gear")
                for f in ("concave", "convex")]
    p1 = plot_flanks_in_mesh(case, surfaces, tmp_path / "mesh.png", teeth=2)
    p2 = plot_projection_grid(surfaces[2], case.gear.blank, tmp_path / "grid.png")
    for p in (p1, p2):
        data = p.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000
    with pytest.raises(InputError, match="directory"):
        plot_projection_grid(surfaces[0], case.pinion.blank, tmp_path / "no" / "x.png")


def test_deviations_table_resolves_round_trips_and_names_errors(tmp_path):
    """[deviations]: paths relative to the case file, absolute in Case.deviations, written
    back by to_toml (round trip), either member optional, a missing file named."""
    wear = load_case(CASES / "kolivand2009_fm_11x41_wear.toml")
    assert wear.deviations.pinion == str((CASES / "deviations/wear_11x41_pinion.csv").resolve())
    assert wear.deviations.gear == str((CASES / "deviations/wear_11x41_gear.csv").resolve())
    # the example is the base case plus the table (make_examples.py): same pair otherwise
    base = load_case(CASES / "kolivand2009_fm_11x41.toml")
    assert base.deviations is None and wear.pinion == base.pinion and wear.gear == base.gear
    again = case_from_dict(tomllib.loads(wear.to_toml()))
    _assert_close(wear, again)
    # a case file elsewhere: relative to that file, not to the working directory
    (tmp_path / "dev").mkdir()
    (tmp_path / "dev" / "g.csv").write_text("v\\u,0,0.5,1\n0,0,0,0\n0.5,0,0,0\n1,0,0,0\n")
    text = S2.read_text(encoding="utf-8") + '\n[deviations]\ngear = "dev/g.csv"\n'
    (tmp_path / "c.toml").write_text(text, encoding="utf-8")
    c = load_case(tmp_path / "c.toml")
    assert c.deviations.pinion is None
    assert c.deviations.gear == str((tmp_path / "dev" / "g.csv").resolve())
    _assert_close(c, case_from_dict(tomllib.loads(c.to_toml())))
    with pytest.raises(InputError, match=r"^deviations\.pinion: no such deviation file"):
        case_from_dict(_mutated(S2, "deviations", {"pinion": "nowhere.csv"}),
                       base_dir=tmp_path)
    with pytest.raises(InputError, match=r"^deviations\.gear: must be a string"):
        case_from_dict(_mutated(S2, "deviations", {"gear": 3}))
    with pytest.raises(InputError, match=r"^deviations\.wheel: unknown field"):
        case_from_dict(_mutated(S2, "deviations", {"wheel": "x.csv"}))
