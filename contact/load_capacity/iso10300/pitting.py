"""Surface durability (pitting) of bevel and hypoid gears, ISO 10300-2:2014 Method B1.

One function per factor, over plain numbers or NumPy arrays:

=============================  ===============================================  =========
factor                         function                                         units
=============================  ===============================================  =========
mid-zone factor Z_M-B          :func:`mid_zone_factor`                          1
load sharing factor Z_LS       :func:`load_sharing_factor`                      1
elasticity factor Z_E          :func:`elasticity_factor`                        √MPa
lubricant factor Z_L           :func:`lubricant_factor`                         1
speed factor Z_v               :func:`speed_factor`                             1
roughness factor Z_R           :func:`roughness_factor`                         1
hypoid factor Z_Hyp            :func:`hypoid_factor`                            1
bevel gear factor Z_K          :data:`BEVEL_GEAR_FACTOR`                        1
work hardening factor Z_W      :func:`work_hardening_factor`                    1
size factor Z_X                :data:`SIZE_FACTOR`                              1
life factor Z_NT               :func:`life_factor`                              1
σ_H0, σ_H, σ_HP, S_H           :func:`nominal_contact_stress`,                  MPa, 1
                               :func:`contact_stress`,
                               :func:`permissible_contact_stress`
=============================  ===============================================  =========

Clauses: ISO 10300-2:2014, clause 6 (Method B1: σ_H0, Z_M-B, Z_LS, Z_Hyp, Z_K) and clause
8 (factors common to Methods B1 and B2: Z_E, Z_L, Z_v, Z_R, Z_W, Z_X, Z_NT); the clause
numbers were not checked against the printed text, the equations against ISO/TR
10300-30:2024's three samples (tests/test_rating_iso10300.py).

σ_HP here is σ_H,lim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp, the permissible stress as the TR
prints it (not divided by S_H,min); the safety factor S_H = σ_HP/σ_H is compared with
S_H,min. Below the knee of the S–N curve Z_L Z_v Z_R enter as (Z_L Z_v Z_R)^s with s of
:func:`long_life_share`: 1 in the static range (ISO 6336-2's static stress), their long-life
values at the knee.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "BEVEL_GEAR_FACTOR",
    "SIZE_FACTOR",
    "contact_stress",
    "elasticity_factor",
    "hypoid_factor",
    "life_factor",
    "load_sharing_factor",
    "long_life_share",
    "lubricant_factor",
    "mid_zone_factor",
    "nominal_contact_stress",
    "permissible_contact_stress",
    "roughness_factor",
    "speed_factor",
    "work_hardening_factor",
]

#: bevel gear factor of Method B1's permissible stress Z_K [1]: ISO 10300-2:2014 cl. 6;
#: ISO/TR 10300-30:2024 sample 1 shows it (σ_HP = 1500 × 0.992 × 0.974 × 0.930 × 1.2 =
#: 1617.8 N/mm²)
BEVEL_GEAR_FACTOR = 1.2
#: size factor for contact Z_X [1]: ISO 10300-2:2014 cl. 8 (1 for the sizes of bevel gears)
SIZE_FACTOR = 1.0


def mid_zone_factor(alpha_vet: float, d_va: ArrayLike, d_vb: ArrayLike, z_v: ArrayLike,
                    eps_va: float, eps_vb: float) -> float:
    """Mid-zone factor Z_M-B: the Hertz stress at the mean point to that at the decisive
    point of contact.

    Parameters
    ----------
    alpha_vet : float — [rad]
    d_va, d_vb : array_like (2,) — [mm]
        Tip and base diameters of the virtual gears, pinion then gear.
    z_v : array_like (2,) — [1]
    eps_va, eps_vb : float — [1]

    Returns
    -------
    float
        Z_M-B = tan α_vet / √{[√((d_va1/d_vb1)² − 1) − F1 π/z_v1]
        [√((d_va2/d_vb2)² − 1) − F2 π/z_v2]}, with F1 = F2 = ε_vα for ε_vβ ≥ 1,
        F1 = 2 + (ε_vα − 2) ε_vβ, F2 = 2 ε_vα − 2 + (2 − ε_vα) ε_vβ for ε_vβ < 1.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1); TR samples: 0.916, 0.963, 0.937.
    """
    if eps_vb >= 1.0:
        F1 = F2 = eps_va
    else:
        F1 = 2.0 + (eps_va - 2.0) * eps_vb
        F2 = 2.0 * eps_va - 2.0 + (2.0 - eps_va) * eps_vb
    d_va, d_vb, z_v = (np.asarray(x, float) for x in (d_va, d_vb, z_v))
    t = np.sqrt((d_va / d_vb) ** 2 - 1.0) - np.array([F1, F2]) * np.pi / z_v
    return float(np.tan(alpha_vet) / np.sqrt(t[0] * t[1]))


def load_sharing_factor(f: ArrayLike, l_b: ArrayLike, f_max: float,
                        exponent: float = 3.0) -> tuple[float, np.ndarray]:
    """Load sharing factor Z_LS: the middle contact line's share of the load.

    Parameters
    ----------
    f : array_like (3,) — [mm]
        Signed distances of the tip, middle and root contact lines.
    l_b : array_like (3,) — [mm]
        Their lengths (:func:`contact.load_capacity.iso10300.virtual_gears.contact_line_length`).
    f_max : float — [mm]
    exponent : float — [1]
        e_LS of the peak-load distribution (3: moderate profile crowning, the TR's).

    Returns
    -------
    Z_LS : float
        √(A_m* / (A_t* + A_m* + A_r*)), the areas A* = (π/4) p* l_b of the elliptical
        load distributions along the lines, their related peaks
        p* = 1 − |f/f_max|^e_LS (0 beyond f_max).
    p_star : ndarray (3,)
        The related peak loads of the tip, middle and root line.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1); TR samples: 0.935, 0.703, 0.961.
    """
    f, l_b = np.asarray(f, float), np.asarray(l_b, float)
    p = np.clip(1.0 - np.abs(f / f_max) ** exponent, 0.0, None)
    area = 0.25 * np.pi * p * l_b
    return float(np.sqrt(area[1] / area.sum())), p


def elasticity_factor(youngs_modulus: ArrayLike, poisson_ratio: ArrayLike) -> float:
    """Elasticity factor Z_E = √(1 / (π Σ (1 − ν²)/E)) — [√MPa].

    Parameters
    ----------
    youngs_modulus : array_like (2,) — [MPa]
    poisson_ratio : array_like (2,) — [1]

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 (as ISO 6336-2); steel/steel E = 210000 MPa, ν = 0.3
    gives the TR's 191.646.
    """
    E, nu = np.asarray(youngs_modulus, float), np.asarray(poisson_ratio, float)
    return float(np.sqrt(1.0 / (np.pi * np.sum((1.0 - nu**2) / E))))


def _c_zl(sigma_Hlim: ArrayLike) -> np.ndarray:
    s = np.clip(np.asarray(sigma_Hlim, float), 850.0, 1200.0)
    return 0.83 + 0.08 * (s - 850.0) / 350.0


def lubricant_factor(sigma_Hlim: ArrayLike, nu40: float) -> np.ndarray:
    """Lubricant factor Z_L = C_ZL + 4 (1 − C_ZL) / (1.2 + 134/ν40)² — [1].

    Parameters
    ----------
    sigma_Hlim : array_like — [MPa]
        C_ZL = 0.83 + 0.08 (σ_H,lim − 850)/350, σ_H,lim taken within [850, 1200].
    nu40 : float — [mm²/s]
        Oil viscosity at 40 °C.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 (as ISO 6336-2).
    """
    c = _c_zl(sigma_Hlim)
    return c + 4.0 * (1.0 - c) / (1.2 + 134.0 / nu40) ** 2


def speed_factor(sigma_Hlim: ArrayLike, v: float) -> np.ndarray:
    """Speed factor Z_v = C_Zv + 2 (1 − C_Zv) / √(0.8 + 32/v) — [1].

    Parameters
    ----------
    sigma_Hlim : array_like — [MPa]
        C_Zv = C_ZL + 0.02.
    v : float — [m/s]
        Tangential speed at the mean point; the gear's v_mt2 (ISO/TR 10300-30:2024's
        choice for hypoids: Z_v 0.970 and 0.998 of samples 2 and 3; v_mt1 gives 0.974,
        1.005).

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 (as ISO 6336-2).
    """
    c = _c_zl(sigma_Hlim) + 0.02
    return c + 2.0 * (1.0 - c) / np.sqrt(0.8 + 32.0 / v)


def roughness_factor(sigma_Hlim: ArrayLike, Rz: ArrayLike, rho_rel: float) -> np.ndarray:
    """Roughness factor Z_R = (3 / Rz10)^C_ZR — [1].

    Parameters
    ----------
    sigma_Hlim : array_like — [MPa]
        C_ZR = 0.12 + (1000 − σ_H,lim)/5000, σ_H,lim within [850, 1200].
    Rz : array_like (2,) — [µm]
        Flank roughness of pinion and gear; their mean Rz = (Rz1 + Rz2)/2.
    rho_rel : float — [mm]
        Relative radius of curvature: Rz10 = Rz (10/ρ_rel)^(1/3).

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 (as ISO 6336-2).
    """
    s = np.clip(np.asarray(sigma_Hlim, float), 850.0, 1200.0)
    c = 0.12 + (1000.0 - s) / 5000.0
    rz10 = float(np.mean(np.asarray(Rz, float))) * (10.0 / rho_rel) ** (1.0 / 3.0)
    return (3.0 / rz10) ** c


def hypoid_factor(a: float, v_mt1: float, beta_m1: float, beta_m2: float, beta_B: float,
                  alpha_n: float) -> tuple[float, dict[str, float]]:
    """Hypoid factor Z_Hyp: the lengthwise sliding of a hypoid pair lowers the permissible
    contact stress.

    Parameters
    ----------
    a : float — [mm]
        Hypoid offset (0: Z_Hyp = 1).
    v_mt1 : float — [m/s]
    beta_m1, beta_m2, beta_B, alpha_n : float — [rad]

    Returns
    -------
    Z_Hyp : float
        1 − 0.3 (v_g,par / v_Σ,vert − 0.15), within [0.6, 1].
    velocities : dict — [m/s]
        ``v_g`` = v_mt1 cos β_m1 (tan β_m1 − tan β_m2), the sliding velocity (along the
        tooth); ``v_g_par`` = |v_g| cos β_B, its part along the contact line;
        ``v_sum_vert`` = v_Σ sin(ω_Σ + β_B), the sum velocity normal to the contact line,
        from v_Σh = 2 v_mt1 cos β_m1 sin α_n (profile) and
        v_Σl = v_mt1 (sin β_m1 + sin β_m2 cos β_m1 / cos β_m2) (lengthwise),
        v_Σ = √(v_Σh² + v_Σl²), ω_Σ = arctan(v_Σh/v_Σl).

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1); TR samples 2 and 3: 0.952, 0.829.
    """
    if a == 0.0:
        return 1.0, {"v_g": 0.0, "v_g_par": 0.0, "v_sum_vert": float("nan")}
    c1 = np.cos(beta_m1)
    v_g = v_mt1 * c1 * (np.tan(beta_m1) - np.tan(beta_m2))
    v_par = abs(v_g) * np.cos(beta_B)
    v_h = 2.0 * v_mt1 * c1 * np.sin(alpha_n)
    v_l = v_mt1 * (np.sin(beta_m1) + np.sin(beta_m2) * c1 / np.cos(beta_m2))
    v_vert = np.hypot(v_h, v_l) * np.sin(np.arctan2(v_h, v_l) + abs(beta_B))
    z = float(np.clip(1.0 - 0.3 * (v_par / v_vert - 0.15), 0.6, 1.0))
    return z, {"v_g": float(v_g), "v_g_par": float(v_par), "v_sum_vert": float(v_vert)}


def work_hardening_factor(n_members: int = 2) -> np.ndarray:
    """Work hardening factor Z_W — [1].

    Parameters
    ----------
    n_members : int
        Length of the result.

    Returns
    -------
    ndarray
        1 for both members: a case-hardened pair (the toolkit's material table) gains
        nothing from work hardening; a through-hardened gear mating a case-hardened pinion
        (ISO's Z_W > 1) is not covered.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8.
    """
    return np.ones(n_members)


def life_factor(cycles: ArrayLike, knee_cycles: ArrayLike, static_cycles: ArrayLike,
                static_factor: ArrayLike) -> np.ndarray:
    """Life factor (Z_NT, and Y_NT with the bending curve) — [1].

    Parameters
    ----------
    cycles : array_like — [1]
        Load cycles N_L; NaN: long life (1).
    knee_cycles, static_cycles : array_like — [1]
        Ends of the sloped part of the S–N curve.
    static_factor : array_like — [1]
        The factor at ``static_cycles`` and below.

    Returns
    -------
    ndarray — [1]
        1 from the knee on, the static factor up to ``static_cycles``, a straight line in
        log–log axes between.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 and ISO 10300-3:2014 cl. 8 (the curves of ISO
    6336-2/-3; the material table's ``sn_contact`` and ``sn_bending`` groups). Beyond the
    knee ISO allows a fall to 0.85 at 10¹⁰ cycles where the conditions are not optimal;
    the reference value 1 is taken.
    """
    n, knee, static, z0 = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (cycles, knee_cycles, static_cycles, static_factor)))
    t = np.clip(np.log(knee / np.where(np.isnan(n), knee, n)) / np.log(knee / static),
                0.0, 1.0)
    return z0 ** t


def long_life_share(cycles: ArrayLike, knee_cycles: ArrayLike,
                    static_cycles: ArrayLike) -> np.ndarray:
    """How much of the long-life influence factors a number of load cycles takes — [1].

    Parameters
    ----------
    cycles : array_like — [1]
        Load cycles N_L; NaN: long life.
    knee_cycles, static_cycles : array_like — [1]
        Ends of the sloped part of the S–N curve.

    Returns
    -------
    ndarray — [1]
        1 from the knee on (and for NaN), 0 at the static end and below, log-linear in
        N_L between: s = log(N_L/N_static)/log(N_knee/N_static). The permissible stress
        takes Z_L Z_v Z_R (and Y_R,relT Y_X for bending) as (product)^s: their long-life
        values at the knee, 1 in the static range.

    Notes
    -----
    Source: ISO 6336-2:2019 cl. 5 and Table 4 (and ISO 6336-3:2019 for bending: Y_R,relT
    and Y_X of the static stress are 1), which ISO 10300-2/-3:2014 cl. 8 follow for the
    life factor: the influence factors of the lubricant film, speed and roughness are 1.0
    for the static stress, their calculated values for the reference (long-life) stress,
    and the permissible stress of limited life is interpolated log-linearly between the
    two. The notch sensitivity Y_δ,relT keeps its long-life value here (its static value
    of ISO 6336-3 is not modelled).
    """
    n, knee, static = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (cycles, knee_cycles, static_cycles)))
    n = np.where(np.isnan(n), knee, n)
    return np.clip(np.log(n / static) / np.log(knee / static), 0.0, 1.0)


def permissible_cycles(required_factor: ArrayLike, knee_cycles: ArrayLike,
                       static_cycles: ArrayLike, static_factor: ArrayLike) -> np.ndarray:
    """Load cycles at which the life factor reaches ``required_factor`` — [1]: the inverse
    of :func:`life_factor` on its sloped part.

    Parameters
    ----------
    required_factor : array_like — [1]
        The life factor Z_NT (or Y_NT) a load needs, e.g. S_min / S at long life.
    knee_cycles, static_cycles, static_factor : array_like
        The S–N curve as in :func:`life_factor`.

    Returns
    -------
    ndarray — [1]
        ``inf`` where ``required_factor`` ≤ 1 (long life), 0 where it exceeds the static
        factor (not even the static strength holds), else N_L with
        life_factor(N_L) = required_factor; NaN where ``required_factor`` is NaN.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 8 and ISO 10300-3:2014 cl. 8 (the S–N curves of ISO
    6336-2/-3 as :func:`life_factor` takes them), solved for N_L:
    N_L = N_knee (N_knee / N_static)^(−ln Z / ln Z_static).
    """
    r, knee, static, z0 = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (required_factor, knee_cycles, static_cycles,
                                          static_factor)))
    with np.errstate(divide="ignore", invalid="ignore"):
        n = knee * (knee / static) ** (-np.log(r) / np.log(z0))
    return np.where(np.isnan(r), np.nan,
                    np.where(r <= 1.0, np.inf, np.where(r > z0, 0.0, n)))


def nominal_contact_stress(F_n: ArrayLike, l_bm: float, rho_rel: float, Z_MB: float,
                           Z_LS: float, Z_E: float) -> np.ndarray:
    """Nominal contact stress σ_H0 = √(F_n / (l_bm ρ_rel)) Z_M-B Z_LS Z_E — [MPa].

    Parameters
    ----------
    F_n : array_like — [N]
    l_bm, rho_rel : float — [mm]
    Z_MB, Z_LS : float — [1]
    Z_E : float — [√MPa]

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1).
    """
    return np.sqrt(np.asarray(F_n, float) / (l_bm * rho_rel)) * Z_MB * Z_LS * Z_E


def contact_stress(sigma_H0: ArrayLike, K_A: float, K_v: ArrayLike, K_Hbeta: float,
                   K_Halpha: ArrayLike) -> np.ndarray:
    """Contact stress σ_H = σ_H0 √(K_A K_v K_Hβ K_Hα) — [MPa] (ISO 10300-2:2014 cl. 6)."""
    return np.asarray(sigma_H0, float) * np.sqrt(
        K_A * np.asarray(K_v, float) * K_Hbeta * np.asarray(K_Halpha, float))


def permissible_contact_stress(sigma_Hlim: ArrayLike, Z_NT: ArrayLike, Z_X: ArrayLike,
                               Z_L: ArrayLike, Z_v: ArrayLike, Z_R: ArrayLike,
                               Z_W: ArrayLike, Z_Hyp: float,
                               Z_K: float = BEVEL_GEAR_FACTOR) -> np.ndarray:
    """Permissible contact stress σ_HP = σ_H,lim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp — [MPa].

    Parameters
    ----------
    sigma_Hlim : array_like — [MPa]
    Z_NT, Z_X, Z_L, Z_v, Z_R, Z_W : array_like — [1]
    Z_Hyp, Z_K : float — [1]

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1), without S_H,min (as the TR prints it).
    """
    return (np.asarray(sigma_Hlim, float) * Z_NT * Z_X * Z_L * Z_v * Z_R * Z_W * Z_K
            * Z_Hyp)
