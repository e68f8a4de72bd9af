"""The mesh interface of a loaded analysis for dynamic models of the gear pair.

Lumped-parameter and multibody models of hypoid drives (Cheng & Lim 2001; commercial
harmonic analyses) replace the mesh by one spring along one line: at each pinion roll
position and torque they need the *effective mesh point*, the *line of action*, the
*effective mesh stiffness* along it and the *transmission-error excitation*. This module
reduces the LTCA's segment forces to them.

At one (torque, roll) the N loaded segments carry forces F_i [N] along the unit contact
normals n_i (out of the pinion, pair frame) at the points r_i [mm], with the moment arms
R_i [mm] about the gear axis the contact problem used (so Σ F_i R_i = T_g, the gear
torque, to the solver's certified residual; seed Eq. 3.14). Then:

* **line of action** l = Σ F_i n_i / |Σ F_i n_i| [1], the direction of the resultant;
  the **mesh force** W = |Σ F_i n_i| [N];
* **load centre** c = Σ F_i r_i / Σ F_i [mm], the load-weighted centre of the contact;
* **mesh point** p [mm]: the point of the line through c along l moved, at right angles
  to l and to the gear axis a_g, by s = (T_g − ((c − o_g) × W l)·a_g) / |W l × a_g| —
  the line parallel to l nearest to c on which the force W l has exactly the gear
  torque's moment about the gear axis. Where every normal is the same (loads on one
  line of action, or one contact line), s = 0 and p = c.
* **rotation radii** λ_g = ((p − o_g) × l)·a_g and λ_p = ((p − o_p) × l)·a_p [mm]
  (Cheng & Lim's directional rotation radii; W λ_g = T_g, W λ_p ≈ −T_p: the pinion's
  torque is opposite about its axis as stored, and equal to T_g/ratio to the
  discretisation's conjugacy);
* **torsional mesh stiffness** k_Θ = dT_g/dΘ [N·mm/rad], the contact compliance
  condensed to the rotation: with the active set A of the final (Newton-linearised,
  Weber-tangent) problem, C_AA dF_A = R_A dΘ and R_Aᵀ dF_A = dT_g give
  k_Θ = R_Aᵀ C_AA⁻¹ R_A. The **mesh stiffness** along the line of action is
  k_m = k_Θ / λ_g² [N/µm after the unit change]: a displacement δ = λ_g Θ along l
  carries dW = dT_g/λ_g;
* **transmission-error excitation** e = λ_g · LTE [µm] (the LTE as a displacement along
  the line of action) and its mesh harmonics (peak amplitude, phase) over the mesh
  cycles, and those of k_m.

Public functions
----------------
mesh_interface          the ``/mesh_interface`` dataset of an analysis
condensed_stiffness     k_Θ of one contact problem and its solution
effective_mesh          mesh point, line of action, force and radii of one force system
MESH_INTERFACE_COLUMNS  the columns of the CSV export (name, unit, meaning)
mesh_interface_table    the CSV rows of a ``/mesh_interface`` dataset
write_mesh_interface_csv  the documented CSV export

References
----------
Y. Cheng, T. C. Lim (2001). Vibration analysis of hypoid transmissions applying an exact
geometry-based gear mesh theory. *J. Sound Vib.* 240(3), 519–543.
Seed (Kolivand 2009) Eq. 3.12–3.14 (the contact problem whose solution is condensed).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import scipy.fft
import scipy.linalg
import xarray as xr

from contact.ltca.roll_loop import RollProblem
from contact.qp import ContactProblem, ContactSolution
from geometry.core.conventions import coords_along, data_var, dataset
from geometry.core.errors import InputError

__all__ = [
    "MESH_INTERFACE_COLUMNS",
    "condensed_stiffness",
    "effective_mesh",
    "mesh_interface",
    "mesh_interface_table",
    "write_mesh_interface_csv",
]

#: mesh harmonics stored (fewer where the roll sampling resolves fewer)
N_HARMONICS = 5

#: the CSV export's columns, one row per (torque, roll): (column, unit, meaning)
MESH_INTERFACE_COLUMNS = (
    ("torque", "N m", "pinion torque T_p"),
    ("roll", "rad", "pinion roll angle from the transition M1 (driving sense)"),
    ("mesh_cycle", "1", "mesh cycles from the first roll position"),
    ("mesh_point_x", "mm", "effective mesh point p, pair frame (gear axis z, origin on it)"),
    ("mesh_point_y", "mm", "effective mesh point p, y"),
    ("mesh_point_z", "mm", "effective mesh point p, z"),
    ("line_of_action_x", "1", "unit line of action l (resultant direction, out of the "
                              "pinion), x"),
    ("line_of_action_y", "1", "line of action l, y"),
    ("line_of_action_z", "1", "line of action l, z"),
    ("mesh_force", "N", "mesh force W = |sum F_i n_i| along l"),
    ("mesh_stiffness", "N/um", "effective mesh stiffness along l, k_m = k_theta / lambda_g^2"),
    ("torsional_mesh_stiffness", "N m/rad", "condensed stiffness k_theta = dT_g/dTheta "
                                            "about the gear axis"),
    ("gear_rotation_radius", "mm", "directional rotation radius lambda_g = ((p - o_g) x l).a_g"),
    ("pinion_rotation_radius", "mm", "directional rotation radius lambda_p = "
                                     "((p - o_p) x l).a_p"),
    ("transmission_error", "urad", "loaded transmission error (gear lag)"),
    ("te_excitation", "um", "transmission error along l, e = lambda_g LTE"),
)


def effective_mesh(force: np.ndarray, point: np.ndarray, normal: np.ndarray,
                   moment_arm: np.ndarray, gear_axis: Sequence[float],
                   gear_origin: Sequence[float]) -> dict[str, np.ndarray | float]:
    """The effective mesh point, line of action and force of segment forces, per roll.

    Parameters
    ----------
    force : ndarray (..., N) — [N]
        Segment forces F_i (≥ 0; NaN or 0 where unloaded); leading dimensions (e.g.
        torque, roll) are force systems reduced each on its own.
    point : ndarray (..., N, 3) — [mm]
        Segment contact points r_i, pair frame.
    normal : ndarray (..., N, 3) — [1]
        Unit contact normals n_i (out of the pinion).
    moment_arm : ndarray (..., N) — [mm]
        Moment arms R_i about the gear axis of the contact problem (Σ F_i R_i = T_g): in
        the sense the torque loads the flank (the LTCA's, positive on either flank) or
        signed about a_g; the mesh point reproduces T_g in the forces' own sense about
        a_g (the sign of Σ F_i ((r_i − o_g) × n_i)·a_g: negative on the coast flank).
    gear_axis, gear_origin : sequence of 3 float — [1], [mm]
        The gear axis a_g (unit) and a point o_g on it.

    Returns
    -------
    dict
        ``mesh_point`` (..., 3) [mm], ``line_of_action`` (..., 3) [1], ``load_centre``
        (..., 3) [mm], ``mesh_force`` (...) [N], ``gear_torque`` Σ F_i R_i (...) [N·mm],
        ``gear_rotation_radius`` λ_g (...) [mm] (W λ_g = Σ F_i R_i); NaN where no segment
        is loaded; floats where the forces are one system (N,).

    Raises
    ------
    InputError
        Shapes that do not match, or a resultant parallel to the gear axis (no torque).

    Notes
    -----
    See the module docstring; after Cheng & Lim (2001), with the mesh point chosen on the
    resultant's line so that the gear torque is reproduced exactly.
    """
    F = np.nan_to_num(np.asarray(force, float))
    r = np.nan_to_num(np.asarray(point, float))
    n = np.nan_to_num(np.asarray(normal, float))
    R = np.nan_to_num(np.asarray(moment_arm, float))
    if F.ndim < 1 or r.shape != (*F.shape, 3) or n.shape != (*F.shape, 3) or R.shape != F.shape:
        raise InputError(f"force, point, normal, moment_arm: shapes (..., N), (..., N, 3), "
                         f"(..., N, 3), (..., N) expected, got {F.shape}, {r.shape}, "
                         f"{n.shape}, {R.shape}")
    a = np.asarray(gear_axis, float)
    o = np.asarray(gear_origin, float)
    F = np.where(F > 0, F, 0.0)
    total = F.sum(axis=-1)
    loaded = total > 0
    resultant = np.einsum("...i,...ij->...j", F, n)
    W = np.linalg.norm(resultant, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        lo = resultant / W[..., None]
        centre = np.einsum("...i,...ij->...j", F, r) / total[..., None]
        torque = np.einsum("...i,...i->...", F, R)
        # the arms are the contact problem's, in the sense the gear torque loads the flank
        # (positive on either flank); about the stored axis the forces' moment has its own
        # sign: opposite on the coast flank (-1 here), where the mesh point must reproduce
        # -T_g about a_g or it lands on the far side of the gear axis (issue 60)
        moment = np.einsum("...i,...i->...", F, np.cross(r - o, n) @ a)
        sense = np.where(moment * torque < 0, -1.0, 1.0)
        across = np.cross(resultant, a)
        reach = np.linalg.norm(across, axis=-1)
        if np.any(loaded & (reach <= 1e-12 * W)):
            raise InputError("force: the resultant of the contact forces is parallel to the "
                             "gear axis; it carries no torque")
        shift = (sense * torque - np.cross(centre - o, resultant) @ a) / reach
        p = centre + (shift / reach)[..., None] * across
        radius = sense * (np.cross(p - o, lo) @ a)
    out = {"mesh_point": p, "line_of_action": lo, "load_centre": centre, "mesh_force": W,
           "gear_torque": torque, "gear_rotation_radius": radius}
    for k, v in out.items():
        v = np.where(loaded[..., None] if v.ndim > loaded.ndim else loaded, v, np.nan)
        out[k] = float(v) if v.ndim == 0 else v
    return out


def condensed_stiffness(problem: ContactProblem, solution: ContactSolution) -> float:
    """[N·mm/rad] The torsional mesh stiffness dT_g/dΘ of one solved contact problem.

    Parameters
    ----------
    problem : contact.qp.ContactProblem
        The final problem of the roll: compliance C [mm/N] (with Weber's tangent
        compliance where the Newton iteration took it, :mod:`contact.ltca.weber`), moment
        arms R [mm].
    solution : contact.qp.ContactSolution
        Its certified solution; its active set A (forces > 0) is held.

    Returns
    -------
    float
        k_Θ = R_Aᵀ C_AA⁻¹ R_A (NaN where the solution is not certified or nothing is in
        contact).

    Notes
    -----
    Differentiating the active rows of the compatibility condition C F + s − R Θ = 0
    and the equilibrium Rᵀ F = T (seed Eq. 3.12–3.14) at a fixed active set:
    C_AA dF_A = R_A dΘ, R_Aᵀ dF_A = dT, hence dT/dΘ = R_Aᵀ C_AA⁻¹ R_A — the contact
    compliance condensed to the gear rotation. It is the tangent of the LTE–torque curve
    between changes of the active set (``tests/test_mesh_interface.py`` compares it with
    a central difference of the LTE between two nearby torques).
    """
    if solution is None or not solution.found:
        return math.nan
    active = solution.active_set
    if not active.any():
        return math.nan
    C = np.asarray(problem.compliance, float)[np.ix_(active, active)]
    R = np.asarray(problem.moment_arm, float)[active]
    # LAPACK's Cholesky and its solve as scipy.linalg.cho_factor / cho_solve call them
    # (the same numbers), without their checks of inputs the problem checked when it was
    # made (finite, square): a third of this function's time at every roll (issue 75)
    potrf, potrs = scipy.linalg.get_lapack_funcs(("potrf", "potrs"), (C,))
    c, info = potrf(C, lower=False, clean=False)
    if info == 0:
        x, info = potrs(c, R, lower=False)
    if info != 0:  # not positive definite on the active set (cho_factor's LinAlgError)
        x = np.linalg.lstsq(C, R, rcond=None)[0]
    return float(R @ x)


def _harmonics(values: np.ndarray, cycles: int, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Peak amplitudes and phases [rad] of mesh harmonics 1…n of samples (…, J) uniform over
    ``cycles`` whole mesh cycles (NaN where a sample is missing): y ≈ Σ A_k cos(2πkφ + φ_k),
    φ the mesh cycles from the first sample (scipy.fft.rfft; equals the least-squares
    Fourier fit of :func:`contact.ltca.transmission_error.mesh_harmonics`)."""
    J = values.shape[-1]
    spec = scipy.fft.rfft(values, axis=-1) * 2.0 / J
    bins = cycles * np.arange(1, n + 1)
    c = spec[..., bins]
    bad = ~np.all(np.isfinite(values), axis=-1)
    amp, phase = np.abs(c), np.angle(c)
    amp[bad] = np.nan
    phase[bad] = np.nan
    return amp, phase


def _nanmean(a: np.ndarray, axis: int, keepdims: bool = False) -> np.ndarray:
    """``np.nanmean`` that gives NaN for a slice of NaN alone silently (a torque
    none of whose rolls has a certified solution: the analysis says why, in its status)."""
    given = ~np.isnan(a)   # as np.nanmean: the same sums, so the same numbers
    n = given.sum(axis=axis, keepdims=keepdims)
    total = np.where(given, a, 0.0).sum(axis=axis, keepdims=keepdims)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(n > 0, total / np.maximum(n, 1), np.nan)


def mesh_interface(ltca: xr.Dataset, problems: Sequence[RollProblem]) -> xr.Dataset:
    """The ``/mesh_interface`` dataset of a loaded analysis (module docstring).

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset of :func:`contact.ltca.loaded_tca` (``force``,
        ``contact_point``, ``contact_normal``, ``moment_arm``, ``transmission_error``;
        attributes ``gear_axis``, ``gear_origin_mm``, ``pinion_axis``,
        ``pinion_origin_mm``, ``mesh_period_rad``, ``options``).
    problems : sequence of RollProblem
        The final problem and solution of every (torque, roll) of the same analysis
        (``loaded_tca(..., roll_problems=[])``).

    Returns
    -------
    xarray.Dataset
        Over (``torque``, ``roll``): ``mesh_point`` and ``load_centre`` (…, ``xyz``)
        [mm], ``line_of_action`` (…, ``xyz``) [1], ``mesh_force`` [N],
        ``torsional_mesh_stiffness`` [N·m/rad], ``mesh_stiffness`` [N/µm],
        ``gear_rotation_radius``, ``pinion_rotation_radius`` [mm],
        ``transmission_error`` [µrad], ``te_excitation`` [µm]; over (``torque``,
        ``harmonic``) the peak amplitude [µm], [N/µm] and phase [rad] of the excitation's
        and the stiffness's mesh harmonics; over ``torque`` their means.

    Raises
    ------
    InputError
        ``ltca`` lacks a variable or attribute named above, or ``problems`` does not
        cover its (torque, roll) grid.

    Notes
    -----
    Source: the mesh point, line of action, mesh stiffness and TE excitation of Cheng & Lim
    (2001) from the LTCA's certified forces (seed Eq. 3.12–3.14); module docstring.
    """
    need = ("force", "contact_point", "contact_normal", "moment_arm", "transmission_error")
    missing = [k for k in need if k not in ltca]
    missing += [k for k in ("gear_axis", "gear_origin_mm", "pinion_axis", "pinion_origin_mm",
                            "mesh_period_rad") if k not in ltca.attrs]
    if missing:
        raise InputError(f"ltca: not an /ltca dataset, lacks {', '.join(missing)}")
    torques = ltca.variables["torque"].values.astype(float)
    NT, J = ltca.sizes["torque"], ltca.sizes["roll"]
    index = {float(t): i for i, t in enumerate(torques)}
    k_theta = np.full((NT, J), np.nan)
    # rolls whole mesh cycles apart share their problem's arrays and their solution
    # (ContactProblem.renamed): condensed once
    done: dict[tuple[int, int, int], float] = {}
    for rp in problems:
        it = index.get(float(rp.torque))
        if it is None or not 0 <= rp.roll < J:
            raise InputError(f"problems: torque {rp.torque:g} N m, roll {rp.roll} is not "
                             "of this analysis")
        key = (id(rp.problem.compliance), id(rp.problem.moment_arm), id(rp.solution))
        if key not in done:
            done[key] = condensed_stiffness(rp.problem, rp.solution)
        k_theta[it, rp.roll] = done[key]
    ag, og = (np.asarray(ltca.attrs[k], float) for k in ("gear_axis", "gear_origin_mm"))
    ap, op = (np.asarray(ltca.attrs[k], float) for k in ("pinion_axis", "pinion_origin_mm"))
    force = ltca.variables["force"].values
    points = ltca.variables["contact_point"].values
    normals = ltca.variables["contact_normal"].values
    arms = ltca.variables["moment_arm"].values
    # every (torque, roll) reduced at once: a roll's segments flattened, its points,
    # normals and arms the same at every torque
    pts, nrm = points.reshape(J, -1, 3), normals.reshape(J, -1, 3)
    e = effective_mesh(force.reshape(NT, J, -1), np.broadcast_to(pts, (NT, *pts.shape)),
                       np.broadcast_to(nrm, (NT, *nrm.shape)),
                       np.broadcast_to(arms.reshape(J, -1), (NT, J, pts.shape[1])), ag, og)
    out3 = {k: e[k] for k in ("mesh_point", "line_of_action", "load_centre")}
    out1 = {k: e[k] for k in ("mesh_force", "gear_rotation_radius", "gear_torque")}
    lam_g = out1["gear_rotation_radius"]
    lam_p = np.einsum("trx,x->tr", np.cross(out3["mesh_point"] - op, out3["line_of_action"]),
                      ap)
    k_mesh = k_theta / lam_g**2 * 1e-3  # [N/mm] → [N/µm]
    lte = ltca.variables["transmission_error"].values.astype(float)
    excitation = lam_g * lte * 1e-3  # [mm]·[µrad] = 1e-6 mm → [µm]: ×1e-3
    opts = _options(ltca)
    cycles = int(opts.get("cycles", 1)) or 1
    n_h = max(1, min(N_HARMONICS, (J // cycles - 1) // 2))
    e_amp, e_phase = _harmonics(excitation - _nanmean(excitation, axis=1, keepdims=True),
                                cycles, n_h)
    k_amp, k_phase = _harmonics(k_mesh, cycles, n_h)
    tr = ("torque", "roll")
    th = ("torque", "harmonic")
    ds = dataset(
        {
            "mesh_point": data_var((*tr, "xyz"), out3["mesh_point"], "mm",
                                   "effective mesh point: on the resultant's line, nearest "
                                   "to the load centre, reproducing the gear torque (pair "
                                   "frame)"),
            "load_centre": data_var((*tr, "xyz"), out3["load_centre"], "mm",
                                    "load-weighted centre of the segment contact points "
                                    "(pair frame)"),
            "line_of_action": data_var((*tr, "xyz"), out3["line_of_action"], "1",
                                       "unit line of action: direction of the resultant of "
                                       "the segment forces (out of the pinion, pair frame)"),
            "mesh_force": data_var(tr, out1["mesh_force"], "N",
                                   "mesh force: magnitude of the resultant along the line "
                                   "of action"),
            "torsional_mesh_stiffness": data_var(
                tr, k_theta * 1e-3, "N m/rad",
                "torsional mesh stiffness dT_g/dTheta about the gear axis: the contact "
                "compliance condensed to the gear rotation on the active set"),
            "mesh_stiffness": data_var(tr, k_mesh, "N/um",
                                       "effective mesh stiffness along the line of action "
                                       "(torsional stiffness / gear rotation radius^2)"),
            "gear_rotation_radius": data_var(tr, lam_g, "mm",
                                             "directional rotation radius of the line of "
                                             "action about the gear axis"),
            "pinion_rotation_radius": data_var(tr, lam_p, "mm",
                                               "directional rotation radius of the line of "
                                               "action about the pinion axis (signed, about "
                                               "the stored pinion axis)"),
            "transmission_error": data_var(tr, lte, "urad",
                                           "loaded transmission error (gear lag)"),
            "te_excitation": data_var(tr, excitation, "um",
                                      "transmission-error excitation: the loaded "
                                      "transmission error as a displacement along the line "
                                      "of action"),
            "te_excitation_mean": data_var("torque", _nanmean(excitation, axis=1), "um",
                                           "mean of the transmission-error excitation"),
            "te_excitation_amplitude": data_var(th, e_amp, "um",
                                                "peak amplitude of the mesh harmonics of the "
                                                "transmission-error excitation"),
            "te_excitation_phase": data_var(th, e_phase, "rad",
                                            "phase of the mesh harmonics of the "
                                            "transmission-error excitation (cosine, from "
                                            "the first roll position)"),
            "mesh_stiffness_mean": data_var("torque", _nanmean(k_mesh, axis=1), "N/um",
                                            "mean effective mesh stiffness over the mesh "
                                            "cycles"),
            "mesh_stiffness_amplitude": data_var(th, k_amp, "N/um",
                                                 "peak amplitude of the mesh harmonics of "
                                                 "the effective mesh stiffness"),
            "mesh_stiffness_phase": data_var(th, k_phase, "rad",
                                             "phase of the mesh harmonics of the effective "
                                             "mesh stiffness (cosine, from the first roll "
                                             "position)"),
        },
        {  # (torque and roll with what they carry: gear_torque, mesh_cycle)
            **coords_along(ltca, ("torque", "roll", "xyz")),
            "harmonic": data_var("harmonic", np.arange(1, n_h + 1, dtype=np.int32), "1",
                                 "mesh harmonic order"),
        },
        {
            "title": "mesh interface for dynamic models",
            "case": ltca.attrs.get("case", ""),
            "gear_axis": ag, "gear_origin_mm": og, "pinion_axis": ap, "pinion_origin_mm": op,
            "mesh_period_rad": float(ltca.attrs["mesh_period_rad"]),
            "method": "segment forces of the LTCA reduced to one force on one line "
                      "(contact.ltca.mesh_interface; Cheng & Lim 2001); stiffness: the "
                      "contact compliance condensed to the gear rotation on the active set",
        },
    )
    return ds


def _options(ltca: xr.Dataset) -> dict:
    import json

    try:
        return json.loads(ltca.attrs.get("options", "{}"))
    except (TypeError, ValueError):
        return {}


def mesh_interface_table(ds: xr.Dataset) -> list[list[float]]:
    """The rows of the CSV export of a ``/mesh_interface`` dataset, one per (torque, roll),
    in the order and units of :data:`MESH_INTERFACE_COLUMNS`."""
    rows = []
    for it, t in enumerate(ds["torque"].values):
        for j, q in enumerate(ds["roll"].values):
            p = ds["mesh_point"].values[it, j]
            lo = ds["line_of_action"].values[it, j]
            rows.append([
                float(t), float(q), float(ds["mesh_cycle"].values[j]), *map(float, p),
                *map(float, lo), float(ds["mesh_force"].values[it, j]),
                float(ds["mesh_stiffness"].values[it, j]),
                float(ds["torsional_mesh_stiffness"].values[it, j]),
                float(ds["gear_rotation_radius"].values[it, j]),
                float(ds["pinion_rotation_radius"].values[it, j]),
                float(ds["transmission_error"].values[it, j]),
                float(ds["te_excitation"].values[it, j]),
            ])
    return rows


def write_mesh_interface_csv(ds: xr.Dataset, path, *, header: str = "") -> Path:
    """Write a ``/mesh_interface`` dataset as CSV, atomically.

    The file starts with comment lines (``#``) giving the case, the frame, and each
    column's unit and meaning (:data:`MESH_INTERFACE_COLUMNS`); then a header row of the
    column names with their units in brackets, e.g. ``mesh_stiffness [N/um]``; then one
    row per (torque, roll). ``pandas.read_csv(path, comment="#")`` and
    ``numpy.genfromtxt(path, delimiter=",", names=True)`` read it.

    Parameters
    ----------
    ds : xarray.Dataset
        From :func:`mesh_interface`.
    path : path-like
        The CSV file; its directory must exist.
    header : str
        Further comment text (e.g. the command that made the file), one line per line.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        The directory does not exist.
    """
    import csv
    import io

    from geometry.core.atomic_files import atomic_path

    target = Path(path)
    if not target.parent.is_dir():
        raise InputError(f"path: directory {str(target.parent)!r} does not exist")
    buf = io.StringIO()
    def vec(key: str) -> list[float]:
        return np.round(np.asarray(ds.attrs[key], float), 9).tolist()

    lines = [f"mesh interface of {ds.attrs.get('case', '')} for dynamic models "
             "(hypoid-ltca, contact.ltca.mesh_interface; docs/mesh_interface.md)",
             f"pair frame: gear axis a_g = {vec('gear_axis')} through o_g = "
             f"{vec('gear_origin_mm')} mm; pinion axis a_p = {vec('pinion_axis')} through "
             f"o_p = {vec('pinion_origin_mm')} mm",
             *[ln for ln in header.splitlines() if ln],
             "columns (name [unit]: meaning):",
             *[f"  {n} [{u}]: {m}" for n, u, m in MESH_INTERFACE_COLUMNS]]
    for ln in lines:
        buf.write(f"# {ln}\n")
    w = csv.writer(buf, lineterminator="\n")
    w.writerow([f"{n} [{u}]" for n, u, _ in MESH_INTERFACE_COLUMNS])
    for row in mesh_interface_table(ds):
        w.writerow([f"{v:.10g}" for v in row])
    with atomic_path(target) as tmp:
        tmp.write_text(buf.getvalue(), encoding="utf-8")
    return target
