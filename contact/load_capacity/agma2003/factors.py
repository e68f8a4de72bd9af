"""The rating factors of ANSI/AGMA 2003-D19 (clauses 10–20, SI "M" equations).

Plain functions of physical inputs, one per factor, each citing the standard's equation
or figure. The standard's text was not at hand: the equations are those of its SI
("M") clauses as a public implementation reads them (an ANSI/AGMA 2003-D19 calculator with
a self-test against the standard's Annex E, docs/rating.md "ANSI/AGMA 2003-D19"), and
every factor Annex E prints is checked against it (tests/test_rating_agma2003.py).

Units: lengths [mm], speeds [m/s], stresses [MPa], temperatures [degC]; factors [1].
"""

from __future__ import annotations

import math

from geometry.core.errors import InputError
from geometry.core.validation import integer, one_of, positive, real

__all__ = [
    "CROWNING_FACTOR",
    "MOUNTING_MODIFIER",
    "RELIABILITY_FACTORS",
    "bending_stress_cycle_factor",
    "dynamic_factor",
    "elastic_coefficient",
    "lengthwise_curvature_factor",
    "load_distribution_factor",
    "max_pitch_line_velocity",
    "pitch_line_velocity",
    "pitting_stress_cycle_factor",
    "reliability_factors",
    "size_factor_bending",
    "size_factor_pitting",
    "temperature_factor",
]

#: K_mb of Eq. 20M by mounting (Figure 4): both members, one member or neither member
#: straddle-mounted
MOUNTING_MODIFIER = {"both": 1.00, "one": 1.10, "neither": 1.25}

#: C_xc of clause 13: properly crowned teeth 1.5; teeth without crowning 2.0 ("2.0 or
#: larger": a larger value is given as ``crowning_factor``)
CROWNING_FACTOR = {True: 1.5, False: 2.0}

#: (C_R, K_R) of Table 2 by reliability (the probability of no failure): fewer than one
#: failure in 10 000, 1 000, 100, 10 and 2
RELIABILITY_FACTORS = {0.9999: (1.22, 1.50), 0.999: (1.12, 1.25), 0.99: (1.00, 1.00),
                       0.9: (0.92, 0.85), 0.5: (0.84, 0.70)}

#: the S–N lines of Figures 5 and 6 (carburised case-hardened steel bevel gears):
#: C_L = 3.4822 N^-0.0602; K_L = 6.1514 N^-0.1192 up to the knee, then 1.3558 N^-0.0178
#: (general) or 1.683 N^-0.0323 (critical service)
_PITTING_LINE = (3.4822, -0.0602)
_BENDING_LOW = (6.1514, -0.1192)
_BENDING_HIGH = {False: (1.3558, -0.0178), True: (1.683, -0.0323)}


def pitch_line_velocity(de1: float, n1: float) -> float:
    """Pitch-line velocity at the outer pitch diameter v_et [m/s].

    Parameters
    ----------
    de1 : float — [mm]
        Pinion outer pitch diameter (> 0).
    n1 : float — [rpm]
        Pinion speed (> 0).

    Returns
    -------
    float — [m/s]
        v_et = π d_e1 n1 / 60 000.

    Raises
    ------
    InputError
        A non-positive diameter or speed (named).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 16M (the standard's 5.236e-5 is π/60 000 rounded).
    """
    return math.pi * positive("de1", de1, "mm") * positive("speed", n1, "rpm") / 60000.0


def dynamic_factor(accuracy_number: int, v_et: float) -> float:
    """Dynamic factor K_v from the transmission accuracy number Q_v.

    Parameters
    ----------
    accuracy_number : int
        Q_v, an integer in [5, 11] (Figure 1; higher is more accurate).
    v_et : float — [m/s]
        Pitch-line velocity at the outer pitch diameter (≥ 0), :func:`pitch_line_velocity`.

    Returns
    -------
    float — [1]
        K_v = (A / (A + √(200 v_et)))^−B with B = 0.25 (12 − Q_v)^0.667 and
        A = 50 + 56 (1 − B).

    Raises
    ------
    InputError
        Q_v outside [5, 11] or a negative velocity.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 13M–15 (clause 10). The SI equation's 200 stands for the US
    equation's 196.85 ft/min per m/s: Annex E's 1.081 (US units) is 1.0822 here
    (0.1 %). The velocity limit of the accuracy number is :func:`max_pitch_line_velocity`.
    """
    _, a, b = _dynamic_coefficients(accuracy_number)
    v = real("v_et", v_et, unit="m/s", low=0.0)
    return (a / (a + math.sqrt(200.0 * v))) ** -b


