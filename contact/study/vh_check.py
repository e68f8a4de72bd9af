"""The V-H check: offset and pinion mounting displacements that move the pattern to toe and heel.

The classic development check of a hypoid set (Gleason's V-H check; seed §2.5, Fig.
2.11 shows the same movements): displace the pinion along the offset direction (V, our
ΔE) and along its axis (H, our ΔP) until the loaded contact pattern reaches the toe and
the heel limits while staying at the same height on the flank. The V and H that do it
say how sensitive the design is to assembly and deflection: a robust set needs large
displacements, with the toe and heel positions about symmetric.

Here the pattern's centre on the gear flank (pressure-weighted, :func:`contact.study.
summary.point_summary`) is mapped over a V × H grid by a sweep on Dask, interpolated
(bilinear) and solved for the two targets with :func:`scipy.optimize.least_squares`;
the solutions are then checked by single analyses at the returned V and H.

Public functions
----------------
vh_check   V and H of the toe and heel positions, with the patterns drawn at each
"""

from __future__ import annotations

import logging
import os
from typing import Any

import numpy as np
import xarray as xr
from scipy.interpolate import RegularGridInterpolator
from scipy.optimize import least_squares

from contact.study.engine import run_points, write_study
from contact.study.grid import study_inputs
from contact.study.run import StudyRun, study_run
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.pair.assembly import Misalignment

__all__ = ["VH_DEFAULT_GRID", "VH_DEFAULT_LIMITS", "VH_DEFAULT_TORQUE", "default_vh_torque",
           "vh_check"]

log = logging.getLogger(__name__)

#: Pattern-centre targets of the check, as fractions of the face width from the toe:
#: (toe, heel). The toolkit's choice: the centre a quarter of the face width from each
#: end, where a pattern of about half the face width reaches the tooth end.
VH_DEFAULT_LIMITS = (0.25, 0.75)

#: Default V (ΔE) and H (ΔP) grid [mm]: 9 × 7 values over ±0.4 and ±0.3 mm.
VH_DEFAULT_GRID = (np.linspace(-0.4, 0.4, 9), np.linspace(-0.3, 0.3, 7))

#: Default pinion torque [N·m] of the check: the seed's light load (Table 3.1).
VH_DEFAULT_TORQUE = 50.0

POSITIONS = ("toe", "nominal", "heel")


def default_vh_torque(case: Case) -> float:
    """The pinion torque [N·m] of a V-H check of ``case`` where none is given: its first
    ``[operating]`` torque, else :data:`VH_DEFAULT_TORQUE`.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    float — [N·m]

    Notes
    -----
    The pattern of the check is the light-load pattern (Gleason's V-H check is made under a
    light test load); the case's first torque is its light load (the seed's Table 3.1
    50 N·m on the default case, the development's light torque on a synthesised case).
    ``ltca vh-check`` and :func:`vh_check` both take it (issue 71, branch api82: the API
    took 50 N·m whatever the case, e.g. seven times the 5×29's light torque of 7 N·m).
    """
    torques = tuple(case.operating.torque or ())
    return float(torques[0]) if torques else VH_DEFAULT_TORQUE


def _solve(cu: RegularGridInterpolator, cv: RegularGridInterpolator, target: np.ndarray,
           V: np.ndarray, H: np.ndarray, grid_cu: np.ndarray,
           grid_cv: np.ndarray) -> tuple[np.ndarray, float]:
    """(V, H) where the interpolated centre equals ``target`` (u, v); and the residual."""
    lo, hi = np.array([V[0], H[0]]), np.array([V[-1], H[-1]])
    scale = np.array([1.0, 1.0])

    def residual(x: np.ndarray) -> np.ndarray:
        r = np.array([cu(x)[0] - target[0], cv(x)[0] - target[1]]) * scale
        return np.where(np.isfinite(r), r, 10.0)

    miss = np.hypot(grid_cu - target[0], grid_cv - target[1])
    if not np.isfinite(miss).any():
        raise InputError("vh_check: no grid point has a loaded pattern")
    i, j = np.unravel_index(np.nanargmin(miss), miss.shape)
    sol = least_squares(residual, np.array([V[i], H[j]]), bounds=(lo, hi),
                        diff_step=1e-3, xtol=1e-10, ftol=1e-12)
    return sol.x, float(np.hypot(*residual(sol.x)))


