"""Keyword arguments renamed across the public API, the old name kept for one release.

The toolkit gives one quantity one argument name (docs/nomenclature.md, "Argument
names"); where a function used another name, :func:`renamed_keywords` keeps the old
keyword working for one release and warns with a :class:`DeprecationWarning` naming the
new one. ``tests/test_api_names.py`` walks the public API and refuses the old names.
"""

from __future__ import annotations

import functools
import inspect
import warnings
from collections.abc import Callable
from typing import Any, TypeVar

from geometry.core.errors import InputError

__all__ = ["renamed_keywords"]

F = TypeVar("F", bound=Callable[..., Any])


def renamed_keywords(**renames: str) -> Callable[[F], F]:
    """Accept each old keyword for one release, mapped to its new name with a warning.

    Parameters
    ----------
    **renames : str
        ``old="new"``: the keyword ``old`` is passed on as ``new``. ``new`` must be a
        parameter of the decorated function (of ``__init__`` for a class).

    Returns
    -------
    callable
        A decorator. On a function it wraps the function; on a class it wraps the
        class's ``__init__`` (a dataclass's generated one included) and returns the class.

    Raises
    ------
    TypeError
        At decoration, when a new name is not a parameter or an old name still is.
    geometry.core.errors.InputError
        At a call that gives both the old and the new keyword.

    Warns
    -----
    DeprecationWarning
        At a call that uses an old keyword, naming the new one.

    Examples
    --------
    >>> @renamed_keywords(speed="pinion_speed")
    ... def rate(*, pinion_speed=None):
    ...     return pinion_speed
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", DeprecationWarning)
    ...     rate(speed=1200.0)
    1200.0
    """
    def decorate(obj: F) -> F:
        target = obj.__init__ if isinstance(obj, type) else obj  # type: ignore[misc]
        params = inspect.signature(target).parameters
        for old, new in renames.items():
            if new not in params:
                raise TypeError(f"renamed_keywords: {new!r} is not a parameter of "
                                f"{obj.__qualname__}")
            if old in params:
                raise TypeError(f"renamed_keywords: {old!r} is still a parameter of "
                                f"{obj.__qualname__}")
        name = obj.__qualname__

        @functools.wraps(target)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            for old, new in renames.items():
                if old in kwargs:
                    if new in kwargs:
                        raise InputError(f"{name}: give {new!r} only ({old!r} is its old "
                                         "name)")
                    warnings.warn(f"{name}: the keyword {old!r} is renamed {new!r}; the old "
                                  "name goes in the next release", DeprecationWarning,
                                  stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return target(*args, **kwargs)

        wrapper.renamed_keywords = dict(renames)  # type: ignore[attr-defined]
        if isinstance(obj, type):
            obj.__init__ = wrapper  # type: ignore[misc]
            return obj
        return wrapper  # type: ignore[return-value]

    return decorate
