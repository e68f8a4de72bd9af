"""Two study files (``ltca sweep``, ``ltca tolerance``) compared variable by variable.

    python benchmarks/sweep_compare.py before.nc after.nc              # relative 1e-12
    python benchmarks/sweep_compare.py before.nc after.nc --rtol 1e-9

The check a speed change of the study path passes (issue 75): the same points give the same
numbers. Every variable and coordinate of either file must be in both, with the same
dimensions and shape; numeric ones must have NaN at the same places and elsewhere agree to
``--rtol`` relative to the larger magnitude of the pair (an exact zero against an exact
zero passes); text and flags must be equal. Attributes are not compared (``date_created``
and ``history`` differ between any two runs). Prints one line per variable that differs at
all (its largest relative difference) and a last line ``same`` or ``DIFFERENT``; the exit
status is 0 for the same numbers, 1 otherwise.

Typical use, the base tree against this one on the same grid::

    PYTHONPATH=/path/to/base python -m contact.cli sweep --dE -0.1:0.1:15 --dP -0.1:0.1:15 \\
        --torque 250 --scheduler synchronous -o base.nc
    PYTHONPATH=$PWD python -m contact.cli sweep ... -o this.nc
    python benchmarks/sweep_compare.py base.nc this.nc
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
import xarray as xr


def relative_difference(a: np.ndarray, b: np.ndarray) -> float:
    """Largest |a − b| / max(|a|, |b|) over the elements where both are finite; inf where
    the NaN/inf places differ or a finite value meets a non-finite one."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    fa, fb = np.isfinite(a), np.isfinite(b)
    if not np.array_equal(fa, fb):
        return float("inf")
    if not np.array_equal(a[~fa], b[~fb], equal_nan=True):  # the same NaN and ±inf
        return float("inf")
    if not fa.any():
        return 0.0
    x, y = a[fa], b[fb]
    scale = np.maximum(np.abs(x), np.abs(y))
    diff = np.abs(x - y)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = np.where(scale > 0, diff / np.where(scale > 0, scale, 1.0), 0.0)
    return float(rel.max())


def compare(before: xr.Dataset, after: xr.Dataset, rtol: float) -> list[str]:
    """One line per variable or coordinate that differs (or that only one file has)."""
    lines = []
    for name in sorted(set(before.variables) | set(after.variables)):
        if name not in before.variables or name not in after.variables:
            lines.append(f"{name}: only in {'after' if name in after.variables else 'before'}")
            continue
        va, vb = before.variables[name], after.variables[name]
        if va.dims != vb.dims or va.shape != vb.shape:
            lines.append(f"{name}: dims {va.dims}{va.shape} against {vb.dims}{vb.shape}")
            continue
        a, b = va.values, vb.values
        if np.issubdtype(a.dtype, np.number) and np.issubdtype(b.dtype, np.number):
            rel = relative_difference(a, b)
            if rel > 0.0:
                flag = "" if rel <= rtol else "  ** above rtol"
                lines.append(f"{name}: largest relative difference {rel:.3g}{flag}")
        elif not np.array_equal(a.astype(str), b.astype(str)):
            lines.append(f"{name}: text differs")
    return lines


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--rtol", type=float, default=1e-12,
                    help="largest relative difference allowed (1e-12)")
    args = ap.parse_args(argv)
    with xr.open_dataset(args.before) as a, xr.open_dataset(args.after) as b:
        lines = compare(a.load(), b.load(), args.rtol)
        n = len(set(a.variables) | set(b.variables))
    bad = [line for line in lines if "only in" in line or "dims" in line
           or "text differs" in line or "above rtol" in line]
    for line in lines:
        print(line)
    print(f"{n} variables: {'same' if not bad else 'DIFFERENT'} (rtol {args.rtol:g}; "
          f"{len(lines)} differ at all, {len(bad)} beyond)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
