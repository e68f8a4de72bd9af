"""Plain progress lines of a command made of named steps (``ltca synthesize``, ``ltca
report``): ``synthesize: step 3/10, pinion concave: generating tools (12 s)``.

Each line is complete, so a log file or a pipe (CI, ``nohup``, a batch system) shows how
far a command of minutes is, as the studies' ``"lines"`` mode does
(:mod:`geometry.core.progress`). ``ltca`` turns them on when the command's ``progress``
(set by :func:`contact.cli.main` from ``--no-progress``, ``-q`` and whether standard error
is a terminal) is not False.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import TextIO

__all__ = ["StepLines"]


class StepLines:
    """A callable that prints one line per step it is told of.

    Parameters
    ----------
    desc : str
        What runs (the line's prefix).
    total : int
        Steps of the whole command, ≥ 1.
    unit : str
        What a step is (``"step"``, ``"figure"``).
    stream : file-like, optional
        Default standard error.
    clock : callable, optional
        The monotonic clock [s] (tests pass their own).
    """

    def __init__(self, desc: str, total: int, unit: str = "step",
                 stream: TextIO | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.desc, self.total, self.unit, self.done = desc, int(total), unit, 0
        self.stream, self.clock = stream, clock
        self.start = clock()

    def __call__(self, step: str) -> None:
        """Step ``step`` starts: ``<desc>: <unit> k/total, <step> (<elapsed>)``.

        A command that goes through its steps again (the development bearing
        re-synthesises a case it has changed) counts them again from 1, the pass named:
        ``<desc>: pass 2, <unit> 1/total, ...`` — never a step beyond the total."""
        self.done += 1
        passes, k = divmod(self.done - 1, self.total)
        elapsed = round(self.clock() - self.start)
        took = f"{elapsed} s" if elapsed < 60 else f"{elapsed // 60} min {elapsed % 60} s"
        again = f"pass {passes + 1}, " if passes else ""
        print(f"{self.desc}: {again}{self.unit} {k + 1}/{self.total}, {step} ({took})",
              file=self.stream if self.stream is not None else sys.stderr, flush=True)
