"""The load-capacity method registry (contact.load_capacity.methods, issue 63 item 2).

A third method is one module and one registry entry: here a method registered by the test
itself (no toolkit module changed) — the nominal mean-point forces and speed of the pair,
F_mt1 = 2000 T1/d_m1, F_mt2 = F_mt1 cos β_m2/cos β_m1 and v_mt1 = π d_m1 n1/60000 (ISO
10300-1:2014 Eq. (1)–(2) and cl. 6.3) — goes through :func:`rate`, ``ltca rate --method``
and the written file exactly as ISO 10300 does. Its numbers are checked against
independent references, not against itself:

* F_mt1 against ISO/TR 10300-30:2024 sample 1's printed 10925.3 N (to the printed
  precision, ±0.05 N) and against the ISO 10300 method's own F_mt1, F_mt2 of the same case
  (the same definition through another code path: to 1e-12);
* v_mt1 against π d_m1 n1 written out here with the TR's printed d_m1 = 54.918 mm
  (sample 1, to the 5e-4 mm printed precision: 1e-5 relative).

The registry's own contract: an unknown name is refused listing the available ones, a
name cannot be registered twice (without ``replace``) or badly, ``/rating`` says which
method made it, the analysis' torques and speed are the defaults when an analysis is
given.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact import resolve_case
from contact.cli import main
from contact.load_capacity import (
    METHODS,
    available_methods,
    rate,
    register_method,
    unregister_method,
)
from contact.load_capacity.iso10300.rating import case_gear_data
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, ModelUnavailableError, PluginError
from geometry.core.io import read_netcdf

SAMPLES = tomllib.loads((Path(__file__).parent / "data" / "iso10300_30_samples.toml")
                        .read_text(encoding="utf-8"))
CASE = "iso10300_30_sample1"  # the TR's sample 1 as a bundled case ([design], [rating])


def mean_point_forces(case, torque, speed, *, flank=None, datasets=None):
    """A rating method of the registry's protocol: the nominal mean-point tangential forces
    [N] of pinion and gear and the pinion's mean-point speed [m/s] of ``case`` at the pinion
    torques ``torque`` [N·m] and speed ``speed`` [rpm] (ISO 10300-1:2014 Eq. (1)–(2),
    cl. 6.3); ``datasets`` and ``flank`` are recorded (the test reads them back)."""
    data, _ = case_gear_data(case)
    f1 = 2000.0 * np.asarray(torque, float) / data.d_m1
    f2 = f1 * math.cos(data.beta_m2) / math.cos(data.beta_m1)
    v = math.pi * data.d_m1 * speed / 60000.0
    # the result contract (contact.load_capacity.contract): a stated capacity of 1000 N m,
    # the contact stress growing as the square root of the torque, the root stress with it
    ratio = np.tile((1000.0 / np.asarray(torque, float))[:, None], (1, 2))
    return xr.Dataset(
        {"F_mt1": data_var(("torque",), f1, "N", "nominal tangential force of the pinion "
                                                 "at the mean point"),
         "F_mt2": data_var(("torque",), f2, "N", "nominal tangential force of the gear at "
                                                 "the mean point"),
         "v_mt1": data_var((), v, "m/s", "pinion pitch-line speed at the mean point"),
         "pitting_safety": data_var(("torque", "member"), np.sqrt(ratio), "1",
                                    "safety against pitting"),
         "pitting_safety_min": data_var((), 1.0, "1", "its minimum"),
         "bending_safety": data_var(("torque", "member"), ratio, "1",
                                    "safety against bending"),
         "bending_safety_min": data_var((), 1.0, "1", "its minimum")},
        coords={"torque": data_var(("torque",), np.asarray(torque, float), "N m",
                                   "pinion torque T1"),
                "member": data_var(("member",), ["pinion", "gear"], None, "member")},
        attrs={"title": "mean-point forces", "case": case.name,
               "groups_seen": ",".join(sorted(datasets or {})), "flank": str(flank)})


@pytest.fixture
def toy():
    """The toy method registered for one test, removed after it."""
    register_method("mean_point_forces", mean_point_forces,
                    title="nominal mean-point forces and speed (ISO 10300-1 Eq. (1)-(2))",
                    source="ISO 10300-1:2014; ISO/TR 10300-30:2024 sample 1")
    yield "mean_point_forces"
    if "mean_point_forces" in METHODS:
        unregister_method("mean_point_forces")


def test_the_bundled_method_is_registered():
    assert "iso10300" in available_methods()
    assert available_methods() == sorted(METHODS)
    entry = METHODS["iso10300"]
    assert "ISO 10300" in entry.title and "10300-30" in entry.source
    assert callable(entry.tables)


def test_a_third_method_is_one_function_and_one_entry(toy):
    """Registered from outside the toolkit: listed, rated through the one entry point, its
    dataset stamped with its name; its F_mt1 is ISO/TR 10300-30 sample 1's printed value,
    its v_mt1 π d_m1 n1 with the TR's printed d_m1."""
    assert toy in available_methods()
    published = SAMPLES["sample1"]["published"]
    torque = SAMPLES["sample1"]["operating"]["torque"]
    speed = SAMPLES["sample1"]["operating"]["pinion_speed"]
    ds = rate(CASE, [torque], speed, method=toy)
    assert ds.attrs["rating_method"] == toy
    assert ds.attrs["rating_method_title"] == METHODS[toy].title
    # the TR prints F_mt1 to 0.1 N: ±0.05 N is its precision
    assert float(ds["F_mt1"][0]) == pytest.approx(float(published["F_mt1"]), abs=0.05)
    d_m1 = float(SAMPLES["sample1"]["gear_data"]["d_m1"])
    # d_m1 printed to 1e-3 mm: 1e-5 relative covers its rounding (54.918 ± 0.0005)
    assert float(ds["v_mt1"]) == pytest.approx(math.pi * d_m1 * speed / 60000.0, rel=1e-5)


