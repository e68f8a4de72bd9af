"""The 5×5 sweep guard: a study's stored summaries, made before the speed work of issue 32.

``tests/data/sweep_guard_5x5.nc`` holds the summaries (:data:`contact.study.
SUMMARY_VARIABLES`) of a ΔE × ΔP sweep of the default case (``contact.catalogue.
DEFAULT_CASE``) around its Table 3.1 mounting (ΔE = −0.15 mm, ΔP = +0.12 mm, ±0.05 mm in
steps of 0.025 mm: 25 points) at one pinion torque, 250 N·m, run by the study engine in
this process (``scheduler="synchronous"``), one BLAS thread. The LTCA is coarse
(:data:`OPTIONS`: 8 roll positions per mesh cycle, 8 segments per curve) so that the
comparison stays cheap enough for CI; the ease-off, the UTCA, the tooth models and the
contact solves are the full ones, so a change of any algorithm on a study point's path
shows. A change that must not move results (issue 32: "every result unchanged") is
checked by ``tests/test_sweep_guard.py`` against this file to 1e-9 relative.

Check a working tree::

    python tests/sweep_guard.py --check

Write it (only before a change, or when a change of results is intended and reviewed)::

    python tests/sweep_guard.py --write
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import xarray as xr

GUARD = Path(__file__).parent / "data" / "sweep_guard_5x5.nc"

#: the mounting of the seed's Table 3.1 [mm] (the default case's [operating] table)
TABLE_3_1 = {"delta_E": -0.15, "delta_P": 0.12}
#: half-width of the grid about it [mm] and the number of values per axis
HALF_WIDTH, N = 0.05, 5
TORQUE = 250.0


def _options():
    from contact.ltca import LTCAOptions

    return LTCAOptions(rolls_per_cycle=8, segments=8)


def axes() -> dict[str, np.ndarray]:
    """The guard's grid axes ΔE, ΔP [mm]."""
    return {k: np.linspace(v - HALF_WIDTH, v + HALF_WIDTH, N) for k, v in TABLE_3_1.items()}


def run_guard() -> xr.Dataset:
    """The guard's sweep, as it was made (one BLAS thread, this process)."""
    from threadpoolctl import threadpool_limits

    from contact.study import StudyRun, sweep

    with threadpool_limits(limits=1, user_api="blas"):
        grid = sweep(None, **axes(), torque=TORQUE,
                     run=StudyRun(options=_options(), scheduler="synchronous"))
    return grid


def differences(new: xr.Dataset, stored: xr.Dataset, rtol: float) -> list[str]:
    """Every summary that differs by more than ``rtol`` relative (elementwise, and at
    least ``rtol`` of the variable's largest magnitude for values at or near 0), or whose
    NaN pattern or integer values differ. Variables the study gained after the file was
    written (``plausibility``, issue 56) are not the guard's subject; a stored one missing
    from the new sweep is a difference."""
    out = []
    if set(stored.data_vars) - set(new.data_vars):
        out.append(f"variables missing: {sorted(set(stored.data_vars) - set(new.data_vars))}")
    for name in sorted(set(new.data_vars) & set(stored.data_vars)):
        x, y = np.asarray(new[name].values), np.asarray(stored[name].values)
        if x.shape != y.shape:
            out.append(f"{name}: shape {x.shape} != {y.shape}")
        elif x.dtype.kind == "f" and y.dtype.kind == "f":
            if not np.array_equal(np.isnan(x), np.isnan(y)):
                out.append(f"{name}: NaN pattern differs")
                continue
            scale = float(np.nanmax(np.abs(y), initial=0.0)) if np.any(~np.isnan(y)) else 0.0
            d = np.nan_to_num(np.abs(x - y))
            bound = rtol * np.maximum(np.nan_to_num(np.abs(y)), scale)
            if np.any(d > bound):
                k = np.unravel_index(np.argmax(d - bound), d.shape)
                out.append(f"{name}: differs by {d[k]:.3g} at {k} (stored {y[k]:.12g}, "
                           f"largest |value| {scale:.3g})")
        elif not np.array_equal(x, y):
            out.append(f"{name}: values differ")
    return out


def write_guard(path: Path = GUARD) -> Path:
    """Run the guard's sweep and store it at ``path`` (how it was made in its attributes)."""
    from geometry.core.atomic_files import atomic_path

    grid = run_guard()
    grid.attrs["made_by"] = ("tests/sweep_guard.py --write: sweep of the default case, "
                             f"{N}x{N} dE x dP about the Table 3.1 mounting, {TORQUE:g} N m, "
                             f"{_options()!r}, scheduler='synchronous', one BLAS thread")
    with atomic_path(path) as tmp:
        grid.to_netcdf(tmp, engine="netcdf4")
    return path


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="(re)write the stored sweep")
    parser.add_argument("--check", action="store_true",
                        help="run and compare to 1e-9 relative; also print the largest "
                             "difference of each variable")
    args = parser.parse_args()
    if args.write:
        print(f"wrote {write_guard()}")
    elif args.check:
        new = run_guard()
        stored = xr.load_dataset(GUARD)
        for name in sorted(stored.data_vars):
            x, y = np.asarray(new[name].values), np.asarray(stored[name].values)
            if x.dtype.kind == "f":
                scale = float(np.nanmax(np.abs(y), initial=0.0)) or 1.0
                print(f"{name}: largest difference {np.nanmax(np.abs(x - y)) / scale:.2e} "
                      "of the largest |value|")
        found = differences(new, stored, rtol=1e-9)
        print("\n".join(found) if found else "the stored sweep reproduced to 1e-9")
        raise SystemExit(1 if found else 0)
    else:
        parser.print_help()