def max_pitch_line_velocity(accuracy_number: int) -> float:
    """The highest pitch-line velocity an accuracy number Q_v is recommended for [m/s].

    Parameters
    ----------
    accuracy_number : int
        Q_v, an integer in [5, 11].

    Returns
    -------
    float — [m/s]
        v_et,max = (A + (Q_v − 3))² / 200.

    Raises
    ------
    InputError
        Q_v outside [5, 11].

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 17M (clause 10.6): above it, a higher Q_v or a dynamic
    analysis (clause 10.7).
    """
    qv, a, _ = _dynamic_coefficients(accuracy_number)
    return (a + (qv - 3.0)) ** 2 / 200.0


def _dynamic_coefficients(accuracy_number: int) -> tuple[int, float, float]:
    """Q_v checked (an integer in [5, 11]) and the dynamic factor's A and B of it
    (ANSI/AGMA 2003-D19 Eq. 14, 15)."""
    qv = integer("accuracy_number", accuracy_number, 5, 11, allow_float=True)
    b = 0.25 * (12.0 - qv) ** 0.667
    return qv, 50.0 + 56.0 * (1.0 - b), b


def size_factor_pitting(b: float) -> float:
    """Size factor for pitting resistance C_s.

    Parameters
    ----------
    b : float — [mm]
        Net face width (> 0).

    Returns
    -------
    float — [1]
        0.5 below 12.7 mm, 0.00492 b + 0.4375 from 12.7 to 79.8 mm, 0.83 above.

    Raises
    ------
    InputError
        A non-positive face width.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 18M (clause 11).
    """
    b = positive("b", b, "mm")
    if b < 12.7:
        return 0.5
    if b > 79.8:
        return 0.83
    return 0.00492 * b + 0.4375


def size_factor_bending(m_et: float) -> float:
    """Size factor for bending strength K_s.

    Parameters
    ----------
    m_et : float — [mm]
        Outer transverse module (> 0).

    Returns
    -------
    float — [1]
        0.5 below 1.6 mm, 0.4867 + 0.008399 m_et from 1.6 mm on.

    Raises
    ------
    InputError
        A non-positive module.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 19M (clause 11).
    """
    m = positive("m_et", m_et, "mm")
    return 0.5 if m < 1.6 else 0.4867 + 0.008399 * m


def load_distribution_factor(mounting: str, b: float) -> float:
    """Load distribution factor K_m.

    Parameters
    ----------
    mounting : {"both", "one", "neither"}
        Which members are straddle-mounted (K_mb 1.00, 1.10, 1.25:
        :data:`MOUNTING_MODIFIER`).
    b : float — [mm]
        Net face width, in (0, 356] (the range of Eq. 20M and Figure 4).

    Returns
    -------
    float — [1]
        K_m = K_mb + 5.6e-6 b².

    Raises
    ------
    InputError
        An unknown mounting, or a face width outside (0, 356] mm.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 20M and Figure 4 (clause 12).
    """
    kmb = MOUNTING_MODIFIER[one_of("mounting", mounting, tuple(MOUNTING_MODIFIER))]
    b = real("b", b, unit="mm", low=0.0, high=356.0, low_open=True)
    return kmb + 5.6e-6 * b * b


def lengthwise_curvature_factor(beta_m: float, r_c0: float, R_m: float) -> float:
    """Lengthwise curvature factor for bending strength K_x.

    Parameters
    ----------
    beta_m : float — [rad]
        Mean spiral angle, in [0, 60°) (0: straight or Zerol bevel gears).
    r_c0 : float — [mm]
        Cutter radius (> 0; unused for β_m = 0).
    R_m : float — [mm]
        Mean cone distance (> 0).

    Returns
    -------
    float — [1]
        1 for straight and Zerol bevel gears (Eq. 22); for spiral bevel gears
        0.211 (r_c0/R_m)^q + 0.789 with q = 0.279 / log10(sin β_m) (Eq. 21M, 23M), held
        within [1.0, 1.15].

    Raises
    ------
    InputError
        A spiral angle outside [0, 60°) or a non-positive radius.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 21M–23M (clause 14); the limits [1.0, 1.15] are the note under
    Eq. 22 as the public reading gives it (Annex E: r_c0/R_m = 1.41 gives 0.931 → 1.0).
    """
    beta = real("beta_m", beta_m, unit="deg", low=0.0, high=math.radians(60.0),
                high_open=True, scale=math.pi / 180.0)
    rm = positive("R_m", R_m, "mm")
    if beta == 0.0:
        return 1.0
    rc = positive("r_c0", r_c0, "mm")
    q = 0.279 / math.log10(math.sin(beta))
    return min(max(0.211 * (rc / rm) ** q + 0.789, 1.0), 1.15)


