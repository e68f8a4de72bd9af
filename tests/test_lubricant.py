"""Tests of friction.lubricant: fits to the seed's 75W90 table, interpolation, TOML loading."""

from __future__ import annotations

import csv
import warnings
from pathlib import Path

import numpy as np
import pytest

from friction.lubricant import (
    BoundaryFrictionTable,
    Lubricant,
    available_lubricants,
    boundary_friction_coefficient,
    boundary_friction_in_range,
    boundary_friction_source,
    density,
    fit_vogel,
    kinematic_viscosity,
    load_lubricant,
    pressure_viscosity_coefficient,
    temperature_range,
    temperature_viscosity_coefficient,
    thermal_conductivity,
    viscosity,
)
from friction.validity import FrictionModelRangeWarning
from geometry.core.errors import InputError, ModelUnavailableError

DATA = Path(__file__).parent / "data"


def _table() -> dict[str, np.ndarray]:
    """Seed Table 5.2, read from the test copy (independent of the bundled TOML)."""
    with open(DATA / "kolivand2009_table5_2_75W90.csv", encoding="utf-8") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


TABLE = _table()


@pytest.fixture(scope="module")
def oil() -> Lubricant:
    return load_lubricant("75W90")


def _toml(**overrides: str) -> str:
    fields = {
        "name": '"test oil"',
        "source": '"made up for a test"',
        "temperature": "[40.0, 70.0, 100.0]",
        "dynamic_viscosity": "[0.08, 0.025, 0.011]",
        "pressure_viscosity_coefficient": "[20.0, 15.0, 12.0]",
        "density": "[860.0, 842.0, 824.0]",
        "thermal_conductivity": "0.14",
    }
    fields.update(overrides)
    body = "\n".join(f"{k} = {v}" for k, v in fields.items() if v is not None)
    units = (
        '[units]\ntemperature = "degC"\ndynamic_viscosity = "Pa s"\n'
        'pressure_viscosity_coefficient = "1/GPa"\ndensity = "kg/m3"\n'
        'thermal_conductivity = "W/(m K)"\n'
    )
    return body + "\n" + units


# ----------------------------------------------------------------------------- fits vs table
@pytest.mark.parametrize("method", ["vogel", "walther"])
def test_viscosity_fit_reproduces_seed_table(oil: Lubricant, method: str) -> None:
    # Brief: within 2 % at the table points. A 3-parameter Vogel (or 2-parameter Walther)
    # least-squares fit to 4 points has one (two) residual degrees of freedom, so the
    # table need not be reproduced exactly; 2 % is well inside the 3-significant-digit
    # rounding of the smallest table entry plus typical fit error of these equations.
    eta = np.asarray(viscosity(oil, TABLE["temperature_degC"], method=method))
    np.testing.assert_allclose(eta, TABLE["dynamic_viscosity_Pa_s"], rtol=0.02)


@pytest.mark.parametrize("method", ["vogel", "walther"])
def test_viscosity_decreases_monotonically(oil: Lubricant, method: str) -> None:
    lo, hi = temperature_range(oil)
    t = np.linspace(lo, hi, 501)
    eta = np.asarray(viscosity(oil, t, method=method))
    assert np.all(np.diff(eta) < 0)
    assert np.all(eta > 0)


def test_vogel_and_walther_agree_between_table_points(oil: Lubricant) -> None:
    # Two different equations (Vogel on η; Walther on ν = η/ρ) fitted to the same table
    # must agree inside the table range to within the fit residuals (each < 0.2 % at the
    # nodes): tolerance 1 % (measured max difference 0.19 %). In the extrapolation
    # margins they diverge more (1.8 % at 140 °C) — a reason the range is bounded.
    t = np.linspace(25.0, 100.0, 31)
    np.testing.assert_allclose(
        viscosity(oil, t, "vogel"), viscosity(oil, t, "walther"), rtol=0.01
    )


def test_beta_is_log_derivative_of_vogel_fit(oil: Lubricant) -> None:
    # Identity: β = −d ln η/dT. Central differences with h = 1e-3 K have truncation error
    # O(h²·β''') ~ 1e-9 relative; tolerance 1e-6.
    t = np.array([30.0, 60.0, 90.0, 120.0])
    h = 1e-3
    fd = -(np.log(viscosity(oil, t + h)) - np.log(viscosity(oil, t - h))) / (2 * h)
    np.testing.assert_allclose(temperature_viscosity_coefficient(oil, t), fd, rtol=1e-6)


