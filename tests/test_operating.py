"""Tests of friction.operating.OperatingConditions: the operating defaults in one place.

The defaults are the toolkit's (1500 rpm, 75W90 at 90 °C, Rq 0.8 µm, thermal_eyring); every
refusal names the field; the command line takes its defaults from the dataclass.
"""

from __future__ import annotations

import dataclasses
import math

import pytest

from friction.operating import OperatingConditions
from geometry.core.errors import InputError, ModelUnavailableError


def test_defaults():
    op = OperatingConditions()
    assert (op.pinion_speed, op.lubricant, op.temperature, op.roughness, op.friction_model) == (
        1500.0, "75W90", 90.0, 0.8, "thermal_eyring")
    assert all(type(v) is float for v in (op.pinion_speed, op.temperature, op.roughness))


def test_frozen_and_replace_validates_again():
    op = OperatingConditions()
    with pytest.raises(dataclasses.FrozenInstanceError):
        op.pinion_speed = 1.0  # type: ignore[misc]
    assert dataclasses.replace(op, temperature=60).temperature == 60.0
    with pytest.raises(InputError, match=r"^roughness: must be in \(0, 5\] \[um\], got 0$"):
        dataclasses.replace(op, roughness=0)


def test_lubricant_by_bundled_name_or_file(tmp_path):
    assert OperatingConditions(lubricant="75w90").lubricant == "75w90"  # case-insensitive
    src = OperatingConditions(lubricant="75W90")
    assert src == OperatingConditions()
    oil = tmp_path / "oil.toml"
    oil.write_text("name = 'x'\n", encoding="utf-8")
    assert OperatingConditions(lubricant=oil).lubricant == oil


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"pinion_speed": 0.0}, InputError,
         r"^pinion_speed: must be in \(0, 50000\] \[rpm\], got 0$"),
        ({"pinion_speed": -1500.0}, InputError, r"^pinion_speed: must be in \(0, 50000\]"),
        # a slip of orders of magnitude: the table of physical bounds (issue 64)
        ({"pinion_speed": 1e12}, InputError, r"^pinion_speed: must be in \(0, 50000\] \[rpm\], "
                                              r"got 1e\+12$"),
        ({"roughness": 100.0}, InputError, r"^roughness: must be in \(0, 5\] \[um\], got 100$"),
        ({"pinion_speed": math.inf}, InputError, r"^pinion_speed: must be finite"),
        ({"pinion_speed": True}, InputError, r"^pinion_speed: must be a real number"),
        ({"pinion_speed": "1500"}, InputError, r"^pinion_speed: must be a real number"),
        ({"temperature": -300.0}, InputError,
         r"^temperature: must be in \[-40, 200\] \[degC\], got -300$"),
        ({"temperature": math.nan}, InputError, r"^temperature: must be finite"),
        ({"roughness": -0.8}, InputError, r"^roughness: must be in \(0, 5\] \[um\]"),
        ({"lubricant": ""}, InputError, r"^lubricant: must be a bundled oil name"),
        ({"lubricant": 75}, InputError, r"^lubricant: must be a bundled oil name"),
        ({"lubricant": "no-such-oil"}, ModelUnavailableError,
         r"^lubricant: must be one of the bundled oils \[.*'75W90'.*\]"),
        ({"friction_model": "kolivand2009_table_5_3"}, ModelUnavailableError,
         r"^friction_model: friction model 'kolivand2009_table_5_3' is unavailable"),
        ({"friction_model": "nope"}, ModelUnavailableError,
         r"^friction_model: unknown friction model 'nope'; available: .*xu2007"),
        ({"friction_model": None}, InputError, r"^friction_model: must be the name"),
    ],
)
def test_refusals_name_the_field(kwargs, error, match):
    with pytest.raises(error, match=match):
        OperatingConditions(**kwargs)


def test_the_command_line_takes_its_defaults_from_the_dataclass():
    """One definition of the operating defaults: the command line has none of its own
    (an option left out means the case's ``[operating]`` table), and a case without one
    gets geometry.case.OPERATING_DEFAULTS, which OperatingConditions' defaults equal; the
    friction model's default is the friction package's (issue 54: a case names none, and
    the efficiency stage takes friction.defaults.DEFAULT_FRICTION_MODEL)."""
    from contact.cli import build_parser
    from friction.defaults import DEFAULT_FRICTION_MODEL
    from geometry.case import OPERATING_DEFAULTS, OperatingPoint

    op = OperatingConditions()
    parser = build_parser()
    for argv in (["run"], ["efficiency-map"]):
        args = parser.parse_args(argv)
        assert (args.speed, args.lubricant, args.temperature, args.roughness,
                args.friction_model) == (None,) * 5, argv
    assert (op.pinion_speed, op.lubricant, op.temperature, op.roughness) == tuple(
        OPERATING_DEFAULTS[k] for k in ("pinion_speed", "lubricant", "temperature",
                                        "roughness"))
    assert "friction_model" not in OPERATING_DEFAULTS
    assert OperatingPoint().friction_model is None
    assert op.friction_model == DEFAULT_FRICTION_MODEL
    assert OperatingConditions.from_point(OperatingPoint()).friction_model == (
        DEFAULT_FRICTION_MODEL)


def test_the_oil_is_read_once_per_conditions(monkeypatch):
    """OperatingConditions.oil reads the oil once and keeps it (an analysis' efficiency,
    scuffing and flash-temperature steps share it; issue 75); load_lubricant returns an
    oil already read as it is; a new conditions object reads its own."""
    import dataclasses

    import friction.lubricant as lubricant_module
    from friction import OperatingConditions

    reads = []
    real = lubricant_module.load_lubricant
    monkeypatch.setattr(lubricant_module, "load_lubricant",
                        lambda name: (reads.append(name), real(name))[1])
    op = OperatingConditions(lubricant="75W90")
    oil = op.oil()
    op.check_oil_temperature()
    assert op.oil() is oil and reads == ["75W90"]
    assert real(oil) is oil
    assert oil == real("75W90")
    other = dataclasses.replace(op, temperature=80.0)
    assert other.oil() == oil and reads == ["75W90", "75W90"]
    assert other == dataclasses.replace(op, temperature=80.0)  # the kept oil is no field
