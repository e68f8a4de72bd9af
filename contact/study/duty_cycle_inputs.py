"""The inputs of a duty cycle: load-spectrum bins and the deflection table.

A duty cycle is a case's ``[duty_cycle]`` table (kept by the case reader in
``Case.extra``) or a TOML file of the same table::

    [duty_cycle]
    name = "axle spectrum"
    grade = "MQ"                  # ISO 6336-5 quality grade of both members' material
    miner_rule = "modified"       # elementary | modified | original
    torque   = [100.0, 300.0]     # pinion torque of each bin [N·m]
    speed    = [3000.0, 1500.0]   # pinion speed [rpm]
    hours    = [500.0, 50.0]      # duration [h] (or `revolutions`, pinion revolutions)
    temperature = [80.0, 95.0]    # oil inlet temperature [degC], optional

    [duty_cycle.deflection]       # housing, bearing and shaft deflections vs pinion torque
    torque      = [0.0, 600.0]    # [N·m], strictly increasing
    delta_E     = [0.0, 0.06]     # [mm]
    delta_P     = [0.0, -0.03]    # [mm]
    delta_G     = [0.0, 0.04]     # [mm]
    delta_Sigma = [0.0, 0.02]     # [deg]

The misalignment of a bin is the table's at its torque (PCHIP between the rows, refused
outside them) plus the case's assembly misalignment (``Case.misalignment``).

Public names
------------
DeflectionTable   ΔE, ΔP, ΔG [mm], ΔΣ [deg] against pinion torque, PCHIP
DutyCycle         the bins and the durability settings
read_duty_cycle   a DutyCycle from a mapping, a TOML file, or a case's [duty_cycle]
example_duty_cycle  the bundled illustrative axle-style spectrum (ltca duty-cycle's default)
"""

from __future__ import annotations

import math
import os
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from scipy.interpolate import PchipInterpolator

from contact.load_capacity.durability.sn_curve import MINER_RULES
from geometry.core.bounds import check_bound
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords
from geometry.core.toml_files import read_toml
from geometry.pair.assembly import Misalignment

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = ["DEFLECTION_FIELDS", "DeflectionTable", "DutyCycle", "example_duty_cycle",
           "illustrative_speed_note", "read_duty_cycle"]

#: the deflection table's columns and their units
DEFLECTION_FIELDS = {"delta_E": "mm", "delta_P": "mm", "delta_G": "mm", "delta_Sigma": "deg"}


def _array(where: str, value: Any, n: int | None = None) -> np.ndarray:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = [value]
    if isinstance(value, (str, bytes)) or not isinstance(value, (Sequence, np.ndarray)):
        raise InputError(f"{where}: must be a list of numbers, got {value!r}")
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{where}: must be a list of numbers, got {value!r}") from None
    if a.ndim != 1 or a.size == 0:
        raise InputError(f"{where}: must be a non-empty list of numbers")
    if not np.all(np.isfinite(a)):
        raise InputError(f"{where}: every value must be finite")
    if n is not None and a.size != n:
        raise InputError(f"{where}: needs {n} values (one per row), got {a.size}")
    return a


