"""Virtual cylindrical gears of a bevel or hypoid pair (ISO 10300-1:2014, Annex A, Method B1).

ISO 10300 rates a bevel or hypoid pair through two virtual cylindrical gear pairs at the
mean point P: one in the transverse section (diameters d_v, teeth z_v, path of contact
g_vα, contact ratios ε_vα, ε_vβ, the zone of action of face width b_v,eff and the contact
lines in it) and one in the normal section (z_vn, d_vn, d_van, d_vbn), whose teeth give the
tooth form factors of ISO 10300-3. Each function below computes one group of Annex A's
quantities from plain numbers or NumPy arrays (any shape that broadcasts; a member axis of
length 2, pinion then gear, where the docstring says so); :func:`virtual_gears` chains
them for one pair and one flank and returns a :class:`VirtualGears`.

Units: lengths [mm], angles [rad].

What was reconstructed
----------------------
The standard's text was not at hand. The equations below are those of Annex A as far as
they could be established, each checked against the intermediate values ISO/TR
10300-30:2024 prints for its three samples (tests/test_rating_iso10300.py):

* the hypoid terms (virtual face width b_v,eff with the auxiliary angles θ_mp, γ′, γ;
  the relative curvature with the limit pressure angle and the offset angle ζ_mp;
  the positions of the contact lines for ε_vβ < 1) reproduce samples 2 and 3 to the
  TR's printed digits;
* the contact lines (:func:`contact_line_length`): the zone of action is the
  parallelogram of width b_v,eff (along the face) and length g_vα (along the path of
  contact), its tip and root edges skewed by γ (0 for bevel gears); a contact line, at
  β_vb to the face direction, at the signed distance f from the middle line, is clipped
  to it (l_b0) — the TR prints the clipped end points (sample 3: x_2 = 0, the face edge)
  — and shortened for the effective face width,
  l_b = l_b0 [1 − (1 − √(b_v,eff/b_v)) √(1 − (f/f_max)²)]. The correction's form is our
  reading: it gives the TR's l_bm (f = 0 in samples 1 and 2, f_m = −0.686 mm in sample
  3) and, through Z_LS, the tip and root lines of all three samples within one unit of
  the TR's last digit; a constant √(b_v,eff/b_v) misses Z_LS by 2–4 units.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "VirtualGears",
    "contact_line_ends",
    "contact_line_length",
    "contact_line_positions",
    "face_contact_ratio",
    "max_contact_line_distance",
    "normal_section",
    "path_of_contact",
    "relative_curvature",
    "transverse_base_pitch",
    "transverse_contact_ratio",
    "virtual_base_helix_angle",
    "virtual_diameters",
    "virtual_face_width",
    "virtual_gears",
    "virtual_helix_angle",
    "virtual_transverse_module",
    "virtual_transverse_pressure_angle",
]


def virtual_diameters(d_m: ArrayLike, delta: ArrayLike, h_am: ArrayLike,
                      alpha_vet: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Reference, tip and base diameters of the virtual cylindrical gear (transverse section).

    Parameters
    ----------
    d_m : array_like — [mm]
        Mean pitch diameter d_m.
    delta : array_like — [rad]
        Pitch angle δ.
    h_am : array_like — [mm]
        Mean addendum h_am.
    alpha_vet : array_like — [rad]
        Transverse pressure angle of the virtual gear α_vet (:func:`virtual_transverse_
        pressure_angle`).

    Returns
    -------
    d_v, d_va, d_vb : ndarray — [mm]
        d_v = d_m / cos δ, d_va = d_v + 2 h_am, d_vb = d_v cos α_vet (broadcast shape).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, virtual cylindrical gear in transverse section).
    """
    d_v = np.asarray(d_m, float) / np.cos(delta)
    return d_v, d_v + 2.0 * np.asarray(h_am, float), d_v * np.cos(alpha_vet)