def test_the_toy_agrees_with_the_iso10300_method_on_the_same_case(toy):
    """The same definition through two methods of the registry: identical to round-off."""
    iso = rate(CASE, [120.0, 300.0], 1200.0, method="iso10300")
    mine = rate(CASE, [120.0, 300.0], 1200.0, method=toy)
    assert iso.attrs["rating_method"] == "iso10300"
    np.testing.assert_allclose(mine["F_mt1"].values, iso["F_mt1"].values, rtol=1e-12)
    np.testing.assert_allclose(mine["F_mt2"].values, iso["F_mt2"].values, rtol=1e-12)


def test_the_registry_rates_iso10300_as_the_function_does():
    """rate(method="iso10300") is iso10300_rating plus the two registry attributes."""
    from contact import iso10300_rating

    direct = iso10300_rating(CASE, [300.0], 1200.0)
    via = rate(CASE, [300.0], 1200.0)
    assert direct.attrs["rating_method"] == "iso10300"  # the method says so itself
    # every variable of the function, and the result contract beside them: S_H, S_F and
    # their minima under the contract's names
    xr.testing.assert_identical(via[list(direct.data_vars)].drop_attrs(deep=False),
                                direct.drop_attrs(deep=False))
    for contract, own in (("pitting_safety", "S_H"), ("bending_safety", "S_F"),
                          ("pitting_safety_min", "S_Hmin"), ("bending_safety_min", "S_Fmin")):
        np.testing.assert_array_equal(via[contract].values, direct[own].values)
    assert via.attrs["rating_method_title"] == METHODS["iso10300"].title
    assert via.attrs["rating_standard"] == "ISO 10300"


def test_defaults_come_from_the_analysis(toy):
    """With an analysis, the torques are its /ltca torques and the speed its /friction
    pinion speed (the chain's datasets), and the method sees the groups by path."""
    ltca = xr.Dataset(coords={"torque": ("torque", [50.0, 250.0])})
    friction = xr.Dataset(attrs={"pinion_speed_rpm": 900.0})
    ds = rate(CASE, method=toy, analysis={"ltca": ltca, "/friction": friction},
              flank="coast")
    np.testing.assert_array_equal(ds["torque"].values, [50.0, 250.0])
    data, _ = case_gear_data(resolve_case(CASE))
    assert float(ds["v_mt1"]) == pytest.approx(math.pi * data.d_m1 * 900.0 / 60000.0,
                                               rel=1e-14)
    assert ds.attrs["groups_seen"] == "/friction,/ltca" and ds.attrs["flank"] == "coast"
    tree = xr.DataTree.from_dict({"ltca": ltca, "friction": friction})
    assert rate(CASE, method=toy, analysis=tree).attrs["groups_seen"] == "/friction,/ltca"


def test_an_unknown_method_is_refused_listing_the_available_ones(toy):
    with pytest.raises(ModelUnavailableError, match="agma2001") as info:
        rate(CASE, method="agma2001")  # AGMA's cylindrical-gear standard: not a method
    assert all(m in str(info.value) for m in ("agma2003", "iso10300", toy))
    with pytest.raises(ModelUnavailableError, match="available: agma2003, iso10300"):
        unregister_method("agma2001")


@pytest.mark.parametrize(("kwargs", "field"), [
    ({"name": "ISO10300"}, "name"),
    ({"name": "2003"}, "name"),
    ({"function": "not callable"}, "function"),
    ({"title": " "}, "title"),
    ({"tables": 3}, "tables"),
])
def test_bad_registrations_are_refused_naming_the_field(kwargs, field):
    args = {"name": "probe", "function": mean_point_forces, "title": "t", "source": "s",
            **kwargs}
    with pytest.raises(PluginError, match=field):
        register_method(args.pop("name"), args.pop("function"), **args)
    assert "probe" not in METHODS