@dataclass(frozen=True)
class DeflectionTable:
    """Deflections of the mounting against pinion torque, interpolated by PCHIP.

    Parameters
    ----------
    torque : (NR,) — [N·m]
        Pinion torques of the rows, strictly increasing, at least 2 rows.
    delta_E, delta_P, delta_G : (NR,) — [mm]
        Offset, pinion and gear axial displacements (the V–H convention of
        :class:`geometry.pair.assembly.Misalignment`).
    delta_Sigma : (NR,) — [deg]
        Shaft-angle change.

    Raises
    ------
    InputError
        Fewer than 2 rows, unsorted or duplicate torques, mismatched lengths (named).

    Notes
    -----
    PCHIP (Fritsch & Carlson 1980; :class:`scipy.interpolate.PchipInterpolator`) passes
    through the rows and is monotone between them wherever the rows are, so a
    deflection that grows with torque in the table grows between its rows too.
    """

    torque: np.ndarray
    delta_E: np.ndarray
    delta_P: np.ndarray
    delta_G: np.ndarray
    delta_Sigma: np.ndarray
    _interp: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self) -> None:
        t = _array("deflection.torque", self.torque)
        if t.size < 2:
            raise InputError("deflection.torque: the table needs at least 2 rows")
        if np.any(np.diff(t) <= 0):
            raise InputError("deflection.torque: rows must be strictly increasing (no "
                             f"duplicates, sorted), got {t.tolist()}")
        object.__setattr__(self, "torque", t)
        for name in DEFLECTION_FIELDS:
            a = _array(f"deflection.{name}", getattr(self, name), t.size)
            object.__setattr__(self, name, a)
            self._interp[name] = PchipInterpolator(t, a)

    def at(self, torque: float, where: str = "torque") -> dict[str, float]:
        """The deflections at a pinion torque [N·m] (ΔE, ΔP, ΔG [mm], ΔΣ [deg]).

        Raises
        ------
        InputError
            A torque outside the table's rows (``where`` names the bin).
        """
        lo, hi = float(self.torque[0]), float(self.torque[-1])
        if not lo <= torque <= hi:
            raise InputError(f"{where}: pinion torque {torque:g} N m is outside the "
                             f"deflection table's rows [{lo:g}, {hi:g}] N m (no "
                             "extrapolation)")
        return {k: float(self._interp[k](torque)) for k in DEFLECTION_FIELDS}

    def misalignment(self, torque: float, assembly: Misalignment,
                     where: str = "torque") -> Misalignment:
        """The bin's misalignment: the table's at ``torque`` plus the assembly's."""
        d = self.at(torque, where)
        return Misalignment(delta_E=assembly.delta_E + d["delta_E"],
                            delta_P=assembly.delta_P + d["delta_P"],
                            delta_G=assembly.delta_G + d["delta_G"],
                            delta_Sigma=assembly.delta_Sigma + math.radians(d["delta_Sigma"]))


@renamed_keywords(speed="pinion_speed")
@dataclass(frozen=True)
class DutyCycle:
    """A load spectrum of bins, its deflection table and the durability settings.

    Parameters
    ----------
    torque : (NB,) — [N·m]
        Pinion torque of each bin, > 0.
    pinion_speed : (NB,) — [rpm]
        Pinion speed of each bin, > 0 (the ``[duty_cycle]`` table's ``speed``; old
        keyword and attribute ``speed``, deprecated).
    revolutions : (NB,) — [1]
        Pinion revolutions of each bin, > 0 (``hours`` converted: n × 60 × h).
    deflection : DeflectionTable or None
        None: the case's own misalignment at every torque.
    temperature : (NB,) — [degC], optional
        Oil inlet temperature of each bin (default the case's).
    grade : str
        ISO 6336-5 quality grade (``ML``, ``MQ``, ``ME``).
    miner_rule : str
        :data:`contact.load_capacity.durability.sn_curve.MINER_RULES`.
    name : str
    illustrative : bool
        True for the bundled example (said in the output).

    Raises
    ------
    InputError
        Mismatched lengths, non-positive values, an unknown rule (named).
    """

    torque: np.ndarray
    pinion_speed: np.ndarray
    revolutions: np.ndarray
    deflection: DeflectionTable | None = None
    temperature: np.ndarray | None = None
    grade: str = "MQ"
    miner_rule: str = "modified"
    name: str = "duty cycle"
    illustrative: bool = False

    def __post_init__(self) -> None:
        t = _array("duty_cycle.torque", self.torque)
        n = t.size
        for name in ("torque", "pinion_speed", "revolutions"):
            field = "speed" if name == "pinion_speed" else name  # the table's key
            a = _array(f"duty_cycle.{field}", getattr(self, name), n)
            if np.any(a <= 0):
                i = int(np.argmax(a <= 0))
                raise InputError(f"duty_cycle.{field}: must be > 0 in every bin, bin {i} "
                                 f"has {a[i]:g}")
            object.__setattr__(self, name, a)
        if self.temperature is not None:
            a = _array("duty_cycle.temperature", self.temperature, n)
            if np.any(a <= -273.15):
                raise InputError("duty_cycle.temperature: must be above absolute zero [degC]")
            object.__setattr__(self, "temperature", a)
        # the one table of physical bounds, bin by bin, before any analysis (issue 64)
        for name, field in (("torque", "torque"), ("pinion_speed", "speed"),
                            ("temperature", "temperature")):
            values = getattr(self, name)
            for i, v in enumerate(() if values is None else values):
                check_bound(name, float(v), field=f"duty_cycle.{field} (bin {i})")
        if self.miner_rule not in MINER_RULES:
            raise InputError(f"duty_cycle.miner_rule: must be one of {', '.join(MINER_RULES)},"
                             f" got {self.miner_rule!r}")
        if self.deflection is not None:
            for i, tq in enumerate(t):
                self.deflection.at(float(tq), f"duty_cycle bin {i}")

    @property
    def speed(self) -> np.ndarray:
        """Deprecated name of :attr:`pinion_speed` (goes in the next release)."""
        warnings.warn("DutyCycle.speed is renamed pinion_speed; the old name goes in the "
                      "next release", DeprecationWarning, stacklevel=2)
        return self.pinion_speed

    @property
    def hours(self) -> np.ndarray:
        """(NB,) [h] duration of each bin: revolutions / (pinion speed × 60)."""
        return self.revolutions / (self.pinion_speed * 60.0)

    @property
    def n_bins(self) -> int:
        return int(self.torque.size)

    def misalignment(self, i: int, assembly: Misalignment) -> Misalignment:
        """The misalignment of bin ``i`` (deflection at its torque + the assembly's)."""
        if self.deflection is None:
            return assembly
        return self.deflection.misalignment(float(self.torque[i]), assembly,
                                            f"duty_cycle bin {i}")

    def to_mapping(self) -> dict[str, Any]:
        """The ``[duty_cycle]`` table of this duty cycle (TOML-ready)."""
        out: dict[str, Any] = {"name": self.name, "grade": self.grade,
                               "miner_rule": self.miner_rule,
                               "illustrative": self.illustrative,
                               "torque": self.torque.tolist(), "speed": self.pinion_speed.tolist(),
                               "revolutions": self.revolutions.tolist()}
        if self.temperature is not None:
            out["temperature"] = self.temperature.tolist()
        if self.deflection is not None:
            out["deflection"] = {k: getattr(self.deflection, k).tolist()
                                 for k in ("torque", *DEFLECTION_FIELDS)}
        return out


