"""The toolkit's exception family.

Every error the toolkit raises on purpose derives from :class:`LTCAError`, so a
user catches one family. The root lives in ``geometry`` because it is the bottom
of the chain (``contact`` and ``friction`` may import ``geometry``, never the
other way round).
"""

from __future__ import annotations

__all__ = ["InputError", "LTCAError", "ModelUnavailableError"]


class LTCAError(Exception):
    """Root of every exception the toolkit raises on purpose."""


class InputError(LTCAError, ValueError):
    """An input is out of its accepted range, of the wrong shape or type, or not finite.

    The message names the field and the accepted range.
    """


class ModelUnavailableError(LTCAError, LookupError):
    """A model or solver was asked for by a name that is not available here.

    The message lists the available names and, where it applies, why the
    requested one is unavailable or how to install it.
    """