def virtual_helix_angle(beta_m1: ArrayLike, beta_m2: ArrayLike) -> np.ndarray:
    """Helix angle of the virtual cylindrical gears β_v = (β_m1 + β_m2)/2 — [rad].

    Parameters
    ----------
    beta_m1, beta_m2 : array_like — [rad]
        Mean spiral angles of pinion and gear (equal for bevel gears without offset).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2).
    """
    return 0.5 * (np.asarray(beta_m1, float) + np.asarray(beta_m2, float))


def virtual_transverse_pressure_angle(alpha_e: ArrayLike, beta_v: ArrayLike) -> np.ndarray:
    """Transverse pressure angle α_vet = arctan(tan α_e / cos β_v) — [rad].

    Parameters
    ----------
    alpha_e : array_like — [rad]
        Effective pressure angle of the rated flank (α_eD drive, α_eC coast; ISO 23509).
    beta_v : array_like — [rad]
        Virtual helix angle.

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2).
    """
    return np.arctan(np.tan(alpha_e) / np.cos(beta_v))


def virtual_transverse_module(m_mn: ArrayLike, beta_v: ArrayLike) -> np.ndarray:
    """Transverse module m_vt = m_mn / cos β_v — [mm] (Annex A, A.2)."""
    return np.asarray(m_mn, float) / np.cos(beta_v)


def virtual_base_helix_angle(beta_v: ArrayLike, alpha_e: ArrayLike) -> np.ndarray:
    """Base helix angle β_vb = arcsin(sin β_v cos α_e) — [rad] (Annex A, A.2)."""
    return np.arcsin(np.sin(beta_v) * np.cos(alpha_e))


def transverse_base_pitch(m_mn: ArrayLike, alpha_vet: ArrayLike,
                          beta_v: ArrayLike) -> np.ndarray:
    """Transverse base pitch p_vet = π m_mn cos α_vet / cos β_v — [mm] (Annex A, A.2)."""
    return np.pi * np.asarray(m_mn, float) * np.cos(alpha_vet) / np.cos(beta_v)


def path_of_contact(d_va: ArrayLike, d_vb: ArrayLike, d_v: ArrayLike,
                    alpha_vet: ArrayLike) -> np.ndarray:
    """Length of the path of contact of the virtual gears g_vα — [mm].

    Parameters
    ----------
    d_va, d_vb, d_v : array_like, shape (..., 2) — [mm]
        Tip, base and reference diameters, the last axis pinion then gear.
    alpha_vet : array_like, shape (...) — [rad]

    Returns
    -------
    ndarray, shape (...) — [mm]
        g_vα = Σ ½ [√(d_va² − d_vb²) − d_v sin α_vet] over both members.

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2).
    """
    d_va, d_vb, d_v = (np.asarray(x, float) for x in (d_va, d_vb, d_v))
    a = np.asarray(alpha_vet, float)[..., None]
    return 0.5 * np.sum(np.sqrt(d_va**2 - d_vb**2) - d_v * np.sin(a), axis=-1)


def transverse_contact_ratio(g_va: ArrayLike, p_vet: ArrayLike) -> np.ndarray:
    """Transverse contact ratio ε_vα = g_vα / p_vet — [1] (Annex A, A.2)."""
    return np.asarray(g_va, float) / np.asarray(p_vet, float)


