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

``auto`` (``LTCA_KERNELS=auto``, opt-in, :func:`prefer_cached`) runs the compiled
kernels only where numba's cache already holds them for this machine
(:func:`cache_ready`), and the NumPy path otherwise. ``ltca run`` run as its own process
takes the NumPy path (:func:`prefer_numpy`): importing numba and loading its cached
kernels cost more than they save in one run (the 10x43's written case, numba's cache
full: 4.2 s of CPU on NumPy against 4.9 s compiled at its two torques, 6.0 against 7.1 s
at nine; docs/performance.md, "A new design on a fresh numba cache: what is left to
compile"), and the same run gives the same numbers whatever the cache holds. Numba
compiles the four modules in ≈ 22 s of CPU on their first use (the envelope's Newton
solve 6.3 s, the iso-line seeds 4.5 s, the block pivoting 4.3 s, measured on the 2-core
machine with ``numba.core.event``), while a warm ``ltca run`` of the default case costs
3.9 s with either path (3.7 s NumPy, 3.9 s numba): one analysis never earns its compile
time back. A study point (0.24 s against 0.40 s) or a synthesis (50 s against 73 s of CPU on
the 10x43 of tests/data/designs) does, so the commands that run many analyses ask for
``numba`` (:func:`prefer_compiled`) and fill the cache; ``ltca compile`` fills it ahead
(a container image, each node of a cluster, or ``NUMBA_CACHE_DIR`` on a shared file
system). ``ltca synthesize`` on a cache without all four modules compiles the envelope's
kernels only, the one module whose compile one synthesis earns back (~10 s of compiling
against ~14 s saved; the others ~15 s against ≤ 2.4 s, docs/performance.md, "A new
design on a fresh numba cache"), and runs the others' NumPy path until they are cached.
Both paths give the same numbers to round-off (the kernels' tests). ``auto`` is
resolved once per process and for the four modules together (:func:`process_choice`),
and a study's local workers are started with the process's choice
(``contact.study.engine.worker_environment``), so a study and the analyses of the process
that started it run the same path.

Public functions
----------------
KERNELS           the implementations' names (and ``auto``)
KERNEL_MODULES    the four compiled kernel modules
kernels_module    the compiled kernel module to use, or None for the NumPy path
compiled_module   a compiled kernel module, imported once per process (None without numba)
cache_ready       whether numba's cache holds a module's kernels for this machine
process_choice    ``numpy`` or ``numba``: what this process runs (``auto`` resolved)
prefer_compiled   make ``auto`` mean ``numba`` in this process (commands of many analyses),
                  or numba for the modules that pay (``ltca synthesize`` on a fresh cache)
compiled_modules  the kernel modules this process runs compiled
prefer_cached     make ``auto`` the default in this process
prefer_numpy      make ``numpy`` the default in this process (a command of one analysis)
announce_compiling  log (once per module and process, :data:`COMPILING_LOGGER`) that numba
                  is about to compile a module's kernels
"""

from __future__ import annotations

import importlib
import logging
import os
import sys
from types import ModuleType

from geometry.core.caches import memoised
from geometry.core.errors import InputError

__all__ = ["COMPILING_LOGGER", "KERNELS", "KERNEL_MODULES", "announce_compiling", "cache_ready",
           "compiled_module", "compiled_modules", "kernels_module", "prefer_cached",
           "prefer_compiled", "prefer_numpy", "process_choice"]

#: the implementations: ``numpy`` (the reference), ``numba`` (compiled; the ``fast``
#: extra) and ``auto`` (numba where its cache holds the kernels, :func:`cache_ready`)
KERNELS = ("numpy", "numba", "auto")

#: the compiled kernel modules of the four hot loops
KERNEL_MODULES = ("geometry.machine.envelope_numba", "contact.utca.isoline_numba",
                  "contact.compliance.tooth_map_numba", "contact.qp.solvers.pivoting_numba")


#: the logger :func:`announce_compiling` tells that numba is about to compile a module's
#: kernels (at INFO, once per module and process): the command line prints its one-time
#: compile note at that record, not before a command has checked its inputs (issue 71)
COMPILING_LOGGER = "geometry.core.kernels.compiling"


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


def _no_index_file(name: str) -> bool:
    """Whether no numba cache index of module ``name`` exists wherever numba could keep
    one (checked without importing numba or the module: on a fresh cache the import, ≈ 1 s
    of CPU, decides nothing; issue 75): ``NUMBA_CACHE_DIR`` and below where set, else on
    Linux the module's ``__pycache__`` and numba's user-wide cache (``$XDG_CACHE_HOME``
    or ``~/.cache``, ``numba`` and below). An index file is named ``<module file's
    stem>.<function>-<line>.py<version>.nbi`` (numba's ``_CacheImpl``). False where
    unsure (another platform, the module not found): :func:`cache_ready` then asks numba.
    """
    import importlib.util
    from pathlib import Path

    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return False
    if spec is None or not spec.origin:
        return False
    source = Path(spec.origin)
    given = os.environ.get("NUMBA_CACHE_DIR")
    if given:
        places = [Path(given)]
    elif sys.platform.startswith("linux"):
        user = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "numba"
        places = [source.parent / "__pycache__", user]
    else:
        return False
    pattern = f"{source.stem}.*.nbi"
    try:
        return not any(p.is_dir() and next(p.rglob(pattern), None) is not None
                       for p in places)
    except OSError:
        return False


@memoised(maxsize=None)
def cache_ready(name: str) -> bool:
    """Whether numba's cache holds every kernel of module ``name`` for this machine.

    Every compiled function (``numba.njit(cache=True)`` dispatcher) of the module has an
    entry in its cache index for this CPU (numba's target triple, CPU name and features)
    and the index matches the module's source (numba drops an index whose source stamp
    differs). Decided once per process, so an analysis runs one path throughout.

    Parameters
    ----------
    name : str
        The kernel module's import name (one of :data:`KERNEL_MODULES`).

    Returns
    -------
    bool
        False where numba is not installed, the cache cannot be read, or a kernel has
        not been compiled on this machine yet.
    """
    if _no_index_file(name):  # a fresh cache: numba is not even imported (~1 s)
        return False
    module = compiled_module(name)
    if module is None:
        return False
    from numba.core.registry import CPUDispatcher

    dispatchers = [f for f in vars(module).values() if isinstance(f, CPUDispatcher)]
    if not dispatchers:
        return False
    try:
        for f in dispatchers:
            magic = f.targetctx.codegen().magic_tuple()
            index = f._cache._cache_file._load_index()  # {(sig, magic, ..): file}
            if not any(key[1] == magic for key in index):
                return False
    except (AttributeError, OSError, EOFError, ValueError) as exc:  # numba's layout moved
        logging.getLogger(__name__).debug("numba cache of %s not readable: %s", name, exc)
        return False
    return True


#: ``auto``'s choice in this process, made at its first use (:func:`process_choice`) and
#: kept by :func:`geometry.core.caches.clear_caches` (it is a decision, not a memo of a
#: value: made again after numba's cache has filled, it would switch the process's path
#: between two analyses that must agree bit for bit)
_AUTO_CHOICE: dict[str, str] = {}

#: the modules ``auto`` runs compiled in this process whatever numba's cache holds (set
#: by :func:`prefer_compiled` with ``modules``: they pay their compile within the command)
_COMPILED_ANYWAY: dict[str, tuple[str, ...]] = {}


def process_choice() -> str:
    """What this process runs: ``LTCA_KERNELS`` where it names ``numpy`` or ``numba``,
    unset or empty ``numba`` where it is installed, ``auto`` ``numba`` where numba's cache
    holds every kernel module for this machine (:func:`cache_ready`) and ``numpy``
    otherwise — the four modules one way, as :func:`kernels_module` runs them, decided
    at the first call in the process and kept (:data:`_AUTO_CHOICE`; ``clear_caches`` leaves it).

    Returns
    -------
    str
        ``"numpy"`` or ``"numba"`` (an unknown ``LTCA_KERNELS`` is returned as given:
        :func:`kernels_module` names it in its error).
    """
    kernels = os.environ.get("LTCA_KERNELS") or None
    if kernels is None:
        return "numba" if compiled_module(KERNEL_MODULES[0]) is not None else "numpy"
    return _auto_choice() if kernels == "auto" else kernels


def _auto_choice() -> str:
    """``auto`` resolved: made at its first use in the process and kept (:data:`_AUTO_CHOICE`)."""
    if "auto" not in _AUTO_CHOICE:
        # a module without an index file first: answered without importing numba (~1 s),
        # also where another module's kernels are cached (the envelope's, after an
        # ltca synthesize on a fresh cache, prefer_compiled's ``modules``)
        first = sorted(KERNEL_MODULES, key=lambda name: not _no_index_file(name))
        ready = all(cache_ready(name) for name in first)
        _AUTO_CHOICE["auto"] = "numba" if ready else "numpy"
    return _AUTO_CHOICE["auto"]


def prefer_compiled(modules: tuple[str, ...] | None = None) -> None:
    """Make ``auto`` (the default) mean ``numba`` in this process and the processes it
    starts (Dask's local workers): for the commands that run many analyses (a synthesis'
    development, a study, a sweep, an optimisation), where the compiled kernels earn their
    first-use compile time back. Sets ``LTCA_KERNELS=numba`` where it is unset and numba
    is installed; a user's ``LTCA_KERNELS`` wins. Called by the command-line layer only.

    Parameters
    ----------
    modules : tuple of str, optional
        Only these kernel modules (of :data:`KERNEL_MODULES`) earn their compile back in
        the command (``ltca synthesize``: the envelope's, measured in docs/performance.md,
        "Compiled kernels on a fresh cache"): where numba's cache does not hold all four
        modules yet, ``LTCA_KERNELS=auto`` is set, these run compiled (numba compiles them
        if it must) and the others the NumPy path (:func:`kernels_module`), decided here
        for the process; where it holds all four, ``numba`` as without ``modules``.
    """
    if os.environ.get("LTCA_KERNELS") or compiled_module(KERNEL_MODULES[0]) is None:
        return
    if modules is not None and not all(cache_ready(name) for name in KERNEL_MODULES):
        os.environ["LTCA_KERNELS"] = "auto"
        _AUTO_CHOICE["auto"] = "numpy"
        _COMPILED_ANYWAY["modules"] = tuple(modules)
        return
    os.environ["LTCA_KERNELS"] = "numba"


def compiled_modules() -> tuple[str, ...]:
    """The kernel modules (of :data:`KERNEL_MODULES`) this process runs compiled as
    :func:`kernels_module` chooses them without a ``kernels`` argument: all four where
    ``LTCA_KERNELS`` (or its default) means ``numba``, those :func:`prefer_compiled` named
    under ``auto``, none on the NumPy path.

    Returns
    -------
    tuple of str
        Module import names (empty: the NumPy path throughout).
    """
    if process_choice() == "numba":
        return KERNEL_MODULES
    if os.environ.get("LTCA_KERNELS") == "auto":
        return _COMPILED_ANYWAY.get("modules", ())
    return ()


@memoised(maxsize=None)
def announce_compiling(name: str) -> bool:
    """Log at INFO on :data:`COMPILING_LOGGER` that numba is about to compile the kernels of
    module ``name`` (its cache holds none for this machine, :func:`cache_ready`), once per
    module and process: called where a compiled module is handed to a hot loop
    (:func:`kernels_module`) or to a study's workers. The command line prints its compile
    note at the first such record, so that a command refused on its inputs prints the
    refusal alone (issue 71: the note used to come first, on every fresh cache).

    Parameters
    ----------
    name : str
        The kernel module's import name (one of :data:`KERNEL_MODULES`).

    Returns
    -------
    bool
        True where numba will compile the module (logged), False where it is cached.
    """
    if cache_ready(name):
        return False
    logging.getLogger(COMPILING_LOGGER).info("compiling the numba kernels of %s", name)
    return True


def _handed(module: ModuleType | None, name: str) -> ModuleType | None:
    """``module`` (compiled kernels about to run, or None: the NumPy path), announced."""
    if module is not None:
        announce_compiling(name)
    return module


def prefer_cached() -> None:
    """Make ``auto`` the choice of this process (and the processes it starts): the
    compiled kernels where numba's cache holds them (:func:`cache_ready`), the NumPy path
    otherwise (opt-in; ``ltca run`` took it as its own process's default until issue 75's
    compile90 measured the NumPy path cheaper even on a full cache, :func:`prefer_numpy`).
    Sets ``LTCA_KERNELS=auto`` where it is unset; a user's ``LTCA_KERNELS`` wins. For
    a command layer only, where the command is the process (not for ``contact.cli.main``
    called with arguments from Python, whose process keeps one path for all its
    analyses)."""
    if not os.environ.get("LTCA_KERNELS"):
        os.environ["LTCA_KERNELS"] = "auto"


def prefer_numpy() -> None:
    """Make the NumPy path the choice of this process (and the processes it starts) where
    the user set no ``LTCA_KERNELS``: for a command of one analysis run as its own
    process (``ltca run``). One analysis never earns numba's first-use compile back (≈ 20 s
    of CPU, docs/performance.md "Compiled kernels"), and on a full cache importing numba
    and loading the kernels cost more than they save: the 10x43 new design's ``ltca run``
    4.2 s of CPU on NumPy against 4.9 s compiled (two torques, four alternated pairs), 6.0
    against 7.1 s at nine torques (two pairs) (docs/performance.md, "A new design on a fresh numba
    cache: what is left to compile", issue 75). The run's numbers then do not depend on
    what numba's cache holds (issue 71; the paths agree to round-off, ≤ 4.2e-10 of each
    variable's largest value there). Sets ``LTCA_KERNELS=numpy`` where it is unset; a
    user's ``LTCA_KERNELS`` wins. Called by the command-line layer only, and only where the
    command is the process (``contact.cli.main([...])`` called from Python leaves the
    process's default alone)."""
    if not os.environ.get("LTCA_KERNELS"):
        os.environ["LTCA_KERNELS"] = "numpy"


def kernels_module(name: str, kernels: str | None = None) -> ModuleType | None:
    """The compiled kernel module to use, or None for the NumPy path.

    Parameters
    ----------
    name : str
        The kernel module's import name (e.g. ``"geometry.machine.envelope_numba"``).
    kernels : {"numpy", "numba", "auto"} or None
        None: the environment variable ``LTCA_KERNELS`` (same values), else numba where
        it is installed and NumPy otherwise. ``auto``: numba where its cache holds the
        four modules' kernels for this machine (:func:`cache_ready`,
        :func:`process_choice`), else NumPy.

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
        if kernels is None:  # the default: numba where it is installed
            return _handed(compiled_module(name), name)
    if kernels not in KERNELS:
        raise InputError(f"{source}: must be one of {', '.join(KERNELS)}, got {kernels!r}")
    if kernels == "numpy":
        return None
    if kernels == "auto":
        anyway = name in _COMPILED_ANYWAY.get("modules", ())
        return (_handed(compiled_module(name), name)
                if anyway or _auto_choice() == "numba" else None)
    mod = compiled_module(name)
    if mod is None:
        raise InputError(f"{source}: 'numba' needs numba installed "
                         "(pip install 'hypoid-ltca[fast]', from a clone: pip install "
                         "'.[fast]')")
    return _handed(mod, name)