def test_beta_matches_table_secant_slopes(oil: Lubricant) -> None:
    # Independent of the fit: the secant slope of ln η between adjacent table points
    # equals β at some interior point (mean value theorem); at the midpoint the two differ
    # by O(Δt²·β''), which for ln η ~ b/(T − c) and Δt = 25 K is ≈ 1 % — tolerance 2 %.
    t = TABLE["temperature_degC"]
    ln_eta = np.log(TABLE["dynamic_viscosity_Pa_s"])
    secant = -np.diff(ln_eta) / np.diff(t)
    mid = 0.5 * (t[1:] + t[:-1])
    np.testing.assert_allclose(temperature_viscosity_coefficient(oil, mid), secant, rtol=0.02)


def test_pressure_viscosity_and_density_reproduce_table(oil: Lubricant) -> None:
    # Interpolation passes through the table points (log-linear α) and the density table
    # is exactly linear (0.6 kg/m3 per K), so a least-squares line reproduces it: 1e-9.
    t = TABLE["temperature_degC"]
    np.testing.assert_allclose(
        pressure_viscosity_coefficient(oil, t),
        TABLE["pressure_viscosity_coefficient_per_GPa"],
        rtol=1e-12,
    )
    np.testing.assert_allclose(density(oil, t), TABLE["density_kg_m3"], rtol=1e-9)


def test_pressure_viscosity_between_neighbours_and_decreasing(oil: Lubricant) -> None:
    t = np.linspace(*temperature_range(oil), 301)
    alpha = np.asarray(pressure_viscosity_coefficient(oil, t))
    assert np.all(np.diff(alpha) < 0)
    # at 90 degC it lies between the 75 and 100 degC values of Table 5.2
    a90 = pressure_viscosity_coefficient(oil, 90.0)
    assert 9.7 < a90 < 11.4


def test_kinematic_viscosity_is_dynamic_over_density(oil: Lubricant) -> None:
    # Identity ν = η/ρ with unit factor 1e6 (Pa s / (kg/m3) = m²/s → mm²/s): rtol 1e-12.
    t = np.array([40.0, 100.0])
    expect = np.asarray(viscosity(oil, t)) / np.asarray(density(oil, t)) * 1e6
    np.testing.assert_allclose(kinematic_viscosity(oil, t), expect, rtol=1e-12)


def test_fit_vogel_recovers_exact_vogel_data() -> None:
    # Data generated from known a, b, c must be recovered (the fit is exact there): the
    # 1-D search tolerance 1e-8 K in c bounds the parameter error; rtol 1e-4.
    a, b, c = 5e-5, 1100.0, -110.0
    t = np.array([20.0, 40.0, 60.0, 80.0, 100.0])
    fit = fit_vogel(t, a * np.exp(b / (t - c)))
    np.testing.assert_allclose([fit.a, fit.b, fit.c], [a, b, c], rtol=1e-4)


def test_vogel_coarse_scan_is_the_least_squares_residual(oil: Lubricant) -> None:
    # The fit's coarse scan over c takes each straight-line fit in closed form for all c
    # at once; it must be the SSE of numpy's least squares at every c of the scan. rtol
    # 1e-9: the residuals are summed directly (no S_yy − S_xy²/S_xx cancellation), so the
    # two agree to round-off of the residuals (~1e-16 of ln η over residuals ~1e-5).
    from friction.lubricant import _vogel_lsq, _vogel_sse_grid

    t = np.asarray(oil.temperature)
    ln_eta = np.log(oil.dynamic_viscosity)
    grid = np.linspace(-273.15, t.min() - 1.0, 200)
    expect = [np.sum(_vogel_lsq(c, t, ln_eta)[1] ** 2) for c in grid]
    np.testing.assert_allclose(_vogel_sse_grid(grid, t, ln_eta), expect, rtol=1e-9)


def test_thermal_conductivity_constant(oil: Lubricant) -> None:
    k = np.asarray(thermal_conductivity(oil, [30.0, 90.0]))
    assert k.shape == (2,)
    assert k[0] == k[1] == oil.thermal_conductivity[0]


# ----------------------------------------------------------------------------- range errors
@pytest.mark.parametrize("t", [-30.0, 200.0, float("nan")])
def test_temperature_outside_range_raises(oil: Lubricant, t: float) -> None:
    with pytest.raises(InputError, match=r"temperature: must be in \[5, 140\]"):
        viscosity(oil, t)


def test_unknown_viscosity_method(oil: Lubricant) -> None:
    with pytest.raises(ModelUnavailableError, match="vogel"):
        viscosity(oil, 50.0, method="linear")


# ----------------------------------------------------------------------------- loading
def test_bundled_by_name_case_insensitive() -> None:
    assert "75W90" in available_lubricants()
    assert load_lubricant("75w90") == load_lubricant("75W90")


