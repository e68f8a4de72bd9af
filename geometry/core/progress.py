"""Progress of long work (studies, FE builds, rolls): a bar on a terminal, else plain lines.

A study of a few hundred points runs for minutes. On a terminal a tqdm bar shows how far
it is; written to a file or a pipe (a CI runner, ``nohup``, a batch system) a bar is one
unreadable line of carriage returns, or nothing at all, and a long study looks hung. So a
study reports in one of two modes:

* ``True``: a tqdm bar (on the stream tqdm writes to, standard error);
* ``"lines"``: plain lines on standard error, each complete —
  ``sweep: 61/121 points (50 %), 1.9 points/s, ETA 32 s`` — at every tenth of the work
  and at least every :data:`LINE_INTERVAL` seconds while points arrive, and a last line
  when the study ends: ``sweep: 121/121 points in 64 s (1.9 points/s)``.

``ltca`` chooses: a bar when standard error is a terminal, lines when it is not (and
nothing with ``-q`` or ``--no-progress``); the Python API takes the mode as the studies'
``progress`` argument.

Public functions
----------------
progress_reporter   the reporter of a mode: a tqdm bar, a ProgressLines or None
ProgressLines       plain periodic progress lines (update, close)
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable
from typing import Any, TextIO

from geometry.core.errors import InputError

__all__ = ["LINE_INTERVAL", "ProgressLines", "progress_reporter"]

#: the longest wait [s] between two progress lines while points arrive
LINE_INTERVAL = 30.0
#: a line at every this share of the work
_STEP = 0.1


def _duration(seconds: float) -> str:
    """``"42 s"``, ``"3 min 20 s"``, ``"2 h 5 min"``."""
    s = round(seconds)
    if s < 60:
        return f"{s} s"
    if s < 3600:
        return f"{s // 60} min {s % 60} s"
    return f"{s // 3600} h {(s % 3600) // 60} min"


class ProgressLines:
    """Plain progress lines of a study (the ``"lines"`` mode of :func:`progress_reporter`).

    Parameters
    ----------
    total : int
        Tasks of the whole study, ≥ 0.
    initial : int
        Tasks done before this run (a resumed study), in [0, total].
    desc, unit : str
        What the study is and what it counts (``"sweep"``, ``"point"``).
    stream : file-like, optional
        Where the lines go; default standard error.
    interval : float — [s]
        The longest wait between two lines while tasks finish; default
        :data:`LINE_INTERVAL`.
    clock : callable, optional
        The monotonic clock [s] (tests pass their own).

    Notes
    -----
    A line is written when the done count crosses a tenth of ``total`` (deterministic:
    ten lines for a study of any size, the last of them :meth:`close`'s) or when
    ``interval`` has passed since the last one, and on :meth:`close`. The rate counts the
    tasks of this run only (a resumed study's ``initial`` ones took no time here); the
    ETA is the remaining tasks at that rate.
    """

    def __init__(self, total: int, initial: int = 0, desc: str = "study", unit: str = "point",
                 stream: TextIO | None = None, interval: float = LINE_INTERVAL,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if isinstance(total, bool) or not isinstance(total, int) or total < 0:
            raise InputError(f"total: must be an integer >= 0, got {total!r}")
        if isinstance(initial, bool) or not isinstance(initial, int) or not \
                0 <= initial <= total:
            raise InputError(f"initial: must be an integer in [0, {total}], got {initial!r}")
        self.total, self.initial, self.done = total, initial, initial
        self.desc, self.unit = desc, unit
        self.stream = stream
        self.interval = float(interval)
        self.clock = clock
        self.start = self.last = clock()
        self._next = self._milestone(initial)
        self.closed = False
        if initial:
            self._write(f"{desc}: resuming, {initial}/{total} {unit}s done before")

    def _milestone(self, done: int) -> int:
        """The next done count at which a tenth of the work is crossed."""
        step = max(1, math.ceil(_STEP * self.total))
        return (done // step + 1) * step

    def _write(self, text: str) -> None:
        out = self.stream if self.stream is not None else sys.stderr
        print(text, file=out, flush=True)

    def _rate(self, now: float) -> float:
        elapsed = now - self.start
        return (self.done - self.initial) / elapsed if elapsed > 0 else math.nan

    def update(self, n: int = 1) -> None:
        """``n`` more tasks done; a line if a tenth of the work was crossed or the
        interval has passed (not for the last task: :meth:`close` says it)."""
        self.done += n
        now = self.clock()
        if self.done >= self.total:
            return  # the last line is close()'s
        if self.done >= self._next or now - self.last >= self.interval:
            self._next = self._milestone(self.done)
            self.last = now
            rate = self._rate(now)
            share = 100.0 * self.done / self.total if self.total else 100.0
            eta = ((self.total - self.done) / rate if rate > 0 and math.isfinite(rate)
                   else math.nan)
            self._write(f"{self.desc}: {self.done}/{self.total} {self.unit}s ({share:.0f} %), "
                        + (f"{rate:.2g} {self.unit}s/s" if math.isfinite(rate) else "rate -")
                        + (f", ETA {_duration(eta)}" if math.isfinite(eta) else ""))

    def close(self) -> None:
        """The last line: how many tasks in how long (once)."""
        if self.closed:
            return
        self.closed = True
        now = self.clock()
        rate = self._rate(now)
        self._write(f"{self.desc}: {self.done}/{self.total} {self.unit}s in "
                    f"{_duration(now - self.start)}"
                    + (f" ({rate:.2g} {self.unit}s/s)" if math.isfinite(rate) and rate > 0
                       else ""))


def progress_reporter(progress: Any, total: int, *, initial: int = 0, desc: str = "study",
                      unit: str = "point", stream: TextIO | None = None) -> Any:
    """The progress reporter of a study for its ``progress`` argument.

    Parameters
    ----------
    progress : bool or {"lines"}
        False: none; True: a tqdm bar; ``"lines"``: :class:`ProgressLines`.
    total, initial, desc, unit
        As :class:`ProgressLines` (and tqdm's).
    stream : file-like, optional
        Where the lines go (``"lines"`` only); default standard error.

    Returns
    -------
    tqdm.tqdm, ProgressLines or None
        Each with ``update(n)`` and ``close()``.

    Raises
    ------
    InputError
        ``progress`` not one of the modes.
    """
    if progress is False or progress is None:
        return None
    if progress == "lines":
        return ProgressLines(total, initial, desc, unit, stream=stream)
    if progress is True:
        from tqdm.auto import tqdm

        return tqdm(total=total, initial=initial, desc=desc, unit=unit)
    raise InputError(f"progress: must be True, False or 'lines', got {progress!r}")
