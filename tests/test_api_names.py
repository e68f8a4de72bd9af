"""One argument name per quantity across the public API (issue 63 item 4).

The public API is the package tops' ``__all__`` (``contact``, ``geometry``, ``friction``).
:data:`CANONICAL` names each quantity's argument (the name the case TOML and the CLI flag
use, docs/nomenclature.md "Argument names") and the names refused for it; a function or
class that takes a refused name fails the walk. The old names still work for one release
through :func:`geometry.core.renamed.renamed_keywords`, tested here once.
"""

from __future__ import annotations

import importlib
import inspect
import warnings

import pytest

from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords

#: canonical argument name -> the names it replaced (refused in the public API)
CANONICAL = {
    "pinion_speed": ("speed", "n1", "rpm"),
    "temperature": ("oil_temperature", "inlet_temperature", "theta_oil"),
    "rolls_per_cycle": ("n_roll", "n_rolls", "rolls"),
    "torque": ("pinion_torque", "T1"),
    "n_workers": ("workers", "processes", "jobs"),
    "lubricant": ("path_or_name", "oil"),
}

PACKAGES = ("contact", "geometry", "friction")


def _public_parameters():
    """(qualified name, parameter names) of every public callable with a signature."""
    for pkg in PACKAGES:
        module = importlib.import_module(pkg)
        for name in module.__all__:
            obj = getattr(module, name)
            if not callable(obj):
                continue
            try:
                params = inspect.signature(obj).parameters
            except (TypeError, ValueError):
                continue
            yield f"{pkg}.{name}", set(params)


def test_public_api_uses_the_canonical_names():
    """No public function or class takes a refused alias of a quantity's name."""
    refused = {alias: canon for canon, aliases in CANONICAL.items() for alias in aliases}
    found = [f"{where}({alias}=…): use {refused[alias]!r}"
             for where, params in _public_parameters()
             for alias in sorted(params & refused.keys())]
    assert not found, "non-canonical argument names:\n" + "\n".join(found)


def test_the_walk_sees_the_renamed_functions():
    """The walk reaches the functions the renames touched (a walk that found nothing
    would pass the test above vacuously)."""
    seen = dict(_public_parameters())
    assert "pinion_speed" in seen["contact.rate_load_capacity"]
    assert "pinion_speed" in seen["contact.iso10300_rating"]
    assert "pinion_speed" in seen["contact.sweep"]
    assert "rolls_per_cycle" in seen["contact.unloaded_tca"]
    assert len(seen) > 60


def test_renamed_keywords_maps_old_to_new_with_a_warning():
    @renamed_keywords(speed="pinion_speed")
    def f(torque, *, pinion_speed=None):
        return torque, pinion_speed

    assert f(1.0, pinion_speed=2.0) == (1.0, 2.0)
    with pytest.warns(DeprecationWarning, match="'speed' is renamed 'pinion_speed'"):
        assert f(1.0, speed=3.0) == (1.0, 3.0)
    with pytest.raises(InputError, match="pinion_speed"):
        f(1.0, speed=3.0, pinion_speed=2.0)
    assert f.renamed_keywords == {"speed": "pinion_speed"}


def test_renamed_keywords_on_a_dataclass_and_refusals_at_decoration():
    import dataclasses

    @renamed_keywords(n_roll="rolls_per_cycle")
    @dataclasses.dataclass
    class Options:
        rolls_per_cycle: int = 20

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert Options(rolls_per_cycle=8).rolls_per_cycle == 8
    with pytest.warns(DeprecationWarning, match="rolls_per_cycle"):
        assert Options(n_roll=6).rolls_per_cycle == 6
    with pytest.raises(TypeError, match="not a parameter"):
        renamed_keywords(a="b")(lambda a: a)
    with pytest.raises(TypeError, match="still a parameter"):
        renamed_keywords(a="b")(lambda a, b: a)


@pytest.mark.parametrize(("function", "old", "new"), [
    ("contact.iso10300_rating", "speed", "pinion_speed"),
    ("contact.rate_load_capacity", "speed", "pinion_speed"),
    ("contact.sweep", "speed", "pinion_speed"),
    ("contact.sample", "speed", "pinion_speed"),
    ("contact.unloaded_tca", "n_roll", "rolls_per_cycle"),
    ("contact.DutyCycle", "speed", "pinion_speed"),
    ("contact.plot_analysis", "workers", "n_workers"),
    ("friction.load_lubricant", "path_or_name", "lubricant"),
])
def test_each_rename_keeps_its_old_keyword_for_one_release(function, old, new):
    """Each renamed public function declares its old keyword (the decorator's record)."""
    pkg, name = function.split(".")
    obj = getattr(importlib.import_module(pkg), name)
    record = obj.__init__ if isinstance(obj, type) else obj
    assert record.renamed_keywords.get(old) == new


def test_duty_cycle_keeps_its_old_attribute_for_one_release():
    from contact import DutyCycle

    duty = DutyCycle(torque=[100.0], pinion_speed=[1000.0], revolutions=[6e4])
    assert duty.hours[0] == 1.0  # 6e4 rev at 1000 rpm: one hour
    with pytest.warns(DeprecationWarning, match="pinion_speed"):
        assert duty.speed[0] == 1000.0


def test_an_old_keyword_gives_the_same_result_as_the_new():
    """Through the decorator the old keyword reaches the same argument: the ISO 10300
    rating at 1200 rpm is identical either way, the oil too."""
    import xarray as xr

    import contact
    import friction

    new = contact.iso10300_rating("iso10300_30_sample1", torque=[300.0], pinion_speed=1200.0)
    with pytest.warns(DeprecationWarning, match="pinion_speed"):
        old = contact.iso10300_rating("iso10300_30_sample1", torque=[300.0], speed=1200.0)
    xr.testing.assert_identical(new, old)
    # the speed reached the rating: the mean-point speed is proportional to it
    double = contact.iso10300_rating("iso10300_30_sample1", torque=[300.0], pinion_speed=2400.0)
    assert float(double["v_mt"].isel(member=0)) == pytest.approx(
        2.0 * float(new["v_mt"].isel(member=0)), rel=1e-12)
    with pytest.warns(DeprecationWarning, match="'lubricant'"):
        assert friction.load_lubricant(path_or_name="75W90") == friction.load_lubricant("75W90")