def pitting_stress_cycle_factor(load_cycles: float) -> float:
    """Stress cycle factor for pitting resistance C_L of carburised case-hardened steel.

    Parameters
    ----------
    load_cycles : float — [1]
        Number of load cycles N_L of the member, in [1e4, 1e10].

    Returns
    -------
    float — [1]
        C_L = 3.4822 N_L^−0.0602 (2.0 at 1e4 cycles, 1.0 at 1e9).

    Raises
    ------
    InputError
        N_L outside [1e4, 1e10]: Figure 5's line is not extrapolated (clause 3.7); below
        1e4 cycles give the factor (``stress_cycle_factor_pitting``).

    Notes
    -----
    ANSI/AGMA 2003-D19 Figure 5 (clause 16.1), carburised case-hardened steel bevel
    gears; other materials give C_L themselves.
    """
    n = real("load_cycles", load_cycles, low=1e4, high=1e10)
    c, e = _PITTING_LINE
    return c * n ** e


def bending_stress_cycle_factor(load_cycles: float, critical_service: bool = False) -> float:
    """Stress cycle factor for bending strength K_L of carburised case-hardened steel.

    Parameters
    ----------
    load_cycles : float — [1]
        Number of load cycles N_L of the member, in [1e3, 1e10].
    critical_service : bool
        The lower edge of Figure 6's band beyond its knee (critical service) instead of the
        upper (general applications).

    Returns
    -------
    float — [1]
        K_L = 6.1514 N_L^−0.1192 up to the knee (≈ 3e6 cycles, where the lines meet), then
        1.3558 N_L^−0.0178 (general) or 1.683 N_L^−0.0323 (critical service).

    Raises
    ------
    InputError
        N_L outside [1e3, 1e10] (Figure 6's range; clause 3.7: not extrapolated).

    Notes
    -----
    ANSI/AGMA 2003-D19 Figure 6 (clause 16.2), carburised case-hardened steel bevel
    gears; other materials give K_L themselves.
    """
    n = real("load_cycles", load_cycles, low=1e3, high=1e10)
    c_low, e_low = _BENDING_LOW
    c_high, e_high = _BENDING_HIGH[bool(critical_service)]
    knee = (c_high / c_low) ** (1.0 / (e_low - e_high))
    return c_low * n ** e_low if n <= knee else c_high * n ** e_high


def temperature_factor(temperature: float) -> float:
    """Temperature factor K_T.

    Parameters
    ----------
    temperature : float — [degC]
        Gear blank temperature during operation (≥ 0).

    Returns
    -------
    float — [1]
        1 up to 120 °C, (273 + T) / 393 above.

    Raises
    ------
    InputError
        A temperature below 0 °C (clause 18 covers 0 °C and above).

    Notes
    -----
    ANSI/AGMA 2003-D19 clause 18, Eq. 31M.
    """
    t = real("temperature", temperature, unit="degC", low=0.0)
    return 1.0 if t <= 120.0 else (273.0 + t) / 393.0


def reliability_factors(reliability: float) -> tuple[float, float]:
    """Reliability factors (C_R, K_R) for pitting and bending.

    Parameters
    ----------
    reliability : float — [1]
        The probability of no failure: 0.9999, 0.999, 0.99, 0.9 or 0.5 (fewer than one
        failure in 10 000, 1 000, 100, 10, 2).

    Returns
    -------
    (float, float) — [1]
        C_R, K_R of :data:`RELIABILITY_FACTORS`.

    Raises
    ------
    InputError
        Another value.

    Notes
    -----
    ANSI/AGMA 2003-D19 Table 2 (clause 19); the allowable stress numbers are for 0.99.
    """
    r = real("reliability", reliability, low=0.0, high=1.0, low_open=True, high_open=True)
    for key, value in RELIABILITY_FACTORS.items():
        if math.isclose(r, key, rel_tol=0.0, abs_tol=1e-9):
            return value
    raise InputError(f"reliability: must be one of {sorted(RELIABILITY_FACTORS)} (Table 2), "
                     f"got {r!r}")


def elastic_coefficient(youngs_modulus: tuple[float, float],
                        poisson_ratio: tuple[float, float]) -> float:
    """Elastic coefficient C_p [MPa^0.5].

    Parameters
    ----------
    youngs_modulus : (float, float) — [MPa]
        E of pinion and gear (> 0).
    poisson_ratio : (float, float) — [1]
        ν of pinion and gear, in [0, 0.5).

    Returns
    -------
    float — [MPa^0.5]
        C_p = (π ((1 − ν1²)/E1 + (1 − ν2²)/E2))^−1/2.

    Raises
    ------
    InputError
        A modulus or ratio out of range (named).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 32M (clause 20); steel/steel (207 000 MPa, 0.3): 190.3,
    Annex E's 2290 psi^0.5 is 190.15 (0.07 %).
    """
    e = [positive("youngs_modulus", x, "MPa") for x in youngs_modulus]
    nu = [real("poisson_ratio", x, low=0.0, high=0.5, high_open=True) for x in poisson_ratio]
    return 1.0 / math.sqrt(math.pi * sum((1.0 - v * v) / m for v, m in zip(nu, e,
                                                                           strict=True)))
