"""One table of the physical bounds of the operating inputs, applied before any work.

Every command and the public API (``ltca run``, ``rate``, ``efficiency-map``,
``duty-cycle``, ``ehl``; :func:`contact.run_analysis`,
:class:`friction.operating.OperatingConditions`,
:func:`contact.load_capacity.iso10300.iso10300_rating`,
:func:`contact.study.efficiency.efficiency_map`) checks a speed, torque, roughness,
temperature or pressure against the same bound here, so that a value no gear pair runs at
— a typing slip of orders of magnitude (``--speed 1e12``, ``--roughness 100`` µm,
``--pressure 1e-9`` GPa) — is refused in one sentence naming the input and the accepted
range, instead of being computed into a plausible-looking number or a solver failure after
minutes of work.

The bounds are physical, not the fitted ranges of a model: a value inside a bound may
still lie outside a friction model's fitted range (flagged, ``friction_model_extrapolated``)
or an oil's temperature table (refused by the oil, :func:`friction.lubricant.temperature_range`).

This module imports nothing heavy (the commands check their options before NumPy loads).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from geometry.core.errors import InputError

__all__ = ["PHYSICAL_BOUNDS", "Bound", "check_bound", "check_torques"]


@dataclass(frozen=True)
class Bound:
    """The accepted range of one physical input.

    Attributes
    ----------
    quantity : str
        What the input is (for messages and docs).
    unit : str
        The unit of ``low`` and ``high`` (UDUNITS spelling).
    low, high : float
        The range's ends.
    low_open : bool
        ``low`` itself excluded (``(low, high]``).
    why : str
        Where the ends come from.
    """

    quantity: str
    unit: str
    low: float
    high: float
    low_open: bool = False
    why: str = ""


#: The bounds, by the name of the input (the toolkit's field names). Sources:
#:
#: * ``torque`` (0, 1e6] N·m pinion torque: the largest spiral-bevel drives built (mill and
#:   marine drives of several MW at ~100 rpm of the pinion) run at ≈ 5e5 N·m;
#: * ``pinion_speed`` (0, 5e4] rpm: above the fastest bevel pinions in service (helicopter
#:   input stages at the turboshaft's ≈ 21 000 rpm output speed) by more than two;
#: * ``roughness`` [0, 5] µm Rq of one flank: a rough-turned flank; ground and lapped gear
#:   flanks are 0.1–1 µm (the bound ``ltca ehl`` applied first, issue 55);
#: * ``temperature`` [-40, 200] °C oil inlet temperature: a cold start to beyond every gear
#:   oil's service limit (each oil's own data range is checked where the oil is known);
#: * ``hertz_pressure`` [10, 6000] MPa: above, the shakedown limit of every steel of the
#:   materials table (5.26 GPa) is passed (:data:`friction.ehl.line_contact.
#:   MAX_HERTZ_PRESSURE`); below 10 MPa (a line load under 0.1 N/mm on R 20 mm) no gear
#:   contact carries load, and the line-contact solvers, converged at 10 MPa, fail there
#:   after tens of seconds (issue 64);
#: * ``radius`` [0.01, 5000] mm equivalent radius, ``entraining_velocity`` (0, 100] m/s,
#:   ``slide_to_roll`` [-2, 2]: the line-contact solvers' range
#:   (:mod:`friction.ehl.line_contact`: a rounded tooth edge to a flat flank; beyond any
#:   gear's pitch-line speed; both surfaces moving the oil in).
PHYSICAL_BOUNDS: Mapping[str, Bound] = MappingProxyType({
    "torque": Bound("pinion torque", "N m", 0.0, 1e6, low_open=True,
                    why="largest spiral-bevel drives ~5e5 N m"),
    "pinion_speed": Bound("pinion speed", "rpm", 0.0, 5e4, low_open=True,
                          why="fastest bevel pinions ~21 000 rpm"),
    "roughness": Bound("RMS roughness Rq of a flank", "um", 0.0, 5.0,
                       why="rough-turned flank; ground 0.1-1 um"),
    "temperature": Bound("oil inlet temperature", "degC", -40.0, 200.0,
                         why="cold start to beyond every gear oil's service limit"),
    "hertz_pressure": Bound("Hertz maximum pressure", "MPa", 10.0, 6000.0,
                            why="loaded gear contact to the shakedown limit of steel"),
    "radius": Bound("equivalent radius of curvature", "mm", 0.01, 5000.0,
                    why="rounded edge to flat flank"),
    "entraining_velocity": Bound("entraining velocity", "m/s", 0.0, 100.0, low_open=True,
                                 why="beyond any gear's pitch-line speed"),
    "slide_to_roll": Bound("slide-to-roll ratio", "1", -2.0, 2.0,
                           why="both surfaces moving the oil in"),
})


def check_bound(name: str, value: Any, *, field: str | None = None, scale: float = 1.0,
                unit: str | None = None, positive: bool = False) -> float:
    """``value`` as a float, checked against the bound :data:`PHYSICAL_BOUNDS` [``name``].

    Parameters
    ----------
    name : str
        The input's name in :data:`PHYSICAL_BOUNDS`.
    value : float
        In the table's unit divided by ``scale`` (``scale`` 1: the table's unit).
    field : str, optional
        The name the message gives the input (an option ``--speed``, a field
        ``pinion_speed``); default ``name``.
    scale : float
        Table unit per unit of ``value`` (1e3 for a Hertz pressure in GPa against the
        table's MPa).
    unit : str, optional
        The unit of ``value`` as the message writes it (default the table's).
    positive : bool
        Refuse 0 too where the table's range includes it (an operating roughness).

    Returns
    -------
    float
        The value, in its own unit.

    Raises
    ------
    InputError
        A value that is no real number, not finite or outside the bound, in the
        toolkit's one form (:func:`geometry.core.validation.real`):
        ``"--speed: must be in (0, 50000] [rpm], got 1e+12"``.
    """
    from geometry.core.validation import real

    b = PHYSICAL_BOUNDS[name]
    low, high = b.low / scale, b.high / scale
    low_open = b.low_open or (positive and b.low == 0.0)
    v = real(field or name, value, unit=unit or b.unit)  # a finite number, else refused
    if not ((v > low if low_open else v >= low) and v <= high):
        raise InputError(f"{field or name}: must be in {'(' if low_open else '['}{low:g}, "
                         f"{high:g}] [{unit or b.unit}], got {v:g}")
    return v


def check_torques(torque, field: str = "torque") -> tuple[float, ...]:
    """Pinion torques [N·m] of an API call, each a number in the table of physical bounds
    (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`, (0, 1e6] N·m).

    Parameters
    ----------
    torque : float or sequence of float — [N·m]
    field : str
        The argument's name in the message.

    Returns
    -------
    tuple of float

    Raises
    ------
    InputError
        Text, an empty sequence, a value not finite or outside the bound (one sentence
        naming ``field`` and the range).
    """
    import numpy as np  # here: `ltca --help` reads the bounds without numpy (test_startup)

    try:
        ndim = -1 if isinstance(torque, (str, bytes)) else np.ndim(torque)
    except ValueError:  # a ragged nesting
        ndim = -1
    if ndim not in (0, 1):
        raise InputError(f"{field}: must be a number or a sequence of numbers in (0, 1e+06] "
                         f"[N m] (pinion torques), got {torque!r}")
    values = [torque] if np.ndim(torque) == 0 else list(torque)
    if not values:
        raise InputError(f"{field}: must hold at least one pinion torque [N m], got none")
    return tuple(check_bound("torque", t, field=field) for t in values)
