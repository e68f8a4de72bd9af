"""Forces and the general load factors of ISO 10300-1:2014 (Method B), one function each.

* :func:`nominal_forces` — tangential forces at the mean point, the virtual gears'
  tangential force and the normal force (cl. 6);
* :func:`mean_point_speeds` — tangential speeds at the mean point (cl. 6);
* :func:`running_in_allowance`, :func:`stiffness_correction` — y_α and C_F;
* :func:`dynamic_factor` — K_v, Method B (cl. 7), with :func:`resonance_ratio` and
  :func:`dynamic_coefficients`;
* :func:`single_pitch_tolerance` — f_pt of an ISO 17485 accuracy grade;
* :func:`mounting_factor`, :func:`face_load_factors`, :func:`lengthwise_curvature_factor`
  — K_Hβ-be, K_Hβ, K_Fβ, K_F0 (cl. 8);
* :func:`transverse_load_factors` — K_Hα, K_Fα, Method B (cl. 9).

The application factor K_A is given (:class:`contact.load_capacity.iso10300.inputs.RatingInputs`).
Every function takes plain numbers or NumPy arrays that broadcast (torque arrays give
arrays). Units: forces [N], torques [N·m], lengths [mm], speeds [rpm] and [m/s], angles
[rad], pitch deviations [µm], mesh stiffness [N/(mm·µm)], density [kg/mm³].

Clause numbers are those of ISO 10300-1:2014 (6 forces, 7 K_v, 8 K_Hβ/K_Fβ, 9 K_Hα/K_Fα);
every equation was checked against ISO/TR 10300-30:2024's three samples
(tests/test_rating_iso10300.py), except where a docstring says what the samples do not
reach (K_v outside the subcritical range, K_Hα for ε_vγ ≤ 2 and for 0 < a_rel < 0.1).
"""

from __future__ import annotations

import logging

import numpy as np
from numpy.typing import ArrayLike

from contact.load_capacity.iso10300.inputs import CONTACT_PATTERNS, MOUNTINGS
from geometry.core.validation import one_of

__all__ = [
    "MOUNTING_FACTORS",
    "dynamic_coefficients",
    "dynamic_factor",
    "face_load_factors",
    "lengthwise_curvature_factor",
    "mean_point_speeds",
    "mounting_factor",
    "nominal_forces",
    "resonance_ratio",
    "running_in_allowance",
    "single_pitch_tolerance",
    "stiffness_correction",
    "transverse_load_factors",
]

log = logging.getLogger(__name__)

#: K_Hβ-be (ISO 10300-1:2014 cl. 8, table of the mounting factor): contact pattern
#: verification → factor for (both, one, neither) member straddle-mounted
MOUNTING_FACTORS: dict[str, tuple[float, float, float]] = {
    "full_load": (1.00, 1.00, 1.00),
    "light_load": (1.05, 1.10, 1.25),
    "estimated": (1.20, 1.32, 1.50),
}

#: single stiffness c′ and mesh stiffness c_γ per unit face width at and above
#: 100 N/mm [N/(mm µm)] (ISO 10300-1:2014 cl. 7, as ISO 6336-1)
SINGLE_STIFFNESS = 14.0
MESH_STIFFNESS = 20.0