def test_a_name_is_registered_once(toy):
    with pytest.raises(PluginError, match="registered already"):
        register_method(toy, mean_point_forces, title="t", source="s")
    register_method(toy, mean_point_forces, title="again", source="s", replace=True)
    assert METHODS[toy].title == "again"


def test_bad_inputs_are_refused_naming_them(toy):
    with pytest.raises(InputError, match="flank"):
        rate(CASE, method=toy, flank="left")
    with pytest.raises(InputError, match="analysis"):
        rate(CASE, method=toy, analysis=[1, 2])
    with pytest.raises(InputError, match="ltca"):
        rate(CASE, method=toy, analysis={"ltca": "not a dataset"})
    register_method("broken", lambda *a, **k: {"F": 1.0}, title="t", source="s")
    try:
        with pytest.raises(PluginError, match="'broken' breaks the result contract: it "
                                              "returned dict"):
            rate(CASE, method="broken")
    finally:
        unregister_method("broken")


def test_ltca_rate_method_goes_through_the_registry(toy, tmp_path, capsys):
    """``ltca rate --method NAME``: the toy's variables printed one per line, its file's
    /rating stamped with the method; ISO 10300's own tables by default; an unknown name
    exits 2 with the available ones."""
    out = tmp_path / "toy.nc"
    assert main(["rate", CASE, "--method", toy, "--torque", "300", "-o", str(out)]) == 0
    text = capsys.readouterr().out
    assert "(method mean_point_forces)" in text
    line = next(ln for ln in text.splitlines() if ln.startswith("F_mt1"))
    assert "N" in line and "10925.3" in line
    tree = read_netcdf(out)
    assert tree["rating"].attrs["rating_method"] == toy
    assert tree.attrs["title"] == "mean-point forces"
    assert main(["rate", CASE, "--torque", "300"]) == 0
    assert capsys.readouterr().out.startswith("ISO 10300 Method B1: iso10300_30_sample1")
    assert main(["rate", CASE, "--method", "agma2001"]) == 2
    err = capsys.readouterr().err
    assert "unknown load-capacity rating method 'agma2001'" in err and "iso10300" in err


def test_the_analysis_chain_rates_by_a_registered_method_chosen_by_name(toy):
    """The chain's load-capacity step is chosen by a registry name (a plug-in's too): the
    analysis' /rating is the toy's, made from the analysis' own torques, speed and groups,
    and its F_mt1 is the ISO 10300 method's for the same case (same definition, 1e-12).
    Without the toy registered its name is refused listing the available ones."""
    from contact import LTCAOptions, available_steps, run_analysis

    assert toy in available_steps()["load_capacity"]
    tree = run_analysis(None, [250.0], options=LTCAOptions(rolls_per_cycle=4, segments=8),
                        geometry=False, root_stress=False, mesh_interface=False,
                        steps={"load_capacity": toy})
    rating = tree["rating"].to_dataset()
    assert rating.attrs["rating_method"] == toy
    assert {"/ltca", "/friction"} <= set(rating.attrs["groups_seen"].split(","))
    speed = float(tree["friction"].attrs["pinion_speed_rpm"])
    iso = rate("kolivand2009_fm_11x41_reference", [250.0], speed, method="iso10300")
    np.testing.assert_allclose(rating["F_mt1"].values, iso["F_mt1"].values, rtol=1e-12)
    assert "flash_temperature" not in tree["rating"].children  # ISO 10300's alone
    assert "scuffing_micropitting" in tree.children
    assert not METHODS[toy].nominal  # a plug-in rates after the analysis unless it says so
    unregister_method(toy)
    with pytest.raises(InputError, match=r"steps\.load_capacity: unknown step "
                                         r"'mean_point_forces'; available: iso10300"):
        run_analysis(None, [250.0], steps={"load_capacity": toy})


def test_a_nominal_method_is_rated_before_any_work():
    """A method that says it rates the nominal geometry (``nominal=True``, as ISO 10300 and
    ANSI/AGMA 2003 do) is rated before the chain's first step, so a bad table is refused
    before the contact analysis: here a nominal method refusing its input stops the chain
    before its LTCA step (a callable that records being called) ever runs."""
    from contact import run_analysis

    assert METHODS["iso10300"].nominal and METHODS["agma2003"].nominal

    def refuses(case, torque, speed, **_kw):
        raise InputError("rating.toy_field: must be in [0, 1], got 2")

    calls = []
    register_method("refusing_nominal", refuses, title="a nominal method refusing its input",
                    source="this test", nominal=True)
    try:
        with pytest.raises(InputError, match="toy_field"):
            run_analysis(None, [250.0], geometry=False, root_stress=False,
                         mesh_interface=False,
                         steps={"load_capacity": "refusing_nominal",
                                "ltca": lambda state: calls.append("ltca")})
    finally:
        unregister_method("refusing_nominal")
    assert calls == []
