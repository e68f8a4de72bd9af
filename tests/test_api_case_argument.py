"""One ``case`` argument type across the public API (issue 63 item 4).

Every public function of the application layer that takes a case accepts a
:class:`geometry.Case`, a case file's path or a bundled case's name (``None``: the default
case), resolved by the one resolver, :func:`contact.resolve_case`: an unknown name and a
directory are refused with its messages, before any analysis starts.
"""

from __future__ import annotations

import importlib
import inspect
from pathlib import Path

import pytest
import scipy.stats
import xarray as xr

import contact
from geometry.core.errors import InputError

#: the public callables taking ``case`` that resolve it, each called as cheaply as it allows
RESOLVING = {
    "run_analysis": lambda c: contact.run_analysis(c, [250.0]),
    "rate_load_capacity": lambda c: contact.rate_load_capacity(c),
    "iso10300_rating": lambda c: contact.iso10300_rating(c),
    "iso10300_capacity": lambda c: contact.iso10300_capacity(c),
    "sweep": lambda c: contact.sweep(c, delta_E=[0.0]),
    "sample": lambda c: contact.sample(c, {"delta_E": scipy.stats.norm(0.0, 0.01)}, 2),
    "vh_check": lambda c: contact.vh_check(c),
    "export_rexs": lambda c: contact.export_rexs(c, Path("never_written.rexs")),
    "run_duty_cycle": lambda c: contact.run_duty_cycle(
        c, contact.DutyCycle(torque=[1.0], pinion_speed=[1.0], revolutions=[1.0])),
    "example_duty_cycle": lambda c: contact.example_duty_cycle(case=c),
}

#: public callables that take a loaded Case only, and why (they live in contact's layers
#: below the application layer, which may not import contact.catalogue, the resolver;
#: tests/test_layers.py), or a record of the chain's state
CASE_ONLY = {
    "contact.ChainState": "the chain's state, built by run_analysis from a resolved case",
    "contact.ease_off": "contact.utca layer",
    "contact.unloaded_tca": "contact.utca layer",
    "contact.loaded_tca": "contact.ltca layer",
    "contact.shell_assembler": "contact.ltca layer",
    "contact.influence_coefficients": "contact.compliance layer",
    "geometry.corrective_settings": "geometry (imports no contact)",
    "geometry.corrected_case": "geometry (imports no contact)",
}


@pytest.mark.parametrize("name", sorted(RESOLVING))
def test_a_case_argument_goes_through_the_resolver(name, tmp_path):
    """An unknown bundled name and a directory get the resolver's own refusals."""
    call = RESOLVING[name]
    with pytest.raises(InputError, match=r"^case: no bundled case 'no_such_case'"):
        call("no_such_case")
    with pytest.raises(InputError, match=r"^case: .* is a directory, not a case file"):
        call(tmp_path)


@pytest.mark.parametrize("name", sorted(RESOLVING))
def test_the_signature_says_case_name_or_path(name):
    annotation = str(inspect.signature(getattr(contact, name)).parameters["case"].annotation)
    assert "Case" in annotation and "str" in annotation and "PathLike" in annotation, (
        f"contact.{name}(case: {annotation}): annotate Case | str | os.PathLike[str] | None")


def test_every_public_case_argument_is_listed():
    """A new public function taking ``case`` is either resolving (and tested above) or
    listed with the reason it takes a Case only."""
    unlisted = []
    for pkg in ("contact", "geometry", "friction"):
        module = importlib.import_module(pkg)
        for name in module.__all__:
            obj = getattr(module, name)
            try:
                params = inspect.signature(obj).parameters
            except (TypeError, ValueError):
                continue
            where = f"{pkg}.{name}"
            if ("case" in params and name not in RESOLVING and where not in CASE_ONLY
                    and name != "resolve_case"):
                unlisted.append(where)
    assert not unlisted, f"public functions taking case, not listed: {unlisted}"


def test_name_path_and_case_give_the_same_rating():
    """The bundled name, the file's path and the loaded Case are one case: the ISO 10300
    rating of each is identical (the resolver returns a Case unchanged)."""
    path = Path(contact.bundled_case_path("iso10300_30_sample1"))
    by_name = contact.iso10300_rating("iso10300_30_sample1", torque=[300.0],
                                      pinion_speed=1200.0)
    by_path = contact.iso10300_rating(path, torque=[300.0], pinion_speed=1200.0)
    by_case = contact.iso10300_rating(contact.resolve_case(path), torque=[300.0],
                                      pinion_speed=1200.0)
    xr.testing.assert_identical(by_name, by_path)
    xr.testing.assert_identical(by_name, by_case)