def nominal_forces(torque: ArrayLike, d_m1: float, beta_m1: float, beta_m2: float,
                   beta_v: float, alpha_n: float) -> dict[str, np.ndarray]:
    """Nominal forces at the mean point.

    Parameters
    ----------
    torque : array_like — [N·m]
        Pinion torque T1, any shape.
    d_m1 : float — [mm]
    beta_m1, beta_m2, beta_v : float — [rad]
        Mean spiral angles and the virtual helix angle.
    alpha_n : float — [rad]
        Generated normal pressure angle of the rated flank.

    Returns
    -------
    dict of ndarray, the shape of ``torque`` — [N]
        ``F_mt1`` = 2000 T1 / d_m1; ``F_mt2`` = F_mt1 cos β_m2 / cos β_m1 (the same normal
        force on the gear); ``F_vmt`` = F_mt1 cos β_v / cos β_m1 (virtual gears);
        ``F_n`` = F_mt1 / (cos α_n cos β_m1).

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 6; ISO 10300-2:2014 Method B1 (F_n).
    """
    f1 = 2000.0 * np.asarray(torque, float) / d_m1
    return {"F_mt1": f1, "F_mt2": f1 * np.cos(beta_m2) / np.cos(beta_m1),
            "F_vmt": f1 * np.cos(beta_v) / np.cos(beta_m1),
            "F_n": f1 / (np.cos(alpha_n) * np.cos(beta_m1))}


