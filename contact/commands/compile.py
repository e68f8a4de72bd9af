"""``ltca compile``: fill numba's cache with the hot loops' compiled kernels ahead of use."""

from __future__ import annotations

import argparse

#: Place in ``ltca --help``.
ORDER = 95


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection (no numerical library
    imported here)."""
    p = sub.add_parser(
        "compile",
        help="compile the numba kernels into the cache (a container image, a cluster node)",
        description="Runs the default case's contact analysis (geometry, UTCA, LTCA; no "
        "root stress) with the compiled kernels, so that numba's cache holds them for this "
        "machine: the first command after it starts without the ~20 s of compiling "
        "(and with the auto choice of kernels, ltca run's default, which runs the NumPy "
        "path until the cache holds them, every command uses them). Point numba's cache "
        "directory at a shared one to fill it once for the nodes of a cluster "
        "(docs/environment.md, docs/performance.md).",
    )
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import time

    from geometry.core.errors import InputError
    from geometry.core.kernels import KERNEL_MODULES, cache_ready, compiled_module

    if compiled_module(KERNEL_MODULES[0]) is None:
        raise InputError("ltca compile: numba is not installed or has no writable cache "
                         "(pip install 'hypoid-ltca[fast]'; NUMBA_CACHE_DIR)")
    ready = {name: cache_ready(name) for name in KERNEL_MODULES}
    start = time.process_time()
    if not all(ready.values()):
        import os

        from contact.pipeline import run_analysis

        os.environ["LTCA_KERNELS"] = "numba"  # this process only: it exists to compile
        run_analysis(None, [250.0], steps={"root_stress": None, "mesh_interface": None,
                                           "efficiency": None, "load_capacity": None})
    cpu = time.process_time() - start
    if not getattr(args, "quiet", False):
        for name, was in ready.items():
            print(f"{name}: {'already in the cache' if was else 'compiled'}")
        print(f"numba kernels ready ({cpu:.1f} s CPU)")
    return 0
