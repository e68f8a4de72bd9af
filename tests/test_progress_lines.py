"""Progress of ``ltca synthesize`` and ``ltca report`` off a terminal (issue 60, item 5):
complete plain lines on standard error, one per step or figure, none with
``--no-progress`` (``ltca synthesize``'s lines: tests/test_synthesis_case.py)."""

from __future__ import annotations

import io
import re

from contact.cli import main
from contact.commands.step_lines import StepLines


def test_step_lines_count_and_time_the_steps():
    """Each call is one line ``desc: unit k/total, step (elapsed)``, the elapsed time in
    s or min and s from the clock the lines were made with."""
    times = iter([0.0, 0.4, 59.6, 125.0])
    out = io.StringIO()
    say = StepLines("synthesize", 3, stream=out, clock=lambda: next(times))
    for step in ("blanks", "pinion concave: modified roll", "the case"):
        say(step)
    assert out.getvalue().splitlines() == [
        "synthesize: step 1/3, blanks (0 s)",
        "synthesize: step 2/3, pinion concave: modified roll (1 min 0 s)",
        "synthesize: step 3/3, the case (2 min 5 s)"]


def test_step_lines_count_a_second_pass_from_one():
    """A command that runs its steps again (the development re-synthesising a case)
    counts them from 1 with the pass named, never ``step 4/3``."""
    out = io.StringIO()
    say = StepLines("synthesize", 2, stream=out, clock=lambda: 0.0)
    for step in ("blanks", "the case", "blanks", "the case", "blanks"):
        say(step)
    assert out.getvalue().splitlines() == [
        "synthesize: step 1/2, blanks (0 s)", "synthesize: step 2/2, the case (0 s)",
        "synthesize: pass 2, step 1/2, blanks (0 s)",
        "synthesize: pass 2, step 2/2, the case (0 s)",
        "synthesize: pass 3, step 1/2, blanks (0 s)"]


def test_report_prints_a_line_per_figure_off_a_terminal(tmp_path, capsys):
    """``ltca report`` to a log: one line per figure before ``wrote``, the figures of the
    page all named; ``--no-progress``: none, and the same page."""
    nc = tmp_path / "run.nc"
    assert main(["run", "--torque", "100", "--rolls-per-cycle", "4", "--segments", "10",
                 "--no-progress", "--speed", "0", "--no-root-stress", "-o", str(nc)]) == 0
    capsys.readouterr()
    out = tmp_path / "r.html"
    assert main(["report", str(nc), "-o", str(out)]) == 0
    err = capsys.readouterr().err
    lines = re.findall(r"^report: figure (\d+)/(\d+), (\w+) \(\d+ s\)$", err, re.M)
    assert lines and [int(k) for k, _, _ in lines] == list(range(1, len(lines) + 1))
    assert {int(n) for _, n, _ in lines} == {len(lines)}
    page = out.read_text(encoding="utf-8")
    for _, _, name in lines:
        assert f'id="fig-{name}"' in page
    quiet = tmp_path / "q.html"
    assert main(["report", str(nc), "-o", str(quiet), "--no-progress"]) == 0
    assert "report: figure" not in capsys.readouterr().err
    strip = re.compile(r"data:image/png;base64,[A-Za-z0-9+/=]+")
    assert strip.sub("", quiet.read_text(encoding="utf-8")) == strip.sub("", page)
