"""Stress numbers, permissible stress numbers and power ratings of ANSI/AGMA 2003-D19.

Clause 5's SI ("M") equations as plain functions over floats or numpy arrays (a torque
axis, a member axis: they broadcast): the calculated contact stress number s_c and
bending stress number s_t, the permissible s_wc and s_wt, and the allowable transmitted
powers P_ac and P_at, with Eq. 9M between torque and power. The rating factors are
:mod:`contact.load_capacity.agma2003.factors`'s.

Units: torque [N·m], lengths [mm], speed [rpm], stresses [MPa], power [kW],
C_p [MPa^0.5]; factors [1].
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "bending_power",
    "bending_stress",
    "contact_stress",
    "permissible_bending_stress",
    "permissible_contact_stress",
    "pitting_power",
    "power_from_torque",
    "torque_from_power",
]


def torque_from_power(power, n1: float):
    """Pinion torque from the transmitted power, T1 = 30 000 P / (π n1).

    Parameters
    ----------
    power : float or array_like — [kW]
    n1 : float — [rpm]
        Pinion speed (> 0).

    Returns
    -------
    float or numpy.ndarray — [N·m]

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 9M.
    """
    return 30000.0 * np.asarray(power, float) / (math.pi * n1)


def power_from_torque(torque, n1: float):
    """Transmitted power of a pinion torque, P = π n1 T1 / 30 000 (Eq. 9M solved for P).

    Parameters
    ----------
    torque : float or array_like — [N·m]
    n1 : float — [rpm]

    Returns
    -------
    float or numpy.ndarray — [kW]

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 9M.
    """
    return math.pi * n1 * np.asarray(torque, float) / 30000.0


def contact_stress(torque, *, b: float, de1: float, I: float, C_p: float,  # noqa: E741
                   K_o: float, K_v: float, K_m: float, C_s: float, C_xc: float):
    """Calculated contact stress number s_c (pitting resistance).

    Parameters
    ----------
    torque : float or array_like — [N·m]
        Pinion operating torque T1 (≥ 0).
    b : float — [mm]
        Net face width.
    de1 : float — [mm]
        Pinion outer pitch diameter.
    I : float — [1]
        Pitting resistance geometry factor.
    C_p : float — [MPa^0.5]
        Elastic coefficient.
    K_o, K_v, K_m, C_s, C_xc : float — [1]
        Overload, dynamic, load distribution, size and crowning factors.

    Returns
    -------
    float or numpy.ndarray — [MPa]
        s_c = C_p √(2000 T1 K_o K_v K_m C_s C_xc / (b d_e1² I)), the shape of ``torque``.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 1M (clause 5.1).
    """
    t = np.asarray(torque, float)
    return C_p * np.sqrt(2000.0 * t * K_o * K_v * K_m * C_s * C_xc / (b * de1 * de1 * I))


def permissible_contact_stress(s_ac, *, C_L, C_H, S_H: float, K_T: float, C_R: float):
    """Permissible contact stress number s_wc.

    Parameters
    ----------
    s_ac : float or array_like — [MPa]
        Allowable contact stress number (per member).
    C_L, C_H : float or array_like — [1]
        Stress cycle and hardness ratio factors (per member).
    S_H, K_T, C_R : float — [1]
        Safety factor for pitting, temperature and reliability factors.

    Returns
    -------
    float or numpy.ndarray — [MPa]
        s_wc = s_ac C_L C_H / (S_H K_T C_R).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 2M (clause 5.1.2).
    """
    return np.asarray(s_ac, float) * C_L * C_H / (S_H * K_T * C_R)


def pitting_power(n1: float, s_wc, *, b: float, de1: float, I: float,  # noqa: E741
                  C_p: float, K_o: float, K_v: float, K_m: float, C_s: float, C_xc: float):
    """Allowable transmitted power for pitting resistance P_ac.

    Parameters
    ----------
    n1 : float — [rpm]
        Pinion speed.
    s_wc : float or array_like — [MPa]
        Permissible contact stress number of the member rated.
    b, de1, I, C_p, K_o, K_v, K_m, C_s, C_xc
        As :func:`contact_stress`.

    Returns
    -------
    float or numpy.ndarray — [kW]
        P_ac = π n1 b I / (6e7 K_v K_m K_o C_s C_xc) (d_e1 s_wc / C_p)², the power at which
        s_c = s_wc.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 4M (clause 5.1.3) with s_wc of Eq. 2M. Both members' ratings
    take the pinion's speed and outer pitch diameter (n1 d_e1 = n2 d_e2): Annex E's
    P_ac of the gear is the gear's s_wc in this equation.
    """
    w = np.asarray(s_wc, float)
    return (math.pi * n1 * b * I / (6.0e7 * K_v * K_m * K_o * C_s * C_xc)
            * (de1 * w / C_p) ** 2)


def bending_stress(torque, *, b: float, de, m_et: float, J, K_o: float, K_v: float,
                   K_s: float, K_m: float, K_x: float):
    """Calculated bending stress number s_t at the tooth root.

    Parameters
    ----------
    torque : float or array_like — [N·m]
        The member's operating torque (pinion T1, gear T2 = T1 z2/z1).
    b : float — [mm]
        Net face width.
    de : float or array_like — [mm]
        The member's outer pitch diameter.
    m_et : float — [mm]
        Outer transverse module.
    J : float or array_like — [1]
        The member's bending strength geometry factor.
    K_o, K_v, K_s, K_m, K_x : float — [1]
        Overload, dynamic, size, load distribution and lengthwise curvature factors.

    Returns
    -------
    float or numpy.ndarray — [MPa]
        s_t = 2000 T K_o K_v K_s K_m / (b d_e m_et K_x J) (broadcast over the arrays).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 5M (clause 5.2).
    """
    t = np.asarray(torque, float)
    return 2000.0 * t * K_o * K_v * K_s * K_m / (b * np.asarray(de, float) * m_et * K_x
                                                   * np.asarray(J, float))


def permissible_bending_stress(s_at, *, K_L, S_F: float, K_T: float, K_R: float):
    """Permissible bending stress number s_wt.

    Parameters
    ----------
    s_at : float or array_like — [MPa]
        Allowable bending stress number (per member).
    K_L : float or array_like — [1]
        Stress cycle factor (per member).
    S_F, K_T, K_R : float — [1]
        Safety factor for bending, temperature and reliability factors.

    Returns
    -------
    float or numpy.ndarray — [MPa]
        s_wt = s_at K_L / (S_F K_T K_R).

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 6M (clause 5.2.2).
    """
    return np.asarray(s_at, float) * K_L / (S_F * K_T * K_R)


def bending_power(n1: float, s_wt, *, b: float, de1: float, m_et: float, J, K_o: float,
                  K_v: float, K_s: float, K_m: float, K_x: float):
    """Allowable transmitted power for bending strength P_at.

    Parameters
    ----------
    n1 : float — [rpm]
        Pinion speed.
    s_wt : float or array_like — [MPa]
        Permissible bending stress number of the member rated.
    b, de1, m_et : float — [mm]
        Net face width, pinion outer pitch diameter, outer transverse module.
    J : float or array_like — [1]
        The member's bending strength geometry factor.
    K_o, K_v, K_s, K_m, K_x : float — [1]
        As :func:`bending_stress`.

    Returns
    -------
    float or numpy.ndarray — [kW]
        P_at = π n1 b / 6e7 · J K_x / (K_s K_m K_o K_v) · s_wt d_e1 m_et, the power at which
        s_t = s_wt.

    Notes
    -----
    ANSI/AGMA 2003-D19 Eq. 8M (clause 5.2.3) with s_wt of Eq. 6M; the pinion's n1 and d_e1
    for both members, as for :func:`pitting_power`.
    """
    return (math.pi * n1 * b / 6.0e7 * np.asarray(J, float) * K_x / (K_s * K_m * K_o * K_v)
            * np.asarray(s_wt, float) * de1 * m_et)
