"""The static contact strength of a flank: the one limit every check of a local flank or
edge pressure judges against (issue 71: ``ltca run``'s verdict and ``ltca duty-cycle``'s
judged the same design at the same torque against 2400 and 2587–2880 MPa).

    σ_H,stat = σ_Hlim · Z_NT,stat · Z_W · Z_X                                        [MPa]

(ISO 6336-2:2019, Method B: the pitting stress limit σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X
at the static stress, where Z_L Z_v Z_R = 1.)

* σ_Hlim — the allowable contact stress number of the material at the ISO 6336-5:2016
  quality grade (``geometry/core/data/materials.toml``, group ``allowable_stress``;
  1500 MPa for the case-carburised steel at MQ);
* Z_NT,stat — the life factor at N_L ≤ N_static, the S–N curve's static end (ISO 6336-2:2019
  Table 2 / Fig. 5, case-hardened steel Eh without limited pitting: 1.6 up to 10⁵ cycles;
  group ``sn_contact``);
* Z_L Z_v Z_R = 1 — the lubricant-film influences are 1 for the static stress (ISO 6336-2's
  static column; ISO 10300-2:2014 cl. 8 follows it, :func:`contact.load_capacity.iso10300.
  pitting.long_life_share` gives them the exponent 0 there);
* Z_W — the work hardening factor, a property of the material pair that holds at every
  life: 1 for the toolkit's case-hardened pair
  (:func:`contact.load_capacity.iso10300.pitting.work_hardening_factor`);
* Z_X = 1 — the size factor of bevel gears (ISO 10300-2:2014 cl. 8,
  :data:`contact.load_capacity.iso10300.pitting.SIZE_FACTOR`);
* no S_H,min: the strength is the limit beyond which a flank has no life (S_H = 1, the
  verdict's FAIL). S_H,min is a design margin on the rating's S_H = σ_HP/σ_H, checked by
  the rating itself (σ_HP = σ_HG/S_H,min in ISO 6336-2, the TR's σ_HP without it).

Not in it: the bevel gear factor Z_K (1.2) and the hypoid factor Z_Hyp of ISO 10300-2:2014
cl. 6 (Method B1). Z_K is the empirical factor that makes Method B1's nominal stress — the
Hertzian stress of the virtual cylindrical gears at the mean point, σ_H0 with Z_M-B and
Z_LS — comparable with the material numbers of cylindrical gears; Z_Hyp rates the lengthwise
sliding of the virtual gears at the mean point, an influence of the lubricant film on
pitting as Z_L Z_v Z_R are, which ISO 6336-2 takes as 1 at the static stress. The pressures
judged here (the LTCA's flank and edge peaks) are no σ_H0 of Method B1 but the local Hertzian
pressure of the loaded flanks themselves, so they meet the material's own static strength.
The rating keeps both factors for its σ_HP against its σ_H (``ltca rate``), and the duty
cycle's S–N line keeps the rating's allowables between its knee and 10⁵ cycles
(:meth:`contact.load_capacity.durability.SNCurve.rated`, docs/duty_cycle.md); its static
check judges against this strength. With Z_K and Z_Hyp, σ_Hlim Z_NT,stat Z_X Z_W Z_K Z_Hyp is
the rating's σ_HP at 10⁵ cycles: 1500 × 1.6 × 1.2 = 2880 MPa for a spiral bevel gear
(Z_Hyp = 1), 2587 MPa at Z_Hyp = 0.898 — what ``ltca duty-cycle`` judged before.

Public names
------------
StaticContactStrength    the strength and its factors, with the words a finding prints
static_contact_strength  the strength of one material at a grade
weaker_static_strength   the weaker of two members' materials (what every check reads)
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from contact.load_capacity.durability.sn_curve import sn_curves
from geometry.core.materials import Material

__all__ = ["StaticContactStrength", "static_contact_strength", "weaker_static_strength"]


@dataclass(frozen=True)
class StaticContactStrength:
    """The static contact strength σ_H,stat = σ_Hlim·Z_NT,stat·Z_W·Z_X of a material.

    Parameters
    ----------
    strength : float — [MPa]
        σ_H,stat.
    sigma_Hlim : float — [MPa]
        The allowable contact stress number at the grade (ISO 6336-5).
    Z_NT : float — [1]
        The life factor at the S–N curve's static end (ISO 6336-2).
    Z_W, Z_X : float — [1]
        Work hardening and size factor (ISO 6336-2; ISO 10300-2 cl. 8).
    material : str
        The material's table name.
    grade : str
        The ISO 6336-5 quality grade.
    """

    strength: float
    sigma_Hlim: float
    Z_NT: float
    Z_W: float
    Z_X: float
    material: str
    grade: str

    @property
    def factors(self) -> str:
        """The product as a finding prints it, e.g. ``"σ_Hlim 1500 MPa × Z_NT 1.6"`` (Z_W and
        Z_X named where they are not 1)."""
        text = f"σ_Hlim {self.sigma_Hlim:.0f} MPa × Z_NT {self.Z_NT:g}"
        for name, value in (("Z_W", self.Z_W), ("Z_X", self.Z_X)):
            if value != 1.0:
                text += f" × {name} {value:g}"
        return text


def static_contact_strength(material: Material | str, grade: str = "MQ"
                            ) -> StaticContactStrength:
    """The static contact strength σ_H,stat = σ_Hlim·Z_NT,stat·Z_W·Z_X [MPa] of a material at
    an ISO 6336-5 quality grade: the limit above which a flank's peak pressure leaves it no
    life (module docstring: which factors and why).

    Parameters
    ----------
    material : geometry.core.materials.Material or str
        A material or its table name (:func:`geometry.core.materials.material`).
    grade : str
        ``"ML"``, ``"MQ"`` (default) or ``"ME"``.

    Returns
    -------
    StaticContactStrength
        2400 MPa (1500 × 1.6) for ``"case_carburised_steel"`` at MQ.

    Raises
    ------
    InputError
        An unknown material or grade (from :func:`~contact.load_capacity.durability.
        sn_curves`).

    Notes
    -----
    Source: ISO 6336-2:2019 Method B, the pitting stress limit at the static stress
    (σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X with Z_L Z_v Z_R = 1; Z_NT,stat of Table 2 by
    material, 1.6 up to N_L = 10⁵ for case-hardened steel); ISO 10300-2:2014 cl. 8 (Z_X = 1,
    Z_W); ISO 6336-5:2016 (σ_Hlim). No S_H,min (a limit, not a permissible stress) and no
    Z_K, Z_Hyp (Method B1's factors of its nominal stress, ISO 10300-2:2014 cl. 6).
    """
    from contact.load_capacity.iso10300.pitting import SIZE_FACTOR, work_hardening_factor

    curve = sn_curves(material, grade)["contact"]
    z_w = float(work_hardening_factor(1)[0])
    z_x = float(SIZE_FACTOR)
    return StaticContactStrength(
        strength=curve.allowable * curve.static_life_factor * z_w * z_x,
        sigma_Hlim=curve.allowable, Z_NT=curve.static_life_factor, Z_W=z_w, Z_X=z_x,
        material=material if isinstance(material, str) else material.key, grade=grade)


def weaker_static_strength(materials: Iterable[str | None], grade: str = "MQ"
                           ) -> StaticContactStrength | None:
    """The smaller :func:`static_contact_strength` of the members' materials: what the
    verdict of ``ltca run`` and of ``ltca duty-cycle``, the next steps and the bearing
    development judge a flank's and an edge's peak pressure against.

    Parameters
    ----------
    materials : iterable of str or None
        The members' material names (None: not named, skipped), e.g. the ``/ltca``
        attributes ``material_pinion``, ``material_gear``.
    grade : str
        The ISO 6336-5 quality grade (``ltca run``'s verdict: MQ; a duty cycle: its own).

    Returns
    -------
    StaticContactStrength or None
        The weaker (the first in the names' sorted order where they tie); None where no
        material is named.

    Raises
    ------
    InputError
        An unknown material or grade.

    Notes
    -----
    Source: as :func:`static_contact_strength`.
    """
    names = sorted({str(m) for m in materials if m is not None})
    if not names:
        return None
    return min((static_contact_strength(m, grade) for m in names),
               key=lambda s: s.strength)
