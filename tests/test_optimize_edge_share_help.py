"""`ltca optimize --help` says the unit of --max-edge-share (issue 71, round 33).

The optimiser's tables print the edge load share in %, while --max-edge-share takes a
fraction in [0, 1]: a user of round 33 typed `--max-edge-share 0 2` for 2 % and was refused
("must be in [0, 1] [1], got 2.0"). The help now names the fraction and its 0.02 = 2 %.
"""

from __future__ import annotations

import subprocess
import sys


def test_max_edge_share_help_names_the_fraction_and_the_percent():
    """The help text as printed (argparse's %% escapes resolved): the fraction, its range and
    the example. An identity of the text, no tolerance."""
    out = subprocess.run([sys.executable, "-m", "contact.cli", "optimize", "--help"],
                         capture_output=True, text=True, check=True, timeout=120).stdout
    flat = " ".join(out.split())
    assert "a fraction of the torque in [0, 1] (0.02 = 2 %" in flat