def virtual_face_width(b2_eff: ArrayLike, g_va: ArrayLike, alpha_vet: ArrayLike,
                       zeta_mp: ArrayLike, zeta_m: ArrayLike, delta2: ArrayLike
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Effective face width of the virtual gears and the skew of the zone of action.

    Parameters
    ----------
    b2_eff : array_like — [mm]
        Effective face width of the gear (the loaded contact pattern; 0.85 b2 when not
        known, ISO 10300-1).
    g_va : array_like — [mm]
        Path of contact.
    alpha_vet : array_like — [rad]
    zeta_mp, zeta_m : array_like — [rad]
        Offset angles in the pitch plane and in the axial plane (0 without offset).
    delta2 : array_like — [rad]
        Gear pitch angle.

    Returns
    -------
    b_veff : ndarray — [mm]
        b_v,eff = [b2,eff / cos(ζ_mp/2) − g_vα cos α_vet tan(ζ_mp/2)] /
        [1 − tan γ′ tan(ζ_mp/2)]; b2,eff for bevel gears (ζ_mp = 0).
    gamma : ndarray — [rad]
        Auxiliary angle of the contact lines γ = arctan(tan γ′ / cos α_vet), with
        γ′ = θ_mp − ζ_mp/2 and θ_mp = arctan(sin δ2 tan ζ_m): the skew of the tip and root
        edges of the zone of action (0 without offset).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, hypoid gears); checked against ISO/TR
    10300-30:2024 samples 2 and 3 (b_v,eff 24.880 and 19.981 mm).
    """
    half = 0.5 * np.asarray(zeta_mp, float)
    theta_mp = np.arctan(np.sin(delta2) * np.tan(zeta_m))
    gamma_p = theta_mp - half
    b_veff = ((np.asarray(b2_eff, float) / np.cos(half)
               - np.asarray(g_va, float) * np.cos(alpha_vet) * np.tan(half))
              / (1.0 - np.tan(gamma_p) * np.tan(half)))
    return b_veff, np.arctan(np.tan(gamma_p) / np.cos(alpha_vet))


def face_contact_ratio(b_veff: ArrayLike, beta_v: ArrayLike, m_mn: ArrayLike) -> np.ndarray:
    """Face contact ratio ε_vβ = b_v,eff sin β_v / (π m_mn) — [1] (Annex A, A.2)."""
    return np.asarray(b_veff, float) * np.sin(beta_v) / (np.pi * np.asarray(m_mn, float))


def contact_line_positions(p_vet: ArrayLike, beta_vb: ArrayLike, eps_va: ArrayLike,
                           eps_vb: ArrayLike) -> np.ndarray:
    """Signed distances of the tip, middle and root contact lines from the middle of the
    zone of action, measured perpendicular to the lines.

    Parameters
    ----------
    p_vet : array_like — [mm]
    beta_vb : array_like — [rad]
    eps_va, eps_vb : array_like — [1]
        Transverse and face contact ratios.

    Returns
    -------
    ndarray, shape (..., 3) — [mm]
        (f_t, f_m, f_r) = f_m + (p_n, 0, −p_n) with the normal base pitch
        p_n = p_vet cos β_vb; f_m = 0 for ε_vβ ≥ 1, else
        f_m = −p_vet (1 − ε_vα/2) (1 − ε_vβ) cos β_vb (the middle line moved so that the
        lines in contact straddle the middle of the zone).

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, positions of the contact lines); checked
    against ISO/TR 10300-30:2024 sample 3 (ε_vβ = 0.860: f_m −0.686, f_t 11.205,
    f_r −12.577 mm).
    """
    p_vet, beta_vb, eps_va, eps_vb = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (p_vet, beta_vb, eps_va, eps_vb)))
    p_n = p_vet * np.cos(beta_vb)
    f_m = np.where(eps_vb >= 1.0, 0.0, -p_vet * (1.0 - 0.5 * eps_va) * (1.0 - eps_vb)
                   * np.cos(beta_vb))
    return np.stack([f_m + p_n, f_m, f_m - p_n], axis=-1)


def max_contact_line_distance(g_va: ArrayLike, b_veff: ArrayLike, beta_vb: ArrayLike,
                              gamma: ArrayLike) -> np.ndarray:
    """Distance f_max of the farthest corner of the zone of action from its middle line.

    Parameters
    ----------
    g_va, b_veff : array_like — [mm]
    beta_vb, gamma : array_like — [rad]

    Returns
    -------
    ndarray — [mm]
        max(|f_max,B|, |f_max,0|), f_max,B/0 = ½ [g_vα ± b_v,eff (tan γ + tan β_vb)] cos β_vb:
        the contact line through a corner of the parallelogram.

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, length of contact lines).
    """
    g_va, b_veff = np.asarray(g_va, float), np.asarray(b_veff, float)
    s = b_veff * (np.tan(gamma) + np.tan(beta_vb))
    return np.maximum(np.abs(0.5 * (g_va + s)), np.abs(0.5 * (g_va - s))) * np.cos(beta_vb)


def _clip(f: np.ndarray, beta_vb: np.ndarray, gamma: np.ndarray, g_va: np.ndarray,
          b_veff: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The parameters (t_lo, t_hi) of a contact line's ends in the zone of action: the line
    (x, y) = f (−sin β_vb, cos β_vb) + t (cos β_vb, sin β_vb), x along the face from its
    middle, y along the path of contact, inside |x| ≤ b_v,eff/2 and |y + x tan γ| ≤ g_vα/2
    (t_lo > t_hi: the line misses the zone)."""
    s, c, tg = np.sin(beta_vb), np.cos(beta_vb), np.tan(gamma)
    lo = np.full(f.shape, -np.inf)
    hi = np.full(f.shape, np.inf)
    for a0, a1, half in ((-f * s, c, 0.5 * b_veff),
                         (f * c - f * s * tg, s + c * tg, 0.5 * g_va)):
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = (-half - a0) / a1
            t2 = (half - a0) / a1
        inside = np.abs(a0) <= half
        t1 = np.where(a1 == 0.0, np.where(inside, -np.inf, np.inf), t1)
        t2 = np.where(a1 == 0.0, np.where(inside, np.inf, -np.inf), t2)
        lo = np.maximum(lo, np.minimum(t1, t2))
        hi = np.minimum(hi, np.maximum(t1, t2))
    return lo, hi


