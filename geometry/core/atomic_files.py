"""Atomic file writes that survive interrupts: the old file or the new one, never half of one.

Every file the toolkit writes (netCDF results, case files, reports, problem sets) goes
through :func:`atomic_path`: the data are written to a hidden temporary file beside the
target (``.NAME.PID.XXXX.tmp``) which is renamed onto the target only once complete
(``os.replace`` is atomic on POSIX and Windows within one file system). Three things can
still go wrong, and each is handled here:

* an exception while writing: the temporary file is removed and the target untouched;
* an interrupt (Ctrl-C = SIGINT, SIGTERM) while writing: the signal is held until the
  writer returns (an exception raised inside the HDF5 library can leave its lock taken and
  hang the process at exit), then the temporary file is removed, the target left as it
  was, and the signal delivered as it would have been (``KeyboardInterrupt`` for SIGINT,
  the process's own SIGTERM handler or the default termination). The delay is the rest of
  one write (seconds at most for the toolkit's files);
* a process killed outright (SIGKILL, power loss) leaves its temporary file behind: the
  next write to the same target removes the temporary files of that target whose writing
  process no longer runs (their PID is in the name).

Signals can only be held in the main thread; elsewhere the write is not shielded (the
temporary file is still removed on any exception).

Public functions
----------------
atomic_path          context manager: a temporary path to write, renamed onto the target
stale_temporaries    the temporary files of a target left by processes that no longer run
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import shutil
import signal
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path

from geometry.core.errors import FileWriteError

__all__ = ["atomic_path", "stale_temporaries", "write_failure"]

#: the signals held while a file is written (those a user sends to stop a program)
HELD_SIGNALS = (signal.SIGINT, signal.SIGTERM)


def _pattern(name: str) -> re.Pattern[str]:
    return re.compile(rf"^\.{re.escape(name)}\.(\d+)\.[^.]+\.tmp$")


def _running(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # another user's process: running
        return True
    except OSError:
        return True
    return True


def stale_temporaries(path: str | os.PathLike[str]) -> list[Path]:
    """Temporary files of ``path`` left by writers that no longer run.

    Parameters
    ----------
    path : path-like
        The target file.

    Returns
    -------
    list of pathlib.Path
        Files ``.NAME.PID.XXXX.tmp`` beside ``path`` whose PID is not a running process.
    """
    p = Path(path)
    pat = _pattern(p.name)
    out = []
    try:
        entries = list(p.parent.iterdir())
    except OSError:
        return []
    for entry in entries:
        m = pat.match(entry.name)
        if m and not _running(int(m.group(1))):
            out.append(entry)
    return sorted(out)


def _remove_stale(path: Path) -> None:
    for stale in stale_temporaries(path):
        with contextlib.suppress(OSError):
            stale.unlink()


@contextlib.contextmanager
def _held_signals() -> Iterator[list[int]]:
    """Hold SIGINT/SIGTERM for the block (main thread only, and only those not ignored);
    yield the list of the signals received meanwhile, and restore the previous handlers on
    exit (without delivering them)."""
    received: list[int] = []
    if threading.current_thread() is not threading.main_thread():
        yield received
        return
    previous = {}

    def hold(signum, frame):
        received.append(signum)

    try:
        for sig in HELD_SIGNALS:
            if signal.getsignal(sig) is not signal.SIG_IGN:
                previous[sig] = signal.signal(sig, hold)
        yield received
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


#: [bytes] free space below which a failed write is put down to a full disk (the netCDF
#: library reports a full disk as "HDF error", without the errno)
FULL_DISK_MARGIN = 4 * 1024 * 1024

#: errno → what it means for a write, in a sentence's words
_WRITE_ERRNO = {code: text for code, text in (
    (errno.ENOSPC, "no space left on {dir}"),
    (getattr(errno, "EDQUOT", None), "the disk quota is exceeded on {dir}"),
    (errno.EROFS, "{dir} is on a read-only file system"),
    (errno.EACCES, "no permission to write in {dir}"),
    (errno.EPERM, "no permission to write in {dir}")) if code is not None}
#: the errors that say "no permission", trusted only where the disk has space left
_PERMISSION_ERRNO = (errno.EACCES, errno.EPERM)


def write_failure(path: str | os.PathLike[str], exc: BaseException) -> str | None:
    """Why writing ``path`` failed, as a sentence, when the cause is the disk's or the
    directory's: no space left, a quota, a read-only file system, no permission.

    Parameters
    ----------
    path : path-like
        The file being written.
    exc : BaseException
        The exception the write raised (its ``errno``, or its cause's, is read; an
        exception without one — the netCDF library's "HDF error" — or one saying "no
        permission" (EACCES, EPERM) is put down to a full disk when less than
        :data:`FULL_DISK_MARGIN` bytes are free: the free space is checked before the
        error is trusted).

    Returns
    -------
    str or None
        ``"could not write PATH: no space left on DIR"`` and the like; None when the cause
        is not one of these (the caller reports it its own way).
    """
    target = Path(path)
    folder = str(target.parent.resolve()) if target.parent.exists() else str(target.parent)
    full = f"could not write {str(target)!r}: no space left on {folder}"
    try:  # the disk first: a full disk is reported as such whatever error the write gave
        free: int | None = shutil.disk_usage(target.parent).free
    except OSError:
        free = None
    disk_full = free is not None and free < FULL_DISK_MARGIN
    seen: BaseException | None = exc
    while seen is not None:
        code = getattr(seen, "errno", None)
        if code in _WRITE_ERRNO:
            if disk_full and code in _PERMISSION_ERRNO:
                # a library that cannot write its file on a full disk may say EACCES (the
                # netCDF library's create, issue 64): no permission is not the cause then
                return full
            return f"could not write {str(target)!r}: {_WRITE_ERRNO[code].format(dir=folder)}"
        seen = seen.__cause__ or seen.__context__
    return full if disk_full else None


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str], *, mode: int | None = None) -> Iterator[Path]:
    """A temporary path to write ``path``'s new content to, renamed onto ``path`` on success.

    Parameters
    ----------
    path : path-like
        Target file; its directory must exist.
    mode : int, optional
        Permission bits of the new file; default ``0o666`` less the process's umask (what
        ``open(path, "w")`` gives; ``mkstemp`` alone would give 0600).

    Yields
    ------
    pathlib.Path
        The temporary file (created empty) to write to, by name or by opening it.

    Raises
    ------
    FileWriteError
        The disk is full, the directory read-only or not writable (one sentence naming the
        file and the directory, :func:`write_failure`); the target is left as it was.
    OSError
        The temporary file cannot be created or renamed for another reason.
    KeyboardInterrupt
        SIGINT arrived while writing: the target is left as it was and the temporary file
        removed (SIGTERM is delivered to the process's handler the same way).
    InterruptedError
        A held signal whose handler returned: the target is left as it was.

    Notes
    -----
    Toolkit convention (DESIGN.md: "files written atomically"); the rename is
    ``os.replace`` (POSIX ``rename(2)``: atomic on one file system).
    """
    target = Path(path)
    _remove_stale(target)
    if mode is None:
        umask = os.umask(0)
        os.umask(umask)
        mode = 0o666 & ~umask
    received: list[int] = []
    try:
        # signals held from before the temporary file exists until it is renamed or gone
        with _held_signals() as received:
            try:
                fd, name = tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.",
                                            suffix=".tmp", dir=target.parent)
            except OSError as exc:
                reason = write_failure(target, exc)
                if reason is None:
                    raise
                raise FileWriteError(reason) from exc
            os.close(fd)
            tmp = Path(name)
            try:
                yield tmp
                if not received:
                    os.chmod(tmp, mode)
                    os.replace(tmp, target)
            except OSError as exc:
                reason = write_failure(target, exc)
                if reason is None or isinstance(exc, FileWriteError):
                    raise
                raise FileWriteError(reason) from exc
            finally:
                # on success tmp no longer exists; after an error or a signal it is removed
                with contextlib.suppress(OSError):
                    tmp.unlink()
    finally:
        if received:
            # delivered now, with the process's own handlers back in place
            signal.raise_signal(received[0])
    if received:  # a handler that returned: the write did not happen, say so
        raise InterruptedError(f"writing {str(target)!r} was interrupted (signal "
                               f"{received[0]}); the file was left as it was")
