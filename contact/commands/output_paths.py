"""Checks of the output paths a command will write, made before any work ("refuse early").

A command that computes for seconds or minutes and then cannot write its result wastes the
user's time and prints a traceback from deep inside the writer. Every sub-command checks
the places it will write to first, and refuses with one line naming the option:

* a file (``-o``): not an existing directory; its directory exists (or, where the command
  creates it, is created now) and a file can be created in it;
* a directory (``--plots``, ``plot-geometry -o``): not an existing file; created now with
  its parents, and a file can be created in it.

Writability is tested by creating (and removing) a temporary file, not by ``os.access``,
which answers yes to the superuser on a read-only file system.

Public functions
----------------
check_output_file   the file an option names can be written
check_output_dir    the directory an option names can be created or written into
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from geometry.core.errors import InputError

__all__ = ["check_output_dir", "check_output_file"]


def _probe(directory: Path, option: str) -> None:
    """Create and remove a temporary file in ``directory``: the real test of writability
    (``os.access`` says yes to the superuser on a read-only file system)."""
    if not directory.is_dir():
        raise InputError(f"{option}: {str(directory)!r} is not a directory")
    try:
        with tempfile.TemporaryFile(dir=directory):
            pass
    except OSError as exc:
        raise InputError(f"{option}: cannot write into {str(directory)!r} "
                         f"({exc.strerror or exc})") from None


def _make_dirs(directory: Path, option: str) -> None:
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"{option}: cannot create the directory {str(directory)!r} "
                         f"({exc.strerror or exc})") from None


def check_output_file(path: str | os.PathLike[str], *, option: str = "-o",
                      create_parents: bool = False) -> Path:
    """Check that a file can be written at ``path`` before the work that produces it.

    Parameters
    ----------
    path : path-like
        The file the command will write (replaced if it exists, through a temporary file
        in the same directory and a rename).
    option : str
        The option that names it, for the message (e.g. ``"-o"``).
    create_parents : bool
        The writer creates missing directories (``ltca synthesize``): they are created
        now; otherwise the file's directory must exist (:func:`geometry.core.io.write_netcdf`).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    geometry.core.errors.InputError
        ``path`` is a directory, its directory does not exist (and is not to be created)
        or cannot be created, or no file can be created in it; the message names
        ``option``.
    """
    p = Path(path)
    if p.is_dir():
        raise InputError(f"{option}: {str(p)!r} is a directory; give a file name")
    parent = p.parent
    if not parent.exists():
        if not create_parents:
            raise InputError(f"{option}: directory {str(parent)!r} does not exist")
        _make_dirs(parent, option)
    _probe(parent, option)
    return p


def check_output_dir(path: str | os.PathLike[str], *, option: str = "--plots") -> Path:
    """Create the directory ``path`` (with its parents) if needed and check it is writable.

    Parameters
    ----------
    path : path-like
        The directory the command will write files into.
    option : str
        The option that names it, for the message.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    geometry.core.errors.InputError
        ``path`` is an existing file, cannot be created, or no file can be created in it;
        the message names ``option``.
    """
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InputError(f"{option}: {str(p)!r} is a file, not a directory")
    _make_dirs(p, option)
    _probe(p, option)
    return p
