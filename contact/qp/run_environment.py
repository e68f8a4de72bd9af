"""What a solver study ran on: backend versions, CPU and BLAS, for its result files.

Timings mean little without the machine and the library versions behind them; qpbenchmark
(Caron et al.) prints both in its reports (``qpbenchmark.utils.get_solver_versions``,
``get_cpu_info_table``). :func:`solver_versions` names each registry backend's package
version the same way, :func:`machine_info` the CPU, BLAS and interpreter.
"""

from __future__ import annotations

import os
import platform
from collections.abc import Sequence
from importlib import metadata

from geometry.core.version import __version__

__all__ = ["cpu_model", "machine_info", "solver_versions"]

#: qpsolvers backend → distribution name where they differ (as qpbenchmark maps them)
_DISTRIBUTION = {
    "gurobi": "gurobipy",
    "highs": "highspy",
    "hpipm": "hpipm_python",
    "proxqp": "proxsuite",
    "qpoases": "qpoases",
    "sip": "sip_qp_python",
    "piqp": "piqp",
}

#: cvxpy solver name → distribution name
_CVXPY_DISTRIBUTION = {
    "CLARABEL": "clarabel",
    "OSQP": "osqp",
    "SCS": "scs",
    "ECOS": "ecos",
    "PIQP": "piqp",
    "PROXQP": "proxsuite",
    "QPALM": "qpalm",
    "DAQP": "daqp",
    "HIGHS": "highspy",
    "GUROBI": "gurobipy",
    "MOSEK": "mosek",
}


def _version(distribution: str) -> str:
    try:
        return metadata.version(distribution)
    except metadata.PackageNotFoundError:
        return "unknown"


def solver_versions(solvers: Sequence[str]) -> dict[str, str]:
    """The package version behind each registry solver name.

    Parameters
    ----------
    solvers : sequence of str
        Registry names (``active_set``, qpsolvers names, ``cvxpy``, ``cvxpy:NAME``).

    Returns
    -------
    dict of str to str
        ``active_set``: ``hypoid-ltca X``; a qpsolvers backend: its package's version and
        qpsolvers'; ``cvxpy:NAME``: cvxpy's and the solver package's; ``unknown`` where
        the distribution is not found.
    """
    out = {}
    qpsolvers = _version("qpsolvers")
    cvxpy = _version("cvxpy")
    for name in solvers:
        if name == "active_set":
            out[name] = f"hypoid-ltca {__version__}"
        elif name == "cvxpy":
            out[name] = f"cvxpy {cvxpy}"
        elif name.startswith("cvxpy:"):
            sub = name.partition(":")[2]
            dist = _CVXPY_DISTRIBUTION.get(sub, sub.lower())
            out[name] = f"cvxpy {cvxpy}, {dist} {_version(dist)}"
        else:
            dist = _DISTRIBUTION.get(name, name)
            out[name] = f"{dist} {_version(dist)} (qpsolvers {qpsolvers})"
    return out


def cpu_model() -> str:
    """The CPU's model name (``/proc/cpuinfo`` on Linux, else :func:`platform.processor`)."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.startswith("model name"):
                    return line.partition(":")[2].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine() or "unknown"


def _blas() -> str:
    """The BLAS NumPy and SciPy call, as threadpoolctl sees it loaded (else NumPy's
    build configuration)."""
    import numpy as np
    import scipy.linalg  # noqa: F401 - loads SciPy's BLAS, so threadpoolctl sees it

    try:
        from threadpoolctl import threadpool_info

        libs = [i for i in threadpool_info() if i.get("user_api") == "blas"]
    except ImportError:  # pragma: no cover - threadpoolctl is a dependency
        libs = []
    if libs:
        return "; ".join(
            f"{i.get('internal_api')} {i.get('version')} ({i.get('architecture')}, "
            f"{i.get('num_threads')} threads, {os.path.basename(i.get('filepath', ''))})"
            for i in libs
        )
    try:
        blas = np.show_config(mode="dicts")["Build Dependencies"]["blas"]
        return f"{blas.get('name')} {blas.get('version')}"
    except (KeyError, TypeError, ValueError):  # pragma: no cover - older NumPy
        return "unknown"


def machine_info() -> dict[str, str | int]:
    """The machine and interpreter a study ran on, as netCDF-safe attributes.

    Returns
    -------
    dict
        ``cpu`` (model name), ``cpu_count`` (logical CPUs), ``platform``, ``python``,
        ``blas`` (library, version, architecture, threads), and the versions of
        ``numpy``, ``scipy``, ``qpsolvers``.
    """
    return {
        "cpu": cpu_model(),
        "cpu_count": os.cpu_count() or 0,
        "platform": platform.platform(),
        "python": platform.python_version(),
        "blas": _blas(),
        "numpy_version": _version("numpy"),
        "scipy_version": _version("scipy"),
        "qpsolvers_version": _version("qpsolvers"),
    }
