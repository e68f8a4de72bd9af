"""Simulated wear of the flanks: Archard's law integrated over load cycles (seed ch. 6 (v)).

The seed closes with "the way local deviation and mounting errors are included in the
proposed model is general such that this model can be used to predict surface wear"
(future work (v)); its Fig. 4.5 deviations are worn flanks predicted by Park & Kahraman's
wear model (seed ref. [4.15]). This module runs that loop on the toolkit's own chain:
each wear step analyses the current (worn) surfaces — ease-off updated by the deviation
grids (:func:`contact.utca.deviations.apply_deviations`, seed Eq. 4.3–4.10), UTCA, LTCA —
computes the wear depth of one mesh at every node of a deviation grid of each member,
multiplies it by the load cycles of the step and removes it from the grids, which the
next step analyses.

Bookkeeping (where the wear depth is computed, how it is put on the deviation grids, what one
load cycle is): :mod:`contact.wear.archard`.

Public functions
----------------
WEAR_GRID              the default deviation grid of the wear (41 × 21 nodes)
simulate_wear          the whole wear loop of a case → an xarray Dataset over ``step``
final_deviations       the worn (pinion, gear) SurfaceDeviations of a wear result

The depth of one mesh (Archard's law) is :mod:`contact.wear.archard`'s.

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009 (the seed), §4.3, ch. 6 (v).
"""

from __future__ import annotations

import dataclasses
import logging
import os
import time

import numpy as np
import xarray as xr

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from contact.utca import unloaded_tca
from contact.utca.deviations import SurfaceDeviation, apply_deviations
from contact.utca.easeoff import ease_off
from contact.wear.archard import depth_on_grid, flank_line_speeds, passage_wear
from geometry import __version__
from geometry.case import Case
from geometry.core.conventions import data_var
from geometry.core.errors import InputError
from geometry.core.validation import integer, positive, real
from geometry.pair.assembly import Misalignment

__all__ = [
    "WEAR_GRID",
    "final_deviations",
    "simulate_wear",
]

log = logging.getLogger(__name__)


#: default deviation grid of the wear of each member: 41 lengthwise (toe → heel) × 21
#: profile (root → tip) nodes over the fractions of the flank grid
#: (:data:`geometry.machine.flank.DEFAULT_GRID`, the ease-off's): far finer than a CMM's 9 × 5
#: because wear stops sharply where the contact region ends, and the interpolating spline
#: of :class:`~contact.utca.deviations.SurfaceDeviation` turns that step into a ramp one
#: grid cell wide (a rim left standing proud inside the contact region on a coarse grid)
WEAR_GRID = {"nu": 41, "nv": 21, "u_limits": (0.0, 1.0), "v_limits": (0.05, 1.0)}


def _grid(grid: dict | None) -> tuple[np.ndarray, np.ndarray]:
    g = dict(WEAR_GRID if grid is None else grid)
    nu = integer("grid.nu", g.get("nu", WEAR_GRID["nu"]), low=3)
    nv = integer("grid.nv", g.get("nv", WEAR_GRID["nv"]), low=3)
    u0, u1 = g.get("u_limits", WEAR_GRID["u_limits"])
    v0, v1 = g.get("v_limits", WEAR_GRID["v_limits"])
    return np.linspace(u0, u1, nu), np.linspace(v0, v1, nv)


def _initial(c: Case, deviations, gu, gv) -> tuple[np.ndarray, np.ndarray]:
    """(pinion, gear) grids [mm] at the start: the given or the case's deviations sampled
    on the wear grid, else zero."""
    from contact.utca.deviation_files import read_deviations

    if deviations is None and c.deviations is not None:
        deviations = (c.deviations.pinion, c.deviations.gear)
    uu, vv = np.meshgrid(gu, gv, indexing="ij")
    out = [np.zeros(uu.shape), np.zeros(uu.shape)]
    if deviations is None or deviations is False:
        return out[0], out[1]
    if not isinstance(deviations, (tuple, list)) or len(deviations) != 2:
        raise InputError("deviations: must be a (pinion, gear) pair of SurfaceDeviation, "
                         f"file path or None, or False; got {deviations!r}")
    for i, (d, member) in enumerate(zip(deviations, ("pinion", "gear"), strict=True)):
        if isinstance(d, (str, os.PathLike)):
            d = read_deviations(d, member)
        if d is not None:
            if not isinstance(d, SurfaceDeviation):
                raise InputError(f"deviations: the {member}'s must be a SurfaceDeviation, a "
                                 f"file path or None, got {type(d).__name__}")
            out[i] = d(uu, vv)
    return out[0], out[1]


