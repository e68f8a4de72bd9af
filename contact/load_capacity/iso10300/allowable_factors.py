"""The factors of the permissible contact stress at long life, σ_HP,∞ = σ_Hlim Z_X Z_L Z_v
Z_R Z_W Z_K Z_Hyp (ISO 10300-2:2014), taken apart: which one lowers it most, and whether
the hypoid factor sits at its lower bound (issue 71: the unseen hypoid 11×43 at Σ 100°,
a = 0.25 d_e2, whose local pitting limit was 998 MPa on σ_Hlim 1500 MPa).

Pure functions over an ISO 10300 ``/rating`` dataset
(:func:`contact.load_capacity.iso10300.rating.iso10300_rating`); the development's
torque-cut line names the factor (:func:`contact.optimize.development_root.root_capacity`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

#: the factors of σ_HP,∞/σ_Hlim (Z_NT = 1) as the rating names them, with their symbols
CONTACT_FACTORS = (("Z_X", "Z_X"), ("Z_L", "Z_L"), ("Z_speed", "Z_v"), ("Z_R", "Z_R"),
                   ("Z_W", "Z_W"), ("Z_K", "Z_K"), ("Z_Hyp", "Z_Hyp"))

#: the bounds of the hypoid factor (:func:`contact.load_capacity.iso10300.pitting.hypoid_factor`)
HYPOID_FACTOR_BOUNDS = (0.6, 1.0)


@dataclass(frozen=True)
class ContactAllowableFactors:
    """σ_HP,∞ of the weaker member taken apart.

    Attributes
    ----------
    sigma_Hlim, sigma_HP : float — [MPa] the endurance limit and σ_HP,∞ (Z_NT = 1)
    factors : dict[str, float] — [1] each factor of σ_HP,∞/σ_Hlim by its symbol
    lowest : str — the symbol of the smallest factor
    hypoid_unclipped : float — [1] 1 − 0.3 (v_g,par/v_Σ,vert − 0.15) before the bounds
        (NaN without offset)
    slide_ratio : float — [1] v_g,par/v_Σ,vert (NaN without offset)
    """

    sigma_Hlim: float
    sigma_HP: float
    factors: dict[str, float]
    lowest: str
    hypoid_unclipped: float
    slide_ratio: float

    @property
    def hypoid_at_bound(self) -> bool:
        """Whether Z_Hyp is held at its lower bound (the formula gives less)."""
        return (math.isfinite(self.hypoid_unclipped)
                and self.hypoid_unclipped < HYPOID_FACTOR_BOUNDS[0])


def _value(rating: Any, name: str, member: int) -> float:
    """One factor of ``rating`` as a float: the member's where it has a member axis, the
    long-life (last) value along any other."""
    v = np.asarray(rating[name].values, float)
    if "member" in rating[name].dims:
        v = np.take(v, member, axis=rating[name].dims.index("member"))
    return float(np.ravel(v)[-1])


def contact_allowable_factors(rating: Any) -> ContactAllowableFactors:
    """σ_HP,∞ = σ_Hlim Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp of the weaker member of ``rating``
    with each factor and the smallest named.

    Parameters
    ----------
    rating : xarray.Dataset
        An ISO 10300 ``/rating``: ``sigma_Hlim`` [MPa] over ``member`` (2,), the factors
        ``Z_X, Z_L, Z_speed, Z_R, Z_W, Z_K, Z_Hyp`` [1] and the sliding velocities
        ``v_g_par``, ``v_sum_vert`` [m/s] of Z_Hyp.

    Returns
    -------
    ContactAllowableFactors

    Raises
    ------
    KeyError
        A factor missing from ``rating``.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1) σ_HP = σ_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K
    Z_Hyp with Z_NT = 1; Z_Hyp = 1 − 0.3 (v_g,par/v_Σ,vert − 0.15) within [0.6, 1] as
    :func:`contact.load_capacity.iso10300.pitting.hypoid_factor` takes it (docs/rating.md).
    """
    n = int(np.asarray(rating["sigma_Hlim"].values).size)
    per = []
    for m in range(max(n, 1)):
        f = {sym: _value(rating, name, m) for name, sym in CONTACT_FACTORS}
        lim = _value(rating, "sigma_Hlim", m)
        per.append((lim * math.prod(f.values()), lim, f))
    hp, lim, f = min(per, key=lambda p: p[0])
    par = float(np.ravel(np.asarray(rating["v_g_par"].values, float))[-1])
    vert = float(np.ravel(np.asarray(rating["v_sum_vert"].values, float))[-1])
    ratio = par / vert if math.isfinite(vert) and vert > 0.0 and par > 0.0 else math.nan
    raw = 1.0 - 0.3 * (ratio - 0.15) if math.isfinite(ratio) else math.nan
    return ContactAllowableFactors(sigma_Hlim=lim, sigma_HP=hp, factors=f,
                                   lowest=min(f, key=f.get), hypoid_unclipped=raw,
                                   slide_ratio=ratio)


def contact_allowable_text(rating: Any) -> str:
    """One phrase saying what σ_HP,∞ of ``rating`` is made of and which factor lowers it
    most, e.g. "sigma_HP 1012 MPa = sigma_Hlim 1500 x Z_Hyp 0.60 x Z_K 1.2 x Z_X Z_L Z_v
    Z_R Z_W 0.94; the lowest factor Z_Hyp ...".

    Parameters
    ----------
    rating : xarray.Dataset — as :func:`contact_allowable_factors` takes it

    Returns
    -------
    str

    Raises
    ------
    KeyError
        A factor missing from ``rating``.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 and 8 (:func:`contact_allowable_factors`).
    """
    a = contact_allowable_factors(rating)
    low = a.lowest
    rest = [s for s in a.factors if s not in (low, "Z_K")]
    text = (f"sigma_HP {a.sigma_HP:.0f} MPa = sigma_Hlim {a.sigma_Hlim:.0f} x {low} "
            f"{a.factors[low]:.2f}"
            + ("" if low == "Z_K" else f" x Z_K {a.factors['Z_K']:.2g}")
            + f" x {' '.join(rest)} {math.prod(a.factors[s] for s in rest):.2f}; "
            f"its lowest factor {low}")
    if low == "Z_Hyp":
        text += (", the hypoid factor (ISO 10300-2 cl. 6: the lengthwise sliding v_g,par "
                 f"{a.slide_ratio:.2f} x the sum velocity v_Sigma,vert")
        text += (f"; the formula's {a.hypoid_unclipped:.3f} held at its lower bound "
                 f"{HYPOID_FACTOR_BOUNDS[0]:g})" if a.hypoid_at_bound else ")")
    return text
