"""``contact.develop`` without ``progress``: its lines go to the logger, not nowhere (issue
71, round 26d, branch api87).

A script user's ``contact.develop(basic)`` (docs/api.md, the gallery's own-gear-set
example) ran 29-47 s of CPU (64-124 s of wall time on the shared machine) with no output
and nothing logged: every line ``ltca synthesize`` prints was dropped. Now the default sends
them to ``contact.optimize.development``'s logger at INFO. Checked on the wiring (the
development itself is tested elsewhere): the development's first line reaches the log.
"""

from __future__ import annotations

import logging
from pathlib import Path

import pytest

import contact
import geometry
from contact.optimize import development
from geometry.core.errors import InputError

DESIGNS = Path(__file__).resolve().parents[1] / "tests" / "data" / "designs"


class _Stop(Exception):
    """Raised by the stand-in after the first line, so that no design is analysed."""


@pytest.mark.parametrize("given", [None, "callable"])
def test_the_lines_reach_the_logger_or_the_callable(monkeypatch, caplog, given):
    seen: list[str] = []

    def wrapped(basic, apply_remedy, **kw):
        kw["progress"]("development: a first line")
        raise _Stop

    monkeypatch.setattr(development, "_wrapped", wrapped)
    basic = geometry.load_basic(DESIGNS / "spiral_bevel_13x39.toml")
    with caplog.at_level(logging.INFO, logger="contact.optimize.development"), \
            pytest.raises(_Stop):
        contact.develop(basic, progress=None if given is None else seen.append)
    logged = [r.getMessage() for r in caplog.records
              if r.name == "contact.optimize.development"]
    if given is None:
        assert logged == ["development: a first line"]
    else:
        assert seen == ["development: a first line"] and logged == []


def test_a_basic_file_path_is_read_and_a_case_is_refused_naming_basic(monkeypatch):
    """Round 26d: ``contact.develop("file.toml")`` and ``contact.develop(case)`` stopped
    with ``AttributeError: ... has no attribute 'root_stress'``. A path is read as
    ``ltca synthesize FILE`` reads it (the same BasicDesign as geometry.load_basic); a
    case is refused naming the argument."""
    got = []

    def wrapped(basic, apply_remedy, **kw):
        got.append(basic)
        raise _Stop

    monkeypatch.setattr(development, "_wrapped", wrapped)
    path = DESIGNS / "spiral_bevel_13x39.toml"
    for given in (path, str(path)):
        with pytest.raises(_Stop):
            contact.develop(given)
    assert got[0].design == got[1].design == geometry.load_basic(path).design
    case, _ = geometry.synthesize(geometry.load_basic(path))
    with pytest.raises(InputError, match=r"^basic: must be a BasicDesign \(geometry\.load_"
                                         r"basic\(FILE\)\) or a basic design file's path, got "
                                         r"the analysis case 'spiral_bevel_13x39'"):
        contact.develop(case)
    with pytest.raises(InputError, match=r"^basic: .* got dict$"):
        contact.develop({})
