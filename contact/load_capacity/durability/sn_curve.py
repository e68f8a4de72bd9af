"""S–N curves of the flanks (pitting) and the roots (bending) and Miner's rule.

The curves are those of ISO 6336-2 (contact) and ISO 6336-3 (bending): the allowable
stress number of the material's quality grade (σ_Hlim, σ_FE; ISO 6336-5) is the endurance
limit at the knee ``N_knee``; above it the life factor rises on a straight line in log–log
axes to its static value at ``N_static`` (Z_NT = 1.6 at 10⁵, Y_NT = 2.5 at 10³ for
case-hardened steel), i.e. Basquin's law σ^m N = σ_lim^m N_knee with
m = ln(N_knee / N_static) / ln(life factor at N_static). The numbers and their sources are
in the material table (``geometry/core/data/materials.toml``, groups
``allowable_stress``, ``sn_contact``, ``sn_bending``).

Below the knee, Miner's rule comes in the variants of :data:`MINER_RULES`:

* ``"elementary"`` (Miner elementary, Corten–Dolan): the line of slope m continued below
  the knee, no endurance limit (conservative: every cycle damages);
* ``"modified"`` (Miner modified after Haibach 1970): below the knee the slope becomes
  2m − 1;
* ``"original"`` (Palmgren–Miner original): no damage below the knee.

Above the static stress (the life factor's static value times the allowable) the Basquin
line is continued (stated: ISO gives no cycles there; :func:`beyond_static` flags those
stresses).

Public names
------------
SNCurve        one S–N curve (allowable, knee, exponent, static end)
MINER_RULES    registry: rule name → the exponent below the knee (None: no damage)
sn_curves      the contact and bending curves of a material and quality grade
GRADES         quality grades of ISO 6336-5 in the table

References
----------
ISO 6336-2:2019, ISO 6336-3:2019, ISO 6336-5:2016 (the material table's sources).
E. Haibach (1970). Modifizierte lineare Schadensakkumulations-Hypothese zur
Berücksichtigung des Dauerfestigkeitsabfalls mit fortschreitender Schädigung. LBF TM
50/70, Darmstadt.
M. A. Miner (1945). Cumulative damage in fatigue. J. Appl. Mech. 12, A159–A164.
A. Palmgren (1924). Die Lebensdauer von Kugellagern. Z. VDI 68, 339–341.
ISO 6336-6:2019 (service life under variable load: Palmgren–Miner on these curves).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from geometry.core.errors import InputError
from geometry.core.materials import Material, material
from geometry.core.validation import real

__all__ = ["GRADES", "MINER_RULES", "SNCurve", "sn_curves"]

#: ISO 6336-5 quality grades the material table may give
GRADES = ("ML", "MQ", "ME")

#: Miner's rule variants: name → the S–N exponent below the knee as a function of the
#: exponent m above it (None: cycles below the knee do no damage)
MINER_RULES: Mapping[str, Callable[[float], float | None]] = {
    "elementary": lambda m: m,
    "modified": lambda m: 2.0 * m - 1.0,
    "original": lambda m: None,
}


@dataclass(frozen=True)
class SNCurve:
    """One S–N curve: σ^m N = σ_lim^m N_knee above the knee.

    Parameters
    ----------
    allowable : float — [MPa]
        The endurance limit at the knee (σ_Hlim or σ_FE), > 0.
    knee_cycles : float — [1]
        Load cycles at the knee N_knee, > static_cycles.
    static_cycles : float — [1]
        Load cycles at the static end of the sloped line, >= 1.
    static_life_factor : float — [1]
        Life factor (Z_NT or Y_NT) at static_cycles, > 1.
    kind : str
        ``"contact"`` or ``"bending"`` (for the messages).
    source : str
        Where the numbers come from.

    Raises
    ------
    InputError
        A number out of its range (named).
    """

    allowable: float
    knee_cycles: float
    static_cycles: float
    static_life_factor: float
    kind: str = "contact"
    source: str = ""

    def __post_init__(self) -> None:
        real("allowable", self.allowable, low=0.0, low_open=True, unit="MPa")
        real("static_cycles", self.static_cycles, low=1.0, unit="1")
        real("knee_cycles", self.knee_cycles, low=self.static_cycles, low_open=True, unit="1")
        real("static_life_factor", self.static_life_factor, low=1.0, low_open=True, unit="1")

    @property
    def exponent(self) -> float:
        """Basquin's exponent m [1] of the sloped line (ISO's life-factor line)."""
        return math.log(self.knee_cycles / self.static_cycles) / math.log(
            self.static_life_factor)

    @property
    def static_stress(self) -> float:
        """The stress [MPa] at the static end: life factor × allowable."""
        return self.static_life_factor * self.allowable

    def rated(self, allowable_factor: float, static_influence: float = 1.0) -> SNCurve:
        """The curve of a rating's permissible stress: the allowable times the rating's
        long-life influence factors, those of them that are 1 for the static stress taken
        out at the static end.

        Parameters
        ----------
        allowable_factor : float — [1]
            σ_HP/(σ_Hlim Z_NT) at long life (Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp of ISO 10300-2),
            or σ_FP/(σ_FE Y_NT) (Y_δ,relT Y_R,relT Y_X of ISO 10300-3), > 0.
        static_influence : float — [1]
            The part of ``allowable_factor`` that is 1 for the static stress (Z_L Z_v Z_R;
            Y_R,relT Y_X), > 0.

        Returns
        -------
        SNCurve
            Allowable × ``allowable_factor`` at the knee; at the static end the static
            life factor × allowable × ``allowable_factor`` / ``static_influence``; the
            straight line in log-log axes between (a new exponent).

        Raises
        ------
        InputError
            A non-positive factor, or one that leaves the static end at or below the
            knee's stress (named).

        Notes
        -----
        ISO 6336-2:2019 cl. 5 and ISO 6336-3:2019 (the influence factors of the static and
        the reference stress; ISO 10300-2/-3:2014 cl. 8 follow them), through
        :func:`contact.load_capacity.iso10300.pitting.long_life_share`.
        """
        f = real("allowable_factor", allowable_factor, low=0.0, low_open=True, unit="1")
        z = real("static_influence", static_influence, low=0.0, low_open=True, unit="1")
        return SNCurve(self.allowable * f, self.knee_cycles, self.static_cycles,
                       self.static_life_factor / z, self.kind, self.source)

    def scaled(self, factor: float) -> SNCurve:
        """The curve of the same allowable and exponent with its constant σ^m N scaled.

        Parameters
        ----------
        factor : float — [1]
            Scale of the constant, > 0: knee cycles × factor; the static-end life factor
            moves so that the exponent m stays.

        Returns
        -------
        SNCurve

        Raises
        ------
        InputError
            A factor that puts the knee at or below the static end.
        """
        return SNCurve(self.allowable, self.knee_cycles * factor, self.static_cycles,
                       self.static_life_factor ** (math.log(self.knee_cycles * factor
                                                            / self.static_cycles)
                                                   / math.log(self.knee_cycles
                                                              / self.static_cycles)),
                       self.kind, self.source)

    def cycles_to_failure(self, stress: np.ndarray, rule: str = "modified") -> np.ndarray:
        """Cycles N [1] the curve allows at each stress amplitude.

        Parameters
        ----------
        stress : array_like — [MPa]
            Peak stresses of the cycles, any shape, >= 0 and finite.
        rule : str
            Miner's variant (:data:`MINER_RULES`): sets the curve below the knee.

        Returns
        -------
        ndarray, the shape of ``stress`` — [1]
            inf where the stress does no damage (0, or below the knee under ``"original"``).

        Raises
        ------
        InputError
            An unknown rule, or a negative or non-finite stress (named).
        """
        if rule not in MINER_RULES:
            raise InputError(f"miner_rule: must be one of {', '.join(MINER_RULES)}, "
                             f"got {rule!r}")
        s = np.asarray(stress, dtype=float)
        if not np.all(np.isfinite(s)) or np.any(s < 0):
            raise InputError(f"stress: {self.kind} stresses must be finite and >= 0 [MPa]")
        m = self.exponent
        low = MINER_RULES[rule](m)
        ratio = np.divide(self.allowable, s, out=np.full_like(s, np.inf), where=s > 0)
        with np.errstate(over="ignore"):
            above = self.knee_cycles * ratio ** m
            if low is None:
                below = np.full_like(s, np.inf)
            else:
                below = self.knee_cycles * ratio ** low
        return np.where(s >= self.allowable, above, below)

    def damage(self, stress: np.ndarray, cycles: np.ndarray, rule: str = "modified"
               ) -> np.ndarray:
        """Miner's damage n / N of ``cycles`` at each ``stress`` (elementwise).

        Parameters
        ----------
        stress : array_like — [MPa]
        cycles : array_like — [1]
            Load cycles n, >= 0, broadcastable with ``stress``.
        rule : str
            Miner's variant (:data:`MINER_RULES`).

        Returns
        -------
        ndarray — [1]
            n / N(σ), 0 where N is infinite.

        Raises
        ------
        InputError
            As :meth:`cycles_to_failure`; negative cycles.
        """
        n = np.asarray(cycles, dtype=float)
        if not np.all(np.isfinite(n)) or np.any(n < 0):
            raise InputError("cycles: load cycles must be finite and >= 0")
        return n / self.cycles_to_failure(stress, rule)

    def beyond_static(self, stress: np.ndarray) -> np.ndarray:
        """True where the stress exceeds the static end (the curve is extrapolated)."""
        return np.asarray(stress, float) > self.static_stress


def _group(mat: Material, name: str) -> Mapping:
    g = mat.groups.get(name)
    if g is None:
        raise InputError(f"material: {mat.key!r} has no {name} group in its table (needed "
                         "for durability)")
    return g


def sn_curves(mat: Material | str, grade: str = "MQ") -> dict[str, SNCurve]:
    """The contact and bending S–N curves of a material at an ISO 6336-5 quality grade.

    Parameters
    ----------
    mat : Material or str
        A material or its table name (:func:`geometry.core.materials.material`).
    grade : str
        ``"ML"``, ``"MQ"`` (default) or ``"ME"`` (those the table gives).

    Returns
    -------
    dict
        ``{"contact": SNCurve(σ_Hlim, …), "bending": SNCurve(σ_FE, …)}``.

    Raises
    ------
    InputError
        An unknown material or grade, or a table without the durability groups.

    Notes
    -----
    Source: the material table's ``allowable_stress``, ``sn_contact`` and ``sn_bending``
    groups (ISO 6336-5:2016; ISO 6336-2/-3:2019 life factors).
    """
    m = material(mat) if isinstance(mat, str) else mat
    allow = _group(m, "allowable_stress")
    grades = list(allow.get("grades", ()))
    if grade not in grades:
        raise InputError(f"grade: must be one of {', '.join(grades)} (ISO 6336-5 quality "
                         f"grades of {m.key}), got {grade!r}")
    i = grades.index(grade)
    out = {}
    for kind, group, key in (("contact", "sn_contact", "contact_allowable"),
                             ("bending", "sn_bending", "bending_allowable")):
        g = _group(m, group)
        out[kind] = SNCurve(float(allow[key][i]), float(g["knee_cycles"]),
                            float(g["static_cycles"]), float(g["static_life_factor"]),
                            kind, f"{allow['source']} {g['source']}")
    return out