def simulate_wear(
    case: Case | str | os.PathLike[str] | None = None,
    torque: float = 200.0,
    *,
    wear_coefficient: float,
    cycles: float,
    steps: int = 5,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    deviations: tuple | bool | None = None,
    grid: dict | None = None,
    progress: bool = False,
) -> xr.Dataset:
    """Wear of the flanks in contact over load cycles: Archard's law stepped with the LTCA.

    Parameters
    ----------
    case : Case, path, bundled name, or None
        As :func:`contact.pipeline.run_analysis` (None: the bundled default case).
    torque : float — [N·m]
        Pinion torque the flanks wear under (> 0; default 200, the seed's Table 4.2).
    wear_coefficient : float — [m²/N]
        Dimensional Archard coefficient k ≥ 0 (m³ worn per N·m of sliding); 0 wears
        nothing.
    cycles : float — [1]
        Load cycles (pinion revolutions) in all, > 0, split into ``steps`` equal steps.
    steps : int
        Wear steps (1–1000): the surfaces are analysed ``steps + 1`` times (the initial
        state and after each step); the wear of a step is that of the state it starts from.
    misalignment : geometry.pair.assembly.Misalignment, optional
        Default the case's own.
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    options : contact.ltca.LTCAOptions, optional
        LTCA settings (default ``LTCAOptions()``).
    deviations : (pinion, gear), False or None
        Deviations the flanks start from (SurfaceDeviation or file path each, or None), as
        :func:`contact.pipeline.run_analysis`; None: the case's ``[deviations]`` if any;
        False: the theoretical surfaces. Sampled on the wear grid.
    grid : dict, optional
        The deviation grid of each member (``nu``, ``nv`` ≥ 3, ``u_limits``,
        ``v_limits``); default :data:`WEAR_GRID`.
    progress : bool
        tqdm progress bar over the steps.

    Returns
    -------
    xarray.Dataset
        Over ``step`` (0 … steps; coordinate ``cycles`` [1], pinion load cycles done, and
        ``gear_cycles``): ``pinion_deviation`` (step, u_pinion, v_pinion) and
        ``gear_deviation`` (step, u_gear, v_gear) [mm] (negative = worn),
        ``pinion_wear_rate``, ``gear_wear_rate`` [mm] (depth per load cycle of that
        state), ``unloaded_transmission_error`` (step, roll_utca) and
        ``transmission_error`` (step, roll) [µrad], their peak-to-peak values
        ``ute_peak_to_peak``, ``lte_peak_to_peak`` [µrad], ``pressure_max_flank`` [MPa],
        ``pressure_envelope`` (step, u, v) [MPa] (the loaded pattern, gear grid),
        ``gear_torque_transmitted`` (step, roll) [N·m] (Σ F R of the solution),
        ``residual_equilibrium`` [1] (largest over the rolls), ``max_pinion_depth``,
        ``max_gear_depth`` [mm], ``step_time`` [s]. Attributes: case, torque, wear
        coefficient, cycles, steps, toolkit version.

    Raises
    ------
    InputError
        Bad case, torque, coefficient, cycles, steps, grid or deviations (naming the
        field); worn deviations beyond :data:`contact.utca.deviations.MAX_DEVIATION`.

    Notes
    -----
    Archard (1953) by single-point observation (Flodin & Andersson 1997), hypoid sliding
    distances from the contact velocities (Park, Kolivand & Kahraman 2014); the worn
    surfaces enter through the seed's ease-off update (§4.3, Eq. 4.3–4.10), the seed's
    future work (v). See the module docstring.
    """
    c = resolve_case(case)
    if misalignment is not None:
        c = dataclasses.replace(c, misalignment=misalignment)
    torque = positive("torque", torque, "N m")
    k = real("wear_coefficient", wear_coefficient, unit="m2/N", low=0.0, high=1e-6)
    cycles = positive("cycles", cycles, "1")
    steps = integer("steps", steps, low=1, high=1000)
    opts = options or LTCAOptions()
    gu, gv = _grid(grid)
    pin, gear = _initial(c, deviations, gu, gv)
    z_ratio = c.pinion.blank.teeth / c.gear.blank.teeth  # gear load cycles per pinion's
    per_step = cycles / steps
    eo0 = ease_off(c, flank=flank)
    speeds = flank_line_speeds(c, eo0)
    records: list[dict] = []
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=steps + 1, desc="wear", unit="step")
    for i in range(steps + 1):
        t0 = time.perf_counter()
        eo = eo0
        if np.any(pin != 0) or np.any(gear != 0):
            eo = apply_deviations(eo0, pinion=SurfaceDeviation(gu, gv, pin),
                                  gear=SurfaceDeviation(gu, gv, gear), case=c)
        _, ut = unloaded_tca(c, flank=flank, easeoff=eo)
        lt = loaded_tca(c, [torque], flank=flank, options=opts, easeoff=eo,
                        transitions=tuple(ut["transition_roll"].values))
        pw = passage_wear(lt, eo0, speeds, k)
        rate_p = depth_on_grid(pw["pinion_u"], pw["pinion_v"], pw["pinion_depth"], gu, gv)
        rate_g = depth_on_grid(pw["gear_u"], pw["gear_v"], pw["gear_depth"], gu, gv)
        rate_g = rate_g * z_ratio
        records.append(_record(i, pin, gear, rate_p, rate_g, ut, lt))
        records[-1]["step_time"] = time.perf_counter() - t0
        log.info("wear step %d: cycles %.4g, max depth pinion %.3g um, gear %.3g um, UTE p-p "
                 "%.3g urad, LTE p-p %.3g urad, peak pressure %.4g MPa", i, i * per_step,
                 max(-1e3 * pin.min(), 0.0), max(-1e3 * gear.min(), 0.0),
                 records[-1]["ute_pp"], records[-1]["lte_pp"], records[-1]["p_max"])
        if i < steps:
            pin = pin - per_step * rate_p
            gear = gear - per_step * rate_g
        if bar is not None:
            bar.update(1)
    if bar is not None:
        bar.close()
    return _wear_dataset(c, records, gu, gv, per_step, z_ratio, torque=torque,
                         wear_coefficient=k, cycles=cycles, steps=steps, lt=lt, ut=ut)


