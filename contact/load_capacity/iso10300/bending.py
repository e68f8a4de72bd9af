"""Tooth root strength of bevel and hypoid gears, ISO 10300-3:2014 Method B1.

One function per factor, over plain numbers or NumPy arrays (a member axis of length 2,
pinion then gear, where the docstring says so):

===================================  ==========================================  ====
factor                               function                                    unit
===================================  ==========================================  ====
tooth form factor Y_Fa (and s_Fn,    :func:`tooth_form` (generated),              1
ρ_F, h_Fa, α_Fan, E, G, H, θ)        :func:`non_generated_tooth_form` (Formate)
stress correction factor Y_Sa        :func:`stress_correction_factor`            1
contact ratio factor Y_ε             :func:`contact_ratio_factor`                1
bevel spiral angle factor Y_BS       :func:`bevel_spiral_angle_factor`           1
load sharing factor Y_LS = Z_LS²     :func:`load_sharing_factor`                 1
relative surface factor Y_R,relT     :func:`relative_surface_factor`             1
relative notch sensitivity Y_δrelT   :func:`relative_notch_sensitivity`          1
size factor Y_X                      :func:`size_factor`                         1
life factor Y_NT                     :func:`contact.load_capacity.iso10300.pitting.life_factor`  1
σ_F0, σ_F, σ_FP                      :func:`nominal_root_stress`,                MPa
                                     :func:`root_stress`,
                                     :func:`permissible_root_stress`
===================================  ==========================================  ====

Clauses: ISO 10300-3:2014, clause 6 (Method B1: σ_F0, Y_Fa, Y_Sa, Y_ε, Y_BS, Y_LS, Y_δrelT,
Y_R,relT) and clause 8 (Y_X, Y_NT); the clause numbers were not checked against the
printed text, the equations against ISO/TR 10300-30:2024's three samples.

σ_FP here is σ_F,lim Y_ST Y_NT Y_δrelT Y_R,relT Y_X, the permissible stress as the TR prints
it (not divided by S_F,min); S_F = σ_FP/σ_F is compared with S_F,min. Y_δrelT and Y_R,relT
are the reference (long-life) values; their static values below the S–N curve's knee are
not covered.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "STRESS_CORRECTION_TEST_GEAR",
    "ToothForm",
    "bevel_spiral_angle_factor",
    "contact_ratio_factor",
    "load_sharing_factor",
    "member_tooth_forms",
    "nominal_root_stress",
    "non_generated_tooth_form",
    "permissible_root_stress",
    "relative_notch_sensitivity",
    "relative_surface_factor",
    "root_stress",
    "size_factor",
    "stress_correction_factor",
    "tooth_form",
]

#: stress correction factor of the standard test gear Y_ST [1] (ISO 10300-3, ISO 6336-3)
STRESS_CORRECTION_TEST_GEAR = 2.0


def _inv(a: np.ndarray) -> np.ndarray:
    return np.tan(a) - a


@dataclass(frozen=True)
class ToothForm:
    """The 30°-tangent tooth of ISO 10300-3 Method B1 for each member (arrays (2,)).

    Attributes
    ----------
    E : ndarray — [mm]
    G, H : ndarray — [1]
        Auxiliary quantities of the root fillet.
    theta : ndarray — [rad]
        Fillet angle ϑ at the 30° tangent.
    s_Fn : ndarray — [mm]
        Root chord at the 30° tangents.
    rho_F : ndarray — [mm]
        Fillet radius there.
    alpha_an, gamma_a, alpha_Fan : ndarray — [rad]
        Pressure angle at the tip, auxiliary angle, load application angle at the tip.
    h_Fa : ndarray — [mm]
        Bending moment arm of a load at the tip.
    Y_Fa : ndarray — [1]
        Tooth form factor 6 (h_Fa/m_mn) cos α_Fan / ((s_Fn/m_mn)² cos α_n).
    """

    E: np.ndarray
    G: np.ndarray
    H: np.ndarray
    theta: np.ndarray
    s_Fn: np.ndarray
    rho_F: np.ndarray
    alpha_an: np.ndarray
    gamma_a: np.ndarray
    alpha_Fan: np.ndarray
    h_Fa: np.ndarray
    Y_Fa: np.ndarray


def tooth_form(m_mn: float, z_vn: ArrayLike, d_van: ArrayLike, d_vbn: ArrayLike,
               x_hm: ArrayLike, x_sm: ArrayLike, h_a0: ArrayLike, rho_a0: ArrayLike,
               s_pr: ArrayLike, alpha_e: float, alpha_n: float) -> ToothForm:
    """Tooth form of a generated tooth loaded at its tip, and its form factor Y_Fa.

    Parameters
    ----------
    m_mn : float — [mm]
    z_vn, d_van, d_vbn : array_like — [1], [mm]
        The normal-section virtual gear
        (:func:`contact.load_capacity.iso10300.virtual_gears.normal_section`).
    x_hm, x_sm : array_like — [1]
        Profile shift and thickness modification coefficients.
    h_a0, rho_a0, s_pr : array_like — [mm]
        Tool addendum, cutter edge radius, protuberance.
    alpha_e : float — [rad]
        Effective pressure angle of the rated flank (the tool's flank in the tooth form).
    alpha_n : float — [rad]
        Generated pressure angle of the rated flank (in Y_Fa's denominator).

    Returns
    -------
    ToothForm
        E = (π/4 − x_sm) m_mn − h_a0 tan α_e + s_pr/cos α_e − ρ_a0 (1 − sin α_e)/cos α_e;
        G = (ρ_a0 − h_a0)/m_mn + x_hm; H = (2/z_vn)(π/2 − E/m_mn) − π/3; ϑ the solution of
        ϑ = (2G/z_vn) tan ϑ − H (fixed point from π/6);
        s_Fn = m_mn [z_vn sin(π/3 − ϑ) + √3 (G/cos ϑ − ρ_a0/m_mn)];
        ρ_F = ρ_a0 + 2 G² m_mn / (cos ϑ (z_vn cos² ϑ − 2G));
        α_an = arccos(d_vbn/d_van); γ_a = [π/2 + 2(x_hm tan α_e + x_sm)]/z_vn + inv α_e
        − inv α_an; α_Fan = α_an − γ_a;
        h_Fa = (m_mn/2)[(cos γ_a − sin γ_a tan α_Fan) d_van/m_mn − z_vn cos(π/3 − ϑ)
        − G/cos ϑ + ρ_a0/m_mn].

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1, generated gears; the form of ISO 6336-3
    Method B on the normal-section virtual gear). ISO/TR 10300-30:2024 fixes the pressure
    angles: α_e in the form (sample 2's E = 0.213 mm; α_nD gives 0.333) and the generated
    α_nD in Y_Fa's denominator (sample 2's Y_Fa1 = 2.047; α_eD gives 2.074).
    """
    z_vn, d_van, d_vbn, x_hm, x_sm, h_a0, rho_a0, s_pr = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (z_vn, d_van, d_vbn, x_hm, x_sm, h_a0, rho_a0, s_pr)))
    ca, sa, ta = np.cos(alpha_e), np.sin(alpha_e), np.tan(alpha_e)
    E = ((0.25 * np.pi - x_sm) * m_mn - h_a0 * ta + s_pr / ca - rho_a0 * (1.0 - sa) / ca)
    G = (rho_a0 - h_a0) / m_mn + x_hm
    H = 2.0 / z_vn * (0.5 * np.pi - E / m_mn) - np.pi / 3.0
    theta = np.full(z_vn.shape, np.pi / 6.0)
    for _ in range(200):  # a contraction: |2G/z_vn| / cos²ϑ < 1 for real teeth
        new = 2.0 * G / z_vn * np.tan(theta) - H
        if np.all(np.abs(new - theta) < 1e-13):
            theta = new
            break
        theta = new
    s_Fn = m_mn * (z_vn * np.sin(np.pi / 3.0 - theta)
                   + np.sqrt(3.0) * (G / np.cos(theta) - rho_a0 / m_mn))
    rho_F = rho_a0 + 2.0 * G**2 * m_mn / (np.cos(theta) * (z_vn * np.cos(theta) ** 2 - 2.0 * G))
    alpha_an = np.arccos(d_vbn / d_van)
    gamma_a = ((0.5 * np.pi + 2.0 * (x_hm * ta + x_sm)) / z_vn + _inv(np.float64(alpha_e))
               - _inv(alpha_an))
    alpha_Fan = alpha_an - gamma_a
    h_Fa = 0.5 * m_mn * ((np.cos(gamma_a) - np.sin(gamma_a) * np.tan(alpha_Fan)) * d_van / m_mn
                         - z_vn * np.cos(np.pi / 3.0 - theta) - G / np.cos(theta)
                         + rho_a0 / m_mn)
    Y_Fa = 6.0 * (h_Fa / m_mn) * np.cos(alpha_Fan) / ((s_Fn / m_mn) ** 2 * np.cos(alpha_n))
    return ToothForm(E=E, G=G, H=H, theta=theta, s_Fn=s_Fn, rho_F=rho_F, alpha_an=alpha_an,
                     gamma_a=gamma_a, alpha_Fan=alpha_Fan, h_Fa=h_Fa, Y_Fa=Y_Fa)


def non_generated_tooth_form(m_mn: float, h_am: ArrayLike, x_hm: ArrayLike, x_sm: ArrayLike,
                             h_a0: ArrayLike, rho_a0: ArrayLike, s_pr: ArrayLike,
                             alpha_e: float, alpha_n: float) -> ToothForm:
    """Tooth form of a non-generated (Formate) tooth loaded at its tip, and its Y_Fa.

    A non-generated member has no generating roll: each slot is a copy of the cutter's
    blade profile (straight-sided, pressure angle α_e, tip rounded with the edge radius
    ρ_a0), so in the normal section its tooth is the straight-sided tooth between two tool
    copies and its root fillet is the blade's edge radius itself.

    Parameters
    ----------
    m_mn : float — [mm]
    h_am : array_like — [mm]
        Mean addendum (the load at the tip).
    x_hm, x_sm : array_like — [1]
        Profile shift and thickness modification coefficients.
    h_a0, rho_a0, s_pr : array_like — [mm]
        Tool addendum, cutter edge radius, protuberance.
    alpha_e : float — [rad]
        Effective pressure angle of the rated flank (the blade's flank in the tooth form).
    alpha_n : float — [rad]
        Generated pressure angle of the rated flank (in Y_Fa's denominator, as for the
        generated tooth).

    Returns
    -------
    ToothForm
        E and G as for the generated tooth (:func:`tooth_form`: E the half-width from the
        slot's centre line to the edge-radius centre, G m_mn the centre's height above the
        reference line); the fillet radius ρ_F = ρ_a0; the 30° tangent on the edge radius,
        s_Fn = π m_mn − 2E − 2 ρ_a0 cos 30°; the load at the tip corner along the flank
        normal, α_Fan = α_e, h_Fa = h_am + h_a0 − x_hm m_mn − ρ_a0/2 − s_an tan α_e with
        the tip's half thickness s_an = (π/4 + x_sm) m_mn − (h_am − x_hm m_mn) tan α_e;
        Y_Fa = 6 (h_Fa/m_mn) cos α_Fan / ((s_Fn/m_mn)² cos α_n). ϑ = π/3, H = −π/3,
        γ_a = 0 and α_an = α_e are the values of the generated tooth's quantities in
        the same limit.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1) rates a non-generated member by a tooth
    form of its own, the fillet being the tool's edge radius; its printed equations could
    not be consulted here. Implemented as the limit z_vn → ∞ of the clause's generated
    equations (:func:`tooth_form`), which is what a tool-copied straight-sided slot is,
    the tooth's flanks taken parallel to the slot's (a rack tooth; their true inclination
    π/z_vn is neglected, 1.6° at the z_vn ≈ 110 of ISO/TR 10300-30's gears). With
    h_am − x_hm m_mn = m_mn (k_hap = 1, ISO 23509's usual basic crown gear addendum) h_Fa
    reads h_a0 − ρ_a0/2 + m_mn − (π/4 + x_sm − tan α_e) m_mn tan α_e, the form in which
    ISO 10300-3 (and DIN 3991-3 before it) give it as remembered, not checked against the
    printed text. Tested (tests/test_rating_iso10300.py): the generated equations converge
    to these as z_vn grows, and a direct construction of the tool-copied slot (30° tangent
    point, load line at the tip) gives the same s_Fn, h_Fa and ρ_F.
    """
    h_am, x_hm, x_sm, h_a0, rho_a0, s_pr = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (h_am, x_hm, x_sm, h_a0, rho_a0, s_pr)))
    ca, sa, ta = np.cos(alpha_e), np.sin(alpha_e), np.tan(alpha_e)
    E = ((0.25 * np.pi - x_sm) * m_mn - h_a0 * ta + s_pr / ca - rho_a0 * (1.0 - sa) / ca)
    G = (rho_a0 - h_a0) / m_mn + x_hm
    s_Fn = np.pi * m_mn - 2.0 * E - np.sqrt(3.0) * rho_a0
    s_an = (0.25 * np.pi + x_sm) * m_mn - (h_am - x_hm * m_mn) * ta
    h_Fa = h_am + h_a0 - x_hm * m_mn - 0.5 * rho_a0 - s_an * ta
    alpha_Fan = np.full(E.shape, float(alpha_e))
    Y_Fa = 6.0 * (h_Fa / m_mn) * np.cos(alpha_Fan) / ((s_Fn / m_mn) ** 2 * np.cos(alpha_n))
    return ToothForm(E=E, G=G, H=np.full(E.shape, -np.pi / 3.0),
                     theta=np.full(E.shape, np.pi / 3.0), s_Fn=s_Fn, rho_F=rho_a0.copy(),
                     alpha_an=alpha_Fan.copy(), gamma_a=np.zeros(E.shape),
                     alpha_Fan=alpha_Fan, h_Fa=h_Fa, Y_Fa=Y_Fa)


def member_tooth_forms(generated: ToothForm, non_generated: ToothForm,
                       is_non_generated: ArrayLike) -> ToothForm:
    """Each member's tooth form by how it is cut: ``non_generated`` where
    ``is_non_generated`` (a Formate member), ``generated`` elsewhere (arrays (2,))."""
    pick = np.asarray(is_non_generated, bool)
    return ToothForm(**{f.name: np.where(pick, getattr(non_generated, f.name),
                                         getattr(generated, f.name))
                        for f in fields(ToothForm)})


def stress_correction_factor(s_Fn: ArrayLike, h_Fa: ArrayLike, rho_F: ArrayLike
                             ) -> tuple[np.ndarray, np.ndarray]:
    """Stress correction factor Y_Sa and notch parameter q_s.

    Parameters
    ----------
    s_Fn, h_Fa, rho_F : array_like — [mm]
        :func:`tooth_form`.

    Returns
    -------
    Y_Sa : ndarray — [1]
        (1.2 + 0.13 L_a) q_s^(1/(1.21 + 2.3/L_a)), L_a = s_Fn/h_Fa.
    q_s : ndarray — [1]
        s_Fn / (2 ρ_F).

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1).
    """
    s_Fn, h_Fa, rho_F = (np.asarray(x, float) for x in (s_Fn, h_Fa, rho_F))
    L_a = s_Fn / h_Fa
    q_s = s_Fn / (2.0 * rho_F)
    return (1.2 + 0.13 * L_a) * q_s ** (1.0 / (1.21 + 2.3 / L_a)), q_s


def contact_ratio_factor(eps_va: float, eps_vb: float) -> float:
    """Contact ratio factor Y_ε — [1].

    Parameters
    ----------
    eps_va, eps_vb : float — [1]

    Returns
    -------
    float
        0.25 + 0.75/ε_vα − ε_vβ (0.75/ε_vα − 0.375) for ε_vβ < 1, 0.625 from ε_vβ = 1 on;
        at least 0.625.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1); TR sample 3 (ε_vβ = 0.860): 0.662.
    """
    if eps_vb >= 1.0:
        return 0.625
    return max(0.25 + 0.75 / eps_va - eps_vb * (0.75 / eps_va - 0.375), 0.625)


def bevel_spiral_angle_factor(b_v: float, beta_v: float, beta_vb: float, l_bm: float,
                              h_m1: float, h_m2: float) -> float:
    """Bevel spiral angle factor Y_BS: the root stress of an inclined contact line on a
    tooth of finite length.

    Parameters
    ----------
    b_v : float — [mm]
    beta_v, beta_vb : float — [rad]
    l_bm : float — [mm]
        Length of the middle contact line.
    h_m1, h_m2 : float — [mm]
        Mean whole depths h_am + h_fm.

    Returns
    -------
    float
        (a_BS/c_BS)(l_bb/b_a − 1.05 b_BS)² + 1 with b_a = b_v/cos β_v,
        l_bb = l_bm cos β_vb / cos β_v, x = 2 b_a/(h_m1 + h_m2) and
        a_BS = −0.0182 x² + 0.4736 x − 0.32, b_BS = −0.0032 x² + 0.0526 x + 0.712,
        c_BS = −0.0050 x² + 0.0850 x + 0.54.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1); TR samples: 1.054, 1.909, 1.014.
    """
    b_a = b_v / np.cos(beta_v)
    l_bb = l_bm * np.cos(beta_vb) / np.cos(beta_v)
    x = 2.0 * b_a / (h_m1 + h_m2)
    a_bs = -0.0182 * x * x + 0.4736 * x - 0.32
    b_bs = -0.0032 * x * x + 0.0526 * x + 0.712
    c_bs = -0.0050 * x * x + 0.0850 * x + 0.54
    return float(a_bs / c_bs * (l_bb / b_a - 1.05 * b_bs) ** 2 + 1.0)


def load_sharing_factor(Z_LS: float) -> float:
    """Load sharing factor for bending Y_LS = Z_LS² — [1] (ISO 10300-3:2014 cl. 6)."""
    return Z_LS**2


def relative_surface_factor(Rz: ArrayLike, coefficients: tuple[float, float, float]
                            = (1.674, 0.529, 0.1), smooth: float = 1.120) -> np.ndarray:
    """Relative surface condition factor Y_R,relT — [1].

    Parameters
    ----------
    Rz : array_like — [µm]
        Root roughness.
    coefficients : (float, float, float)
        (a, b, c) of Y_R,relT = a − b (Rz + 1)^c, valid for 1 ≤ Rz ≤ 40 µm; default the
        case-hardened steels' (the material table's ``rating_factors``).
    smooth : float
        The value below Rz = 1 µm.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (as ISO 6336-3, reference stress).
    """
    a, b, c = coefficients
    rz = np.asarray(Rz, float)
    return np.where(rz < 1.0, smooth, a - b * (rz + 1.0) ** c)


def relative_notch_sensitivity(q_s: ArrayLike, slip_layer: float = 0.0030) -> np.ndarray:
    """Relative notch sensitivity factor Y_δrelT — [1].

    Parameters
    ----------
    q_s : array_like — [1]
        Notch parameter (:func:`stress_correction_factor`).
    slip_layer : float — [mm]
        Slip-layer thickness ρ′ of the material (0.0030 mm for case-hardened steels, the
        material table's ``rating_factors``).

    Returns
    -------
    ndarray
        (1 + √(ρ′ χ*)) / (1 + √(ρ′ χ*_T)), χ* = (1 + 2 q_s)/5, χ*_T = 1.2 (q_sT = 2.5 of the
        test gear).

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (as ISO 6336-3, reference stress).
    """
    chi = 0.2 * (1.0 + 2.0 * np.asarray(q_s, float))
    return (1.0 + np.sqrt(slip_layer * chi)) / (1.0 + np.sqrt(slip_layer * 1.2))


def size_factor(m_mn: float) -> float:
    """Size factor for bending Y_X of case-hardened steel — [1].

    Returns
    -------
    float
        1 up to m_mn = 5 mm, 1.05 − 0.01 m_mn up to 25 mm, 0.8 above.

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 8 (as ISO 6336-3).
    """
    return float(np.clip(1.05 - 0.01 * m_mn, 0.8, 1.0))


def nominal_root_stress(F_vmt: ArrayLike, b_v: float, m_mn: float, Y_Fa: ArrayLike,
                        Y_Sa: ArrayLike, Y_eps: float, Y_BS: float, Y_LS: float
                        ) -> np.ndarray:
    """Nominal tooth root stress σ_F0 = F_vmt/(b_v m_mn) Y_Fa Y_Sa Y_ε Y_BS Y_LS — [MPa].

    Parameters
    ----------
    F_vmt : array_like, shape (n, 1) or broadcastable with Y_Fa — [N]
    b_v, m_mn : float — [mm]
    Y_Fa, Y_Sa : array_like (2,) — [1]
    Y_eps, Y_BS, Y_LS : float — [1]

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1).
    """
    return (np.asarray(F_vmt, float) / (b_v * m_mn) * np.asarray(Y_Fa, float)
            * np.asarray(Y_Sa, float) * Y_eps * Y_BS * Y_LS)


def root_stress(sigma_F0: ArrayLike, K_A: float, K_v: ArrayLike, K_Fbeta: float,
                K_Falpha: ArrayLike) -> np.ndarray:
    """Tooth root stress σ_F = σ_F0 K_A K_v K_Fβ K_Fα — [MPa] (ISO 10300-3:2014 cl. 6)."""
    return (np.asarray(sigma_F0, float) * K_A * np.asarray(K_v, float) * K_Fbeta
            * np.asarray(K_Falpha, float))


def permissible_root_stress(sigma_Flim: ArrayLike, Y_NT: ArrayLike, Y_delta: ArrayLike,
                            Y_R: ArrayLike, Y_X: float,
                            Y_ST: float = STRESS_CORRECTION_TEST_GEAR) -> np.ndarray:
    """Permissible tooth root stress σ_FP = σ_F,lim Y_ST Y_NT Y_δrelT Y_R,relT Y_X — [MPa].

    Notes
    -----
    Source: ISO 10300-3:2014 cl. 6 (Method B1), without S_F,min (as the TR prints it).
    """
    return np.asarray(sigma_Flim, float) * Y_ST * Y_NT * Y_delta * Y_R * Y_X
