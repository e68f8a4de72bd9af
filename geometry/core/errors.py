"""The toolkit's exception family.

Every error the toolkit raises on purpose derives from :class:`LTCAError`, so a
user catches one family. The root lives in ``geometry`` because it is the bottom
of the chain (``contact`` and ``friction`` may import ``geometry``, never the
other way round).
"""

from __future__ import annotations

__all__ = ["FileWriteError", "InputError", "LTCAError", "ModelUnavailableError", "PluginError",
           "StudyFailedError", "UnknownNameError"]


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


class UnknownNameError(ModelUnavailableError, InputError):
    """A solver, model or method of a registry asked for by a name that is none of those
    available here (an unknown name, or a known one whose optional package or data is
    missing).

    The message names the field and lists the accepted names. It is bad input (an
    :class:`InputError`, a ``ValueError``: what a caller checking its inputs catches) and
    a :class:`ModelUnavailableError` (a ``LookupError``), as these errors were before
    (issue 71, branch api82: ``LTCAOptions(solver="x")``, ``rate_load_capacity(method="x")``
    and ``friction_coefficient("x")`` raised a LookupError no ``except InputError`` caught).
    """


class PluginError(InputError):
    """A model or solver given by the user (registered, a plug-in or the object itself)
    raised, or returned what its contract refuses, when called: the wrong shape, a
    negative or non-finite value.

    The message names the plug-in, what it raised or returned and what is accepted
    (docs/extending.md); the toolkit's own exceptions raised inside a plug-in pass
    through unchanged.
    """


class StudyFailedError(LTCAError, RuntimeError):
    """A study produced no result at all: every one of its points failed.

    A point that fails is a result of a study (stored with its reason); a study none of
    whose points succeeded is an error. The message gives the number of points and the
    first point's reason.
    """


class FileWriteError(LTCAError, OSError):
    """A file could not be written: no space left, a read-only or forbidden directory.

    The message is one sentence naming the file and what failed (``no space left on
    DIR``); the file's previous content, if any, is left as it was
    (:mod:`geometry.core.atomic_files`).
    """


def raise_if_interrupted(exc: BaseException) -> None:
    """Raise the KeyboardInterrupt (Ctrl-C, or the CLI's SIGTERM) that ``exc`` wraps, if any.

    A signal's handler runs wherever the interpreter next checks for signals; inside a
    numba kernel's call that is numba's own Python callback, and the kernel then raises
    ``SystemError: CPUDispatcher(...) returned a result with an exception set`` with the
    KeyboardInterrupt as its cause. A handler that takes any ``Exception`` as one failed
    trial ("one failing design never ends the development") would swallow the user's
    stop: ``ltca synthesize`` ran on for minutes after SIGTERM (round 18, measured: 73
    more lines in 120 s, then SIGKILL). Such handlers call this first.

    Parameters
    ----------
    exc : BaseException
        The exception caught; its ``__cause__`` / ``__context__`` chain is followed.

    Returns
    -------
    None
        Where no KeyboardInterrupt is in the chain.

    Raises
    ------
    KeyboardInterrupt
        The one found in the chain (itself, with its own traceback), so that the command
        stops as Ctrl-C stops it.

    Notes
    -----
    Source: Python's C API, ``_Py_CheckFunctionResult`` (a call that returns a result with
    an exception set raises SystemError chained to that exception), as numba's dispatcher
    reports an exception raised in its Python callbacks.
    """
    seen: set[int] = set()
    e: BaseException | None = exc
    while e is not None and id(e) not in seen:
        if isinstance(e, KeyboardInterrupt):
            raise e
        seen.add(id(e))
        e = e.__cause__ if e.__cause__ is not None else e.__context__