def test_bundled_table_equals_seed_table(oil: Lubricant) -> None:
    np.testing.assert_array_equal(oil.temperature, TABLE["temperature_degC"])
    np.testing.assert_array_equal(oil.dynamic_viscosity, TABLE["dynamic_viscosity_Pa_s"])
    np.testing.assert_array_equal(
        oil.pressure_viscosity_coefficient, TABLE["pressure_viscosity_coefficient_per_GPa"]
    )
    np.testing.assert_array_equal(oil.density, TABLE["density_kg_m3"])


def test_load_from_path(tmp_path: Path) -> None:
    p = tmp_path / "oil.toml"
    p.write_text(_toml(), encoding="utf-8")
    oil = load_lubricant(p)
    assert oil.name == "test oil"
    np.testing.assert_allclose(viscosity(oil, [40.0, 100.0]), [0.08, 0.011], rtol=0.02)


def test_tabulated_beta_is_used(tmp_path: Path) -> None:
    p = tmp_path / "oil.toml"
    text = _toml(temperature_viscosity_coefficient="[0.04, 0.03, 0.02]")
    p.write_text(text.replace("[units]\n", '[units]\ntemperature_viscosity_coefficient = "1/K"\n'))
    oil = load_lubricant(p)
    np.testing.assert_allclose(temperature_viscosity_coefficient(oil, 55.0), 0.035, rtol=1e-12)


@pytest.mark.parametrize(
    ("override", "field"),
    [
        ({"dynamic_viscosity": None}, "dynamic_viscosity"),
        ({"density": "[860.0, 842.0]"}, "density"),
        ({"temperature": "[40.0, 30.0, 100.0]"}, "temperature"),
        ({"dynamic_viscosity": "[0.08, 0.09, 0.011]"}, "dynamic_viscosity"),
        (
            {"pressure_viscosity_coefficient": "[20.0, -1.0, 12.0]"},
            "pressure_viscosity_coefficient",
        ),
        ({"thermal_conductivity": "[0.14, 0.13]"}, "thermal_conductivity"),
        ({"viscosity": "1.0"}, "viscosity"),
        ({"name": '""'}, "name"),
    ],
)
def test_invalid_file_names_the_field(tmp_path: Path, override: dict, field: str) -> None:
    p = tmp_path / "bad.toml"
    p.write_text(_toml(**override), encoding="utf-8")
    with pytest.raises(InputError, match=field):
        load_lubricant(p)


def test_wrong_units_refused(tmp_path: Path) -> None:
    p = tmp_path / "bad.toml"
    p.write_text(_toml().replace('"1/GPa"', '"1/Pa"'), encoding="utf-8")
    with pytest.raises(InputError, match=r"units\.pressure_viscosity_coefficient"):
        load_lubricant(p)


def test_unknown_name_lists_bundled() -> None:
    with pytest.raises(ModelUnavailableError, match="75W90"):
        load_lubricant("no-such-oil")


def test_invalid_toml(tmp_path: Path) -> None:
    p = tmp_path / "bad.toml"
    p.write_text("name = ", encoding="utf-8")
    with pytest.raises(InputError, match="TOML"):
        load_lubricant(p)


# ----------------------------------------------------------------------------- boundary friction
#: A measured μ_b table (the docs' example): 0.11 / 0.12 / 0.13 at 40 / 80 / 120 degC.
MU_B_TABLE = (
    "\n[boundary_friction]\ntemperature = [40.0, 80.0, 120.0]\nvalue = [0.11, 0.12, 0.13]\n"
    'source = "MTM, 20 N, 10 mm/s, SRR 50 %, AISI 52100, a test"\n'
)


def _oil_with_boundary_friction(tmp_path: Path, table: str = MU_B_TABLE,
                                 constant: str | None = None) -> Path:
    """The test oil with a ``[boundary_friction]`` table (or one number) and its unit."""
    text = _toml(boundary_friction=constant).replace(
        "[units]\n", '[units]\nboundary_friction = "1"\n')
    p = tmp_path / "oil.toml"
    p.write_text(text if constant is not None else text + table, encoding="utf-8")
    return p


