"""Operating conditions of the efficiency stage, with the toolkit's defaults in one place.

:class:`OperatingConditions` holds what the efficiency stage (seed ch. 5,
:func:`friction.efficiency.efficiency_analysis`) needs beyond the loaded contact: the
pinion speed, the lubricant and its inlet temperature, the surface roughness and the
friction coefficient model. Its defaults are the toolkit's operating defaults — the
``ltca`` command line (``ltca run``, ``ltca efficiency-map``) and
:func:`contact.pipeline.run_analysis` / :func:`contact.study.efficiency.efficiency_map` take
theirs from here::

    >>> from friction.operating import OperatingConditions
    >>> OperatingConditions().pinion_speed, OperatingConditions().lubricant
    (1500.0, '75W90')
    >>> OperatingConditions(temperature=60.0).temperature
    60.0

Units: rpm, degC, µm.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

from friction.coefficient import FrictionModelLike, friction_model_name, get_friction_model
from friction.defaults import DEFAULT_FRICTION_MODEL
from friction.lubricant import available_lubricants
from geometry.case import OPERATING_DEFAULTS, OperatingPoint
from geometry.core.bounds import check_bound
from geometry.core.errors import InputError, ModelUnavailableError, UnknownNameError

__all__ = ["RUNNING_IN_FACTORS", "SURFACE_STATES", "OperatingConditions"]

#: Rq of a flank after running-in over its Rq as manufactured, by surface state: "run_in"
#: 17/25 = 0.68, the improvement AGMA's scuffing guidance gives for high-speed carburised
#: gears ("may improve from 25 µin rms to 17 µin rms by running-in"; ground flanks 10–40 →
#: 10–25 µin rms), as quoted in the GearCalc manual, §14.12 "Surface roughness"
#: (http://www.gearcalc.com/downloads/manual/manualse81.html, after AGMA 925-A03); "new":
#: 1, the flank as manufactured (a new gear's first hours).
RUNNING_IN_FACTORS = MappingProxyType({"run_in": 17.0 / 25.0, "new": 1.0})

#: the surface states :class:`OperatingConditions` accepts
SURFACE_STATES = tuple(RUNNING_IN_FACTORS)

@dataclass(frozen=True)
class OperatingConditions:
    """Operating point of the efficiency stage (seed §5.2–5.3), validated on construction.

    Parameters
    ----------
    pinion_speed : float — [rpm]
        Pinion speed, in (0, 5e4] (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`). Default
        1500 rpm (the toolkit's choice, inside the 500–4000 rpm of
        ``ltca efficiency-map``'s default sweep).
    lubricant : str or path
        A bundled oil name (case-insensitive, :func:`friction.lubricant.available_lubricants`)
        or the path of an oil TOML file (:func:`friction.lubricant.load_lubricant`).
        Default ``"75W90"``, the axle oil of the seed's Table 5.2.
    temperature : float — [degC]
        Oil inlet temperature, in [-40, 200] (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`);
        the lubricant's own range (its table plus extrapolation margins,
        :func:`friction.lubricant.temperature_range`) is checked when its properties are
        evaluated, or before an analysis by :meth:`check_oil_temperature`. Default 90 °C
        (the toolkit's choice, inside the 25–100 °C of the seed's Table 5.2).
    roughness : float — [µm]
        RMS roughness Rq of each flank, in (0, 5] (the table of bounds; composite
        σ = √2 Rq, seed §5.2.3).
        Default 0.8 µm, the seed's operating roughness (§5.3) and inside the fitted
        0.1–1 µm of ``kolivand2009`` and ``xu2007``.
    friction_model : str, friction.coefficient.FrictionModel or callable
        A registered friction coefficient model
        (:func:`friction.coefficient.available_friction_models`), or a model of one's own
        (a FrictionModel, or a model function, checked and wrapped by
        :func:`friction.coefficient.as_friction_model`; results record its name,
        :attr:`friction_model_name`). Default
        :data:`friction.defaults.DEFAULT_FRICTION_MODEL`, ``"thermal_eyring"`` since issue
        74: Zhou & Hoeprich's asperity load share, boundary friction and a thermal Eyring
        film, which ranks surface finishes, oils and temperatures as ISO/TR 14179-2 and Xu
        et al. (2007) do (docs/friction.md, "Which model is the default");
        ``"mixed_ehl"`` (Johnson, Greenwood & Poon's sharing with an isothermal Eyring
        film) was the default in issues 61–74, ``"kolivand2009"`` (the seed's Eq. 5.11
        method fitted to the toolkit's stochastic solver) in issues 34–61 and
        ``"xu2007"`` before it.
    surface_state : {"run_in", "new"}
        The flanks' state: ``"run_in"`` (default: a gear in service) runs the film and the
        friction model on the run-in roughness Rq × :data:`RUNNING_IN_FACTORS` ["run_in"]
        (0.68, AGMA's carburised high-speed gears); ``"new"`` on ``roughness`` as given
        (the flanks as manufactured). ``roughness`` is always the as-manufactured value
        (what a drawing or a profilometer on a new flank gives); the surface-durability
        checks (λ_GF of ISO/TS 6336-22) use it as given.

    Raises
    ------
    InputError
        A speed, temperature or roughness out of range, or a lubricant that is not a
        string or path (``<field>: must be … [<unit>], got …``).
    ModelUnavailableError
        A lubricant that is neither bundled nor an existing file, or an unknown or
        unavailable friction model (the message lists what is available).

    Notes
    -----
    Sources: seed ch. 5 (Kolivand 2009: §5.2 the efficiency model and its inputs, Table
    5.2 the 75W90 oil, §5.3 the operating-condition sweeps); Xu, Kahraman, Anderson &
    Maddock, J. Mech. Des. 129 (2007) 58–68 and Johnson, Greenwood & Poon, Wear 19 (1972)
    91–108 for the friction models.
    """

    pinion_speed: float = OPERATING_DEFAULTS["pinion_speed"]
    lubricant: str | os.PathLike[str] = OPERATING_DEFAULTS["lubricant"]
    temperature: float = OPERATING_DEFAULTS["temperature"]
    roughness: float = OPERATING_DEFAULTS["roughness"]
    friction_model: FrictionModelLike = DEFAULT_FRICTION_MODEL
    surface_state: str = "run_in"

    @classmethod
    def from_point(cls, point: OperatingPoint, **override) -> OperatingConditions:
        """The conditions of a case's operating point (:attr:`geometry.case.Case.operating`,
        its ``[operating]`` table), fields of ``override`` replacing its values (a field
        neither gives — a case without ``friction_model`` — takes the default).

        Raises
        ------
        InputError, ModelUnavailableError
            As the constructor (a pinion speed of 0, which a case uses to say "no
            efficiency stage", is refused here).
        """
        kw = {"pinion_speed": point.pinion_speed, "lubricant": point.lubricant,
              "temperature": point.temperature, "roughness": point.roughness,
              "friction_model": point.friction_model}
        kw.update({k: v for k, v in override.items() if v is not None})
        return cls(**{k: v for k, v in kw.items() if v is not None})

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        # the one table of physical bounds (a speed of 1e12 rpm or an Rq of 100 um is a
        # slip, refused before any work; issue 64), then each oil's range where it is read
        set_(self, "pinion_speed", check_bound("pinion_speed", self.pinion_speed))
        set_(self, "temperature", check_bound("temperature", self.temperature))
        set_(self, "roughness", check_bound("roughness", self.roughness, positive=True))
        oil = self.lubricant
        if not isinstance(oil, (str, os.PathLike)) or not str(oil).strip():
            raise InputError("lubricant: must be a bundled oil name or the path of an oil "
                             f"TOML file, got {oil!r}")
        bundled = available_lubricants()
        if not ((isinstance(oil, str) and oil.lower() in {b.lower() for b in bundled})
                or Path(oil).is_file()):
            raise ModelUnavailableError(f"lubricant: must be one of the bundled oils "
                                        f"{list(bundled)} or an existing oil TOML file, got "
                                        f"{str(oil)!r}")
        model = self.friction_model
        if not (isinstance(model, str) or callable(model)):
            raise InputError("friction_model: must be the name of a friction model, a "
                             f"FrictionModel or a model function, got {model!r}")
        try:
            resolved = get_friction_model(model)
        except ModelUnavailableError as exc:  # the message lists the available models
            raise UnknownNameError(f"friction_model: {exc}") from None
        except InputError as exc:  # a function failing the registry's checks
            raise InputError(f"friction_model: {exc}") from None
        if not isinstance(model, str):
            set_(self, "friction_model", resolved)
        if self.surface_state not in RUNNING_IN_FACTORS:
            raise InputError(f"surface_state: must be one of {list(SURFACE_STATES)}, got "
                             f"{self.surface_state!r}")

    @property
    def effective_roughness(self) -> float:
        """Rq [µm] of each flank in the film and the friction model: ``roughness`` ×
        :data:`RUNNING_IN_FACTORS` [``surface_state``]."""
        return self.roughness * RUNNING_IN_FACTORS[self.surface_state]

    def oil(self):
        """The oil :attr:`lubricant` names, read once per conditions object and kept on it
        (the conditions are frozen): an analysis' efficiency, scuffing and flash-temperature
        steps read the same oil (:func:`friction.lubricant.load_lubricant`, ~2 ms each).

        Returns
        -------
        friction.lubricant.Lubricant
            The oil's properties and sources, the same object at every call.

        Raises
        ------
        InputError, ModelUnavailableError
            As :func:`friction.lubricant.load_lubricant`.
        """
        oil = self.__dict__.get("_oil")
        if oil is None:
            from friction.lubricant import load_lubricant

            oil = load_lubricant(self.lubricant)
            object.__setattr__(self, "_oil", oil)
        return oil

    def check_oil_temperature(self) -> None:
        """Refuse an inlet temperature outside the oil's data range
        (:func:`friction.lubricant.temperature_range`) now, before an analysis, rather than
        when the efficiency stage reads the oil's properties after the loaded contact.

        Raises
        ------
        InputError
            ``temperature: must be in [5, 140] [degC] for the lubricant '75W90' (its
            data and extrapolation margins), got 150``; an unreadable oil file.
        """
        from friction.lubricant import temperature_range

        lo, hi = temperature_range(self.oil())
        if not lo <= self.temperature <= hi:
            raise InputError(f"temperature: must be in [{lo:g}, {hi:g}] [degC] for the "
                             f"lubricant {str(self.lubricant)!r} (its data and extrapolation "
                             f"margins), got {self.temperature:g}")

    @property
    def friction_model_name(self) -> str:
        """The friction model's name, as results record it (``friction_model`` attribute)."""
        return friction_model_name(self.friction_model)
