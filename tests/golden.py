"""The golden file of the default ``ltca run``: how it is made and how a run is compared.

``tests/data/golden_default_run.nc`` is the netCDF that ``ltca run`` (no arguments: the
bundled default case at the seed's Table 3.1 conditions, the efficiency stage at 1500 rpm)
writes, encoded with zlib so that it is small enough to keep in the repository (lossless).
First written before the restructuring of ``contact/`` into its layers (issue 20), which
reproduced it; rewritten when the default case became the reference design
``kolivand2009_fm_11x41_reference`` (issue 19), an intended change of every result; and
when ``kolivand2009`` became the default friction model (issue 34: ``/friction`` and the
summary's efficiency changed, every other variable identical); and when ``kolivand2009``
was refitted to the stochastic mixed-EHL solver and fed the total slide-to-roll ratio
(issue 51: ``/friction`` — its new ``slide_to_roll_total`` — and the summary's efficiency
changed, every other variable within the tolerances below); and when the default run
gained the tooth-root stress (issue 53: ``/ltca/root_stress``, ``root_stress_max``), the
ISO 10300 rating (issue 52: the ``/rating`` group; the cases' ``inputs`` gained their
``[design]`` and ``[rating]`` tables), scuffing and micropitting (issue 52: new
``/friction`` variables) and version 0.2.0 — every variable of the previous file
unchanged (``--check`` listed only new variables, groups and attributes); and for 0.3.0,
whose run stores the standard's flash temperature method as ``/rating/flash_temperature``
(the group added, every other group and value kept, the version attribute adopted). It
guards every refactoring that must not change results: a new run must reproduce every
variable and attribute but the timings and the file's creation stamp.

Check a working tree bit for bit (every float identical, the residuals excepted)::

    python tests/golden.py --check

Regenerate it only when a change of results is intended and reviewed::

    python tests/golden.py --write

When only the attributes the writer stamps change (e.g. the ACDD attributes, issue 21; the
module names in the provenance text when ``geometry/`` got its subpackages, issue 31),
take the new run's attributes into the golden file, its values kept, only after the
values were found identical::

    python tests/golden.py --adopt-attributes
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import NamedTuple

import numpy as np
import xarray as xr

GOLDEN = Path(__file__).parent / "data" / "golden_default_run.nc"

#: attributes that record when and how fast, not what
_SKIP_ATTRS = ("history", "date_created", "date_modified", "date_metadata_modified")
#: variables that are timings [s]
_SKIP_VARS = ("solve_time", "compliance_time")
#: [1] the relative residuals of the contact conditions are round-off (~1e-16): they vary
#: from run to run in their last bits even on one machine (numpy's vectorised sums depend on
#: the arrays' alignment), so they are compared to this absolute tolerance, 1e5 below the
#: certification tolerance (contact.DEFAULT_TOLERANCE, 1e-7)
RESIDUAL_ATOL = 1e-12


class Tolerance(NamedTuple):
    """How a float variable or attribute is compared across machines (``rtol > 0``)."""

    rtol: float  #: [1] of the variable's largest magnitude (an attribute: of its value)
    atol: float  #: in the variable's units
    why: str


#: float variables (by path, or by name in every group) and attributes (by name) whose
#: comparison across CPUs and BLAS builds cannot be the default ``rtol`` of the variable's
#: largest magnitude. Measured with ``OPENBLAS_CORETYPE`` forced to Zen, Sandybridge,
#: Nehalem and Prescott against the file written with SkylakeX kernels (issue 31): every
#: other variable and attribute agreed to ≤ 2e-10 of its scale.
ACROSS_MACHINES: dict[str, Tolerance] = {
    "/friction/friction_coefficient": Tolerance(
        1e-7, 0.0,
        "a friction coefficient is a function of its segment's own load (kolivand2009: "
        "the Eyring traction over the segment's Hertz zone and powers of p_h; xu2007: "
        "p_h^1.03), not of the largest load: at the lightest loaded "
        "segments (force ~1e-3 of the largest) the forces' round-off, ~1e-11 of the largest "
        "force, is ~1e-8 of the segment's own, and μ there moved by 4-5e-9 of the largest μ; "
        "1e-7 keeps a factor 20"),
    "/friction/film_thickness": Tolerance(
        1e-7, 0.0,
        "[µm] a minimum film thickness is a power of its segment's own load "
        "(Dowson-Higginson h ∝ w^-0.13, and the thermal factor through p_h), not of the "
        "largest load: at the lightest loaded segments the forces' round-off (~1e-8 of the "
        "segment's own force) moved h by 1.4e-9 µm of the largest 0.72 µm (2e-9) on CI's "
        "forced Katmai kernels (issue 31); 1e-7 keeps the factor of friction_coefficient"),
    "/friction/lambda_ratio": Tolerance(
        1e-7, 0.0,
        "[1] the film thickness over the composite roughness (see film_thickness): "
        "1.3e-9 of the largest 0.64 measured"),
    "/friction/specific_film_thickness": Tolerance(
        1e-7, 0.0,
        "[1] λ_GF = h_min / Ra of the segment (issue 52): the film thickness's tolerance (see "
        "film_thickness), 1.3e-9 of the largest 1.12 measured on forced kernels"),
    "/friction/specific_film_thickness_min": Tolerance(
        1e-7, 0.0, "[1] the least specific_film_thickness of a torque (see that entry)"),
    "placement_error": Tolerance(
        0.0, 1e-9,
        "[mm] a convergence diagnostic, not a result: the residual of the conjugate point's "
        "last Newton step (accepted below 1e-7 mm, contact.utca.easeoff), round-off of that "
        "step's arithmetic (1e-13 mm measured); 1e-9 mm is 1 % of the acceptance tolerance, "
        "and a different iteration count would move the ease-off by far more than the "
        "default rtol, so it shows there"),
    "meshing_residual": Tolerance(
        0.0, 1e-12,
        "[1] the equation-of-meshing residual at a solved point (~1e-12): round-off of the "
        "last Newton step, 1e-15 measured; the identity is asserted at 1e-10 by the "
        "geometry tests, so 1e-12 is 1 % of that bound"),
    "max_placement_error_mm": Tolerance(
        0.0, 1e-9, "the largest placement_error of the file (see placement_error)"),
    "max_abs_meshing_residual": Tolerance(
        0.0, 1e-12, "the largest |meshing_residual| of a flank (see meshing_residual)"),
}


def tolerance(where: str, rtol: float) -> Tolerance:
    """The tolerance of a float variable at ``where`` (``/group/name``) or of an attribute
    (its name): :data:`ACROSS_MACHINES`' entry for its path or name, the contact residuals'
    :data:`RESIDUAL_ATOL`, else ``rtol`` of its scale. With ``rtol = 0`` (bit for bit on the
    machine that wrote the file) only the residuals' round-off is allowed."""
    name = where.rpartition("/")[2]
    if name.startswith("residual_"):
        return Tolerance(rtol, RESIDUAL_ATOL, "the contact residuals are round-off")
    if rtol == 0.0:
        return Tolerance(0.0, 0.0, "bit for bit")
    return ACROSS_MACHINES.get(where, ACROSS_MACHINES.get(name, Tolerance(rtol, 0.0, "")))