def test_boundary_friction_table_interpolates_and_holds_its_ends(tmp_path: Path) -> None:
    """Linear between the measured points, the end values held outside: by hand, 0.115 at
    60 degC (half-way 0.11 → 0.12), 0.1225 at 90 (a quarter of 0.12 → 0.13), 0.11 at 25 and
    0.13 at 135 degC (held), with the range warning only for the held ones."""
    oil = load_lubricant(_oil_with_boundary_friction(tmp_path))
    assert isinstance(oil.boundary_friction, BoundaryFrictionTable)
    assert oil.boundary_friction.source.startswith("MTM")
    inside = np.array([40.0, 60.0, 80.0, 90.0, 120.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", FrictionModelRangeWarning)
        mu = boundary_friction_coefficient(oil, inside)
    np.testing.assert_allclose(mu, [0.11, 0.115, 0.12, 0.1225, 0.13], rtol=1e-14)
    assert np.all(boundary_friction_in_range(oil, inside))
    grid = np.array([[25.0, 60.0], [121.0, 135.0]])  # array in, array out (same shape)
    with pytest.warns(FrictionModelRangeWarning, match=r"measured at 40-120 degC.*3 of 4"):
        held = boundary_friction_coefficient(oil, grid)
    np.testing.assert_allclose(held, [[0.11, 0.115], [0.13, 0.13]], rtol=1e-14)
    np.testing.assert_array_equal(boundary_friction_in_range(oil, grid),
                                  [[False, True], [False, False]])
    assert isinstance(boundary_friction_coefficient(oil, 80.0), float)
    assert "0.12 at 80 degC" in boundary_friction_source(oil)
    assert "AISI 52100" in boundary_friction_source(oil)
    with pytest.raises(InputError, match="temperature"):  # the oil's own range still holds
        boundary_friction_coefficient(oil, 150.0)


def test_boundary_friction_constant_as_before(oil: Lubricant) -> None:
    """The bundled 75W90's one number: the same μ_b at every temperature, never flagged."""
    assert oil.boundary_friction == 0.1
    t = np.array([10.0, 90.0, 140.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error", FrictionModelRangeWarning)
        np.testing.assert_array_equal(boundary_friction_coefficient(oil, t), 0.1)
    assert np.all(boundary_friction_in_range(oil, t))
    assert "0.1 [1], constant" in boundary_friction_source(oil)


def test_boundary_friction_missing_is_refused_by_name(tmp_path: Path) -> None:
    p = tmp_path / "oil.toml"
    p.write_text(_toml(), encoding="utf-8")
    with pytest.raises(InputError, match="boundary_friction: the lubricant 'test oil' gives none"):
        boundary_friction_coefficient(load_lubricant(p), 80.0)


@pytest.mark.parametrize(
    ("table", "field"),
    [
        ("temperature = [80.0, 40.0, 120.0]\nvalue = [0.1, 0.1, 0.1]\nsource = 'x'",
         r"boundary_friction\.temperature: must be strictly increasing"),
        ("temperature = [40.0, 40.0]\nvalue = [0.1, 0.1]\nsource = 'x'",
         r"boundary_friction\.temperature: must be strictly increasing"),
        ("temperature = [40.0]\nvalue = [0.1]\nsource = 'x'",
         r"boundary_friction\.temperature: must be at least 2"),
        ("temperature = [40.0, 80.0]\nvalue = [0.1, 0.1, 0.1]\nsource = 'x'",
         r"boundary_friction\.value: must be one value per temperature"),
        ("temperature = [40.0, 80.0]\nvalue = [0.1, 1.2]\nsource = 'x'",
         r"boundary_friction\.value.*\[0, 1\]"),
        ("temperature = [40.0, 80.0]\nvalue = [-0.01, 0.1]\nsource = 'x'",
         r"boundary_friction\.value.*\[0, 1\]"),
        ("temperature = [40.0, 80.0]\nvalue = [0.1, 0.1]",
         r"boundary_friction\.source: missing"),
        ("temperature = [40.0, 80.0]\nvalue = [0.1, 0.1]\nsource = ' '",
         r"boundary_friction\.source: must be a non-empty string"),
        ("temperature = [40.0, 80.0]\nvalue = [0.1, 0.1]\nsource = 'x'\nunit = '1'",
         r"boundary_friction\.unit: unknown field; accepted: temperature, value, source"),
        ("temperature = ['hot', 'cold']\nvalue = [0.1, 0.1]\nsource = 'x'",
         r"boundary_friction\.temperature: must be a list of numbers"),
    ],
)
def test_boundary_friction_table_refusals_name_the_field(tmp_path: Path, table: str,
                                                         field: str) -> None:
    p = _oil_with_boundary_friction(tmp_path, "\n[boundary_friction]\n" + table + "\n")
    with pytest.raises(InputError, match=field) as err:
        load_lubricant(p)
    assert str(p) in str(err.value)  # and the file


@pytest.mark.parametrize(("value", "field"), [("1.5", r"boundary_friction: .*\[0, 1\]"),
                                              ("[0.1, 0.12]", r"boundary_friction: must be one "
                                               r"number in \[0, 1\] \[1\] or a "
                                               r"\[boundary_friction\] table")])
def test_boundary_friction_number_refusals(tmp_path: Path, value: str, field: str) -> None:
    with pytest.raises(InputError, match=field):
        load_lubricant(_oil_with_boundary_friction(tmp_path, constant=value))
