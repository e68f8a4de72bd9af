"""Which implementation of the hot loops runs: NumPy (the reference) or numba's compiled kernels.

Four loops of an analysis run small computations point by point many thousand times:
the envelope solve of the tooth surfaces (:mod:`geometry.machine.meshing`, kernels
:mod:`geometry.machine.envelope_numba`), the contact curves' iso-line searches on the
ease-off splines (:mod:`contact.utca.fields`, kernels :mod:`contact.utca.isoline_numba`),
the shell tooth's point mapping (:mod:`contact.compliance.tooth_map`, kernels
:mod:`contact.compliance.tooth_map_numba`) and the contact problem's block pivoting
(:mod:`contact.qp.solvers.active_set`, kernels :mod:`contact.qp.solvers.pivoting_numba`).
Each has a NumPy path, batched over the points, and a compiled one (numba, the ``fast``
extra) that runs the same iterations point by point. This module chooses between them,
the same way for all: an explicit ``kernels`` argument where a function takes one, else
the environment variable ``LTCA_KERNELS``, else numba where it is installed.

Public functions
----------------
KERNELS           the implementations' names
kernels_module    the compiled kernel module to use, or None for the NumPy path
compiled_module   a compiled kernel module, imported once per process (None without numba)
"""

from __future__ import annotations

import importlib
import logging
import os
from types import ModuleType

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["KERNELS", "compiled_module", "kernels_module"]

#: the implementations: ``numpy`` (the reference) and ``numba`` (compiled; the ``fast`` extra)
KERNELS = ("numpy", "numba")


@memoised(maxsize=None)
def compiled_module(name: str) -> ModuleType | None:
    """The compiled kernel module ``name``, or None where numba is not installed or cannot
    cache the kernels (logged); imported once per process."""
    try:
        return importlib.import_module(name)
    except ImportError:
        return None
    except RuntimeError as exc:  # numba finds no writable cache directory
        logging.getLogger(__name__).warning(
            "compiled kernels %s unavailable (%s); the NumPy path runs (set "
            "NUMBA_CACHE_DIR to a writable directory to use them)", name, exc)
        return None


def kernels_module(name: str, kernels: str | None = None) -> ModuleType | None:
    """The compiled kernel module to use, or None for the NumPy path.

    Parameters
    ----------
    name : str
        The kernel module's import name (e.g. ``"geometry.machine.envelope_numba"``).
    kernels : {"numpy", "numba"} or None
        None: the environment variable ``LTCA_KERNELS`` (same values), else ``numba``
        where it is installed and ``numpy`` otherwise.

    Returns
    -------
    module or None
        The kernel module, or None (NumPy).

    Raises
    ------
    InputError
        An unknown name, or ``numba`` asked for where it is not installed.
    """
    source = "kernels"
    if kernels is None:
        kernels = os.environ.get("LTCA_KERNELS") or None
        source = "LTCA_KERNELS"
        if kernels is None:
            return compiled_module(name)
    if kernels not in KERNELS:
        raise InputError(f"{source}: must be one of {', '.join(KERNELS)}, got {kernels!r}")
    if kernels == "numpy":
        return None
    mod = compiled_module(name)
    if mod is None:
        raise InputError(f"{source}: 'numba' needs numba installed "
                         "(pip install 'hypoid-ltca[fast]', from a clone: pip install "
                         "'.[fast]')")
    return mod