#: reviewed changes of results since the golden file was written: variable → (largest
#: difference relative to the variable's largest magnitude, why). The bit-for-bit check
#: allows these and no more.
REVIEWED: dict[str, tuple[float, str]] = {}


def _skipped_attr(name: str) -> bool:
    return name in _SKIP_ATTRS or name.startswith("time_")


def run_default(directory: Path) -> Path:
    """Run ``ltca run`` exactly as a user types it (no arguments) into ``directory``."""
    from contact.cli import main

    out = Path(directory) / "ltca.nc"
    code = main(["run", "--no-progress", "-o", str(out)])
    if code != 0:
        raise RuntimeError(f"ltca run exited with {code}")
    return out


def differences(new: xr.DataTree, golden: xr.DataTree, *, rtol: float = 0.0) -> list[str]:
    """Every difference between two analysis trees, timings excepted.

    Parameters
    ----------
    new, golden : xarray.DataTree
    rtol : float
        Largest difference of a float variable relative to the variable's largest
        magnitude, and of a float attribute relative to its value (0: bit-identical, NaN
        where NaN, the contact residuals to :data:`RESIDUAL_ATOL`); with ``rtol > 0`` the
        variables and attributes of :data:`ACROSS_MACHINES` to their own tolerance;
        the :data:`REVIEWED` changes to their bound. Integers and text must always be
        identical.

    Returns
    -------
    list of str
        One line per difference (empty when the trees agree).
    """
    out: list[str] = []
    new_paths = {n.path for n in new.subtree}
    old_paths = {n.path for n in golden.subtree}
    if new_paths != old_paths:
        out.append(f"groups differ: new {sorted(new_paths ^ old_paths)}")
    for path in sorted(new_paths & old_paths):
        a = new[path].to_dataset(inherit=False)
        b = golden[path].to_dataset(inherit=False)
        out += _attr_differences(path, a.attrs, b.attrs, rtol)
        names_a = {k for k in a.variables if k not in _SKIP_VARS}
        names_b = {k for k in b.variables if k not in _SKIP_VARS}
        if names_a != names_b:
            out.append(f"{path}: variables differ: {sorted(names_a ^ names_b)}")
        for name in sorted(names_a & names_b):
            va, vb = a.variables[name], b.variables[name]
            where = f"{path.rstrip('/')}/{name}"
            if va.dims != vb.dims or va.shape != vb.shape:
                out.append(f"{where}: dims {va.dims}{va.shape} != {vb.dims}{vb.shape}")
                continue
            out += _attr_differences(where, va.attrs, vb.attrs, rtol)
            x, y = np.asarray(va.values), np.asarray(vb.values)
            if x.dtype.kind == "f" and y.dtype.kind == "f":
                same_nan = np.array_equal(np.isnan(x), np.isnan(y))
                d = np.nan_to_num(np.abs(x - y), nan=0.0)
                scale = float(np.nanmax(np.abs(y), initial=0.0)) if np.any(~np.isnan(y)) else 0.0
                worst = float(d.max(initial=0.0))
                tol = tolerance(where, rtol)
                reviewed = REVIEWED.get(where, (0.0, ""))[0]
                if not same_nan or worst > max(tol.rtol * scale, reviewed * scale, tol.atol):
                    out.append(f"{where}: differs by {worst:.3g} (largest |value| "
                               f"{scale:.3g}; NaN pattern same: {same_nan})")
            elif not np.array_equal(x, y):
                out.append(f"{where}: values differ")
    return out


