"""The friction study on Dask: the mixed-EHL solver over a design of contact conditions.

:func:`run_friction_study` solves every point of a design
(:mod:`friction.study.design`: Table 5.1's factorial grid or a space-filling sample) with
:func:`friction.study.points.solve_design_point` on the study engine
(:func:`contact.study.engine.run_tasks`: a LocalCluster by default, ``"synchronous"`` in
this process, or any scheduler address), streams the finished points to
``OUTPUT.parts/`` (:class:`contact.study.store.ResultStore`) and resumes a killed study
with the same output and design. A point the solver does not converge on is a row with
``status`` ``not_converged`` and its ``reason``, never a result. The dataset carries its
provenance: toolkit version and commit, the design (method, seed, size), the solver
settings (nodes …), the wall time and how many points were resumed.

Public functions
----------------
run_friction_study   solve a design on Dask; one dataset over ``point``
study_provenance     the provenance attributes of a study file
"""

from __future__ import annotations

import hashlib
import json
import logging
import os
import subprocess
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from contact.study.store import ChunkSpec, ResultStore
from friction.study.design import DESIGN_INPUTS, check_design
from friction.study.points import (
    POINT_STATUS,
    RESULT_VARIABLES,
    PointOutcome,
    SolveSettings,
    solve_design_point,
)
from geometry import __version__
from geometry.core.conventions import data_var
from geometry.core.errors import InputError

__all__ = ["run_friction_study", "study_provenance"]

log = logging.getLogger(__name__)


def _commit() -> str:
    """The toolkit's git commit (with '-dirty' for local changes), or 'unknown'."""
    root = Path(__file__).resolve().parents[2]
    try:
        out = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True,
                             text=True, timeout=10, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--",
                                "friction"], capture_output=True, text=True, timeout=10,
                               check=True).stdout.strip()
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return out + ("-dirty" if dirty else "")


def study_provenance(settings: SolveSettings, design_attrs: Mapping[str, Any]) -> dict[str, Any]:
    """Provenance attributes of a friction-study file.

    Parameters
    ----------
    settings : SolveSettings
        The solver settings every point shared.
    design_attrs : mapping
        How the design was made (e.g. ``{"design": "sobol", "seed": 2009, "n": 128}``).

    Returns
    -------
    dict
        ``toolkit_version``, ``solver_commit`` (git HEAD, ``-dirty`` if ``friction/`` has
        local changes, or 'unknown'), ``solver`` (the function), ``solver_*`` settings,
        ``design_*``.
    """
    attrs: dict[str, Any] = {
        "toolkit_version": __version__,
        "solver_commit": _commit(),
        "solver": _SOLVER_TEXT.format(
            viscosity=settings.viscosity_model.capitalize(),
            thermal="flash temperature" if settings.thermal else "isothermal"),
    }
    for k, v in settings.as_dict().items():
        attrs[f"solver_{k}"] = json.dumps(v) if isinstance(v, list) else v
    for k, v in design_attrs.items():
        attrs[f"design_{k}"] = v
    return attrs


#: the ``solver`` attribute of a study file (the stochastic solver, the study's only mode
#: since issue 61; stored studies of issue 34 name the resolved transient one)
_SOLVER_TEXT = ("friction.ehl.stochastic.stochastic_summary (steady, statistical roughness: "
                "average-flow Reynolds, elastic-plastic GW summits; {viscosity}, "
                "Dowson-Higginson, Eyring + limiting shear at the {thermal}, boundary mu_b "
                "on the asperity pressure)")


def _point_dataset(index: int, point: Mapping[str, float], res: PointOutcome) -> xr.Dataset:
    data: dict[str, Any] = {
        k: data_var(("point",), np.array([res.values[k]]), units, long_name)
        for k, (units, long_name) in RESULT_VARIABLES.items()}
    data["status"] = data_var(("point",), np.array([res.status], np.int8), "1",
                              "outcome of the solver call",
                              flag_values=np.arange(len(POINT_STATUS), dtype=np.int8),
                              flag_meanings=" ".join(POINT_STATUS))
    data["reason"] = data_var(("point",), np.array([res.reason], dtype=object), None,
                              "why the point failed (empty when it did not)")
    coords: dict[str, Any] = {"point": ("point", np.array([index]),
                                        {"units": "1", "long_name": "design point index"})}
    for name, (units, long_name) in DESIGN_INPUTS.items():
        coords[name] = ("point", np.array([float(point[name])]),
                        {"units": units, "long_name": long_name})
    return xr.Dataset(data, coords=coords)


#: result scalars set at every converged point (``status`` 0): NaN there is a damaged
#: chunk, never a result. Not ``pressure_max``: a smooth point's steady film reports
#: none, so it is NaN at converged smooth points
_FINITE_WHEN_CONVERGED = tuple(k for k in RESULT_VARIABLES if k != "pressure_max")


