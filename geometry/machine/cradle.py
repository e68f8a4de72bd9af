"""Cradle-type generator kinematics: from the cutter to the blank (seed §2.2.1–2.2.2, Eq. 2.1–2.7).

Frames (all right-handed; see ``docs/machine.md`` for the figure)
-------------------------------------------------------------------
* **Cutter frame S_t** — origin at the centre of the blade-tip plane, z_t along the cutter
  axis from the cutter body towards the blade tips (towards the work); see
  :mod:`geometry.machine.cutter`.
* **Machine frame S_m** — origin at the machine centre O_m, z_m along the cradle axis
  pointing from the cradle towards the work. With zero tilt the blade tips sweep the plane
  z_m = 0. The work axis lies in the plane y_m = E_m; x_m is the direction of the work axis's
  projection on the cradle plane.
* **Blank (member) frame S_g** — origin at the member's crossing point, z_g along the member
  axis from the apex side into the member body (towards its heel/back), y_g = y_m at zero
  work rotation. The tooth slot cut at q = 0 lies near the plane y_g = 0 on the +x_g side.

Settings (positive senses)
--------------------------
S_r radial setting (distance cradle axis → cutter centre), q_c cradle angle (from +x_m to
the cutter centre, about +z_m), j swivel (from the radial line to the tilt axis, about
+z_m), i tilt (rotation about the tilt axis; the cutter axis leans towards −y of the
swivelled frame), γ_m machine root angle (between the work axis and the cradle plane,
the work axis rising towards +z_m), X_p machine centre to back (position of the member's
crossing point along the work axis; larger X_p retracts the work), X_b sliding base
(displacement of the work along −z_m; larger X_b cuts deeper), E_m blank offset (work axis
displaced along +y_m), R_a ratio of roll (work rotation / cradle rotation, seed Eq. 2.2a).

The chain (our reading of seed Eq. 2.7a, cf. ``seed/NOTES.md``), r in homogeneous form:

    r_g = R_z(−φ(q)) · T(0, 0, −X_p) · R_y(γ_m − π/2) · T(0, −E_m(q), X_b(q))
          · R_z(q_c + q) · T(S_r, 0, 0) · R_z(j) · R_x(i) · r_t(s, θ)

R_k are active right-hand rotations, T translations. In *Generate* the cradle turns by
q and the work by φ(q) = R_a (q − C q² − D q³ − E q⁴ − F q⁵) (modified roll, with the
summary's 2C, 6D, 24E, 120F the Taylor derivatives), the sliding base by the helical motion
X_b(q) = X_b + Σ H_k q^k/k! and the blank offset by the vertical motion
E_m(q) = E_m + Σ V_k q^k/k!. In *Formate* q ≡ 0 and the gear is the imprint of the cutter.

Hand: settings are read for a **right-hand** member (with q_c > 0 the cutter centre lies on
the +y_m side and the generated member is right-hand). A left-hand member is the mirror
image y_g → −y_g of the right-hand one; :func:`mirror_settings` gives the signed settings
that generate the mirror image directly.

Public functions
----------------
MachineSettings        frozen dataclass of one flank's settings (rad, mm)
PROCESSES              the registry of generating processes
taylor_motion          a setting and its q-derivatives from Taylor coefficients
roll_angle             φ(q), φ'(q), φ''(q) with modified roll
indexing_ratio         κ = −z0/z of a face-hobbing member
work_rotation          φ(q, θ) = φ_roll(q) + κθ and its q-derivatives
machine_transform      4×4 M(q), dM/dq, d²M/dq² (cutter → blank), batched
generated_family       r_g(s, θ, q) and all first and second derivatives in the blank frame
meshing_function       seed Eq. 2.8, normalised, and its gradient
mirror_settings        settings of the mirror-image (opposite hand) member
cutter_pose            cutter centre and axis in the blank frame
settings_from_poses    inverse kinematics: settings that place a cutter and a work axis
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np

from geometry.core.caches import memoised
from geometry.core.errors import InputError
from geometry.core.validation import integer, real

__all__ = [
    "PROCESSES",
    "MachineSettings",
    "PoseSettings",
    "cradle_pose",
    "cutter_pose",
    "indexing_ratio",
    "machine_transform",
    "mirror_settings",
    "roll_angle",
    "settings_from_poses",
    "taylor_coefficients",
    "taylor_motion",
    "work_rotation",
]

def _roll_formate(settings: MachineSettings, q: np.ndarray):
    zero = np.zeros_like(q)
    return zero, zero, zero


def _roll_generate(settings: MachineSettings, q: np.ndarray):
    # φ(q) = R_a (q − Σ_{k≥2} c_k q^k / k!), c = (2C, 6D, 24E, 120F)
    coeffs = (1.0, *(-c for c in settings.modified_roll))
    val, d1, d2 = taylor_motion(0.0, coeffs, q)
    ra = settings.ratio_of_roll
    return ra * val, ra * d1, ra * d2


#: generating processes: name → roll function φ(settings, q) → (φ, φ', φ'')
PROCESSES: dict[str, Callable] = {"Formate": _roll_formate, "Generate": _roll_generate}


@dataclass(frozen=True)
class MachineSettings:
    """Machine settings of a cradle-type generator for one flank (angles rad, lengths mm).

    Parameters
    ----------
    process : str
        ``"Formate"`` (no roll: the member is the cutter's imprint) or ``"Generate"``.
    radial_setting : float — [mm]
        S_r ≥ 0.
    cradle_angle : float — [rad]
        q_c, |q_c| ≤ 2π.
    swivel : float — [rad]
        j, |j| ≤ 2π.
    tilt : float — [rad]
        i, |i| < π/2.
    machine_root_angle : float — [rad]
        γ_m, |γ_m| < π/2.
    machine_center_to_back : float — [mm]
        X_p, axial position of the member's crossing point (see module docstring).
    sliding_base : float — [mm]
        X_b.
    blank_offset : float — [mm]
        E_m.
    ratio_of_roll : float — [1]
        R_a = work rotation / cradle rotation; > 0 for Generate, 0 for Formate.
    modified_roll : sequence of float
        (2C [1/rad], 6D [1/rad²], 24E [1/rad³], 120F [1/rad⁴]); Generate only.
    helical_motion : sequence of float
        Derivatives of the sliding base with respect to q: (H1 [mm/rad], H2 [mm/rad²], …).
    vertical_motion : sequence of float
        Derivatives of the blank offset with respect to q: (V1 [mm/rad], V2 [mm/rad²], …).
    indexing_ratio : float — [1]
        κ, work rotation per radian of cutter spin at a fixed cradle (face hobbing, seed
        Eq. 2.1 and 2.4b): κ = −z0/z with z0 the cutter's blade groups and z the member's
        teeth (:func:`indexing_ratio`), |κ| ≤ 50; 0 for face milling (default). Allowed for
        Formate and Generate.

    Raises
    ------
    InputError
        A field is not finite or out of range, or the process and the roll are inconsistent.
    """

    process: str
    radial_setting: float
    cradle_angle: float
    swivel: float = 0.0
    tilt: float = 0.0
    machine_root_angle: float = 0.0
    machine_center_to_back: float = 0.0
    sliding_base: float = 0.0
    blank_offset: float = 0.0
    ratio_of_roll: float = 0.0
    modified_roll: tuple[float, ...] = field(default=())
    helical_motion: tuple[float, ...] = field(default=())
    vertical_motion: tuple[float, ...] = field(default=())
    indexing_ratio: float = 0.0

    def __post_init__(self) -> None:
        if self.process not in PROCESSES:
            raise InputError(
                f"process: must be one of {sorted(PROCESSES)}, got {self.process!r}")
        for name in ("radial_setting", "cradle_angle", "swivel", "tilt", "machine_root_angle",
                     "machine_center_to_back", "sliding_base", "blank_offset",
                     "ratio_of_roll", "indexing_ratio"):
            object.__setattr__(self, name, real(name, getattr(self, name)))
        if abs(self.indexing_ratio) > 50.0:
            raise InputError(f"indexing_ratio: must be in [-50, 50] (-z0/z), got "
                             f"{self.indexing_ratio:.6g}")
        for name in ("modified_roll", "helical_motion", "vertical_motion"):
            seq = getattr(self, name)
            if isinstance(seq, (str, bytes)) or not isinstance(seq, Sequence):
                raise InputError(f"{name}: must be a list of numbers, got {seq!r}")
            vals = tuple(real(f"{name}[{k}]", v) for k, v in enumerate(seq))
            object.__setattr__(self, name, vals)
        if len(self.modified_roll) > 4:
            raise InputError(
                f"modified_roll: at most 4 coefficients (2C, 6D, 24E, 120F), got "
                f"{len(self.modified_roll)}")
        if self.radial_setting < 0.0:
            raise InputError(f"radial_setting: must be >= 0 mm, got {self.radial_setting}")
        for name, bound, text in (("cradle_angle", 2 * math.pi, "[-360, 360]"),
                                  ("swivel", 2 * math.pi, "[-360, 360]")):
            if abs(getattr(self, name)) > bound + 1e-12:
                raise InputError(f"{name}: must be in {text} deg, got "
                                 f"{math.degrees(getattr(self, name)):.6g}")
        for name in ("tilt", "machine_root_angle"):
            if abs(getattr(self, name)) >= 0.5 * math.pi:
                raise InputError(f"{name}: must be in (-90, 90) deg, got "
                                 f"{math.degrees(getattr(self, name)):.6g}")
        if self.process == "Generate":
            if not self.ratio_of_roll > 0.0:
                raise InputError(
                    f"ratio_of_roll: must be > 0 for a generated member, got {self.ratio_of_roll}")
        elif (self.ratio_of_roll != 0.0 or any(self.modified_roll) or any(self.helical_motion)
              or any(self.vertical_motion)):
            raise InputError(
                "ratio_of_roll: a Formate member has no roll: ratio_of_roll, modified_roll, "
                "helical_motion and vertical_motion must be 0 or absent")


def taylor_motion(value0: float, derivatives: Sequence[float], q):
    """A motion given by its value and q-derivatives at q = 0, and its first two derivatives.

    Parameters
    ----------
    value0 : float
        Value at q = 0 (same unit as the motion).
    derivatives : sequence of float
        k-th derivative at q = 0 for k = 1, 2, … [unit/rad^k].
    q : array_like — [rad]
        Cradle rotation from the reference position.

    Returns
    -------
    value, first, second : ndarray
        f(q) = value0 + Σ d_k q^k/k!, f'(q), f''(q).
    """
    q = np.asarray(q, dtype=float)
    if not any(derivatives):
        return np.full_like(q, value0), np.zeros_like(q), np.zeros_like(q)
    coef = taylor_coefficients(float(value0), tuple(float(d) for d in derivatives))
    out = np.vander(q.ravel(), coef.shape[0], increasing=True) @ coef
    return (out[:, 0].reshape(q.shape), out[:, 1].reshape(q.shape),
            out[:, 2].reshape(q.shape))


@memoised(maxsize=64)
def taylor_coefficients(value0: float, derivatives: tuple[float, ...]) -> np.ndarray:
    """Polynomial coefficients of a machine motion f(q) = value0 + Σ d_k q^k/k! and its
    first two derivatives (the modified roll, helical and vertical motions of seed Eq. 2.4).

    Parameters
    ----------
    value0 : float
        f(0), in the motion's unit (rad, or mm for the helical and vertical motions).
    derivatives : tuple of float, length deg
        d_k = f^(k)(0) per unit cradle angle^k (k = 1…deg).

    Returns
    -------
    ndarray, shape (deg + 1, 3)
        Rows: powers q^0…q^deg; columns: the coefficients of f, f', f''. Read-only and
        memoised (the machine's solvers evaluate the same motions thousands of times per
        analysis), so the caller must not modify it.

    Source: the Taylor form of the modified roll, seed Eq. 2.4a (:func:`taylor_motion`).
    """
    deg = len(derivatives)
    coef = [[0.0, 0.0, 0.0] for _ in range(deg + 1)]
    coef[0][0] = value0
    for k, dk in enumerate(derivatives, start=1):
        coef[k][0] = dk / math.factorial(k)
        coef[k - 1][1] = dk / math.factorial(k - 1)
        if k >= 2:
            coef[k - 2][2] = dk / math.factorial(k - 2)
    out = np.array(coef)
    out.flags.writeable = False
    return out


def roll_angle(settings: MachineSettings, q):
    """Work rotation φ(q) and its derivatives (seed Eq. 2.4a with modified roll).

    Parameters
    ----------
    settings : MachineSettings
    q : array_like — [rad]
        Cradle rotation from the reference position.

    Returns
    -------
    phi, dphi, d2phi : ndarray — [rad], [1], [1/rad]
        φ = R_a (q − C q² − D q³ − E q⁴ − F q⁵) for Generate (Litvin & Fuentes 2004,
        §22 "modified roll"), 0 for Formate.
    """
    return PROCESSES[settings.process](settings, np.asarray(q, dtype=float))


def indexing_ratio(blade_groups: int, teeth: int) -> float:
    """Face-hobbing indexing ratio κ = −z0/z of a member (seed Eq. 2.1, 2.4b).

    Parameters
    ----------
    blade_groups : int
        z0, number of blade groups of the cutter head (seed N_t), in [1, 50]; 0 means face
        milling (κ = 0).
    teeth : int
        z, number of teeth of the member being cut, in [3, 500].

    Returns
    -------
    float — [1]
        κ: work rotation per radian of cutter spin measured on the cutter spindle (relative
        to the cradle), negative in this toolkit's frames: the head and the generating gear
        turn in opposite senses, like two external gears (``docs/machine.md``).

    Raises
    ------
    InputError
        ``blade_groups`` not an integer in [0, 50], or sharing a common factor with
        ``teeth``: then every slot is cut by only some of the blade groups (the blade-group
        runout prints as a spacing error repeating every z/gcd teeth) and the cutter and
        the member do not hunt.
    """
    z0 = integer("blade_groups", blade_groups, 0, 50, allow_float=True)
    z = integer("teeth", teeth, 3, 500, allow_float=True)
    if z0 == 0:
        return 0.0
    g = math.gcd(z0, z)
    if g != 1:
        raise InputError(
            f"blade_groups: must share no common factor with the member's teeth (z = {z}) so "
            f"that every blade group cuts every slot, got {z0} (common factor {g})")
    return -z0 / z


def work_rotation(settings: MachineSettings, q, theta=0.0):
    """Work rotation φ(q, θ) = φ_roll(q) + κ θ and its q-derivatives (seed Eq. 2.4).

    Parameters
    ----------
    settings : MachineSettings
    q : array_like — [rad]
        Cradle rotation (ignored, i.e. 0, for Formate).
    theta : array_like — [rad]
        Cutter spin on the cutter spindle (broadcast with q).

    Returns
    -------
    phi, dphi, d2phi : ndarray — [rad], [1], [1/rad]
        φ and its first and second derivatives with respect to q (∂φ/∂θ = κ,
        ``settings.indexing_ratio``).
    """
    q, theta = np.broadcast_arrays(np.asarray(q, dtype=float), np.asarray(theta, dtype=float))
    if settings.process == "Formate":
        q = np.zeros_like(q)
    phi, d1, d2 = roll_angle(settings, q)
    return phi + settings.indexing_ratio * theta, d1, d2


def rot(axis: str, angle) -> np.ndarray:
    a = np.asarray(angle, dtype=float)
    c, s = np.cos(a), np.sin(a)
    m = np.zeros((*a.shape, 4, 4))
    m[..., 3, 3] = 1.0
    i, j = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[axis]
    k = 3 - i - j
    m[..., k, k] = 1.0
    m[..., i, i] = c
    m[..., j, j] = c
    m[..., i, j] = -s
    m[..., j, i] = s
    return m


def _rot_z_derivs(angle, d1, d2):
    """R_z(a(q)) and its first two q-derivatives given a, a', a''."""
    a = np.asarray(angle, dtype=float)
    c, s = np.cos(a), np.sin(a)
    m = rot("z", a)
    dm = np.zeros_like(m)
    dm[..., 0, 0] = -s * d1
    dm[..., 0, 1] = -c * d1
    dm[..., 1, 0] = c * d1
    dm[..., 1, 1] = -s * d1
    d2m = np.zeros_like(m)
    d2m[..., 0, 0] = -s * d2 - c * d1**2
    d2m[..., 0, 1] = -c * d2 + s * d1**2
    d2m[..., 1, 0] = c * d2 - s * d1**2
    d2m[..., 1, 1] = -s * d2 - c * d1**2
    return m, dm, d2m


def trans(t) -> np.ndarray:
    t = np.asarray(t, dtype=float)
    m = np.zeros((*t.shape[:-1], 4, 4))
    m[..., 0, 0] = m[..., 1, 1] = m[..., 2, 2] = m[..., 3, 3] = 1.0
    m[..., :3, 3] = t
    return m


def _trans_only(t) -> np.ndarray:
    t = np.asarray(t, dtype=float)
    m = np.zeros((*t.shape[:-1], 4, 4))
    m[..., :3, 3] = t
    return m


def machine_transform(settings: MachineSettings, q, theta=0.0):
    """Homogeneous transform from the cutter frame to the blank frame, with q-derivatives.

    Parameters
    ----------
    settings : MachineSettings
    q : array_like — [rad]
        Cradle rotation from the reference position (ignored, i.e. 0, for Formate).
    theta : array_like — [rad]
        Cutter spin (broadcast with q); it turns the work by κθ in face hobbing
        (:func:`work_rotation`) and leaves a face-milling transform unchanged. The spin's
        own rotation R_z(θ) of the cutter is not included.

    Returns
    -------
    M, dM, d2M : ndarray, shape broadcast(q, θ) + (4, 4)
        M(q, θ) = R_z(−φ) T(0,0,−X_p) R_y(γ_m − π/2) T(0,−E_m,X_b) R_z(q_c+q) T(S_r,0,0)
        R_z(j) R_x(i), φ = φ_roll(q) + κθ, and its first and second derivatives with
        respect to q [per rad].

    Notes
    -----
    Seed Eq. 2.7a–e, order of the factors as read in ``seed/NOTES.md``; the signs and the
    frame orientations are this toolkit's convention (module docstring and
    ``docs/machine.md``), proven by the envelope tests rather than matched to a formula.
    """
    q, theta = np.broadcast_arrays(np.asarray(q, dtype=float), np.asarray(theta, dtype=float))
    if settings.process == "Formate":
        q = np.zeros_like(q)
    phi, dphi, d2phi = work_rotation(settings, q, theta)
    xb, dxb, d2xb = taylor_motion(settings.sliding_base, settings.helical_motion, q)
    em, dem, d2em = taylor_motion(settings.blank_offset, settings.vertical_motion, q)
    # factors depending on q: F1 = R_z(-phi), F3 = T(0, -Em, Xb), F4 = R_z(qc + q)
    f1 = _rot_z_derivs(-phi, -dphi, -d2phi)
    zero = np.zeros_like(q)
    f3 = (trans(np.stack([zero, -em, xb], -1)), _trans_only(np.stack([zero, -dem, dxb], -1)),
          _trans_only(np.stack([zero, -d2em, d2xb], -1)))
    one = np.ones_like(q)
    f4 = _rot_z_derivs(settings.cradle_angle + q, one, zero)
    # constant factors
    f2 = trans([0.0, 0.0, -settings.machine_center_to_back]) @ rot(
        "y", settings.machine_root_angle - 0.5 * math.pi)
    f5 = (trans([settings.radial_setting, 0.0, 0.0]) @ rot("z", settings.swivel)
          @ rot("x", settings.tilt))
    m, dm, d2m = f1
    m, dm, d2m = m @ f2, dm @ f2, d2m @ f2
    for g, dg, d2g in (f3, f4):
        m, dm, d2m = m @ g, dm @ g + m @ dg, d2m @ g + 2.0 * (dm @ dg) + m @ d2g
    return m @ f5, dm @ f5, d2m @ f5


def mirror_settings(settings: MachineSettings) -> MachineSettings:
    """Settings that generate the mirror image (y_g → −y_g) of the member: the other hand.

    Parameters
    ----------
    settings : MachineSettings

    Returns
    -------
    MachineSettings
        q_c, j, i, E_m negated; even-order modified-roll terms (2C, 24E), odd-order helical
        terms (H1, H3, …) and even-order vertical terms (V2, V4, …) negated.

    Notes
    -----
    With D = diag(1, −1, 1), D R_z(a) D = R_z(−a), D R_x(a) D = R_x(−a), D R_y(a) D = R_y(a)
    and D T(x, y, z) D = T(x, −y, z); conjugating the chain of :func:`machine_transform` by D
    and substituting q → −q gives these rules (the cutter surface of revolution is its own
    mirror image, θ → −θ).
    """
    def flip(seq, even_flips: bool):
        # seq[k-1] is the k-th derivative; flip where (k even) == even_flips
        return tuple(-v if ((k % 2 == 0) == even_flips) else v
                     for k, v in enumerate(seq, start=1))

    return replace(
        settings, cradle_angle=-settings.cradle_angle, swivel=-settings.swivel,
        tilt=-settings.tilt, blank_offset=-settings.blank_offset,
        # modified_roll[0] is 2C, the k = 2 coefficient: index offset by one
        modified_roll=tuple(-v if k % 2 == 0 else v
                            for k, v in enumerate(settings.modified_roll, start=2)),
        helical_motion=flip(settings.helical_motion, even_flips=False),
        vertical_motion=flip(settings.vertical_motion, even_flips=True))


def cutter_pose(settings: MachineSettings, q=0.0, theta=0.0):
    """Cutter tip-plane centre and cutter axis (towards the tips) in the blank frame.

    Parameters
    ----------
    settings : MachineSettings
    q : float or array_like — [rad]
    theta : float or array_like — [rad]
        Cutter spin; moves the pose only in face hobbing (the work indexes by κθ).

    Returns
    -------
    centre : ndarray (..., 3) — [mm]
    axis : ndarray (..., 3) — [1]
    """
    m, _, _ = machine_transform(settings, q, theta)
    return m[..., :3, 3], m[..., :3, 2]


def cradle_pose(settings: MachineSettings, q=0.0,
                theta=0.0) -> tuple[np.ndarray, np.ndarray]:
    """A point of the cradle axis and its direction (towards the work) in the blank frame.

    Parameters
    ----------
    settings : MachineSettings
        Machine settings (face milling or face hobbing).
    q : float — [rad]
        Cradle rotation from the reference position: the blank frame turns with the
        work's roll φ(q) (0 for Formate).
    theta : float — [rad]
        Cutter spin: in face hobbing the work also indexes by κθ, which turns the blank
        frame about the work axis (and with it the cradle axis's image where the machine
        root angle is not 90°); no effect in face milling (κ = 0). Default 0.

    Returns
    -------
    point : ndarray (3,) — [mm]
        The machine centre O_m's image: the cradle axis's point level with the sliding base.
    axis : ndarray (3,) — [1]
        Unit direction z_m of the cradle axis, from the cradle towards the work.

    Notes
    -----
    The first four factors of :func:`machine_transform` (seed Eq. 2.7a–e), R_z(−φ)
    T(0,0,−X_p) R_y(γ_m − π/2) T(0,−E_m,X_b): the frame the cradle turns in (the inverse
    of :func:`settings_from_poses`' cradle pose; tested against it).
    """
    if settings.process == "Formate":
        q = 0.0
    phi = float(work_rotation(settings, np.asarray(float(q)), float(theta))[0])
    xb = float(taylor_motion(settings.sliding_base, settings.helical_motion, float(q))[0])
    em = float(taylor_motion(settings.blank_offset, settings.vertical_motion, float(q))[0])
    m = (rot("z", -phi) @ trans([0.0, 0.0, -settings.machine_center_to_back])
         @ rot("y", settings.machine_root_angle - 0.5 * math.pi) @ trans([0.0, -em, xb]))
    return m[:3, 3].copy(), m[:3, 2].copy()


class PoseSettings(NamedTuple):
    """Result of :func:`settings_from_poses`."""

    settings: MachineSettings
    blank_phase: float  # [rad] rotation about z_g from the generated frame to the given frame


def settings_from_poses(*, cradle_point, cradle_axis, cutter_centre, cutter_axis,
                        process: str, ratio_of_roll: float = 0.0) -> PoseSettings:
    """Inverse kinematics: the settings that realise given cutter and cradle poses.

    All inputs are expressed in the (right-hand reference) blank frame at q = 0.

    Parameters
    ----------
    cradle_point : array_like (3,) — [mm]
        Any point on the cradle axis.
    cradle_axis : array_like (3,) — [1]
        Direction of the cradle axis, from the cradle towards the work (z_m).
    cutter_centre : array_like (3,) — [mm]
        Centre of the cutter's tip plane.
    cutter_axis : array_like (3,) — [1]
        Cutter axis from the cutter body towards the tips (z_t).
    process : str
    ratio_of_roll : float — [1]

    Returns
    -------
    PoseSettings
        ``settings`` and ``blank_phase`` [rad]: the machine places the blank with y_g = y_m,
        so the member it generates is the given one turned about z_g by −blank_phase; a
        point p of the generated member lies at R_z(blank_phase) p in the given frame.

    Raises
    ------
    InputError
        If the work axis is parallel to the cradle axis (no machine root angle exists).

    Notes
    -----
    Inverts :func:`machine_transform` at q = 0: O_m is the point of the cradle axis level with
    the cutter centre; x_m is the projection of the work axis on the cradle plane. Then
    γ_m = atan2(a·z_m, a·x_m), E_m = o·y_m, X_p = (o·x_m)/cos γ_m and
    X_b = X_p sin γ_m − o·z_m with o the crossing point relative to O_m; S_r, q_c from the
    cutter centre; i = arccos(z_t·z_m), q_c + j = atan2(z_t·x_m, −z_t·y_m).
    """
    zm = np.asarray(cradle_axis, dtype=float)
    zm = zm / np.linalg.norm(zm)
    c = np.asarray(cutter_centre, dtype=float)
    p0 = np.asarray(cradle_point, dtype=float)
    om = p0 + np.dot(c - p0, zm) * zm
    a = np.array([0.0, 0.0, 1.0])  # member axis in its own frame
    a_perp = a - np.dot(a, zm) * zm
    if np.linalg.norm(a_perp) < 1e-12:
        raise InputError("cradle_axis: parallel to the work axis; no machine root angle exists")
    xm = a_perp / np.linalg.norm(a_perp)
    ym = np.cross(zm, xm)
    gamma = math.atan2(float(np.dot(a, zm)), float(np.dot(a, xm)))
    o = -om  # crossing point (blank origin) relative to the machine centre
    em = float(np.dot(o, ym))
    xp = float(np.dot(o, xm)) / math.cos(gamma)
    xb = xp * math.sin(gamma) - float(np.dot(o, zm))
    cm = np.array([np.dot(c - om, xm), np.dot(c - om, ym)])
    sr = float(np.hypot(*cm))
    qc = math.atan2(cm[1], cm[0]) if sr > 0 else 0.0
    u = np.asarray(cutter_axis, dtype=float)
    u = u / np.linalg.norm(u)
    u_m = np.array([np.dot(u, xm), np.dot(u, ym), np.dot(u, zm)])
    tilt = math.acos(max(-1.0, min(1.0, u_m[2])))
    if math.sin(tilt) > 1e-14:
        swivel = math.atan2(u_m[0], -u_m[1]) - qc
        swivel = math.atan2(math.sin(swivel), math.cos(swivel))
    else:
        swivel = 0.0
    settings = MachineSettings(
        process=process, radial_setting=sr, cradle_angle=qc, swivel=swivel, tilt=tilt,
        machine_root_angle=gamma, machine_center_to_back=xp, sliding_base=xb,
        blank_offset=em, ratio_of_roll=ratio_of_roll)
    x_chain = np.cross(ym, a)
    return PoseSettings(settings, math.atan2(float(x_chain[1]), float(x_chain[0])))
