"""The flash temperature of a surface sliding through a line contact.

The heat of friction q(x) = τ(x) u_s (the film's shear and the asperities' boundary
friction, per unit area) is generated in the contact and carried away by the two
surfaces as they move through it. A surface moving at u under a band of heat flux q
(its share) warms by

    ΔT(x) = 1/(√π B √u) ∫_{−∞}^x q(ξ) / √(x − ξ) dξ,     B = √(kρc),

Jaeger's moving heat source at high Péclet number (heat conducted into the surface only
normal to it; Pe = u b/(2κ) ≈ 10–1000 in gear contacts), B the surface's thermal
effusivity (the "thermal contact coefficient" of ISO/TS 6336-20's flash-temperature
method). :func:`flash_temperature` integrates it exactly for a flux constant over each
node's cell.

The stochastic solver (:mod:`friction.ehl.stochastic`) evaluates the oil's viscosity at
the surfaces' temperature, inlet + flash, and iterates traction and temperature to a
fixed point — the thermal correction of the seed's Eq. 5.7 film shear (the seed corrects
its rolling traction likewise, Eq. 5.10). The film's own rise above its walls by
Couette conduction, τu_s h/(8k) at the mid-plane (Johnson & Greenwood 1980), is not
added: added in full, at two thirds or at half it drove μ below a tenth of the `xu2007`
thermal EHL regression at high sliding speed and trebled the scatter against it, where
the surfaces' temperature alone stays within a factor of 1.5 on average (docs/ehl.md) —
EHL films at GPa shear in thin bands near a wall (Bair, Qureshi & Winer 1993), not with
the uniform dissipation that formula assumes.

References
----------
Jaeger, J. C., "Moving sources of heat and the temperature at sliding contacts",
J. Proc. R. Soc. N.S.W. 76 (1942) 203–224; Carslaw, H. S., Jaeger, J. C., *Conduction of
Heat in Solids*, 2nd ed., Oxford (1959) §10.7; Archard, J. F., "The temperature of
rubbing surfaces", Wear 2 (1958/59) 438–455; Blok, H., "Theoretical study of temperature
rise at surfaces of actual contact under oiliness lubricating conditions", Proc. Gen.
Disc. Lubrication, IMechE 2 (1937) 222–235.
Johnson, K. L., Greenwood, J. A., "Thermal analysis of an Eyring fluid in
elastohydrodynamic traction", Wear 61 (1980) 353–374; Bair, S., Qureshi, F., Winer, W. O.,
"Observations of shear localization in liquid lubricants under pressure", J. Tribol. 115
(1993) 507–514.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from geometry.core.validation import real, real_array

__all__ = ["flash_temperature", "moving_source_weights"]

Array = NDArray[np.float64]


def moving_source_weights(nodes: int) -> Array:
    """w_k = 2(√(k + ½) − √(max(k − ½, 0))): ∫ of 1/√(x_i − ξ) over node j's cell, k = i − j.

    Returns
    -------
    array (nodes,) — [1]
        In units of √Δ (the cell's width): ΔT_i = Σ_(j ≤ i) w_(i−j) q_j √Δ /(…).
        Exact for a heat flux constant over each cell (the source ahead of a node, k < 0,
        does not heat it at high Péclet number).
    """
    k = np.arange(nodes, dtype=float)
    return 2.0 * (np.sqrt(k + 0.5) - np.sqrt(np.maximum(k - 0.5, 0.0)))


def flash_temperature(heat_flux: ArrayLike, spacing: float, speed: float,
                      effusivity: float) -> Array:
    """Surface temperature rise of a surface moving under a band of heat flux.

    Parameters
    ----------
    heat_flux : array (n,) — [W/m2]
        Heat flux into this surface at equally spaced places along its motion (≥ 0;
        its share of the heat generated).
    spacing : float — [m]
        Node spacing, > 0.
    speed : float — [m/s]
        The surface's speed through the contact, > 0.
    effusivity : float — [W s^0.5/(m2 K)]
        B = √(kρc) of the surface, > 0.

    Returns
    -------
    array (n,) — [K]
        ΔT(x_i) = (√Δ/(√π B √u)) Σ_(j ≤ i) w_(i−j) q_j (:func:`moving_source_weights`).

    Raises
    ------
    InputError
        A non-finite flux or a non-positive spacing, speed or effusivity.

    Notes
    -----
    Source: Jaeger (1942); Carslaw & Jaeger (1959) §10.7 (module docstring). Tested
    against the closed form of a uniform band: ΔT(x) = 2q√(x − x₀)/(√π B √u).
    """
    q = real_array("heat_flux", heat_flux, unit="W/m2", ndim=1)
    dx = real("spacing", spacing, unit="m", low=0.0, low_open=True)
    u = real("speed", speed, unit="m/s", low=0.0, low_open=True)
    b = real("effusivity", effusivity, unit="W s0.5/(m2 K)", low=0.0, low_open=True)
    w = moving_source_weights(q.size)
    conv = np.convolve(q, w)[: q.size]
    return conv * math.sqrt(dx) / (math.sqrt(math.pi) * b * math.sqrt(u))