def contact_line_ends(f: ArrayLike, beta_vb: ArrayLike, gamma: ArrayLike, g_va: ArrayLike,
                      b_veff: ArrayLike) -> np.ndarray:
    """End points of a contact line in the zone of action, in ISO/TR 10300-30's frame.

    Parameters
    ----------
    f : array_like — [mm]
        Signed distance of the line from the middle line.
    beta_vb, gamma : array_like — [rad]
    g_va, b_veff : array_like — [mm]

    Returns
    -------
    ndarray, shape (..., 4) — [mm]
        (x1, y1, x2, y2): x across the face width from its edge (0 … b_v,eff), y along the
        path of contact from its middle; the end x1 ≥ x2 first (NaN for a line that misses
        the zone). Sample 3's middle line: (19.918, −6.712, 0.000, —) in the TR, the end
        x2 = 0 on the face edge.

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, length of contact lines).
    """
    f, beta_vb, gamma, g_va, b_veff = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (f, beta_vb, gamma, g_va, b_veff)))
    lo, hi = _clip(f, beta_vb, gamma, g_va, b_veff)
    ends = []
    for t in (lo, hi):
        x = -f * np.sin(beta_vb) + t * np.cos(beta_vb)
        y = f * np.cos(beta_vb) + t * np.sin(beta_vb)
        ends.append((0.5 * b_veff - x, y))
    out = np.stack([ends[0][0], ends[0][1], ends[1][0], ends[1][1]], axis=-1)
    return np.where((hi >= lo)[..., None], out, np.nan)


