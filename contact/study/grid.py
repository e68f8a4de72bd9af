"""Full-grid sweeps: misalignment maps and the like, over named dimensions.

Public functions
----------------
sweep         a full grid of study inputs × torques × speeds, on Dask
study_inputs  the shared inputs of a study of a case (resolving the case, deviations)
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Sequence
from typing import Any

import numpy as np
import xarray as xr

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions
from contact.pipeline import resolve_deviations
from contact.study.engine import run_points, write_study
from contact.study.points import POINT_INPUTS, StudyInputs
from contact.study.run import StudyRun, study_run
from friction.operating import OperatingConditions
from geometry.case import Case
from geometry.core.errors import InputError
from geometry.core.renamed import renamed_keywords
from geometry.core.validation import real_array

__all__ = ["DEFAULT_TORQUE", "study_inputs", "sweep"]

#: The studies' former default pinion torque [N·m] (the middle of the seed's Table 3.1
#: torques), kept for the scripts that name it: the default is now the case's
#: ``[operating]`` torques, as ``ltca sweep`` and ``ltca tolerance`` take them (api83).
DEFAULT_TORQUE = (250.0,)


def _values(name: str, values: Any, units: str) -> np.ndarray:
    """A swept input as a 1-D float array (a scalar is one value)."""
    arr = np.atleast_1d(real_array(name, values, unit=units))
    if arr.ndim != 1 or arr.size == 0:
        raise InputError(f"{name}: must be a number or a non-empty 1-D sequence [{units}], "
                         f"got shape {arr.shape}")
    if np.unique(arr).size != arr.size:
        raise InputError(f"{name}: values must be distinct [{units}], got {arr.tolist()}")
    return arr


def study_inputs(
    case: Case | str | os.PathLike[str] | None,
    torque: Any = None,
    speed: Any = None,
    *,
    operating: OperatingConditions | None = None,
    options: LTCAOptions | None = None,
    flank: str | None = None,
    deviations: bool = True,
    root_stress: Any = False,
) -> StudyInputs:
    """The inputs every point of a study of ``case`` shares.

    Parameters
    ----------
    case : Case, path, bundled name or None (the default case)
    torque : float or sequence — [N·m], optional
        Pinion torques (default the case's ``[operating]`` torques, as ``ltca sweep``).
    speed : float or sequence — [rpm], optional
        Pinion speeds of an efficiency stage (default none).
    operating : friction.operating.OperatingConditions, optional
        Lubricant, oil temperature, roughness, friction model of the efficiency stage
        (default the case's ``[operating]`` oil, temperature, roughness and friction model
        when a speed is given).
    options : contact.ltca.LTCAOptions, optional
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    deviations : bool
        Use the case's ``[deviations]`` (read here, once) — needed by a
        ``deviation_scale`` dimension; False: theoretical flanks.
    root_stress : bool or contact.compliance.fe.FEOptions
        :attr:`StudyInputs.root_stress` (default False).

    Returns
    -------
    StudyInputs

    Raises
    ------
    InputError
        Bad case, torque, speed, options or operating conditions.
    """

    c = resolve_case(case)
    if torque is None:  # the command's default (contact.commands.study._torques)
        torque = tuple(c.operating.torque)
    torques = _values("torque", torque, "N m")
    if np.any(torques <= 0):
        raise InputError(f"torque: must be > 0 [N m], got {torques.tolist()}")
    speeds = () if speed is None else tuple(float(x) for x in _values("speed", speed, "rpm"))
    if any(s <= 0 for s in speeds):
        raise InputError(f"speed: must be > 0 [rpm], got {list(speeds)}")
    if operating is not None and not isinstance(operating, OperatingConditions):
        raise InputError("operating: must be a friction.operating.OperatingConditions or "
                         f"None, got {type(operating).__name__}")
    op = operating if operating is not None or not speeds else OperatingConditions.from_point(
        c.operating, pinion_speed=speeds[0])
    if options is not None and not isinstance(options, LTCAOptions):
        raise InputError("options: must be a contact.ltca.LTCAOptions or None, got "
                         f"{type(options).__name__}")
    devs = resolve_deviations(c, None) if deviations else None
    return StudyInputs(case=c, torque=tuple(float(t) for t in torques), speed=speeds,
                       operating=op, options=options or LTCAOptions(), flank=flank,
                       deviations=devs, root_stress=root_stress)


@renamed_keywords(speed="pinion_speed")
def sweep(
    case: Case | str | os.PathLike[str] | None = None,
    *,
    delta_E: Any = None,
    delta_P: Any = None,
    delta_G: Any = None,
    delta_Sigma: Any = None,
    deviation_scale: Any = None,
    torque: Any = None,
    pinion_speed: Any = None,
    run: StudyRun | None = None,
    **legacy: Any,
) -> xr.Dataset:
    """Analyse a case over a full grid of misalignments, deviation scales, torques, speeds.

    Every combination of the given values of ΔE, ΔP, ΔG, ΔΣ and ``deviation_scale`` is a
    point (one :func:`contact.run_analysis` with all torques, plus the efficiency at each
    speed); inputs not given keep the case's values.

    Parameters
    ----------
    case : Case, path, bundled name or None (the default case)
    delta_E, delta_P, delta_G : float or sequence — [mm], optional
        Offset, pinion-axial and gear-axial misalignments (seed §2.5, Fig. 2.11).
    delta_Sigma : float or sequence — [rad], optional
        Shaft-angle misalignment (as :class:`geometry.pair.assembly.Misalignment`).
    deviation_scale : float or sequence — [1], optional
        Factors on the case's ``[deviations]`` (0 theoretical, 1 as measured).
    torque : float or sequence — [N·m], optional
        Pinion torques (default the case's ``[operating]`` torques, as ``ltca sweep``;
        before api83 :data:`DEFAULT_TORQUE`, 250 N·m).
    pinion_speed : float or sequence — [rpm], optional
        Pinion speeds (the result's ``speed`` dimension; old name ``speed``, deprecated):
        adds efficiency and power loss (default none).
    run : contact.study.StudyRun, optional
        The LTCA options, flank and efficiency conditions of every point, the output file
        (streamed, resumable) and where the points run (default a LocalCluster of one
        worker per core, no file). The former keywords ``options``, ``flank``,
        ``operating``, ``output``, ``scheduler``, ``n_workers``, ``progress`` still work
        for one release (DeprecationWarning).
    **legacy
        Those former keywords (fields of :class:`StudyRun`), deprecated.

    Returns
    -------
    xarray.Dataset
        Dims: the given inputs in the order ΔE, ΔP, ΔG, ΔΣ, deviation scale, then
        ``torque``, ``harmonic`` (of ``lte_harmonics``) and ``speed`` (of ``efficiency``,
        ``power_loss``). Variables: :data:`contact.study.summary.SUMMARY_VARIABLES`,
        ``status`` (CF flag 0 ok, 1 uncertified, 2 failed), ``reason``. Attribute
        ``not_checked``: what the summary prints and no limit judges, one line per reason
        in the verdict's words (:func:`contact.study.verdicts.study_not_checked_text`).

    Raises
    ------
    InputError
        No swept input, a bad value (the message names it and its units), parts of
        another study at the output.

    Examples
    --------
    >>> from contact.study import sweep
    >>> from contact.study import StudyRun
    >>> m = sweep(delta_E=[-0.1, 0, 0.1], delta_P=[-0.1, 0, 0.1], torque=250,
    ...           run=StudyRun(scheduler="synchronous"))  # doctest: +SKIP
    >>> m["lte_peak_to_peak"].sel(torque=250).plot()  # doctest: +SKIP
    """
    run = study_run(run, legacy, "sweep")
    given = {"delta_E": delta_E, "delta_P": delta_P, "delta_G": delta_G,
             "delta_Sigma": delta_Sigma, "deviation_scale": deviation_scale}
    axes = {n: _values(n, v, POINT_INPUTS[n][0]) for n, v in given.items() if v is not None}
    if not axes:
        raise InputError("sweep: give at least one of delta_E, delta_P, delta_G, "
                         "delta_Sigma, deviation_scale")
    shared = study_inputs(case, torque, pinion_speed, operating=run.operating, options=run.options,
                          flank=run.flank, root_stress=run.study_root_stress)
    names = list(axes)
    points = [dict(zip(names, map(float, combo), strict=True))
              for combo in itertools.product(*(axes[n] for n in names))]
    flat = run_points(shared, points, names=names, output=run.output, scheduler=run.scheduler,
                      n_workers=run.n_workers, progress=run.progress, kind="sweep",
                      force=run.force)
    grid = _to_grid(flat, axes)
    from contact.study.verdicts import study_not_checked_attrs

    # what the summary prints and no limit judges, in the file too (issue 71)
    grid.attrs.update(study_not_checked_attrs(grid))
    if run.output is not None:
        write_study(grid, run.output, shared)
    return grid


def _to_grid(flat: xr.Dataset, axes: dict[str, np.ndarray]) -> xr.Dataset:
    """The ``point`` dim of a sweep's result unfolded into the grid's dims (C order, as
    itertools.product made the points)."""
    shape = tuple(a.size for a in axes.values())
    names = list(axes)
    data = {}
    for name, var in flat.data_vars.items():
        rest = [d for d in var.dims if d != "point"]
        values = var.transpose("point", *rest).values.reshape(*shape, *var.shape[1:])
        data[name] = ((*names, *rest), values, var.attrs)
    coords = {n: (n, axes[n], flat[n].attrs) for n in names}
    for c in ("torque", "harmonic", "speed", "member"):
        if c in flat.coords:
            coords[c] = flat[c]
    return xr.Dataset(data, coords=coords, attrs=flat.attrs)


def grid_axes(names: Sequence[str], values: Sequence[Any]) -> dict[str, np.ndarray]:
    """Checked grid axes ``{name: values}`` (helper of the CLI)."""
    return {n: _values(n, v, POINT_INPUTS[n][0]) for n, v in zip(names, values, strict=True)}
