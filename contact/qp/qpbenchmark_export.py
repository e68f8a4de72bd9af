"""The toolkit's contact problems as a qpbenchmark test set.

qpbenchmark (Caron et al., https://github.com/qpsolvers/qpbenchmark) runs every
qpsolvers backend on a ``TestSet`` and writes its own reports. This module
exposes :func:`contact.qp.benchmark_problems.standard_problem_set` in that form, scaled as
the toolkit scales problems for its backends (:meth:`ContactProblem.scaled`), so
that absolute tolerances mean the same for every problem. Requires the optional
dependency ``qpbenchmark`` (``pip install 'hypoid-ltca[bench]'``); use it through
``benchmarks/ltca_contact.py``::

    qpbenchmark benchmarks/ltca_contact.py run
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
from qpbenchmark import Problem, TestSet

from contact.qp.benchmark_problems import standard_problem_set

__all__ = ["LtcaContact", "to_qpbenchmark"]


def to_qpbenchmark(test_problem) -> Problem:
    """A :class:`~contact.qp.benchmark_problems.TestProblem` as a dense, scaled qpbenchmark
    ``Problem``.

    minimise ½ F̃ᵀ C̃ F̃ + s̃ᵀ F̃ subject to R̃ᵀ F̃ = T̃, F̃ ≥ 0 (see ``ContactProblem.scaled``).
    """
    C, s, R, T = test_problem.problem.scaled()
    return Problem(
        C, s, None, None, R[None, :], np.array([T]), np.zeros(s.size), None, name=test_problem.name
    )


class LtcaContact(TestSet):
    """Loaded-contact problems of hypoid gear LTCA: Hertz checks and LTCA-like instances."""

    quick: bool = False

    @property
    def description(self) -> str:
        return (
            "Contact problems of loaded tooth contact analysis: Hertz sphere and cylinder "
            "discretised with exact half-space influence coefficients, and random "
            "instances with the structure of a hypoid-gear mesh (N = 50 to 2000)."
        )

    @property
    def title(self) -> str:
        return "hypoid-ltca loaded-contact test set"

    @property
    def sparse_only(self) -> bool:
        return False

    def __iter__(self) -> Iterator[Problem]:
        for tp in standard_problem_set(quick=self.quick):
            yield to_qpbenchmark(tp)
