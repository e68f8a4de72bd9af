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


def check_file(path: str | Path) -> dict[str, dict[str, dict[str, list[str]]]]:
    """:func:`check_group` on every group of ``path``: group → checker → priority → failures."""
    out = {}
    suite = _suite()
    with tempfile.TemporaryDirectory() as tmp:
        for i, group in enumerate(group_paths(path)):
            flat = extract_group(path, group, Path(tmp) / f"group{i}.nc")
            out[group] = check_group(flat, suite)
    return out


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("path")
    parser.add_argument("-v", "--verbose", action="store_true", help="list every failed check")
    args = parser.parse_args()
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