def _record(i, pin, gear, rate_p, rate_g, ut: xr.Dataset, lt: xr.Dataset) -> dict:
    F = lt["force"].fillna(0.0)
    moment = (F * lt["moment_arm"].fillna(0.0)).sum(("pair", "segment"))  # N·mm
    if not bool(lt["found"].all()):
        log.warning("wear step %d: %d roll positions without a certified solution", i,
                    int((lt["found"] == 0).sum()))
    return {
        "pinion": pin.copy(), "gear": gear.copy(), "rate_p": rate_p, "rate_g": rate_g,
        "ute": ut["unloaded_transmission_error"].values,
        "ute_pp": float(ut["peak_to_peak_transmission_error"]),
        "lte": lt["transmission_error"].values[0],
        "lte_pp": float(lt["lte_peak_to_peak"].values[0]),
        "p_max": float(lt["pressure_max_flank"].values[0]),
        "envelope": lt["pressure_envelope"].values[0],
        "moment": moment.values[0] * 1e-3,
        "residual": float(lt["residual_equilibrium"].max()),
    }


def _wear_dataset(c: Case, records: list[dict], gu, gv, per_step: float, z_ratio: float, *,
                  torque: float, wear_coefficient: float, cycles: float, steps: int,
                  lt: xr.Dataset, ut: xr.Dataset) -> xr.Dataset:
    n = len(records)

    def stack(key):
        return np.stack([r[key] for r in records])

    done = per_step * np.arange(n)
    fr = {"units": "1"}
    coords = {
        "step": ("step", np.arange(n), {"units": "1", "long_name": "wear step"}),
        "cycles": ("step", done, {**fr, "long_name": "pinion load cycles (revolutions) worn "
                                  "before the state analysed"}),
        "gear_cycles": ("step", done * z_ratio, {**fr, "long_name": "load cycles of each "
                                                 "gear tooth (meshes) worn before the state"}),
        "u_pinion": ("u_pinion", gu, {**fr, "long_name": "pinion lengthwise fraction of the "
                                      "projection plane, toe 0 to heel 1"}),
        "v_pinion": ("v_pinion", gv, {**fr, "long_name": "pinion profile fraction of the "
                                      "projection plane, root 0 to tip 1"}),
        "u_gear": ("u_gear", gu, {**fr, "long_name": "gear lengthwise fraction of the "
                                  "projection plane, toe 0 to heel 1"}),
        "v_gear": ("v_gear", gv, {**fr, "long_name": "gear profile fraction of the "
                                  "projection plane, root 0 to tip 1"}),
        "roll": ("roll", lt["roll"].values, dict(lt["roll"].attrs)),
        "roll_utca": ("roll_utca", ut["roll"].values,
                      {**dict(ut["roll"].attrs), "long_name": "pinion roll of the UTCA"}),
        "u": ("u", lt["u"].values, dict(lt["u"].attrs)),
        "v": ("v", lt["v"].values, dict(lt["v"].attrs)),
    }
    pin, gear = stack("pinion"), stack("gear")
    data = {
        "pinion_deviation": data_var(("step", "u_pinion", "v_pinion"), pin, "mm",
                                     "pinion flank normal deviation, positive = material "
                                     "added (negative = worn)"),
        "gear_deviation": data_var(("step", "u_gear", "v_gear"), gear, "mm",
                                   "gear flank normal deviation, positive = material added "
                                   "(negative = worn)"),
        "pinion_wear_rate": data_var(("step", "u_pinion", "v_pinion"), stack("rate_p"), "mm",
                                     "pinion wear depth per load cycle at the state"),
        "gear_wear_rate": data_var(("step", "u_gear", "v_gear"), stack("rate_g"), "mm",
                                   "gear wear depth per pinion load cycle at the state (per "
                                   "gear tooth, z_p/z_g meshes)"),
        "max_pinion_depth": data_var("step", np.maximum(-pin.min(axis=(1, 2)), 0.0), "mm",
                                     "largest pinion wear depth"),
        "max_gear_depth": data_var("step", np.maximum(-gear.min(axis=(1, 2)), 0.0), "mm",
                                   "largest gear wear depth"),
        "unloaded_transmission_error": data_var(("step", "roll_utca"), stack("ute"), "urad",
                                                "unloaded transmission error"),
        "transmission_error": data_var(("step", "roll"), stack("lte"), "urad",
                                       "loaded transmission error"),
        "ute_peak_to_peak": data_var("step", stack("ute_pp"), "urad",
                                     "peak-to-peak unloaded transmission error"),
        "lte_peak_to_peak": data_var("step", stack("lte_pp"), "urad",
                                     "peak-to-peak loaded transmission error"),
        "pressure_max_flank": data_var("step", stack("p_max"), "MPa",
                                       "peak Hertzian pressure on the contact curves"),
        "pressure_envelope": data_var(("step", "u", "v"), stack("envelope"), "MPa",
                                      "loaded contact pattern: envelope of the maximum "
                                      "pressure over the roll positions, gear grid"),
        "gear_torque_transmitted": data_var(("step", "roll"), stack("moment"), "N m",
                                            "gear torque of the contact forces (sum F R)"),
        "residual_equilibrium": data_var("step", stack("residual"), "1",
                                         "largest relative equilibrium residual over the "
                                         "rolls"),
        "step_time": data_var("step", stack("step_time"), "s",
                              "wall time of the step's analysis"),
    }
    return xr.Dataset(data, coords=coords, attrs={
        "title": f"hypoid-ltca simulated wear of {c.name}",
        "case": c.name,
        "toolkit_version": __version__,
        "torque_Nm": float(torque),
        "gear_torque_Nm": float(torque / z_ratio),
        "wear_coefficient_m2_per_N": float(wear_coefficient),
        "cycles": float(cycles),
        "steps": int(steps),
        "pinion_flank": str(lt.attrs["pinion_flank"]),
        "gear_flank": str(lt.attrs["gear_flank"]),
        "method": "Archard wear, single-point observation (Flodin & Andersson 1997), "
                  "contact-velocity sliding distance (Park, Kolivand & Kahraman 2014), "
                  "ease-off update of seed section 4.3",
        "options": lt.attrs["options"],
    })