def run_friction_study(
    design: Mapping[str, Any],
    settings: SolveSettings | None = None,
    *,
    design_attrs: Mapping[str, Any] | None = None,
    output: str | os.PathLike[str] | None = None,
    scheduler: Any = None,
    n_workers: int | None = None,
    progress: bool | str = False,
    chunk_size: int = 8,
) -> xr.Dataset:
    """Solve every point of a friction-study design on Dask; one dataset over ``point``.

    Parameters
    ----------
    design : mapping of str to array (n,)
        :data:`friction.study.design.DESIGN_INPUTS` (MPa, mm, m/s, 1, degC, µm).
    settings : SolveSettings, optional
        Solver grid and oil (default ``SolveSettings()``: the stochastic solver, 512 nodes,
        75W90).
    design_attrs : mapping, optional
        How the design was made, stored as ``design_*`` attributes.
    output : path-like, optional
        Stream finished points to ``OUTPUT.parts/`` (the directory must exist); a study
        started again with the same output, design and settings computes only the missing
        points. The final file is written by the caller (``geometry.core.io.write_netcdf``,
        then ``ResultStore.remove_parts``) — the command ``ltca friction-study`` does both.
        A chunk of the parts that is not this study's (unreadable, other variables or
        inputs, NaN results at a converged point) is named in a warning, moved to
        ``OUTPUT.parts/set-aside/`` and its points solved again.
    scheduler, n_workers
        Where to run (:func:`contact.study.engine.open_client`): None a LocalCluster of
        ``n_workers`` processes, ``"synchronous"`` this process, an address a cluster.
    progress : bool or {"lines"}
        A tqdm bar (True) or plain periodic lines (``"lines"``,
        :mod:`geometry.core.progress`).
    chunk_size : int
        Points per chunk file.

    Returns
    -------
    xarray.Dataset
        dim ``point``; the inputs as coordinates; :data:`friction.study.points.
        RESULT_VARIABLES`, ``status`` (flag: converged, not_converged, input_refused) and
        ``reason``; attributes of :func:`study_provenance` plus ``wall_time`` [s] of this
        run, ``points_resumed`` and ``points_converged``.

    Raises
    ------
    InputError
        A bad design (named input), parts of another study at ``OUTPUT.parts``, a missing
        output directory, a bad scheduler or worker count, points missing from the parts
        after the run (a chunk set aside meanwhile: the study started again solves them).
    """
    from contact.study.engine import stream_tasks

    t0 = time.perf_counter()
    settings = settings or SolveSettings()
    if not isinstance(settings, SolveSettings):
        raise InputError(f"settings: must be a friction.study.points.SolveSettings, got "
                         f"{type(settings).__name__}")
    pts = check_design(design, lubricant=settings.lubricant)  # the oil and its temperatures
    n = next(iter(pts.values())).size
    points = [{k: float(pts[k][i]) for k in DESIGN_INPUTS} for i in range(n)]
    provenance = study_provenance(settings, dict(design_attrs or {}))  # the code that runs
    store = None
    done: set[int] = set()
    if output is not None:
        out = Path(output)
        if not out.parent.is_dir():
            raise InputError(f"output: directory {str(out.parent)!r} does not exist")
        rows = json.dumps([[p[k] for k in DESIGN_INPUTS] for p in points])
        manifest = {"kind": "friction_study", "settings": settings.as_dict(),
                    "design": hashlib.sha256(rows.encode()).hexdigest(), "points": n}
        spec = ChunkSpec(points=n, variables=(*RESULT_VARIABLES, "status", "reason"),
                         finite=_FINITE_WHEN_CONVERGED,
                         coords={k: np.array([p[k] for p in points]) for k in DESIGN_INPUTS})
        store = ResultStore(out, manifest, chunk_size=chunk_size, spec=spec)
        done = store.done()
        if done:
            log.info("resuming %s: %d of %d points already solved", out, len(done), n)
    todo = [(i, points[i]) for i in range(n) if i not in done]
    kept = stream_tasks(solve_design_point, settings, todo,
                        lambda res: _point_dataset(res.index, points[res.index], res),
                        store=store, progress=progress, desc="friction study", unit="point",
                        total=n, initial=len(done), scheduler=scheduler, n_workers=n_workers)
    ds = store.combined() if store is not None else xr.concat(kept, dim="point")
    ds = ds.isel(point=np.argsort(ds["point"].values, kind="stable"))
    if ds.sizes["point"] != n:
        raise InputError(f"output: {ds.sizes['point']} of {n} points after the run (a "
                         "chunk of the parts failed its check, see the warning); start the "
                         "study again to solve the missing points")
    ds["reason"] = ds["reason"].astype(str)
    ds.attrs = {
        "title": "hypoid-ltca friction study: mixed-EHL line contacts over a design "
                 "(seed section 5.2.3, Table 5.1)",
        **provenance,
        "wall_time": float(time.perf_counter() - t0),
        "wall_time_units": "s",
        "points_resumed": len(done),
        "points_converged": int(np.count_nonzero(ds["status"].values == 0)),
    }
    return ds