def contact_line_length(f: ArrayLike, beta_vb: ArrayLike, gamma: ArrayLike, g_va: ArrayLike,
                        b_veff: ArrayLike, b_v: ArrayLike, f_max: ArrayLike
                        ) -> tuple[np.ndarray, np.ndarray]:
    """Length of a contact line in the zone of action, clipped and corrected.

    Parameters
    ----------
    f : array_like — [mm]
        Signed distance of the line from the middle line (:func:`contact_line_positions`).
    beta_vb, gamma : array_like — [rad]
        Base helix angle (the lines' inclination to the face direction) and skew of the
        zone's tip and root edges (:func:`virtual_face_width`).
    g_va, b_veff, b_v : array_like — [mm]
        Path of contact, effective and whole face width of the virtual gears.
    f_max : array_like — [mm]
        :func:`max_contact_line_distance`.

    Returns
    -------
    l_b0 : ndarray — [mm]
        The line's length inside the zone |x| ≤ b_v,eff/2, |y + x tan γ| ≤ g_vα/2 (x along
        the face, y along the path of contact; 0 for a line that misses it), between the
        ends of :func:`contact_line_ends`.
    l_b : ndarray — [mm]
        l_b = l_b0 [1 − (1 − √(b_v,eff/b_v)) √(1 − (f/f_max)²)].

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, length of contact lines); the correction's form
    is our reading, chosen as it reproduces ISO/TR 10300-30:2024 (module docstring).
    """
    f, beta_vb, gamma, g_va, b_veff, b_v, f_max = np.broadcast_arrays(
        *(np.asarray(x, float) for x in (f, beta_vb, gamma, g_va, b_veff, b_v, f_max)))
    lo, hi = _clip(f, beta_vb, gamma, g_va, b_veff)
    l_b0 = np.maximum(hi - lo, 0.0)
    ratio = np.clip(f / f_max, -1.0, 1.0)
    corr = 1.0 - (1.0 - np.sqrt(b_veff / b_v)) * np.sqrt(1.0 - ratio**2)
    return l_b0, l_b0 * corr


def relative_curvature(alpha_n: ArrayLike, alpha_lim: ArrayLike, alpha_e: ArrayLike,
                       beta_v: ArrayLike, beta_m1: ArrayLike, beta_m2: ArrayLike,
                       zeta_mp: ArrayLike, R_m1: ArrayLike, R_m2: ArrayLike,
                       delta1: ArrayLike, delta2: ArrayLike
                       ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Relative curvature at the mean point, normal to the contact line.

    Parameters
    ----------
    alpha_n : array_like — [rad]
        Generated normal pressure angle of the rated flank (α_nD or α_nC).
    alpha_lim : array_like — [rad]
        Limit pressure angle, signed for the rated flank (+α_lim drive, −α_lim coast;
        0 without offset).
    alpha_e : array_like — [rad]
        Effective pressure angle of the rated flank.
    beta_v, beta_m1, beta_m2, zeta_mp : array_like — [rad]
    R_m1, R_m2 : array_like — [mm]
        Mean cone distances.
    delta1, delta2 : array_like — [rad]

    Returns
    -------
    rho_t : ndarray — [mm]
        Radius of relative curvature in the normal section,
        1/ρ_t = (cos β_m1 cos β_m2 / cos ζ_mp) (1/(R_m1 tan δ1) + 1/(R_m2 tan δ2)) /
        [cos α_n (tan α_n − tan α_lim) + tan ζ_mp tan β_B].
    beta_B : ndarray — [rad]
        Inclination of the contact line β_B = arctan(tan β_v sin α_e).
    rho_rel : ndarray — [mm]
        Radius of relative curvature normal to the contact line ρ_rel = ρ_t cos² β_B.

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.2, radius of relative curvature); checked
    against ISO/TR 10300-30:2024 (ρ_t 13.173, 19.924, 14.703 mm).
    """
    beta_B = np.arctan(np.tan(beta_v) * np.sin(alpha_e))
    denom = (np.cos(alpha_n) * (np.tan(alpha_n) - np.tan(alpha_lim))
             + np.tan(zeta_mp) * np.tan(beta_B))
    inv = (np.cos(beta_m1) * np.cos(beta_m2) / np.cos(zeta_mp)
           * (1.0 / (np.asarray(R_m2, float) * np.tan(delta2))
              + 1.0 / (np.asarray(R_m1, float) * np.tan(delta1))) / denom)
    rho_t = 1.0 / inv
    return rho_t, beta_B, rho_t * np.cos(beta_B) ** 2


def normal_section(z_v: ArrayLike, beta_v: ArrayLike, beta_vb: ArrayLike, m_mn: ArrayLike,
                   h_am: ArrayLike, alpha_e: ArrayLike
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The virtual cylindrical gear in the normal section (the tooth of ISO 10300-3).

    Parameters
    ----------
    z_v : array_like — [1]
        Virtual number of teeth (transverse section).
    beta_v, beta_vb : array_like — [rad]
    m_mn, h_am : array_like — [mm]
    alpha_e : array_like — [rad]

    Returns
    -------
    z_vn, d_vn, d_van, d_vbn : ndarray
        z_vn = z_v / (cos² β_vb cos β_v) [1]; d_vn = z_vn m_mn, d_van = d_vn + 2 h_am,
        d_vbn = d_vn cos α_e [mm].

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A (A.3, virtual cylindrical gear in normal section).
    """
    z_vn = np.asarray(z_v, float) / (np.cos(beta_vb) ** 2 * np.cos(beta_v))
    d_vn = z_vn * np.asarray(m_mn, float)
    return z_vn, d_vn, d_vn + 2.0 * np.asarray(h_am, float), d_vn * np.cos(alpha_e)


