"""The run file's write: CPU and the memory it adds over the run tree (issue 75; helper
speed83: the defined-first writer, ``geometry.core.netcdf_tree_write``, held every
variable's data in HDF5's chunk caches until the file closed).

``ltca run`` of a case (default: the bundled default case; its FE cache as this machine
has it) runs once in this process and its run tree is kept (the tree ``write_netcdf``
gets). Then, each in a fresh child process that reads the tree back (pickle) and writes it
once to warm its imports:

* ``xarray``: ``DataTree.to_netcdf`` (``write_netcdf``'s fallback; a define and a write
  per variable, the netCDF library leaving define mode each time);
* ``defined first, all cached``: ``write_tree_defined_first`` with every variable's
  encoded data kept from its definition and written through HDF5's chunk cache
  (``UNCACHED_BYTES`` above every variable: speed82's writer);
* ``defined first``: ``write_tree_defined_first`` as it is (variables of at least
  ``UNCACHED_BYTES`` encoded again when written, past the chunk cache).

Printed: the least and median CPU of ``--repeats`` writes (``time.process_time``) and the
peak resident memory during one write over the resident memory before it (``VmHWM``
reset through ``/proc/self/clear_refs``; Linux). CPU, not wall time: the machine may be
shared.

Usage: ``python benchmarks/run_write_memory.py [CASE] [--repeats N]``.
"""

from __future__ import annotations

import argparse
import pickle
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: (label, UNCACHED_BYTES set in the child: None xarray's to_netcdf, 0 the module's own)
WAYS = (("xarray to_netcdf", None), ("defined first, all cached", 1 << 62),
        ("defined first", 0))


def _status() -> dict[str, float]:
    """VmRSS and VmHWM of this process [MB]."""
    out = {}
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(("VmRSS", "VmHWM")):
                out[line.split(":")[0]] = int(line.split()[1]) / 1024
    return out


def _child(tree_file: str, uncached: str, repeats: int, out: str) -> None:
    """Write the pickled tree ``repeats`` + 1 times; print CPU and the peak over RSS."""
    import geometry.core.io as io
    import geometry.core.netcdf_tree_write as tree_write

    with open(tree_file, "rb") as f:
        tree, kwargs = pickle.load(f)
    if uncached == "xarray":
        io.write_tree_defined_first = lambda *a, **k: False
    elif int(uncached):
        tree_write.UNCACHED_BYTES = int(uncached)
    io.write_netcdf(tree, out, **kwargs)  # imports, first use
    before = _status()["VmRSS"]
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")
    cpu = []
    for _ in range(repeats):
        t0 = time.process_time()
        io.write_netcdf(tree, out, **kwargs)
        cpu.append(time.process_time() - t0)
    print(f"{min(cpu):.3f} {statistics.median(cpu):.3f} {_status()['VmHWM'] - before:.1f}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("case", nargs="?", default=None, help="case (default the default)")
    parser.add_argument("--repeats", type=int, default=5, help="writes per way")
    parser.add_argument("--child", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        _child(*args.child[:2], args.repeats, args.child[2])
        return 0

    import geometry.core.io as io
    from contact.cli import main as ltca
    from geometry.core.netcdf_tree_write import UNCACHED_BYTES

    with tempfile.TemporaryDirectory() as tmp:
        tree_file = str(Path(tmp) / "tree.pkl")
        real = io.write_netcdf

        def kept(obj, path, **kwargs):
            with open(tree_file, "wb") as f:
                pickle.dump((obj, kwargs), f)
            return real(obj, path, **kwargs)

        io.write_netcdf = kept
        try:
            rc = ltca(["run", *([args.case] if args.case else []),
                       "-o", str(Path(tmp) / "run.nc"), "-q"])
        finally:
            io.write_netcdf = real
        if rc:
            print(f"ltca run failed (exit code {rc})")
            return int(rc)
        with open(tree_file, "rb") as f:
            tree = pickle.load(f)[0]
        nodes = list(tree.subtree)
        sizes = [v.nbytes for n in nodes for v in n.to_dataset(inherit=False).variables.values()]
        print(f"run tree: {len(nodes)} groups, {len(sizes)} variables, "
              f"{sum(sizes) / 2**20:.1f} MB; {sum(s >= UNCACHED_BYTES for s in sizes)} "
              f"variables of at least UNCACHED_BYTES = {UNCACHED_BYTES} B")
        print("\n| writer | CPU least [s] | CPU median [s] | peak over the RSS before [MB] |")
        print("|---|---|---|---|")
        for label, uncached in WAYS:
            got = subprocess.run(
                [sys.executable, __file__, "--repeats", str(args.repeats), "--child",
                 tree_file, "xarray" if uncached is None else str(uncached),
                 str(Path(tmp) / "out.nc")],
                capture_output=True, text=True, cwd=ROOT, check=True).stdout.split()
            least, median, peak = (float(x) for x in got[-3:])
            print(f"| {label} | {least:.3f} | {median:.3f} | {peak:+.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