def final_deviations(wear: xr.Dataset, step: int = -1) -> tuple[SurfaceDeviation,
                                                                 SurfaceDeviation]:
    """The (pinion, gear) deviation grids of one step of a wear result.

    Parameters
    ----------
    wear : xarray.Dataset
        Output of :func:`simulate_wear` (or read back from its file).
    step : int
        Position along ``step`` (default the last: the worn surfaces).

    Returns
    -------
    (SurfaceDeviation, SurfaceDeviation)
        [mm], negative = worn; for :func:`contact.pipeline.run_analysis` ``deviations=`` or
        :func:`contact.utca.deviation_files.write_deviation_netcdf`.

    Raises
    ------
    InputError
        Missing variables or a step out of range.
    """
    for name in ("pinion_deviation", "gear_deviation"):
        if name not in wear.variables:
            raise InputError(f"wear: dataset lacks {name!r} (expected simulate_wear output)")
    n = wear.sizes["step"]
    step = integer("step", step, low=-n, high=n - 1)
    p = wear["pinion_deviation"].isel(step=step).transpose("u_pinion", "v_pinion")
    g = wear["gear_deviation"].isel(step=step).transpose("u_gear", "v_gear")
    return (SurfaceDeviation(wear["u_pinion"].values, wear["v_pinion"].values, p.values),
            SurfaceDeviation(wear["u_gear"].values, wear["v_gear"].values, g.values))