@dataclass(frozen=True)
class VirtualGears:
    """The virtual cylindrical gears of one pair and flank (ISO 10300-1 Annex A).

    Member quantities are arrays of shape (2,), pinion then gear; contact-line
    quantities of shape (3,), tip, middle and root line. Lengths [mm], angles [rad].

    Attributes
    ----------
    d_v, d_va, d_vb, z_v : ndarray (2,)
        Reference, tip and base diameter, number of teeth (transverse section).
    u_v : float
        Ratio z_v2 / z_v1.
    beta_v, alpha_vet, m_vt, beta_vb, p_vet : float
        Helix angle, transverse pressure angle, transverse module, base helix angle,
        transverse base pitch.
    g_va, eps_va : float
        Path of contact, transverse contact ratio.
    b_veff, b_v, gamma : float
        Effective and whole face width of the virtual gears, skew of the zone of action.
    eps_vb, eps_vg : float
        Face contact ratio and virtual contact ratio ε_vγ = ε_vα + ε_vβ.
    f, l_b0, l_b : ndarray (3,)
        Distances of the tip, middle and root contact lines, their clipped and their
        corrected lengths.
    f_max : float
        Distance of the zone's farthest corner.
    rho_t, beta_B, rho_rel : float
        Relative curvature (normal section), inclination of the contact line, relative
        curvature normal to the contact line.
    z_vn, d_vn, d_van, d_vbn : ndarray (2,)
        The normal-section gear.
    eps_van : float
        Transverse contact ratio in the normal section ε_vαn = ε_vα / cos² β_vb.
    """

    d_v: np.ndarray
    d_va: np.ndarray
    d_vb: np.ndarray
    z_v: np.ndarray
    u_v: float
    beta_v: float
    alpha_vet: float
    m_vt: float
    beta_vb: float
    p_vet: float
    g_va: float
    eps_va: float
    b_veff: float
    b_v: float
    gamma: float
    eps_vb: float
    eps_vg: float
    f: np.ndarray
    f_max: float
    l_b0: np.ndarray
    l_b: np.ndarray
    rho_t: float
    beta_B: float
    rho_rel: float
    z_vn: np.ndarray
    d_vn: np.ndarray
    d_van: np.ndarray
    d_vbn: np.ndarray
    eps_van: float

    @property
    def l_bm(self) -> float:
        """Length of the middle contact line l_bm [mm] (the line through the mean point)."""
        return float(self.l_b[1])

    def items(self):
        """(name, value) of every field, in order."""
        return ((f.name, getattr(self, f.name)) for f in fields(self))