_KEYS = {"name", "grade", "miner_rule", "illustrative", "torque", "speed", "hours",
         "revolutions", "temperature", "deflection"}


def read_duty_cycle(source: Mapping[str, Any] | str | os.PathLike[str] | Any) -> DutyCycle:
    """A :class:`DutyCycle` from a ``[duty_cycle]`` table, a TOML file holding one, or a case.

    Parameters
    ----------
    source : mapping, path or geometry.case.Case
        The table itself; a TOML file with a ``[duty_cycle]`` table; a case whose file
        has one (``Case.extra["duty_cycle"]``).

    Returns
    -------
    DutyCycle
        The bins (torque [N·m], speed [rpm], time or revolutions) as read and checked.

    Raises
    ------
    InputError
        A file that is missing, not UTF-8 text (a binary file) or not valid TOML (named);
        no table, unknown keys, both or neither of ``hours`` and ``revolutions``, bad
        values (named).
    """
    if hasattr(source, "extra") and hasattr(source, "pinion"):
        table = source.extra.get("duty_cycle")
        if table is None:
            raise InputError(f"duty_cycle: case {source.name!r} has no [duty_cycle] table")
    elif isinstance(source, Mapping):
        table = source.get("duty_cycle", source)
    else:
        path = Path(source)
        # one reader for input files: missing, binary, non-UTF-8 or invalid TOML refused
        # in one line naming the file (geometry.core.toml_files.read_toml)
        raw = read_toml(path, "duty_cycle: spectrum file")
        if "duty_cycle" not in raw:
            raise InputError(f"duty_cycle: {str(path)!r} has no [duty_cycle] table")
        table = raw["duty_cycle"]
    if not isinstance(table, Mapping):
        raise InputError("duty_cycle: must be a table")
    unknown = sorted(set(table) - _KEYS)
    if unknown:
        raise InputError(f"duty_cycle: unknown key(s) {', '.join(unknown)}; accepted "
                         f"{', '.join(sorted(_KEYS))}")
    for key in ("torque", "speed"):
        if key not in table:
            raise InputError(f"duty_cycle.{key}: missing (one value per bin)")
    if ("hours" in table) == ("revolutions" in table):
        raise InputError("duty_cycle.hours: give either hours [h] or revolutions (pinion "
                         "revolutions) per bin, not both nor neither")
    torque = _array("duty_cycle.torque", table["torque"])
    speed = _array("duty_cycle.speed", table["speed"], torque.size)
    if "hours" in table:
        hours = _array("duty_cycle.hours", table["hours"], torque.size)
        if np.any(hours <= 0):
            i = int(np.argmax(hours <= 0))
            raise InputError(f"duty_cycle.hours: must be > 0 in every bin, bin {i} has "
                             f"{hours[i]:g}")
        revolutions = hours * speed * 60.0
    else:
        revolutions = table["revolutions"]
    deflection = None
    if "deflection" in table:
        d = table["deflection"]
        if not isinstance(d, Mapping):
            raise InputError("duty_cycle.deflection: must be a table")
        missing = [k for k in ("torque", *DEFLECTION_FIELDS) if k not in d]
        if missing:
            raise InputError(f"duty_cycle.deflection.{missing[0]}: missing")
        deflection = DeflectionTable(**{k: d[k] for k in ("torque", *DEFLECTION_FIELDS)})
    return DutyCycle(torque=torque, pinion_speed=speed, revolutions=revolutions,
                     deflection=deflection, temperature=table.get("temperature"),
                     grade=str(table.get("grade", "MQ")),
                     miner_rule=str(table.get("miner_rule", "modified")),
                     name=str(table.get("name", "duty cycle")),
                     illustrative=bool(table.get("illustrative", False)))