def _attr_differences(where: str, a: dict, b: dict, rtol: float) -> list[str]:
    out = []
    keys_a = {k for k in a if not _skipped_attr(k)}
    keys_b = {k for k in b if not _skipped_attr(k)}
    if keys_a != keys_b:
        out.append(f"{where}: attributes differ: {sorted(keys_a ^ keys_b)}")
    for k in sorted(keys_a & keys_b):
        x, y = np.asarray(a[k]), np.asarray(b[k])
        if x.dtype.kind == "f" and y.dtype.kind == "f" and x.shape == y.shape:
            tol = tolerance(k, rtol)
            bound = np.maximum(tol.rtol * np.maximum(np.abs(x), np.abs(y)), tol.atol)
            close = (np.abs(x - y) <= bound) | (np.isnan(x) & np.isnan(y))
            if not np.all(close):
                out.append(f"{where}: attribute {k}: {a[k]!r} != {b[k]!r}")
        elif not np.array_equal(x, y):
            out.append(f"{where}: attribute {k} differs")
    return out


def _store(tree: xr.DataTree, path: Path) -> Path:
    encoding = {}
    for node in tree.subtree:
        ds = node.to_dataset(inherit=False)
        encoding[node.path] = {k: {"zlib": True, "complevel": 9, "shuffle": True}
                               for k in ds.data_vars if ds[k].dtype.kind in "fiu"}
    tmp_path = path.with_suffix(".tmp")
    tree.to_netcdf(tmp_path, engine="netcdf4", encoding=encoding)
    tmp_path.replace(path)
    return path


def adopt_attributes(new: xr.DataTree, path: Path = GOLDEN) -> list[str]:
    """Give the golden file the attributes of ``new`` (groups and variables), its values
    untouched, if ``new`` differs from it in attributes only; else leave it and return
    the differences of values."""
    from geometry.core.io import read_netcdf

    golden = read_netcdf(path, tree=True)
    values = [d for d in differences(new, golden) if "attribute" not in d]
    if values:
        return values
    for node in golden.subtree:
        mine = new[node.path].to_dataset(inherit=False)
        ds = node.to_dataset(inherit=False)
        ds.attrs = dict(mine.attrs)
        for name in ds.variables:
            ds[name].attrs = dict(mine[name].attrs)
        node.dataset = ds
    _store(golden, path)
    return []


def write_golden(path: Path = GOLDEN) -> Path:
    """Run ``ltca run`` and store its file, zlib-compressed, at ``path``."""
    import tempfile

    from geometry.core.io import read_netcdf

    with tempfile.TemporaryDirectory() as tmp:
        tree = read_netcdf(run_default(Path(tmp)), tree=True)
    return _store(tree, path)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="(re)write the golden file")
    parser.add_argument("--check", action="store_true",
                        help="run and compare bit for bit (the residuals to RESIDUAL_ATOL)")
    parser.add_argument("--adopt-attributes", action="store_true",
                        help="take a new run's attributes into the golden file if its values "
                             "are identical")
    args = parser.parse_args()
    from threadpoolctl import threadpool_limits

    # as the test suite runs (tests/conftest.py): one BLAS thread
    with threadpool_limits(limits=1, user_api="blas"):
        if args.write:
            print(f"wrote {write_golden()}")
        elif args.adopt_attributes:
            import tempfile

            from geometry.core.io import read_netcdf

            with tempfile.TemporaryDirectory() as tmp:
                new = read_netcdf(run_default(Path(tmp)), tree=True)
            found = adopt_attributes(new)
            print("\n".join(found) if found else f"adopted the attributes into {GOLDEN}")
            raise SystemExit(1 if found else 0)
        elif args.check:
            import tempfile

            from geometry.core.io import read_netcdf

            with tempfile.TemporaryDirectory() as tmp:
                new = read_netcdf(run_default(Path(tmp)), tree=True)
            found = differences(new, read_netcdf(GOLDEN, tree=True), rtol=0.0)
            reviewed = "; ".join(f"{k}: {why}" for k, (_, why) in REVIEWED.items())
            print("\n".join(found) if found else "identical to the golden file"
                  + (f" (but the reviewed changes: {reviewed})" if reviewed else ""))
            raise SystemExit(1 if found else 0)
        else:
            parser.print_help()
