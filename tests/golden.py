"""The golden file of the default ``ltca run``: how it is made and how a run is compared.

``tests/data/golden_default_run.nc`` is the netCDF that ``ltca run`` (no arguments: the
bundled default case at the seed's Table 3.1 conditions, the efficiency stage at 1500 rpm)
writes, encoded with zlib so that it is small enough to keep in the repository (lossless).
First written before the restructuring of ``contact/`` into its layers (issue 20), which
reproduced it; rewritten when the default case became the reference design
``kolivand2009_fm_11x41_reference`` (issue 19), an intended change of every result. It
guards every refactoring that must not change results: a new run must reproduce every
variable and attribute but the timings and the file's creation stamp.

Check a working tree bit for bit (every float identical, the residuals excepted)::

    python tests/golden.py --check

Regenerate it only when a change of results is intended and reviewed::

    python tests/golden.py --write

When only the attributes the writer stamps change (e.g. the ACDD attributes, issue 21),
take the new run's attributes into the golden file, its values kept, only after the
values were found identical::

    python tests/golden.py --adopt-attributes
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np
import xarray as xr

GOLDEN = Path(__file__).parent / "data" / "golden_default_run.nc"

#: attributes that record when and how fast, not what
_SKIP_ATTRS = ("history", "date_created")
#: variables that are timings [s]
_SKIP_VARS = ("solve_time", "compliance_time")
#: [1] the relative residuals of the contact conditions are round-off (~1e-16): they vary
#: from run to run in their last bits even on one machine (numpy's vectorised sums depend on
#: the arrays' alignment), so they are compared to this absolute tolerance, 1e5 below the
#: certification tolerance (contact.DEFAULT_TOLERANCE, 1e-7)
RESIDUAL_ATOL = 1e-12


#: module paths the file's text attributes name, moved when ``contact/`` was split into its
#: layers (issue 20): the golden file's text is read with the new paths (the old ones still
#: import for one release, contact._moved)
MOVED_PATHS = {
    "contact.easeoff.ease_off": "contact.utca.ease_off",
    "contact.edge.EDGE_KINDS": "contact.ltca.EDGE_KINDS",
}


#: reviewed changes of results since the golden file was written: variable → (largest
#: difference relative to the variable's largest magnitude, why). The bit-for-bit check
#: allows these and no more.
REVIEWED: dict[str, tuple[float, str]] = {}


def _moved(value):
    if isinstance(value, str):
        for old, new in MOVED_PATHS.items():
            value = value.replace(old, new)
    return value


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
        magnitude (0: bit-identical, NaN where NaN; the contact residuals to
        :data:`RESIDUAL_ATOL`, the :data:`REVIEWED` changes to their bound); integers,
        text and attributes must always be identical (the golden file's text read with
        :data:`MOVED_PATHS`).

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
        out += _attr_differences(path, a.attrs, b.attrs)
        names_a = {k for k in a.variables if k not in _SKIP_VARS}
        names_b = {k for k in b.variables if k not in _SKIP_VARS}
        if names_a != names_b:
            out.append(f"{path}: variables differ: {sorted(names_a ^ names_b)}")
        for name in sorted(names_a & names_b):
            va, vb = a.variables[name], b.variables[name]
            where = f"{path}/{name}"
            if va.dims != vb.dims or va.shape != vb.shape:
                out.append(f"{where}: dims {va.dims}{va.shape} != {vb.dims}{vb.shape}")
                continue
            out += _attr_differences(where, va.attrs, vb.attrs)
            x, y = np.asarray(va.values), np.asarray(vb.values)
            if x.dtype.kind == "f" and y.dtype.kind == "f":
                same_nan = np.array_equal(np.isnan(x), np.isnan(y))
                d = np.nan_to_num(np.abs(x - y), nan=0.0)
                scale = float(np.nanmax(np.abs(y), initial=0.0))
                worst = float(d.max(initial=0.0))
                atol = RESIDUAL_ATOL if name.startswith("residual_") else 0.0
                reviewed = REVIEWED.get(where, (0.0, ""))[0]
                if not same_nan or worst > max(rtol * scale, reviewed * scale, atol):
                    out.append(f"{where}: differs by {worst:.3g} (largest |value| "
                               f"{scale:.3g}; NaN pattern same: {same_nan})")
            elif not np.array_equal(x, y):
                out.append(f"{where}: values differ")
    return out


def _attr_differences(where: str, a: dict, b: dict) -> list[str]:
    out = []
    keys_a = {k for k in a if not _skipped_attr(k)}
    keys_b = {k for k in b if not _skipped_attr(k)}
    if keys_a != keys_b:
        out.append(f"{where}: attributes differ: {sorted(keys_a ^ keys_b)}")
    for k in sorted(keys_a & keys_b):
        x, y = a[k], _moved(b[k])
        if isinstance(x, (float, np.floating)) and isinstance(y, (float, np.floating)):
            if not (x == y or (math.isnan(x) and math.isnan(y))):
                out.append(f"{where}: attribute {k}: {x!r} != {y!r}")
        elif not np.array_equal(np.asarray(x), np.asarray(y)):
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
    from contact.io import read_netcdf

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

    from contact.io import read_netcdf

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

            from contact.io import read_netcdf

            with tempfile.TemporaryDirectory() as tmp:
                new = read_netcdf(run_default(Path(tmp)), tree=True)
            found = adopt_attributes(new)
            print("\n".join(found) if found else f"adopted the attributes into {GOLDEN}")
            raise SystemExit(1 if found else 0)
        elif args.check:
            import tempfile

            from contact.io import read_netcdf

            with tempfile.TemporaryDirectory() as tmp:
                new = read_netcdf(run_default(Path(tmp)), tree=True)
            found = differences(new, read_netcdf(GOLDEN, tree=True), rtol=0.0)
            reviewed = "; ".join(f"{k}: {why}" for k, (_, why) in REVIEWED.items())
            print("\n".join(found) if found else "identical to the golden file"
                  + (f" (but the reviewed changes: {reviewed})" if reviewed else ""))
            raise SystemExit(1 if found else 0)
        else:
            parser.print_help()