#: the pinion flanks a duty cycle loads, by role or by name (``ltca duty-cycle --flank``)
FLANKS = ("drive", "coast", "concave", "convex")

#: the illustrative axle spectrum: (fraction of the maximum torque, fraction of the
#: maximum speed, share of the hours) of each bin — not from a measured drive cycle: a
#: made-up shape with the usual look of one (much time at low torque and high speed,
#: little at full torque and low speed)
EXAMPLE_BINS = (
    (0.10, 1.00, 0.30),
    (0.25, 0.85, 0.28),
    (0.40, 0.70, 0.20),
    (0.55, 0.55, 0.12),
    (0.70, 0.40, 0.06),
    (0.85, 0.30, 0.03),
    (1.00, 0.20, 0.01),
)


def example_duty_cycle(max_torque: float | None = None, max_speed: float = 3000.0,
                       hours: float = 2000.0, bins: int | None = None, *,
                       case: Case | str | os.PathLike[str] | None = None,
                       flank: str | None = None) -> DutyCycle:
    """The bundled **illustrative** axle-style spectrum: what ``ltca duty-cycle`` runs for
    a case without a ``[duty_cycle]`` table and without ``--duty``.

    Parameters
    ----------
    max_torque : float, optional — [N·m]
        Pinion torque of the top bin. Default the largest of the torques an analysis of
        ``case``'s ``flank`` runs at (:func:`contact.pipeline.flank_torques`: the case's
        ``[operating]`` torques, on the coast flank no more than its coast design
        torque), as ``ltca duty-cycle`` takes it; 500 for the default case's drive flank.
    max_speed : float — [rpm]
        Pinion speed of the lowest-torque bin (default 3000).
    hours : float — [h]
        The spectrum's duration (default 2000).
    bins : int, optional
        Keep only the first ``bins`` bins (cheap tests), 1–7.
    case : Case, path, bundled name or None (the default case), keyword-only
        The gear set whose top torque ``max_torque`` defaults to
        (:func:`contact.resolve_case`); not read where ``max_torque`` is given.
    flank : {"drive", "coast", "concave", "convex"}, optional, keyword-only
        The pinion flank the duty cycle loads (``ltca duty-cycle --flank``; default the
        drive flank).

    Returns
    -------
    DutyCycle
        7 bins from 10 % to 100 % of ``max_torque`` (:data:`EXAMPLE_BINS`: illustrative
        proportions, not measured; ``illustrative`` True, which the duty cycle's verdict
        reports), MQ grade, modified Miner, and a deflection table linear in torque from
        0 to 1.2 × ``max_torque``: at ``max_torque`` ΔE = 0.05, ΔP = −0.03, ΔG = 0.03 mm,
        ΔΣ = 0.01 deg (illustrative magnitudes of an axle's deflections, signs those that
        move the pattern towards the heel).

    Raises
    ------
    InputError
        Non-positive or non-finite ``max_torque``, ``max_speed`` or ``hours``; a bin
        count outside 1–7; an unknown case (the resolver's message) or flank.

    Notes
    -----
    Source: none measured — the shape (much time at low torque and high speed, little at
    full torque and low speed) is the usual look of an axle's load spectrum, made up for
    a first look (docs/duty_cycle.md). The top torque as ``ltca duty-cycle`` takes it
    (issue 71, branch api82): the API and the command run the same bins.

    Examples
    --------
    >>> import contact
    >>> duty = contact.example_duty_cycle()
    >>> duty.n_bins, float(duty.torque[-1])
    (7, 500.0)
    """
    if flank is not None and flank not in FLANKS:
        raise InputError(f"flank: must be one of {', '.join(FLANKS)}, got {flank!r}")
    if max_torque is None:
        from contact.catalogue import resolve_case
        from contact.pipeline import flank_torques

        max_torque = max(flank_torques(resolve_case(case), flank)[0] or (500.0,))
    for name, value in (("max_torque", max_torque), ("max_speed", max_speed),
                        ("hours", hours)):
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
            raise InputError(f"{name}: must be a finite number > 0, got {value!r}")
    rows = EXAMPLE_BINS[:bins] if bins is not None else EXAMPLE_BINS
    if bins is not None and not 1 <= bins <= len(EXAMPLE_BINS):
        raise InputError(f"bins: must be in [1, {len(EXAMPLE_BINS)}], got {bins!r}")
    share = np.array([r[2] for r in rows])
    speed = np.array([r[1] for r in rows]) * max_speed
    top = 1.2 * max_torque
    scale = top / max_torque
    table = DeflectionTable(torque=[0.0, top], delta_E=[0.0, 0.05 * scale],
                            delta_P=[0.0, -0.03 * scale], delta_G=[0.0, 0.03 * scale],
                            delta_Sigma=[0.0, 0.01 * scale])
    return DutyCycle(torque=np.array([r[0] for r in rows]) * max_torque, pinion_speed=speed,
                     revolutions=share / share.sum() * hours * speed * 60.0,
                     deflection=table, grade="MQ", miner_rule="modified",
                     name="illustrative axle spectrum (not a measured drive cycle)",
                     illustrative=True)