def _cell_step(grid: np.ndarray, V: np.ndarray, H: np.ndarray, x: np.ndarray) -> float:
    """The largest change of ``grid`` between neighbouring nodes of the cell holding x:
    the resolution the grid gives the interpolated value there."""
    i = int(np.clip(np.searchsorted(V, x[0]) - 1, 0, V.size - 2))
    j = int(np.clip(np.searchsorted(H, x[1]) - 1, 0, H.size - 2))
    cell = grid[i:i + 2, j:j + 2]
    return float(np.nanmax(cell) - np.nanmin(cell)) if np.isfinite(cell).any() else np.nan


def vh_check(
    case: Case | str | os.PathLike[str] | None = None,
    *,
    torque: float | None = None,
    toe: float = VH_DEFAULT_LIMITS[0],
    heel: float = VH_DEFAULT_LIMITS[1],
    profile: float | None = None,
    delta_E: Any = None,
    delta_P: Any = None,
    run: StudyRun | None = None,
    **legacy: Any,
) -> xr.Dataset:
    """The V-H check of a case: V (ΔE) and H (ΔP) that move the loaded pattern to toe and heel.

    Parameters
    ----------
    case : Case, path, bundled name or None (the default case)
    torque : float — [N·m], optional
        Pinion torque of the loaded pattern; default the case's first ``[operating]``
        torque (its light load: 50 N·m on the default case, the development's light torque
        on a case ``ltca synthesize`` wrote), else :data:`VH_DEFAULT_TORQUE`
        (:func:`default_vh_torque`) — as ``ltca vh-check``.
    toe, heel : float — [1]
        Targets of the pattern centre, fractions of the face width from the toe, in
        (0, 1), toe < heel (default :data:`VH_DEFAULT_LIMITS`).
    profile : float — [1], optional
        Height the pattern centre keeps (fraction of the whole depth from the root);
        default the nominal assembly's.
    delta_E, delta_P : sequence — [mm], optional
        The V and H grid of the map (default :data:`VH_DEFAULT_GRID` about the nominal
        mounting); the solutions are sought inside it.
    run : contact.study.StudyRun, optional
        As :func:`contact.study.sweep` (``output``: the check's netCDF file; no efficiency
        stage runs, so ``run.operating`` must be None). The former run keywords likewise,
        deprecated.
    **legacy
        Those former run keywords (fields of :class:`StudyRun`), deprecated.

    Returns
    -------
    xarray.Dataset
        Over ``position`` (toe, nominal, heel): ``V`` = ΔE and ``H`` = ΔP [mm], the
        targets ``target_u``, ``target_v``, the centre ``pattern_centre_u``/``_v``
        found by the analysis at (V, H), ``grid_tolerance_u``/``_v`` (the change of the
        centre across the grid cell, the accuracy the grid allows) and
        ``pressure_envelope`` (position, u, v) [MPa], the loaded pattern drawn at each;
        over (``delta_E``, ``delta_P``) the mapped centres ``map_centre_u``/``_v``, the
        points' ``map_status`` and ``map_plausibility`` (the study's flags).
        Misalignments ΔG and ΔΣ keep the case's values.

    Raises
    ------
    InputError
        Bad targets or grid; a target the grid's patterns do not reach (the message
        gives the range they span).

    Notes
    -----
    The pattern centre is the pressure-weighted centre of the envelope of maximum
    pressure over the mesh cycles on the gear flank (seed §3.5). The nominal position is
    the case's own mounting, its ``[operating]`` ΔE, ΔP (the default case's are the seed's
    Table 3.1 values), as every other command takes them; V and H are absolute ΔE and ΔP.
    """
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis
    from contact.study.summary import point_summary

    run = study_run(run, legacy, "vh_check")
    if run.operating is not None:
        raise InputError("run.operating: the V-H check runs no efficiency stage; leave it None")
    options, flank = run.options, run.flank
    for name, x in (("toe", toe), ("heel", heel)):
        if not (isinstance(x, (int, float)) and 0.0 < x < 1.0):
            raise InputError(f"{name}: must be a face-width fraction in (0, 1), got {x!r}")
    if toe >= heel:
        raise InputError(f"toe, heel: need toe < heel, got {toe} and {heel}")
    from contact.catalogue import resolve_case

    resolved = resolve_case(case)
    base = resolved.misalignment  # the nominal mounting: the case's own
    torque = default_vh_torque(resolved) if torque is None else torque
    V = np.sort(np.asarray(VH_DEFAULT_GRID[0] + base.delta_E if delta_E is None else delta_E,
                           float))
    H = np.sort(np.asarray(VH_DEFAULT_GRID[1] + base.delta_P if delta_P is None else delta_P,
                           float))
    for name, g in (("delta_E", V), ("delta_P", H)):
        if g.ndim != 1 or g.size < 2 or not np.all(np.isfinite(g)) or np.any(np.diff(g) <= 0):
            raise InputError(f"{name}: the V-H grid needs >= 2 distinct finite values [mm], "
                             f"got {g.tolist()}")
    shared = study_inputs(case, torque, options=options, flank=flank)
    points = [{"delta_E": float(v), "delta_P": float(h)} for v in V for h in H]
    flat = run_points(shared, points, names=["delta_E", "delta_P"], scheduler=run.scheduler,
                      n_workers=run.n_workers, progress=run.progress, kind="V-H check map",
                      force=run.force)
    grid_cu = flat["pattern_centre_u"].values[:, 0].reshape(V.size, H.size)
    grid_cv = flat["pattern_centre_v"].values[:, 0].reshape(V.size, H.size)
    cu = RegularGridInterpolator((V, H), grid_cu, bounds_error=False, fill_value=np.nan)
    cv = RegularGridInterpolator((V, H), grid_cv, bounds_error=False, fill_value=np.nan)
    c = shared.case
    mis = c.misalignment
    nominal = run_analysis(c, [float(torque)], misalignment=Misalignment(
        delta_E=mis.delta_E, delta_P=mis.delta_P, delta_G=mis.delta_G,
        delta_Sigma=mis.delta_Sigma),
        flank=flank, options=shared.options, deviations=shared.deviations_at(None),
        theoretical=False, steps=AnalysisChain.contact_only().with_mesh_interface())
    nom = point_summary(nominal, c)
    v_target = float(nom["pattern_centre_v"][0]) if profile is None else float(profile)
    if not np.isfinite(v_target):
        raise InputError("profile: the nominal assembly has no loaded pattern; give the "
                         "height to keep")
    span = (np.nanmin(grid_cu), np.nanmax(grid_cu))
    for name, x in (("toe", toe), ("heel", heel)):
        if not span[0] <= x <= span[1]:
            raise InputError(
                f"{name}: the patterns of the V-H grid have centres in [{span[0]:.3f}, "
                f"{span[1]:.3f}] of the face width, not {x}; widen delta_E/delta_P")
    solutions = {}
    for name, x in (("toe", toe), ("heel", heel)):
        sol, res = _solve(cu, cv, np.array([x, v_target]), V, H, grid_cu, grid_cv)
        if res > 0.02:
            log.warning("vh_check: the %s target is met only to %.3f of the face width "
                        "within the grid", name, res)
        solutions[name] = sol
    solutions["nominal"] = np.array([mis.delta_E, mis.delta_P])
    envelopes, centres = [], []
    for pos in POSITIONS:
        V_, H_ = solutions[pos]
        tree = nominal if pos == "nominal" else run_analysis(
            c, [float(torque)], misalignment=Misalignment(delta_E=float(V_), delta_P=float(H_),
                                                       delta_G=mis.delta_G,
                                                       delta_Sigma=mis.delta_Sigma),
            flank=flank, options=shared.options, deviations=shared.deviations_at(None),
            theoretical=False,
            steps=AnalysisChain.analysis().without("geometry", "root_stress", "efficiency",
                                                   "load_capacity"))
        s = point_summary(tree, c)
        centres.append((float(s["pattern_centre_u"][0]), float(s["pattern_centre_v"][0])))
        envelopes.append(tree["/ltca"]["pressure_envelope"].values[0])
    ltca = nominal["/ltca"]
    tol_u = [_cell_step(grid_cu, V, H, solutions[p]) for p in POSITIONS]
    tol_v = [_cell_step(grid_cv, V, H, solutions[p]) for p in POSITIONS]
    pos = ("position",)
    ds = xr.Dataset(
        {
            "V": (pos, [solutions[p][0] for p in POSITIONS],
                  {"units": "mm", "long_name": "offset displacement V (delta_E)"}),
            "H": (pos, [solutions[p][1] for p in POSITIONS],
                  {"units": "mm", "long_name": "pinion mounting displacement H (delta_P)"}),
            "target_u": (pos, [toe, np.nan, heel],
                         {"units": "1", "long_name": "target pattern centre, fraction of "
                                                     "face width from the toe"}),
            "target_v": (pos, [v_target] * 3,
                         {"units": "1", "long_name": "target pattern centre, fraction of "
                                                     "the whole depth from the root"}),
            "pattern_centre_u": (pos, [x[0] for x in centres],
                                 {"units": "1", "long_name": "pattern centre found by the "
                                                             "analysis at (V, H), lengthwise"}),
            "pattern_centre_v": (pos, [x[1] for x in centres],
                                 {"units": "1", "long_name": "pattern centre found by the "
                                                             "analysis at (V, H), profile"}),
            "grid_tolerance_u": (pos, tol_u, {"units": "1", "long_name": "change of the "
                                              "lengthwise centre across the grid cell"}),
            "grid_tolerance_v": (pos, tol_v, {"units": "1", "long_name": "change of the "
                                              "profile centre across the grid cell"}),
            "pressure_envelope": (("position", "u", "v"), np.stack(envelopes),
                                  {"units": "MPa", "long_name": "loaded contact pattern: "
                                   "envelope of the maximum pressure over the roll positions"}),
            "map_centre_u": (("delta_E", "delta_P"), grid_cu,
                             {"units": "1", "long_name": "pattern centre over the V-H grid, "
                                                         "lengthwise"}),
            "map_centre_v": (("delta_E", "delta_P"), grid_cv,
                             {"units": "1", "long_name": "pattern centre over the V-H grid, "
                                                         "profile"}),
            "map_status": (("delta_E", "delta_P"),
                           flat["status"].values.reshape(V.size, H.size),
                           flat["status"].attrs),
            "map_plausibility": (("delta_E", "delta_P"),
                                 flat["plausibility"].values[:, 0].reshape(V.size, H.size),
                                 flat["plausibility"].attrs),
        },
        coords={
            "position": ("position", list(POSITIONS), {"long_name": "pattern position"}),
            "u": ltca["u"].variable, "v": ltca["v"].variable,
            "delta_E": ("delta_E", V, {"units": "mm", "long_name": "offset displacement V"}),
            "delta_P": ("delta_P", H, {"units": "mm",
                                       "long_name": "pinion mounting displacement H"}),
        },
        attrs={**flat.attrs, "title": f"V-H check of {c.name}", "study": "vh-check",
               "torque_N_m": float(torque)},
    )
    if run.output is not None:
        write_study(ds, run.output, shared)
    return ds
