"""What the synthesis benchmarks share: the CPU clock and wrapping a toolkit function
wherever it is looked up.

``benchmarks/synthesis_calls.py`` (each analysis of a synthesize) and
``benchmarks/synthesis_stages.py`` (each development stage) both time functions of the
toolkit while ``ltca synthesize`` runs in their process: the same clock (this process's
and its ended children's CPU) and the same wrapping (the function replaced in every loaded
module of ``contact`` and ``geometry`` that holds it, ``from ... import`` copies too, and
put back afterwards). They had each their own copy (the ``duplicates`` tool's D1).
"""

from __future__ import annotations

import importlib
import resource
import sys
from collections.abc import Callable

#: the modules imported before wrapping, so that every ``from ... import`` copy of a
#: wrapped name is there to be replaced (the command's and the development's)
DEVELOPMENT_MODULES = ("contact.commands.synthesize", "contact.optimize.development",
                       "contact.pipeline", "geometry.synthesis.case_synthesis",
                       "contact.compliance.fe.influence")


def cpu_seconds() -> float:
    """This process's and its ended children's user + system CPU [s]."""
    s, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return s.ru_utime + s.ru_stime + c.ru_utime + c.ru_stime


def import_development() -> None:
    """Import :data:`DEVELOPMENT_MODULES` (see there)."""
    for module in DEVELOPMENT_MODULES:
        importlib.import_module(module)


class Wrapped:
    """Functions of the toolkit replaced by wrappers wherever they are looked up, until
    :meth:`remove` puts the originals back."""

    def __init__(self, where: str) -> None:
        self.where = where  # the benchmark, for the message of a moved function
        self._patches: list[tuple[object, str, object]] = []

    def wrap(self, module: str, name: str, wrapper: Callable[[Callable], Callable]) -> None:
        """Replace ``module.name`` by ``wrapper(function)`` in every loaded module of
        ``contact`` and ``geometry`` that holds the function.

        Raises
        ------
        LookupError
            ``module`` has no function ``name`` (it moved: the benchmark's table needs
            updating).
        """
        fn = getattr(importlib.import_module(module), name, None)
        if not callable(fn):
            raise LookupError(f"{self.where}: {module}.{name} is not there (moved?); update "
                              f"benchmarks/{self.where.replace(' ', '_')}.py")
        timed = wrapper(fn)
        timed.__wrapped__ = fn
        for mod in list(sys.modules.values()):
            if (getattr(mod, "__name__", "").split(".")[0] in ("contact", "geometry")
                    and getattr(mod, name, None) is fn):
                setattr(mod, name, timed)
                self._patches.append((mod, name, fn))

    def remove(self) -> None:
        """Put every original back."""
        for owner, name, fn in reversed(self._patches):
            setattr(owner, name, fn)
        self._patches.clear()
