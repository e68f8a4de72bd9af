"""One spelling of each unit and symbol on the console (issue 63 item 4).

The console writes ASCII (docs/nomenclature.md, Units): the units as the files' UDUNITS
``units`` (``N m``, ``um``, ``urad``, ``degC``), the misalignments as the CLI flags name them
(``dE``, ``dP``, ``dG``, ``dSigma``), the Greek symbols as the files' variables
(``sigma_Hlim``, ``lambda_GF``, ``mu_m``); the figures and the HTML report keep
``N·m``, ``µrad``, ``ΔE``, ``σ_Hlim``. Texts the library shares with the report reach the
console through :func:`contact.commands.run.console_text`. (The netCDF ``units``
attributes are CF/UDUNITS strings and not this test's business.)
"""

from __future__ import annotations

import contextlib
import io
import re

import pytest

from contact.cli import main
from contact.commands.run import CONSOLE_SYMBOLS, CONSOLE_UNITS, console_text

#: the commands of ``ltca --help``
COMMANDS = ("cases", "run", "plot", "report", "mesh-interface", "efficiency-map",
            "duty-cycle", "wear", "geometry", "plot-geometry", "synthesize", "correct",
            "optimize", "utca", "rate", "sweep", "tolerance", "vh-check", "ehl",
            "friction-study")


#: other spellings of a console unit → the one the console uses (a stress in MPa as the
#: files' ``units`` and ``ltca run``'s tables, not ISO's N/mm²)
REFUSED = {r"N/mm2": "MPa", r"N/mm\^2": "MPa", r"N\^0\.5/mm": "MPa^0.5", r"\bNm\b": "N m",
           r"\bmicrons?\b": "um", r"\bdeg C\b": "degC"}


def _refused(text: str) -> list[str]:
    return [f"{m.group(0)!r} (write {REFUSED[pattern]!r})" for pattern in REFUSED
            for m in re.finditer(pattern, text)]


def _printed(argv: list[str]) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
        main(argv)
    return out.getvalue()


def _not_ascii(text: str) -> list[str]:
    return [line for line in text.splitlines() if not line.isascii()]


def test_console_text_spells_units_and_symbols_in_ascii():
    """The page's spellings map to the console's: each table entry once, the longer
    symbol first (ΔΣ is dSigma, not dSigma's Σ read alone)."""
    page = ("at 50 N·m: 2.5 µm, 3 µrad, 90 °C; ΔE −0.15 mm, ΔΣ 0.01; σ_Hlim 1500 MPa, "
            "λ_GF 0.2, μ_m 0.05, θ_M 90, S–N curve, ≥ 1 … and 2 more")
    assert console_text(page) == (
        "at 50 N m: 2.5 um, 3 urad, 90 degC; dE -0.15 mm, dSigma 0.01; sigma_Hlim 1500 MPa, "
        "lambda_GF 0.2, mu_m 0.05, theta_M 90, S-N curve, >= 1 ... and 2 more")
    assert all(v.isascii() for v in (*CONSOLE_UNITS.values(), *CONSOLE_SYMBOLS.values()))


@pytest.mark.parametrize("command", COMMANDS)
def test_every_command_help_is_ascii(command):
    text = _printed([command, "--help"])
    assert "usage: ltca" in text
    assert not _not_ascii(text), _not_ascii(text)


def test_the_top_help_lists_the_commands_tested():
    text = _printed(["--help"])
    assert all(f"    {c} " in text or f"    {c}\n" in text for c in COMMANDS)
    assert not _not_ascii(text)


@pytest.mark.parametrize("argv", [["cases"], ["rate", "iso10300_30_sample1"]])
def test_cheap_commands_print_ascii(argv):
    text = _printed(argv)
    assert text.strip()
    assert not _not_ascii(text), _not_ascii(text)
    assert not _refused(text), _refused(text)


def test_a_run_prints_ascii(tmp_path):
    """``ltca run`` on a cheap setting: the case line (dE, dP …), the tables, the
    efficiency and scuffing lines, the verdict's findings (σ_Hlim, S–N of the library's
    texts converted)."""
    text = _printed(["run", "--torque", "50", "500", "--rolls-per-cycle", "4", "--segments",
                     "8", "--no-root-stress", "-o", str(tmp_path / "r.nc")])
    assert "case kolivand2009_fm_11x41_reference: dE -0.15 mm" in text
    assert "T_p [N m]" in text and "[urad]" in text
    assert not _not_ascii(text), _not_ascii(text)
    assert not _refused(text), _refused(text)


def test_the_rating_prints_stresses_in_mpa():
    """``ltca rate`` writes its stresses in MPa as ``ltca run``'s rating table does (the
    standard's N/mm² is the same number)."""
    text = _printed(["rate", "iso10300_30_sample1"])
    assert "sigma_H [MPa]" in text and "sigma_F [MPa]" in text and "Z_E [MPa^0.5]" in text
