"""The toolkit's contact problems as a qpbenchmark test set.

qpbenchmark (Caron et al., https://github.com/qpsolvers/qpbenchmark) runs every
qpsolvers backend on a ``TestSet`` and writes its own report (solver versions, CPU,
success rates, shifted geometric means). :class:`LtcaContact` holds

* the real contact problems of the LTCA of cases, read from a directory written by
  ``ltca export-problems CASE … -o DIR`` (:mod:`contact.qp.problem_files`), and
* :func:`contact.qp.benchmark_problems.standard_problem_set` (Hertz problems with known
  answers, LTCA-like random instances),

each scaled as the toolkit scales problems for its backends
(:meth:`ContactProblem.scaled`), so that absolute tolerances mean the same for every
problem. Only qpbenchmark's ``high_accuracy`` settings are run (absolute tolerance
1e-9, relative 0, time limit 10 s): the level the toolkit's certification needs.

Requires the optional dependency ``qpbenchmark`` (``pip install 'hypoid-ltca[bench]'``,
from a clone ``pip install '.[bench]'``); used through ``benchmarks/ltca_contact.py``, whose
docstring gives the command.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import numpy as np
from qpbenchmark import Problem, TestSet

from contact.qp.benchmark_problems import TestProblem, standard_problem_set
from contact.qp.problem_files import read_problem_set

__all__ = ["QPBENCHMARK_SETTINGS", "LtcaContact", "to_qpbenchmark"]

#: The qpbenchmark settings the test set runs.
QPBENCHMARK_SETTINGS = "high_accuracy"


def to_qpbenchmark(test_problem: TestProblem) -> Problem:
    """A :class:`~contact.qp.benchmark_problems.TestProblem` as a dense, scaled qpbenchmark
    ``Problem``.

    minimise ½ F̃ᵀ C̃ F̃ + s̃ᵀ F̃ subject to R̃ᵀ F̃ = T̃, 0 ≤ F̃ ≤ F̃_max (see
    ``ContactProblem.scaled``; the force limits, where a problem has some, as one
    inequality row per limited segment); the arrays are fresh, writable copies (DAQP
    refuses read-only inputs).
    """
    problem = test_problem.problem
    C, s, R, T = problem.scaled()
    G = h = None
    if problem.has_bounds:
        b = np.flatnonzero(problem.bounded)
        G = np.zeros((b.size, s.size))
        G[np.arange(b.size), b] = 1.0
        h = np.array(problem.scaled_upper_bound()[b])
    return Problem(
        np.array(C), np.array(s), G, h, np.array(R[None, :]), np.array([T]),
        np.zeros(s.size), None, name=test_problem.name,
    )


class LtcaContact(TestSet):
    """Loaded-contact problems of hypoid gear LTCA: real problems of cases, Hertz checks and
    LTCA-like instances.

    Class attributes (set by a subclass, e.g. ``benchmarks/ltca_contact.py``):

    problems_dir : str or None
        Directory of an exported problem set (``ltca export-problems``); the environment
        variable ``HYPOID_LTCA_PROBLEMS`` overrides it (set but empty: no real problems).
        None: no real problems.
    standard : bool
        Include the standard problem set (default True).
    quick : bool
        The quick standard set.
    """

    problems_dir: str | None = None
    standard: bool = True
    quick: bool = False

    def __init__(self) -> None:
        super().__init__()
        self.__problems: list[TestProblem] | None = None

    def define_solver_settings(self) -> None:
        """qpbenchmark's settings, restricted to :data:`QPBENCHMARK_SETTINGS`."""
        super().define_solver_settings()
        self.solver_settings = {QPBENCHMARK_SETTINGS: self.solver_settings[QPBENCHMARK_SETTINGS]}
        self.tolerances = {QPBENCHMARK_SETTINGS: self.tolerances[QPBENCHMARK_SETTINGS]}

    @property
    def real_problems_dir(self) -> Path | None:
        """The directory of the real problems in use (None: none)."""
        d = os.environ.get("HYPOID_LTCA_PROBLEMS", self.problems_dir)
        return Path(d) if d else None

    def test_problems(self) -> list[TestProblem]:
        """The set's problems as the toolkit's test problems (read once, then kept)."""
        if self.__problems is None:
            d = self.real_problems_dir
            problems = read_problem_set(d) if d is not None else []
            if self.standard:
                problems += standard_problem_set(quick=self.quick)
            self.__problems = problems
        return self.__problems

    @property
    def description(self) -> str:
        return (
            "Contact problems of loaded tooth contact analysis of hypoid and spiral bevel "
            "gears (minimise ½FᵀCF + sᵀF subject to F ≥ 0, RᵀF = T; C dense SPD): the real "
            "problems of every roll position of a mesh cycle of the toolkit's bundled "
            "cases at three torques, aligned and misaligned (`ltca export-problems`), "
            "Hertz sphere and cylinder discretised with exact half-space influence "
            "coefficients, and random instances with the structure of a hypoid-gear mesh."
        )

    @property
    def title(self) -> str:
        return "hypoid-ltca loaded-contact test set"

    @property
    def sparse_only(self) -> bool:
        return False

    def __iter__(self) -> Iterator[Problem]:
        for tp in self.test_problems():
            yield to_qpbenchmark(tp)
