"""Studies talk without a terminal and close their cluster quietly (issue 56, item 3).

* :class:`geometry.core.progress.ProgressLines` on a clock the test moves: a line at every
  tenth of the work, one when the interval passes between them, the rate and the ETA of
  the tasks done so far, a last line — asserted on content, the clock is the test's;
* ``ltca sweep`` in a subprocess with its output in pipes (not a terminal) on a local
  cluster of two workers: its progress lines appear on standard error, and distributed
  says nothing of workers killed at the close or of a port in use.
"""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys

import pytest

from geometry.core.errors import InputError
from geometry.core.progress import ProgressLines, progress_reporter


class _Clock:
    def __init__(self) -> None:
        self.now = 100.0

    def __call__(self) -> float:
        return self.now


def test_lines_at_every_tenth_and_at_the_interval():
    clock, out = _Clock(), io.StringIO()
    bar = ProgressLines(20, desc="sweep", unit="point", stream=out, interval=30.0, clock=clock)
    for _ in range(4):  # 2 s per point: a line at 2 and 4 points (each tenth: 2 points)
        clock.now += 2.0
        bar.update()
    lines = out.getvalue().splitlines()
    assert lines == ["sweep: 2/20 points (10 %), 0.5 points/s, ETA 36 s",
                     "sweep: 4/20 points (20 %), 0.5 points/s, ETA 32 s"]
    clock.now += 31.0  # a slow point: the interval passes before the next tenth
    bar.update()
    assert out.getvalue().splitlines()[-1] == "sweep: 5/20 points (25 %), 0.13 points/s, " \
                                              "ETA 1 min 57 s"
    for _ in range(15):
        clock.now += 1.0
        bar.update()
    bar.close()
    bar.close()  # once
    lines = out.getvalue().splitlines()
    assert lines[-1] == "sweep: 20/20 points in 54 s (0.37 points/s)"
    assert len(lines) == 2 + 1 + 7 + 1  # tenths 2, 4; the interval; 6 … 18; the end


def test_a_resumed_study_counts_its_own_rate():
    clock, out = _Clock(), io.StringIO()
    bar = ProgressLines(10, initial=6, desc="tolerance", stream=out, clock=clock)
    clock.now += 4.0
    bar.update()
    lines = out.getvalue().splitlines()
    assert lines[0] == "tolerance: resuming, 6/10 points done before"
    assert lines[1] == "tolerance: 7/10 points (70 %), 0.25 points/s, ETA 12 s"


def test_modes_and_bad_input():
    assert progress_reporter(False, 5) is None
    assert isinstance(progress_reporter("lines", 5, stream=io.StringIO()), ProgressLines)
    bar = progress_reporter(True, 5, desc="x")
    assert hasattr(bar, "update") and hasattr(bar, "close")
    bar.close()
    with pytest.raises(InputError, match="progress"):
        progress_reporter("bar", 5)
    with pytest.raises(InputError, match="initial"):
        ProgressLines(5, initial=6)
    with pytest.raises(InputError, match="total"):
        ProgressLines(-1)


def test_study_run_checks_progress():
    from contact.study.run import StudyRun

    assert StudyRun(progress="lines").progress == "lines"
    with pytest.raises(InputError, match="progress"):
        StudyRun(progress="bar")


def test_sweep_in_a_pipe_prints_progress_and_closes_quietly(tmp_path):
    """Output to pipes: plain progress lines, and no distributed warnings at the close."""
    env = {**os.environ, "HYPOID_LTCA_CACHE": os.environ.get("HYPOID_LTCA_CACHE",
                                                            str(tmp_path / "cache"))}
    proc = subprocess.run(
        [sys.executable, "-m", "contact", "sweep", "--dE", "-0.05:0.05:3", "--torque", "250",
         "--rolls-per-cycle", "4", "--no-root-stress", "--workers", "2",
         "-o", str(tmp_path / "map.nc")],
        capture_output=True, text=True, cwd=tmp_path, env=env, timeout=600)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    progress = [ln for ln in lines if re.fullmatch(
        r"sweep: \d/3 points \(\d+ %\), [\d.]+ points/s, ETA .+", ln)]
    assert progress, proc.stderr
    # the time as the progress lines write it: "42 s" or, past a minute (a loaded machine:
    # "3/3 points in 1 min 12 s" failed the earlier pattern), "1 min 12 s"
    assert any(re.fullmatch(r"sweep: 3/3 points in (\d+ min )?\d+ s \([\d.]+ points/s\)", ln)
               for ln in lines), proc.stderr
    assert "\r" not in proc.stderr  # no bar
    assert "still alive" not in proc.stderr and "killing" not in proc.stderr
    assert "already in use" not in proc.stderr