def mean_point_speeds(speed: ArrayLike, d_m1: float, d_m2: float, z1: int, z2: int
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Tangential speeds at the mean point v_mt1,2 = π d_m n / 60000 — [m/s].

    Parameters
    ----------
    speed : array_like — [rpm]
        Pinion speed n1 (the gear's n2 = n1 z1/z2).
    d_m1, d_m2 : float — [mm]
    z1, z2 : int

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 6.
    """
    n1 = np.asarray(speed, float)
    return np.pi * d_m1 * n1 / 60000.0, np.pi * d_m2 * n1 * z1 / z2 / 60000.0


def running_in_allowance(f_pt: ArrayLike) -> np.ndarray:
    """Running-in allowance y_α = y_p = 0.075 f_pt, at most 3 µm — [µm].

    Parameters
    ----------
    f_pt : array_like — [µm]
        Single pitch deviation.

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 7 and 9 (as ISO 6336-1), for case-hardened and
    nitrided steels — the material of the toolkit's table.
    """
    return np.minimum(0.075 * np.asarray(f_pt, float), 3.0)


def stiffness_correction(F_vmt: ArrayLike, K_A: float, b_v: float) -> np.ndarray:
    """Correction of the mesh stiffness for a light load C_F = min(F_vmt K_A / b_v / 100, 1).

    Parameters
    ----------
    F_vmt : array_like — [N]
    K_A : float — [1]
    b_v : float — [mm]

    Returns
    -------
    ndarray — [1]
        1 at and above 100 N/mm of face width.

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 7 (as ISO 6336-1).
    """
    return np.minimum(np.asarray(F_vmt, float) * K_A / b_v / 100.0, 1.0)


def resonance_ratio(speed: ArrayLike, z1: int, d_m1: float, d_m2: float, alpha_n: float,
                    density: float, c_gamma: ArrayLike) -> np.ndarray:
    """Resonance ratio N = n1 / n_E1 of the pinion speed to the mesh's resonance speed.

    Parameters
    ----------
    speed : array_like — [rpm]
        Pinion speed n1.
    z1 : int
    d_m1, d_m2 : float — [mm]
    alpha_n : float — [rad]
        Generated normal pressure angle of the rated flank.
    density : float — [kg/mm³]
        Density of the gear material.
    c_gamma : array_like — [N/(mm·µm)]
        Mesh stiffness.

    Returns
    -------
    ndarray — [1]
        N = n1 / n_E1, n_E1 = 30000/(π z1) √(c_γ / m_red), with the reduced mass per unit
        face width m_red = m*₁ m*₂/(m*₁ + m*₂), m*_i = (π/8) ρ d_mi² / cos² α_n (solid
        blanks) [kg/mm].

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 7 (Method B); ISO/TR 10300-30:2024 sample 3 (N = 0.084)
    fixes α_n as the rated flank's generated pressure angle.
    """
    m1 = np.pi / 8.0 * density * d_m1**2 / np.cos(alpha_n) ** 2
    m2 = np.pi / 8.0 * density * d_m2**2 / np.cos(alpha_n) ** 2
    m_red = m1 * m2 / (m1 + m2)
    n_E1 = 30000.0 / (np.pi * z1) * np.sqrt(np.asarray(c_gamma, float) / m_red)
    return np.asarray(speed, float) / n_E1


def dynamic_coefficients(eps_vg: float) -> dict[str, float]:
    """The coefficients c_v1 … c_v7 of Method B's dynamic factor.

    Parameters
    ----------
    eps_vg : float — [1]
        Virtual contact ratio ε_vγ.

    Returns
    -------
    dict
        ``c_v1`` … ``c_v7``: for ε_vγ ≤ 2: 0.32, 0.34, 0.23, 0.90, 0.47, 0.47; above:
        0.32, 0.57/(ε_vγ − 0.3), 0.096/(ε_vγ − 1.56), (0.57 − 0.05 ε_vγ)/(ε_vγ − 1.44),
        0.47, 0.12/(ε_vγ − 1.74); c_v7 = 0.75 (ε_vγ ≤ 1.5), 0.125 sin[π(ε_vγ − 2)] + 0.875
        (≤ 2.5), 1.0 above.

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 7 (table of c_v1 … c_v7, as ISO 6336-1).
    """
    e = float(eps_vg)
    if e <= 2.0:
        c = {"c_v1": 0.32, "c_v2": 0.34, "c_v3": 0.23, "c_v4": 0.90, "c_v5": 0.47,
             "c_v6": 0.47}
    else:
        c = {"c_v1": 0.32, "c_v2": 0.57 / (e - 0.3), "c_v3": 0.096 / (e - 1.56),
             "c_v4": (0.57 - 0.05 * e) / (e - 1.44), "c_v5": 0.47, "c_v6": 0.12 / (e - 1.74)}
    c["c_v7"] = (0.75 if e <= 1.5 else
                 0.125 * float(np.sin(np.pi * (e - 2.0))) + 0.875 if e <= 2.5 else 1.0)
    return c


def dynamic_factor(N: ArrayLike, F_vmt: ArrayLike, K_A: float, b_v: float, f_pt: float,
                   eps_vg: float) -> tuple[np.ndarray, np.ndarray]:
    """Dynamic factor K_v, Method B.

    Parameters
    ----------
    N : array_like — [1]
        Resonance ratio (:func:`resonance_ratio`).
    F_vmt : array_like — [N]
        Tangential force of the virtual gears (broadcasts with N).
    K_A : float — [1]
    b_v : float — [mm]
        Face width of the virtual gears.
    f_pt : float — [µm]
        Single pitch deviation (the larger of pinion and gear).
    eps_vg : float — [1]

    Returns
    -------
    K_v : ndarray — [1]
        Subcritical (N ≤ 0.75): K_v = N K + 1, K = B_p (c_v1 + c_v2) + c_v3; main resonance
        (0.75 < N ≤ 1.25): B_p (c_v1 + c_v2) + c_v4 + 1; supercritical (N ≥ 1.5):
        B_p (c_v5 + c_v6) + c_v7; linear between 1.25 and 1.5.
        B_p = b_v f_p,eff c′ / (F_vmt K_A), f_p,eff = f_pt − y_p, c′ = 14 C_F.
    K : ndarray — [1]
        The subcritical constant K.

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 7 (Method B). ISO/TR 10300-30:2024 checks the subcritical
    range (K = 0.589 of sample 3 fixes b_v, not b_v,eff, in B_p); a load in the main
    resonance range is logged as a warning naming its own N (ISO: to be avoided).
    """
    N, F_vmt = np.broadcast_arrays(np.asarray(N, float), np.asarray(F_vmt, float))
    c = dynamic_coefficients(eps_vg)
    C_F = stiffness_correction(F_vmt, K_A, b_v)
    f_eff = max(float(f_pt - running_in_allowance(f_pt)), 0.0)
    B_p = b_v * f_eff * SINGLE_STIFFNESS * C_F / (F_vmt * K_A)
    K = B_p * (c["c_v1"] + c["c_v2"]) + c["c_v3"]
    main = B_p * (c["c_v1"] + c["c_v2"]) + c["c_v4"] + 1.0
    sup = B_p * (c["c_v5"] + c["c_v6"]) + c["c_v7"]
    inter = sup + (main - sup) * (1.5 - N) / 0.25
    main_range = (N > 0.75) & (N <= 1.25)
    if np.any(main_range):  # the N of each load in the range, not the largest of all
        log.warning("dynamic factor: resonance ratio N = %s in the main resonance range "
                    "(0.75, 1.25] at %d of %d loads (F_vmt %s N; ISO 10300-1: avoid; a "
                    "Method A analysis is advised)",
                    ", ".join(f"{n:.3g}" for n in N[main_range].ravel()),
                    int(main_range.sum()), N.size,
                    ", ".join(f"{f:.0f}" for f in F_vmt[main_range].ravel()))
    K_v = np.where(N <= 0.75, N * K + 1.0, np.where(N <= 1.25, main,
                                                     np.where(N < 1.5, inter, sup)))
    return K_v, K


def single_pitch_tolerance(d_T: ArrayLike, m_mn: float, grade: ArrayLike) -> np.ndarray:
    """Single pitch tolerance of an ISO 17485 accuracy grade — [µm].

    Parameters
    ----------
    d_T : array_like — [mm]
        Tolerance diameter; taken here as the mean-point tip diameter d_m + 2 h_am cos δ.
    m_mn : float — [mm]
    grade : array_like of int
        Accuracy grade B, 2 … 11.

    Returns
    -------
    ndarray — [µm]
        f_ptT = (0.003 d_T + 0.3 m_mn + 5) √2^(B − 4), unrounded.

    Notes
    -----
    Source: ISO 17485:2006 (bevel gear accuracy; tolerance diameter and rounding rules not
    checked here: ISO/TR 10300-30:2024 gives f_pt directly).
    """
    b = np.asarray(grade, float)
    return (0.003 * np.asarray(d_T, float) + 0.3 * m_mn + 5.0) * np.sqrt(2.0) ** (b - 4.0)


def mounting_factor(mounting: str, contact_pattern: str = "light_load") -> float:
    """Mounting factor K_Hβ-be [1].

    Parameters
    ----------
    mounting : {"both", "one", "neither"}
        Members straddle-mounted.
    contact_pattern : {"full_load", "light_load", "estimated"}
        How the contact pattern was verified.

    Returns
    -------
    float
        :data:`MOUNTING_FACTORS`.

    Raises
    ------
    InputError
        An unknown choice (named).

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 8 (table of the mounting factor K_Hβ-be).
    """
    one_of("mounting", mounting, MOUNTINGS)
    one_of("contact_pattern", contact_pattern, CONTACT_PATTERNS)
    return MOUNTING_FACTORS[contact_pattern][MOUNTINGS.index(mounting)]


def lengthwise_curvature_factor(r_c0: float, R_m2: float, beta_m2: float) -> float:
    """Lengthwise curvature factor for bending K_F0 [1].

    Parameters
    ----------
    r_c0 : float — [mm]
        Cutter radius.
    R_m2 : float — [mm]
        Mean cone distance of the gear.
    beta_m2 : float — [rad]
        Mean spiral angle of the gear.

    Returns
    -------
    float
        K_F0 = 0.211 (r_c0/R_m2)^q + 0.789, q = 0.279 / lg(sin β_m2), within [1, 1.15];
        1 for straight and zerol gears (β_m2 = 0).

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 8; ISO/TR 10300-30:2024 samples 2 and 3 (K_F0 1.060,
    1.011 — the face-hobbed sample 3 with its nominal cutter radius).
    """
    if beta_m2 <= 0.0:
        return 1.0
    q = 0.279 / np.log10(np.sin(beta_m2))
    return float(np.clip(0.211 * (r_c0 / R_m2) ** q + 0.789, 1.0, 1.15))


def face_load_factors(K_Hbeta_be: float, K_F0: float) -> tuple[float, float]:
    """Face load factors K_Hβ = 1.5 K_Hβ-be and K_Fβ = K_Hβ / K_F0 [1].

    Parameters
    ----------
    K_Hbeta_be : float — [1]
        :func:`mounting_factor`.
    K_F0 : float — [1]
        :func:`lengthwise_curvature_factor`.

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 8 (Method C of K_Hβ: a favourable contact pattern
    under load, the usual case).
    """
    K_Hb = 1.5 * K_Hbeta_be
    return K_Hb, K_Hb / K_F0


def transverse_load_factors(F_vmt: ArrayLike, K_A: float, K_v: ArrayLike, K_Hbeta: float,
                            b_v: float, f_pt: float, eps_vg: float, a: float, d_m2: float,
                            limit_H: float = np.inf, limit_F: float = np.inf
                            ) -> dict[str, np.ndarray]:
    """Transverse load factors K_Hα, K_Fα, Method B.

    Parameters
    ----------
    F_vmt : array_like — [N]
    K_A : float — [1]
    K_v : array_like — [1]
    K_Hbeta : float — [1]
    b_v : float — [mm]
    f_pt : float — [µm]
        Single pitch deviation (the larger of pinion and gear).
    eps_vg : float — [1]
    a : float — [mm]
        Hypoid offset.
    d_m2 : float — [mm]
    limit_H, limit_F : float — [1]
        Upper limits of K_Hα and K_Fα: ε_vγ/(ε_vα Z_LS²) and ε_vγ/(ε_vα Y_ε).

    Returns
    -------
    dict of ndarray
        ``F_mtH`` [N] = F_vmt K_A K_v K_Hβ; ``K_Halpha_star`` [1]: for ε_vγ ≤ 2
        (ε_vγ/2)(0.9 + 0.4 X), above 0.9 + 0.4 √(2(ε_vγ − 1)/ε_vγ) X, with
        X = c_γ (f_pt − y_α) / (F_mtH / b_v); ``a_rel`` [1] = 2a/d_m2; ``K_Halpha``,
        ``K_Falpha`` [1]: K* − (K* − 1) min(a_rel, 0.1)/0.1 (1 from a_rel = 0.1 on),
        within [1, limit].

    Notes
    -----
    Source: ISO 10300-1:2014 cl. 9 (Method B). ISO/TR 10300-30:2024 checks K* (sample 1,
    1.161; sample 3, 1.109) and a_rel ≥ 0.1 (samples 2 and 3, K_Hα = 1); the linear
    reduction for 0 < a_rel < 0.1, the ε_vγ ≤ 2 form and the upper limits (as ISO 6336-1)
    are not reached by its samples.
    """
    F_mtH = (np.asarray(F_vmt, float) * K_A * np.asarray(K_v, float) * K_Hbeta)
    C_F = stiffness_correction(F_vmt, K_A, b_v)
    x = MESH_STIFFNESS * C_F * (f_pt - running_in_allowance(f_pt)) / (F_mtH / b_v)
    if eps_vg <= 2.0:
        star = 0.5 * eps_vg * (0.9 + 0.4 * x)
    else:
        star = 0.9 + 0.4 * np.sqrt(2.0 * (eps_vg - 1.0) / eps_vg) * x
    a_rel = 2.0 * a / d_m2
    blended = star - (star - 1.0) * min(a_rel, 0.1) / 0.1
    return {"F_mtH": F_mtH, "K_Halpha_star": star, "a_rel": np.float64(a_rel),
            "K_Halpha": np.clip(blended, 1.0, limit_H), "K_Falpha": np.clip(blended, 1.0,
                                                                              limit_F)}
