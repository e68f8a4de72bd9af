"""Run the IOOS compliance-checker (CF and ACDD) on every group of a netCDF file.

The compliance-checker reads the root group of a file only, so each group is copied,
as a user extracting it would get it, to a flat file of its own (its dimensions,
variables, variable attributes and group attributes; nothing inherited from the root)
and checked there. Used by ``tests/test_cf_compliance.py`` and, from the command line,
to report the failed checks of a file per group and priority::

    python tests/cf_check.py ltca.nc [-v]
"""

from __future__ import annotations

import argparse
import contextlib
import tempfile
from pathlib import Path

import netCDF4

#: the checker suites run on every group: the CF version the files declare, and ACDD 1.3
CHECKERS = ("cf:1.8", "acdd:1.3")
PRIORITIES = {3: "high", 2: "medium", 1: "low"}


def group_paths(path: str | Path) -> list[str]:
    """Paths of every group of a netCDF file that holds variables or attributes."""
    out = []

    def walk(group, where):
        if group.variables or group.ncattrs():
            out.append(where)
        for name, child in group.groups.items():
            walk(child, f"{where.rstrip('/')}/{name}")

    with netCDF4.Dataset(path) as nc:
        walk(nc, "/")
    return out


def extract_group(path: str | Path, group: str, target: str | Path) -> Path:
    """Copy one group of ``path`` to the root of a new file ``target`` (byte for byte:
    the variables keep their types, fill values and attributes)."""
    with netCDF4.Dataset(path) as src, netCDF4.Dataset(target, "w") as dst:
        g = src[group] if group != "/" else src
        dims = {d for v in g.variables.values() for d in v.dimensions} | set(g.dimensions)
        for name in sorted(dims):
            size = len(_dimension(g, name))
            dst.createDimension(name, size)
        for name, var in g.variables.items():
            attrs = {k: var.getncattr(k) for k in var.ncattrs()}
            fill = attrs.pop("_FillValue", None)
            out = dst.createVariable(name, var.datatype, var.dimensions, fill_value=fill)
            out.setncatts(attrs)
            for v in (out, var):  # the bytes as stored (char arrays stay char arrays)
                v.set_auto_maskandscale(False)
                v.set_auto_chartostring(False)
            out[...] = var[...]
        dst.setncatts({k: g.getncattr(k) for k in g.ncattrs()})
    return Path(target)


def _dimension(group, name):
    while group is not None:
        if name in group.dimensions:
            return group.dimensions[name]
        group = group.parent
    raise KeyError(name)


#: compliance-checker 6.1's scans of a whole dataset (``compliance_checker.cf.util``), each a
#: function of the open file alone, that its checks call again for every variable: on the
#: /ltca group (62 variables) ``get_auxiliary_coordinate_variables`` ran 1498 times and the
#: scans took 24 of the 31 s of its check (cProfile). They are remembered per dataset for
#: the duration of :func:`check_file` (the file is opened read-only and never changes
#: during a check), so each runs once per group; the report is the same, failure for
#: failure (checked with and without: ``python tests/cf_check.py FILE --compare``).
_SCANS = ("get_auxiliary_coordinate_variables", "get_forecast_metadata_variables",
          "get_cell_boundary_map", "get_cell_boundary_variables", "get_bounds_variables",
          "get_geophysical_variables", "get_z_variables", "get_time_variable",
          "get_time_variables", "get_axis_variables", "get_climatology_variable",
          "get_platform_variables", "get_instrument_variables", "coordinate_dimension_matrix",
          "is_geophysical")


def _copy(value):
    """A fresh container of a remembered result (a check may change the list it gets)."""
    if isinstance(value, list | set | tuple):
        return type(value)(value)
    if type(value) is dict:
        return dict(value)
    return value


@contextlib.contextmanager
def _scans_remembered():
    """Replace :data:`_SCANS` in ``compliance_checker.cf.util`` (the checks call them through
    that module) by versions that remember their result per dataset; put back on exit."""
    from compliance_checker.cf import util

    saved = {name: getattr(util, name) for name in _SCANS}

    def remembering(function):
        memo = {}

        def scan(nc, *args):
            key = (id(nc), *args)
            if key not in memo:
                memo[key] = (nc, function(nc, *args))  # nc kept: its id is not reused
            return _copy(memo[key][1])
        return scan

    try:
        for name, function in saved.items():
            setattr(util, name, remembering(function))
        yield
    finally:
        for name, function in saved.items():
            setattr(util, name, function)


def _suite():
    from compliance_checker.runner import CheckSuite

    suite = CheckSuite()
    suite.load_all_available_checkers()
    return suite


def check_group(path: str | Path, suite=None) -> dict[str, dict[str, list[str]]]:
    """Run :data:`CHECKERS` on a flat file: checker → priority → failed checks (one line
    each: the check's name and its messages)."""
    suite = suite or _suite()
    ds = suite.load_dataset(str(path))
    out: dict[str, dict[str, list[str]]] = {}
    for checker, (results, errors) in suite.run_all(ds, list(CHECKERS)).items():
        failed: dict[str, list[str]] = {p: [] for p in PRIORITIES.values()}
        if errors:
            failed["high"] += [f"checker error in {name}: {err}" for name, err in errors.items()]
        for res in suite.build_structure(checker, results, str(path))["all_priorities"]:
            if res.value[1] and res.value[0] < res.value[1]:
                msgs = "; ".join(str(m) for m in res.msgs)
                failed[PRIORITIES.get(res.weight, "low")].append(f"{res.name}: {msgs}")
        out[checker] = failed
    ds.close()
    return out


def check_file(path: str | Path, remember_scans: bool = True
               ) -> dict[str, dict[str, dict[str, list[str]]]]:
    """:func:`check_group` on every group of ``path``: group → checker → priority → failures.
    ``remember_scans``: the checker's whole-dataset scans run once per group
    (:func:`_scans_remembered`); False runs the checker as installed."""
    out = {}
    suite = _suite()
    scans = _scans_remembered() if remember_scans else contextlib.nullcontext()
    with tempfile.TemporaryDirectory() as tmp, scans:
        for i, group in enumerate(group_paths(path)):
            flat = extract_group(path, group, Path(tmp) / f"group{i}.nc")
            out[group] = check_group(flat, suite)
    return out


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("path")
    parser.add_argument("-v", "--verbose", action="store_true", help="list every failed check")
    parser.add_argument("--compare", action="store_true",
                        help="check with the remembered scans and without: the reports agree")
    args = parser.parse_args()
    if args.compare:
        same = check_file(args.path) == check_file(args.path, remember_scans=False)
        print("the reports agree" if same else "THE REPORTS DIFFER")
        raise SystemExit(0 if same else 1)
    totals: dict[tuple[str, str], int] = {}
    for group, by_checker in check_file(args.path).items():
        for checker, by_priority in by_checker.items():
            counts = {p: len(f) for p, f in by_priority.items()}
            print(f"{group:28s} {checker:9s} " + " ".join(f"{p} {n}" for p, n in counts.items()))
            for p, n in counts.items():
                totals[checker, p] = totals.get((checker, p), 0) + n
            if args.verbose:
                for p, fails in by_priority.items():
                    for f in fails:
                        print(f"    [{p}] {f}")
    print("total: " + ", ".join(f"{c} {p} {n}" for (c, p), n in totals.items()))