def virtual_gears(data, side: str = "drive", effective_width_ratio: float = 0.85
                  ) -> VirtualGears:
    """The virtual cylindrical gears of a pair for one flank.

    Parameters
    ----------
    data : contact.load_capacity.iso10300.inputs.GearData
        The pair's ISO 10300 geometry (from its ISO 23509 blank).
    side : {"drive", "coast"}
        The rated flank in ISO 23509's naming (drive: the pinion's concave flank).
    effective_width_ratio : float — [1]
        b2,eff / b2, the loaded contact pattern's share of the gear face width.

    Returns
    -------
    VirtualGears

    Notes
    -----
    Source: ISO 10300-1:2014, Annex A; the coast side uses α_nC, α_eC and −α_lim (not
    checked by ISO/TR 10300-30, which rates the drive side).
    """
    alpha_n, alpha_e, alpha_lim = data.flank_angles(side)
    delta = np.array([data.delta1, data.delta2])
    d_m = np.array([data.d_m1, data.d_m2])
    h_am = np.array([data.h_am1, data.h_am2])
    beta_v = float(virtual_helix_angle(data.beta_m1, data.beta_m2))
    alpha_vet = float(virtual_transverse_pressure_angle(alpha_e, beta_v))
    m_vt = float(virtual_transverse_module(data.m_mn, beta_v))
    d_v, d_va, d_vb = virtual_diameters(d_m, delta, h_am, alpha_vet)
    z_v = d_v / m_vt
    beta_vb = float(virtual_base_helix_angle(beta_v, alpha_e))
    p_vet = float(transverse_base_pitch(data.m_mn, alpha_vet, beta_v))
    g_va = float(path_of_contact(d_va, d_vb, d_v, alpha_vet))
    eps_va = float(transverse_contact_ratio(g_va, p_vet))
    b2_eff = effective_width_ratio * data.b2
    b_veff, gamma = (float(x) for x in virtual_face_width(
        b2_eff, g_va, alpha_vet, data.zeta_mp, data.zeta_m, data.delta2))
    b_v = data.b2 * b_veff / b2_eff
    eps_vb = float(face_contact_ratio(b_veff, beta_v, data.m_mn))
    f = contact_line_positions(p_vet, beta_vb, eps_va, eps_vb)
    f_max = float(max_contact_line_distance(g_va, b_veff, beta_vb, gamma))
    l_b0, l_b = contact_line_length(f, beta_vb, gamma, g_va, b_veff, b_v, f_max)
    R_m = d_m / (2.0 * np.sin(delta))
    rho_t, beta_B, rho_rel = (float(x) for x in relative_curvature(
        alpha_n, alpha_lim, alpha_e, beta_v, data.beta_m1, data.beta_m2, data.zeta_mp,
        R_m[0], R_m[1], data.delta1, data.delta2))
    z_vn, d_vn, d_van, d_vbn = normal_section(z_v, beta_v, beta_vb, data.m_mn, h_am, alpha_e)
    return VirtualGears(
        d_v=d_v, d_va=d_va, d_vb=d_vb, z_v=z_v, u_v=float(z_v[1] / z_v[0]), beta_v=beta_v,
        alpha_vet=alpha_vet, m_vt=m_vt, beta_vb=beta_vb, p_vet=p_vet, g_va=g_va,
        eps_va=eps_va, b_veff=b_veff, b_v=b_v, gamma=gamma, eps_vb=eps_vb,
        eps_vg=eps_va + eps_vb, f=f, f_max=f_max, l_b0=l_b0, l_b=l_b, rho_t=rho_t,
        beta_B=beta_B, rho_rel=rho_rel, z_vn=z_vn, d_vn=d_vn, d_van=d_van, d_vbn=d_vbn,
        eps_van=eps_va / np.cos(beta_vb) ** 2)
