"""The whole analysis of a case as one DataTree: geometry → ease-off/UTCA → LTCA.

Like pvlib's ``ModelChain`` this only wires the stage functions together; each stage
can be called on its own. The tree's groups are ``/geometry`` (``/geometry/pinion/
concave`` …), ``/easeoff``, ``/utca`` and ``/ltca``; the root records the case (as
TOML text), the toolkit version and the operating conditions, so the netCDF file alone
says how it was produced.

The bundled cases live in ``cases/`` (installed as the package data
``contact.cases``); :data:`DEFAULT_CASE` is the reference design of the seed's 11×41
face-milled hypoid pair (synthesised from its basic data, its synthesis inputs and settings
optimised by ``ltca optimize`` against the loaded result; docs/optimize.md), and
:data:`SEED_TABLE_3_1` its operating points (seed Fig. 3.6, Table 3.1).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import os
import time
from importlib import resources
from pathlib import Path

import numpy as np
import xarray as xr

from contact.ltca import LTCAOptions, loaded_tca
from contact.utca import unloaded_tca
from contact.utca.easeoff import ease_off
from friction.operating import OperatingConditions
from geometry import __version__
from geometry.case import OPERATING_DEFAULTS, Case, load_case
from geometry.core.errors import InputError
from geometry.machine.flank import geometry_datasets
from geometry.pair.assembly import Misalignment

__all__ = [
    "DEFAULT_CASE",
    "EFFICIENCY_MAP_SPEEDS",
    "EFFICIENCY_MAP_TORQUES",
    "MISALIGNMENT_ATTRS",
    "SEED_TABLE_3_1",
    "bundled_case_path",
    "bundled_cases",
    "efficiency_map",
    "misalignment_attrs",
    "operating_conditions",
    "resolve_case",
    "resolve_deviations",
    "run_analysis",
]

log = logging.getLogger(__name__)

#: File name of the default case: the reference design of the seed's Table 2.1 / 4.1 pair
#: (``kolivand2009_fm_11x41.toml`` is the same pair's long-bearing synthesis without relief,
#: the optimiser's edge-loaded start).
DEFAULT_CASE = "kolivand2009_fm_11x41_reference.toml"

#: The seed's Table 3.1 operating points: pinion torques [N·m] and misalignment
#: |ΔE| = 0.15 mm, |ΔP| = 0.12 mm, ΔG = 0, ΔΣ = 0. The text extraction lost the signs of
#: the seed's ΔE, ΔP (Table 3.1, Figs. 2.11, 3.6, 3.7). In the toolkit's convention
#: (docs/machine.md) we read ΔE = −0.15, ΔP = +0.12: of the four sign choices it is the one
#: for which the seed's two other cases of Table 3.1 / Fig. 3.7 move the pattern as
#: described there — (−0.08, +0.05) towards toe and root, (−0.26, +0.13) towards the heel
#: (tests/test_ltca_seed.py) — and for which its Fig. 2.11 shifts (ΔE 0.08 → toe, ΔE 0.15 →
#: heel) need opposite signs of ΔE, as they do.
#:
#: These are the ``[operating]`` table of the default case (``cases/kolivand2009_fm_11x41
#: .toml``, from its basic file), so ``ltca run``, ``ltca run kolivand2009_fm_11x41`` and
#: ``run_analysis()`` all run them; pass ``misalignment=Misalignment()`` for the aligned pair.
SEED_TABLE_3_1 = {
    "torque": (50.0, 250.0, 500.0),
    "misalignment": Misalignment(delta_E=-0.15, delta_P=0.12),
}

#: root attributes of an analysis file holding its misalignment, once (units in the names;
#: the groups' ``misalignment`` attribute refers to them)
MISALIGNMENT_ATTRS = tuple(f"misalignment_{k}" for k in Misalignment().labelled())
#: what the groups of an analysis tree say instead of repeating the misalignment
MISALIGNMENT_REFERENCE = "see the root group's attributes " + ", ".join(MISALIGNMENT_ATTRS)

#: The default grid of :func:`efficiency_map` (and ``ltca efficiency-map``): pinion
#: torques [N·m] and pinion speeds [rpm] (the toolkit's choice: light to full load, low
#: to high speed).
EFFICIENCY_MAP_TORQUES = (100.0, 250.0, 500.0)
EFFICIENCY_MAP_SPEEDS = (500.0, 1000.0, 1500.0, 2500.0, 4000.0)


def _cases_root():
    """The bundled cases: in a source tree (``python -m pytest`` or ``python -m contact``
    from a clone or a git worktree, installed editable or not) the repository's
    ``cases/`` beside this package; else the installed package data ``contact.cases``."""
    source = Path(__file__).resolve().parents[1]
    if (source / "pyproject.toml").is_file() and (source / "cases" / "__init__.py").is_file():
        return source / "cases"
    try:
        return resources.files("contact.cases")
    except ModuleNotFoundError:
        return Path(__file__).resolve().parents[1] / "cases"


def bundled_cases() -> list[str]:
    """File names of the cases shipped with the toolkit."""
    root = _cases_root()
    return sorted(p.name for p in root.iterdir() if p.name.endswith(".toml"))


def bundled_case_path(name: str = DEFAULT_CASE) -> Path:
    """Path of a bundled case file.

    Raises
    ------
    InputError
        Unknown name (the message lists the bundled cases).
    """
    root = _cases_root()
    fname = name if name.endswith(".toml") else f"{name}.toml"
    path = root / fname
    if not path.is_file():
        raise InputError(f"case: no bundled case {name!r}; bundled: {', '.join(bundled_cases())}")
    return Path(str(path))


def resolve_case(case: Case | str | os.PathLike[str] | None) -> Case:
    """A Case from a Case, a file path, a bundled case name, or None (the default case)."""
    if isinstance(case, Case):
        return case
    if case is None:
        return load_case(bundled_case_path())
    path = Path(case)
    if path.is_file():
        return load_case(path)
    return load_case(bundled_case_path(str(case)))


def resolve_deviations(c: Case, deviations) -> tuple | None:
    """The (pinion, gear) SurfaceDeviations of :func:`run_analysis`'s ``deviations``.

    Parameters
    ----------
    c : geometry.case.Case
    deviations : (pinion, gear), False or None
        As :func:`run_analysis`: None reads the case's ``[deviations]`` files.

    Returns
    -------
    (SurfaceDeviation or None, SurfaceDeviation or None) or None
        None for the theoretical surfaces only.

    Raises
    ------
    InputError
        A malformed pair or an unreadable deviation file.
    """
    if deviations is None:
        files = c.deviations
        deviations = None if files is None else (files.pinion, files.gear)
    if deviations is None or deviations is False:
        return None
    if not isinstance(deviations, (tuple, list)) or len(deviations) != 2:
        raise InputError("deviations: must be a (pinion, gear) pair of SurfaceDeviation, "
                         f"file path or None, or False; got {deviations!r}")
    from contact.utca.deviation_files import read_deviations

    out = tuple(
        read_deviations(d, member) if isinstance(d, (str, os.PathLike)) else d
        for d, member in zip(deviations, ("pinion", "gear"), strict=True)
    )
    return None if all(d is None for d in out) else out


def misalignment_attrs(misalignment: Misalignment) -> dict[str, float]:
    """The root attributes that hold a file's misalignment, once: ``misalignment_delta_E_mm``,
    ``…_delta_P_mm``, ``…_delta_G_mm`` [mm] and ``…_delta_Sigma_deg`` [deg]
    (:meth:`geometry.pair.assembly.Misalignment.labelled`)."""
    return {f"misalignment_{k}": v for k, v in misalignment.labelled().items()}


def operating_conditions(case: Case, **override) -> OperatingConditions | None:
    """The efficiency stage's conditions of a case: its ``[operating]`` table
    (``Case.operating``), fields of ``override`` (not None) replacing its values.

    Returns
    -------
    friction.operating.OperatingConditions or None
        None where the pinion speed (the case's or the override) is 0: no efficiency stage.

    Raises
    ------
    InputError, ModelUnavailableError
        An unknown lubricant or friction model, a value out of range (named).
    """
    speed = override.get("pinion_speed")
    speed = case.operating.pinion_speed if speed is None else speed
    if speed == 0:
        return None
    return OperatingConditions.from_point(case.operating, **{**override, "pinion_speed": speed})


def _point_as_run(c: Case, torques, operating: OperatingConditions | None):
    """The case's OperatingPoint with the torques and efficiency conditions actually run."""
    t = [torques] if np.ndim(torques) == 0 else list(torques)
    kw = {"torque": tuple(float(x) for x in t)}
    if operating is None:
        kw["pinion_speed"] = 0.0
    else:
        kw.update(pinion_speed=operating.pinion_speed, lubricant=os.fspath(operating.lubricant),
                  temperature=operating.temperature, roughness=operating.roughness,
                  friction_model=operating.friction_model)
    return dataclasses.replace(c.operating, **kw)


def run_analysis(
    case: Case | str | os.PathLike[str] | None = None,
    torque=None,
    *,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    operating: OperatingConditions | bool | None = None,
    deviations: tuple | bool | None = None,
    geometry: bool = True,
    progress: bool = False,
    theoretical: bool = True,
) -> xr.DataTree:
    """Run geometry, ease-off UTCA and LTCA of a case; return one DataTree.

    Parameters
    ----------
    case : Case, path, bundled name, or None
        None runs the bundled default case (:data:`DEFAULT_CASE`, whose ``[operating]``
        table holds the seed's Table 3.1 conditions, :data:`SEED_TABLE_3_1`).
    torque : float or sequence — [N·m], optional
        Pinion torques; default the case's ``[operating]`` torques
        (``Case.operating.torque``; 50, 250, 500 where the table gives none).
    misalignment : geometry.pair.assembly.Misalignment, optional
        Default: the case's own (its ``[operating]`` ΔE, ΔP, ΔG, ΔΣ; ``Case.misalignment``).
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    options : contact.ltca.LTCAOptions, optional
        LTCA settings, the solver among them (``LTCAOptions.solver``, default our exact
        ``active_set``); default ``LTCAOptions()``.
    operating : friction.operating.OperatingConditions, False or None
        The conditions of the efficiency stage (pinion speed [rpm], lubricant, oil inlet
        temperature [degC], roughness Rq [µm], friction model; ``/friction``,
        :func:`friction.efficiency.efficiency_analysis`). None (default): the case's
        ``[operating]`` table (:func:`operating_conditions`; no efficiency stage where its
        ``pinion_speed`` is 0); False: no efficiency stage.
    deviations : (pinion, gear), False or None
        Measured or wear deviations of the (pinion, gear) flanks in contact
        (:mod:`contact.utca.deviations`, seed ch. 4): each a SurfaceDeviation [mm], a
        CSV/netCDF file path (:func:`contact.utca.deviation_files.read_deviations`) or None.
        The main groups then hold the deviated surfaces' results and
        ``/theoretical/{easeoff,utca,ltca}`` the theoretical ones, side by side;
        ``/easeoff`` gains ``ease_off_change`` [um]. None (default) uses the case's
        ``[deviations]`` table if it has one (``Case.deviations``); ``False`` or
        ``(None, None)`` ignores it (theoretical surfaces only).
    geometry : bool
        Include the four generated flanks as ``/geometry`` (default True).
    progress : bool
        Progress bar over the LTCA roll positions.
    theoretical : bool
        With deviations, also analyse the theoretical surfaces (``/theoretical``,
        default True); False skips them (studies keep only the deviated results, which
        are the same either way).

    Returns
    -------
    xarray.DataTree
        Groups ``/geometry``, ``/easeoff``, ``/utca``, ``/ltca`` (and ``/friction`` with
        operating conditions); root attributes ``case``, ``inputs`` (the case as TOML, its
        ``[operating]`` table as run), the misalignment once (:data:`MISALIGNMENT_ATTRS`:
        ``misalignment_delta_E_mm`` … ``misalignment_delta_Sigma_deg``; the groups'
        ``misalignment`` attribute refers to them), per-stage times ``time_*_s``.

    Raises
    ------
    InputError
        Bad case, torque, misalignment, options or operating conditions (the message
        names the field).

    Notes
    -----
    Seed ch. 2 (geometry, ease-off), ch. 3 (UTCA, LTCA), ch. 4 (deviations), ch. 5
    (efficiency).
    """
    c = resolve_case(case)
    if misalignment is not None:
        c = dataclasses.replace(c, misalignment=misalignment)
    torques = c.operating.torque if torque is None else torque
    opts = options or LTCAOptions()
    if operating is None:
        operating = operating_conditions(c)
    elif operating is False:
        operating = None
    elif not isinstance(operating, OperatingConditions):
        raise InputError("operating: must be a friction.operating.OperatingConditions, False "
                         f"or None, got {operating!r}")
    # the case as run: its [operating] table (in the file's ``inputs``) records what ran
    c = dataclasses.replace(c, operating=_point_as_run(c, torques, operating))
    times: dict[str, float] = {}
    tree: dict[str, xr.Dataset] = {}
    t0 = time.perf_counter()
    if geometry:
        for (m, f), ds in geometry_datasets(c).items():
            tree[f"/geometry/{m}/{f}"] = ds
    times["geometry"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    eo = ease_off(c, flank=flank)
    times["easeoff"] = time.perf_counter() - t0
    deviations = resolve_deviations(c, deviations)
    if deviations is not None:
        from contact.utca.deviations import apply_deviations

        pin_dev, gear_dev = deviations
        t_eo, t_ut = unloaded_tca(c, flank=flank, easeoff=eo)
        tree["/theoretical/easeoff"] = t_eo
        if theoretical:
            tree["/theoretical/utca"] = t_ut
            tree["/theoretical/ltca"] = loaded_tca(
                c, torques, flank=flank, options=opts, easeoff=eo,
                transitions=tuple(t_ut["transition_roll"].values),
            )
        eo = apply_deviations(eo, pinion=pin_dev, gear=gear_dev, case=c)
    t0 = time.perf_counter()
    eo_ds, utca_ds = unloaded_tca(c, flank=flank, easeoff=eo)
    times["utca"] = time.perf_counter() - t0
    if "/theoretical/easeoff" in tree:
        change = (eo_ds["ease_off"] - tree["/theoretical/easeoff"]["ease_off"]).astype(float)
        if not theoretical:
            del tree["/theoretical/easeoff"]
        eo_ds["ease_off_change"] = change.assign_attrs(
            units=eo_ds["ease_off"].attrs.get("units", "um"),
            long_name="ease-off change by the surface deviations (deviated - theoretical)",
        )
        eo_ds.attrs["deviations"] = (
            "pinion: "
            + ("yes" if deviations[0] is not None else "no")
            + ", gear: "
            + ("yes" if deviations[1] is not None else "no")
        )
    t0 = time.perf_counter()
    ltca_ds = loaded_tca(c, torques, flank=flank, options=opts, easeoff=eo, progress=progress,
                         transitions=tuple(utca_ds["transition_roll"].values))
    times["ltca"] = time.perf_counter() - t0
    tree["/easeoff"] = eo_ds
    tree["/utca"] = utca_ds
    tree["/ltca"] = ltca_ds
    if operating is not None:
        from friction.efficiency import efficiency_analysis

        t0 = time.perf_counter()
        tree["/friction"] = efficiency_analysis(ltca_ds, operating)
        times["friction"] = time.perf_counter() - t0
    for path, ds in tree.items():
        if "misalignment" in ds.attrs:  # stored once, at the root
            tree[path] = ds.assign_attrs(misalignment=MISALIGNMENT_REFERENCE)
    root = xr.Dataset(
        attrs={
            "title": f"hypoid-ltca analysis of {c.name}",
            "case": c.name,
            "case_source": c.source,
            "toolkit_version": __version__,
            "solver": opts.solver,
            **misalignment_attrs(c.misalignment),
            **{f"time_{k}_s": v for k, v in times.items()},
        }
    )
    tree["/"] = root
    out = xr.DataTree.from_dict(tree)
    out.attrs["inputs"] = c.to_toml()
    if not math.isfinite(float(ltca_ds["transmission_error"].mean())):
        log.warning("some roll positions have no certified solution (see /ltca status)")
    return out


def efficiency_map(
    case: Case | str | os.PathLike[str] | None = None,
    torque=None,
    speed=None,
    *,
    temperature=None,
    roughness=None,
    operating: OperatingConditions | None = None,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    progress: bool = False,
    scheduler="synchronous",
    n_workers: int | None = None,
) -> xr.Dataset:
    """Efficiency over operating points: speed × torque × temperature × roughness (seed §5.3).

    The LTCA (static) runs once per torque — each torque one task of the study engine
    (:func:`contact.study.engine.run_tasks`, Dask) —; the efficiency stage
    (:func:`friction.efficiency.efficiency_analysis`) then runs for every speed,
    temperature and roughness on those loads.

    Parameters
    ----------
    case : Case, path, bundled name or None (default case)
    torque : sequence, optional — [N·m]
        Pinion torques; default :data:`EFFICIENCY_MAP_TORQUES` (100, 250, 500).
    speed : sequence, optional — [rpm]
        Pinion speeds; default :data:`EFFICIENCY_MAP_SPEEDS` (500 … 4000).
    temperature : sequence, optional — [degC]
        Oil inlet temperatures; default the one of ``operating``.
    roughness : sequence, optional — [µm]
        RMS roughness Rq of each surface; default the one of ``operating``.
    operating : friction.operating.OperatingConditions, optional
        The lubricant and friction model (and the default temperature and roughness);
        its pinion speed is replaced by the swept ones. Default the case's ``[operating]``
        table (:func:`operating_conditions`).
    misalignment, flank, options
        As :func:`run_analysis` (default the case's misalignment, the drive flank).
    progress : bool
        tqdm progress bar over the torques (and, run in this process, over each
        torque's roll positions).
    scheduler, n_workers
        Where the torques run (:func:`contact.study.engine.open_client`): default
        ``"synchronous"`` (this process, one after the other); None a LocalCluster of
        ``n_workers`` processes; an address or a ``distributed.Client`` a cluster.

    Returns
    -------
    xarray.Dataset
        dims (``torque``, ``speed``, ``temperature``, ``roughness``): ``efficiency`` [1],
        ``power_loss`` [W] (means over the mesh cycles), ``friction_coefficient_mean``,
        ``lambda_ratio_mean`` [1] (load-weighted means over the loaded segments),
        ``friction_model_extrapolated_share`` [1] (share of the loaded segments where the
        friction model is extrapolated, flagged per segment by the efficiency stage).

    Raises
    ------
    InputError
        Bad case, options or operating point (the message names the field).
    ModelUnavailableError
        Unknown lubricant or friction model.

    Notes
    -----
    Seed §5.3 (efficiency over operating conditions).
    """
    from contact.study.efficiency import EfficiencyInputs, efficiency_at_torque
    from contact.study.engine import run_tasks

    c = resolve_case(case)
    if misalignment is not None:
        c = dataclasses.replace(c, misalignment=misalignment)
    if operating is None:  # the case's conditions; the speeds are swept
        operating = OperatingConditions.from_point(
            c.operating, pinion_speed=c.operating.pinion_speed or OPERATING_DEFAULTS[
                "pinion_speed"])
    op = operating
    torque = EFFICIENCY_MAP_TORQUES if torque is None else torque
    speed = EFFICIENCY_MAP_SPEEDS if speed is None else speed
    temperature = (op.temperature,) if temperature is None else temperature
    roughness = (op.roughness,) if roughness is None else roughness
    shared = EfficiencyInputs(c, options or LTCAOptions(), op,
                              tuple(float(x) for x in speed),
                              tuple(float(x) for x in temperature),
                              tuple(float(x) for x in roughness), flank=flank,
                              progress=bool(progress) and scheduler == "synchronous")
    shape = (len(torque), len(speed), len(temperature), len(roughness))
    eff, loss, mu_m, lam_m, extra = (np.full(shape, np.nan) for _ in range(5))
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=len(torque), desc="efficiency map", unit="torque")
    for it, res in run_tasks(efficiency_at_torque, shared,
                             [(i, float(t)) for i, t in enumerate(torque)],
                             scheduler=scheduler, n_workers=n_workers):
        eff[it], loss[it] = res["efficiency"], res["power_loss"]
        mu_m[it], lam_m[it] = res["friction_coefficient_mean"], res["lambda_ratio_mean"]
        extra[it] = res["extrapolated_share"]
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    dims4 = ("torque", "speed", "temperature", "roughness")
    return xr.Dataset(
        {
            "efficiency": (dims4, eff, {"units": "1", "long_name": "mean mechanical efficiency"}),
            "power_loss": (dims4, loss, {"units": "W", "long_name": "mean mesh power loss"}),
            "friction_coefficient_mean": (
                dims4,
                mu_m,
                {"units": "1", "long_name": "load-weighted mean friction coefficient"},
            ),
            "lambda_ratio_mean": (
                dims4,
                lam_m,
                {"units": "1", "long_name": "load-weighted mean lambda ratio"},
            ),
            "friction_model_extrapolated_share": (
                dims4,
                extra,
                {"units": "1", "long_name": "share of the loaded segments where the friction "
                 "model is evaluated outside its fitted range"},
            ),
        },
        coords={
            "torque": (
                "torque",
                np.asarray(torque, float),
                {"units": "N m", "long_name": "pinion torque"},
            ),
            "speed": (
                "speed",
                np.asarray(speed, float),
                {"units": "rpm", "long_name": "pinion speed"},
            ),
            "temperature": (
                "temperature",
                np.asarray(temperature, float),
                {"units": "degC", "long_name": "oil inlet temperature"},
            ),
            "roughness": (
                "roughness",
                np.asarray(roughness, float),
                {"units": "um", "long_name": "RMS roughness Rq of each surface"},
            ),
        },
        attrs={
            "title": "mechanical efficiency map",
            "case": c.name,
            **misalignment_attrs(c.misalignment),
            "lubricant": str(op.lubricant),
            "friction_model": op.friction_model,
            "toolkit_version": __version__,
        },
    )