def illustrative_speed_note(duty: DutyCycle, case_speed: float) -> str | None:
    """What the illustrative spectrum's speeds are not, where the case runs faster.

    The bundled spectrum (:func:`example_duty_cycle`) falls from 3000 to 600 rpm for every
    case; an e-axle whose ``[operating] pinion_speed`` is 12000 rpm ran it without a word
    that its bins are a quarter of the case's speed and below (issue 71, round 29 of
    docs/own_gear_set.md).

    Parameters
    ----------
    duty : DutyCycle
        The spectrum run; only an ``illustrative`` one gets a note.
    case_speed : float — [rpm]
        The case's ``[operating] pinion_speed`` (0: no speed given, no note).

    Returns
    -------
    str or None
        The note, naming both speeds and how to give a measured spectrum; None where the
        spectrum is a user's or its top speed is at or above the case's.

    Notes
    -----
    Source: :data:`EXAMPLE_BINS` (the speeds' shares of ``max_speed``); docs/duty_cycle.md.
    """
    top = float(np.max(duty.pinion_speed))
    if not duty.illustrative or not math.isfinite(case_speed) or case_speed <= top:
        return None
    return (f"the illustrative bins run at {top:g} ... {float(np.min(duty.pinion_speed)):g} "
            f"rpm, below the case's [operating] pinion_speed {case_speed:g} rpm: its speed "
            "factors, film and losses are not the case's; a measured spectrum (--duty FILE "
            "or a [duty_cycle] table, docs/duty_cycle.md) gives them")
