"""The oil library (issue 74, deliver item 4): ISO VG 68–460 of mineral, PAO and PAG gear
oils by name.

References, each independent of the code under test:

* ASTM D2270's viscosity index of each stored (ν40, ν100) pair, computed by an independent
  implementation of the standard (``chemicals.viscosity.viscosity_index``, Caleb Bell's
  Chemical Engineering Design Library, with the standard's L and H tables): the class VI
  within 0.1 — the file stores ν100 rounded to 0.01 mm²/s, which moves the VI by at most
  0.07 at VG 68 (dVI/dν100 ≈ 14 per mm²/s there) and less at the higher grades;
* ISO 3448's mid-point: ν40 equals the grade in each name, exactly;
* the oil built from the sheet: its table lies on the ASTM D341 line through ν40 and
  ν100, so its own Walther fit returns them to the table's 6 printed digits (1e-5); the
  efficiency stage's Vogel fit through the same table within 1 % (measured ≤ 0.8 %: a
  three-constant Vogel curve through six points of a Walther line);
* ISO/TR 15144-1's α₃₈ = a η₃₈^b by hand for each base stock (1e-9);
* a case naming a library oil runs through ``ltca run`` from another working directory,
  the rating and the scuffing step included, and records the oil's name.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from friction.lubricant import (
    available_lubricants,
    density,
    kinematic_viscosity,
    load_lubricant,
    pressure_viscosity_coefficient,
    viscosity,
)
from friction.oil_library import (
    LIBRARY_SCHEMA,
    _parse,
    library_oil,
    library_oil_names,
    library_oils,
)
from geometry.core.errors import InputError, ModelUnavailableError

REPO = Path(__file__).resolve().parents[1]
GRADES = (68, 100, 150, 220, 320, 460)
CLASSES = {"mineral": ("mineral", 95.0), "PAO": ("polyalphaolefin", 150.0),
           "PAG": ("polyglycol_water_soluble", 220.0)}


def test_the_library_holds_the_grades_of_each_class():
    assert library_oil_names() == tuple(f"ISO_VG{g}_{c}" for c in CLASSES for g in GRADES)
    for name, oil in library_oils().items():
        grade = int(re.fullmatch(r"ISO_VG(\d+)_\w+", name).group(1))
        assert oil.sheet.kinematic_viscosity_40 == grade  # ISO 3448's mid-point
        base, vi = CLASSES[oil.oil_class]
        assert oil.sheet.base_oil == base and oil.viscosity_index == vi


@pytest.mark.parametrize("name", [f"ISO_VG{g}_{c}" for c in CLASSES for g in GRADES])
def test_nu100_gives_the_class_viscosity_index_by_astm_d2270(name):
    chem = pytest.importorskip("chemicals.viscosity")
    oil = library_oil(name)
    vi = chem.viscosity_index(oil.sheet.kinematic_viscosity_40 * 1e-6,
                              oil.sheet.kinematic_viscosity_100 * 1e-6)
    assert abs(vi - oil.viscosity_index) <= 0.1, (name, vi)


@pytest.mark.parametrize("name", [f"ISO_VG{g}_{c}" for c in CLASSES for g in GRADES])
def test_the_built_oil_reproduces_its_nu40_and_nu100(name):
    sheet = library_oil(name).sheet
    oil = load_lubricant(name)
    want = [sheet.kinematic_viscosity_40, sheet.kinematic_viscosity_100]
    np.testing.assert_allclose(kinematic_viscosity(oil, [40.0, 100.0], method="walther"),
                               want, rtol=1e-5)
    np.testing.assert_allclose(kinematic_viscosity(oil, [40.0, 100.0]), want, rtol=0.01)
    # ρ15 of the sheet on ISO/TR 15144-1's line, η = ν ρ
    np.testing.assert_allclose(density(oil, 15.0), sheet.density_15 - 0.7 * (15 + 273 - 289),
                               rtol=1e-9)
    np.testing.assert_allclose(viscosity(oil, 40.0), kinematic_viscosity(oil, 40.0) * 1e-6
                               * density(oil, 40.0), rtol=1e-9)


@pytest.mark.parametrize(("name", "a", "b"), [("ISO_VG220_mineral", 2.657e-8, 0.1348),
                                              ("ISO_VG220_PAO", 1.466e-8, 0.0507),
                                              ("ISO_VG220_PAG", 1.392e-8, 0.1572)])
def test_alpha_is_iso_tr_15144_1s_of_the_base_stock(name, a, b):
    sheet = library_oil(name).sheet
    # η38 by hand: ASTM D341 through ν40 and ν100, ρ(38) = ρ15 − 0.7 (38 + 273 − 289)
    x = np.log10(np.array([313.15, 373.15]))
    z = np.log10(np.log10(np.array([sheet.kinematic_viscosity_40,
                                    sheet.kinematic_viscosity_100]) + 0.7))
    z38 = z[0] + (z[1] - z[0]) / (x[1] - x[0]) * (np.log10(311.15) - x[0])
    eta38 = (10 ** 10 ** z38 - 0.7) * 1e-6 * (sheet.density_15 - 0.7 * 22.0)
    alpha38 = a * eta38 ** b * 1e9
    alpha40 = alpha38 * (1 + 516 * (1 / 313.0 - 1 / 311.0))
    # the file stores α to 5 significant digits
    np.testing.assert_allclose(pressure_viscosity_coefficient(load_lubricant(name), 40.0),
                               alpha40, rtol=2e-4)


def test_every_oil_states_its_sources():
    for name in library_oil_names():
        oil = load_lubricant(name)
        assert oil.name == name and oil.base_oil == library_oil(name).sheet.base_oil
        for what in ("ISO 3448", "ASTM D2270", "assumed class value", "not one product's",
                     "ISO/TR 15144-1"):
            assert what in oil.source, (name, what)
        assert oil.fzg_load_stage == 12.0 and "DIN 51517-3" in oil.durability_source


def test_names_are_bundled_oils_and_the_fit_file_is_not():
    names = available_lubricants()
    assert names[0] == "75W90" and set(library_oil_names()) <= set(names)
    assert "kolivand2009_75W90" not in names  # the fitted coefficients are no oil
    assert load_lubricant("iso_vg320_pao").name == "ISO_VG320_PAO"
    with pytest.raises(ModelUnavailableError, match="ISO_VG220_mineral"):
        load_lubricant("ISO_VG230_mineral")
    with pytest.raises(ModelUnavailableError, match="library"):
        library_oil("VG220")


def _file() -> dict:
    import tomllib

    return tomllib.loads((REPO / "friction" / "data" / "oils" / "library.toml").read_text(
        encoding="utf-8"))


@pytest.mark.parametrize(("edit", "field"), [
    (lambda d: d.update(schema="x"), "schema"),
    (lambda d: d["units"].update(density_15="g/ml"), "units"),
    (lambda d: d["oil"]["ISO_VG68_PAO"].update(viscosity_index=151.0),
     r"oil\.ISO_VG68_PAO\.viscosity_index"),
    (lambda d: d["oil"]["ISO_VG68_PAO"].pop("density_15"), r"oil\.ISO_VG68_PAO"),
    (lambda d: d["oil"]["ISO_VG68_PAO"].update({"class": "ester"}), r"ISO_VG68_PAO\.class"),
])
def test_a_broken_library_file_is_refused_naming_the_field(edit, field):
    data = _file()
    assert data["schema"] == LIBRARY_SCHEMA
    edit(data)
    with pytest.raises(InputError, match=field):
        _parse(data, "library.toml")


def test_ltca_oil_list_prints_the_bundled_oils():
    done = subprocess.run([sys.executable, "-m", "contact", "oil", "--list"],
                          capture_output=True, text=True, cwd=REPO, check=False)
    assert done.returncode == 0, done.stderr
    for name in available_lubricants():
        assert re.search(rf"^{name}\s", done.stdout, re.M), name
    bad = subprocess.run([sys.executable, "-m", "contact", "oil", "--name", "x"],
                         capture_output=True, text=True, cwd=REPO, check=False)
    assert bad.returncode == 2 and "--nu40" in bad.stderr


@pytest.mark.parametrize(("oil", "model"), [("ISO_VG220_mineral", None),
                                             ("vg220.toml", "thermal_eyring")])
def test_a_case_with_an_oil_runs_from_another_directory(tmp_path, oil, model):
    """``[operating] lubricant = "ISO_VG220_mineral"`` (a library oil) or ``"vg220.toml"``
    (an ISO VG 220 mineral oil's data-sheet file beside the case, issue 74's "Done when",
    with ``thermal_eyring``) through ``ltca run`` (one torque, a coarse LTCA), the rating
    and the scuffing step included, from another working directory."""
    from contact.catalogue import bundled_case_path
    from friction.oil_data_sheet import OilDataSheet, oil_file_mapping
    from geometry.core.toml_files import dump_toml

    text = bundled_case_path().read_text(encoding="utf-8")
    assert 'lubricant = "75W90"' in text
    casedir, elsewhere = tmp_path / "case", tmp_path / "elsewhere"
    casedir.mkdir()
    elsewhere.mkdir()
    name = oil
    if oil.endswith(".toml"):
        name = "VG220_mineral"
        sheet = OilDataSheet(name=name, kinematic_viscosity_40=220.0,
                             kinematic_viscosity_100=19.4, density_15=890.0,
                             base_oil="mineral", fzg_load_stage=12.0,
                             source="typical ISO VG 220 mineral EP gear oil (class values)")
        (casedir / oil).write_text(dump_toml(oil_file_mapping(sheet)), encoding="utf-8")
    case = casedir / "mycase.toml"
    case.write_text(text.replace('lubricant = "75W90"', f'lubricant = "{oil}"', 1),
                    encoding="utf-8")
    out = elsewhere / "out.nc"
    cmd = [sys.executable, "-m", "contact", "run", str(case), "--torque", "250",
           "--rolls-per-cycle", "6", "--segments", "12", "--no-root-stress", "--no-progress",
           "-o", str(out)]
    if model:
        cmd += ["--friction-model", model]
    done = subprocess.run(cmd, capture_output=True, text=True, cwd=elsewhere, check=False,
                          env={**os.environ, "PYTHONPATH": str(REPO)})
    assert done.returncode == 0, done.stderr[-2000:]
    assert f"{name} at 90 degC" in done.stdout
    assert "FZG load stage 12" in done.stdout
    with xr.open_dataset(out, group="friction") as fr:
        assert fr.attrs["lubricant"] == name
        eff = float(fr["efficiency_mean"].values[0])
    assert 0.9 < eff < 1.0
    with xr.open_dataset(out, group="rating") as rating:
        assert rating.sizes["torque"] == 1
