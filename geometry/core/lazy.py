"""Package attributes imported when first used (PEP 562), for packages whose public names
come from heavy modules.

``ltca --help`` and ``ltca cases`` need a few names of a package, not the NumPy, SciPy,
xarray and pandas its public functions pull in; a package lists its exports as
``{name: module}`` and gets a module ``__getattr__`` and ``__dir__`` that import the
module of a name when the name is first asked for (issue 32: start-up ≤ 0.5 s).

Public functions
----------------
lazy_exports   the ``__getattr__`` and ``__dir__`` of a package's lazy exports
"""

from __future__ import annotations

import importlib
import sys
import types
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["lazy_exports"]


def lazy_exports(package: str, exports: Mapping[str, str],
                 namespace: Mapping[str, Any]) -> tuple[Callable[[str], Any],
                                                        Callable[[], list[str]]]:
    """The module ``__getattr__`` and ``__dir__`` of a package's lazily imported names.

    Parameters
    ----------
    package : str
        The package's name (``__name__``), for the error message.
    exports : mapping of str to str
        Public name → the module that defines it (absolute module path).
    namespace : mapping
        The package's ``globals()`` (its eagerly defined names, listed by ``__dir__``).

    Returns
    -------
    (__getattr__, __dir__)
        ``__getattr__(name)`` imports ``exports[name]`` and returns its attribute ``name``
        (AttributeError for a name not listed, as Python's own); ``__dir__()`` lists the
        package's names and the lazy ones.

    Examples
    --------
    In a package's ``__init__.py``::

        __getattr__, __dir__ = lazy_exports(__name__, {"Case": "geometry.case"}, globals())
    """

    def __getattr__(name: str) -> Any:
        module = exports.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        return getattr(importlib.import_module(module), name)

    def __dir__() -> list[str]:
        return sorted({*namespace, *exports})

    mod = sys.modules.get(package)
    if mod is not None and type(mod) is types.ModuleType:
        # a name exported from a submodule of the same name (``mean_point`` of
        # ``geometry.synthesis.mean_point``) stays the exported object when that submodule
        # is first imported, as when the package imported it eagerly
        mod.__class__ = _LazyPackage
        mod.__dict__["_lazy_shadowed"] = frozenset(
            name for name, where in exports.items() if where == f"{package}.{name}")
    return __getattr__, __dir__


class _LazyPackage(types.ModuleType):
    """A package with lazy exports: the import system's binding of a submodule to the
    package attribute of its name is skipped where that name is an export of the
    submodule itself (the export, not the module, is the package's attribute)."""

    def __setattr__(self, name: str, value: Any) -> None:
        if (isinstance(value, types.ModuleType) and name in self.__dict__.get(
                "_lazy_shadowed", ()) and value.__name__ == f"{self.__name__}.{name}"):
            return
        super().__setattr__(name, value)
