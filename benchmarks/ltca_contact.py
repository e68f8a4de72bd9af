"""qpbenchmark test set of the toolkit: real LTCA contact problems, Hertz and LTCA-like ones.

Run every qpsolvers backend on it and write qpbenchmark's report (``ltca_contact.md``:
solver versions, CPU, success rates, shifted geometric means of time and residuals)
beside the results file::

    pip install '.[bench]'
    ltca export-problems -o benchmarks/problems          # once: ~1 min, 1200 problems
    qpbenchmark benchmarks/ltca_contact.py --results-path benchmarks/results/ltca_contact.csv \\
        run --author "$USER"

or, the same with these paths as defaults, ``python benchmarks/ltca_contact.py run --author
"$USER"``. qpbenchmark needs ``--results-path`` (before ``run``) to know where to write,
and ``--author`` (after ``run``) or it asks for a name on the terminal. Results already in
the file are kept and not run again (``run --rerun`` runs them again); ``report`` rewrites
the report from the file alone.

The real problems are read from ``benchmarks/problems`` (``HYPOID_LTCA_PROBLEMS=DIR``
points elsewhere; ``HYPOID_LTCA_PROBLEMS=`` with no value leaves them out); if that
directory has no manifest yet, it is exported first (every bundled case, 50/250/500 N·m,
aligned and misaligned). qpbenchmark loads the class named after this file
(``LtcaContact``); the set is :class:`contact.qp.qpbenchmark_export.LtcaContact`.
Our own solver ``active_set`` is not a qpsolvers backend and so not in qpbenchmark's
tables: ``python benchmarks/active_set_real.py`` compares it with them on the same
problems, with qpbenchmark's shifted geometric mean.
"""

from __future__ import annotations

import logging
import os
import sys
from pathlib import Path

from contact.qp import qpbenchmark_export
from contact.qp.problem_files import MANIFEST

HERE = Path(__file__).resolve().parent
#: where the exported real problems are read from (and exported to if missing)
PROBLEMS_DIR = HERE / "problems"
#: the results file ``python benchmarks/ltca_contact.py`` writes (report beside it)
RESULTS_PATH = HERE / "results" / "ltca_contact.csv"


class LtcaContact(qpbenchmark_export.LtcaContact):
    """The toolkit's test set with the real problems of ``benchmarks/problems``."""

    problems_dir = str(PROBLEMS_DIR)

    def test_problems(self):
        d = self.real_problems_dir
        if d is not None and not (d / MANIFEST).is_file():
            from contact.catalogue import bundled_cases
            from contact.commands.export_problems import export_problems

            logging.getLogger(__name__).warning(
                "no exported problems in %s: exporting every bundled case first "
                "(several minutes)", d)
            export_problems([c.removesuffix(".toml") for c in bundled_cases()], d,
                            command="benchmarks/ltca_contact.py (first use)")
        return super().test_problems()


if __name__ == "__main__":
    from qpbenchmark.benchmark import main

    # qpbenchmark prefers the results_path given here to its --results-path option:
    # pass ours only when the command line names none
    given = any(a.startswith("--results-path") for a in sys.argv[1:])
    RESULTS_PATH.parent.mkdir(parents=True, exist_ok=True)
    main(test_set_path=os.path.abspath(__file__), results_path=None if given else RESULTS_PATH)
