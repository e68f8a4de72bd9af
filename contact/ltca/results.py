"""The results of every (torque, roll) contact problem of an analysis, accumulated.

Public functions
----------------
RollResults   per-segment loads and pressures, per-roll rotation, status and residuals
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from contact.qp import ContactSolution
from contact.qp.problem import RESIDUALS
from geometry.core.hertz import hertz_line_contact_of_checked

__all__ = ["SEGMENT_STATES", "RollResults"]

#: the states of a segment (``/ltca/segment_state``): unloaded, loaded below its force
#: limit, at its limit (the elastic–perfectly-plastic bound of the contact QP)
SEGMENT_STATES = ("free", "elastic", "plastic")


@dataclass(eq=False)
class RollResults:
    """Results of NT torques × J rolls × K pairs × S segments (NaN or 0 where not solved).

    Attributes
    ----------
    force : ndarray (NT, J, K, S) — [N]
    load_per_length : ndarray (NT, J, K, S) — [N/mm]
    pressure_max : ndarray (NT, J, K, S) — [MPa]
        Peak Hertz pressure of the line contact (0 where unloaded).
    half_width : ndarray (NT, J, K, S) — [mm]
        Hertz half-width (0 where unloaded).
    contact, in_problem : ndarray (NT, J, K, S) of int8
        Segment in contact (its gap closed); segment in the roll's problem.
    state : ndarray (NT, J, K, S) of int8
        :data:`SEGMENT_STATES`: 0 free (unloaded), 1 elastic (loaded below its force
        limit), 2 plastic (at its limit).
    rotation : ndarray (NT, J) — [rad]
        Loaded rotation Θ (NaN where no certified solution).
    residuals : dict of str to ndarray (NT, J) — [1]
        The relative residuals of the four conditions (:data:`contact.qp.problem.RESIDUALS`).
    found : ndarray (NT, J) of int8
        1 where the solution is certified.
    status : ndarray (NT, J) of object (str)
        The solver's status, or why a roll has no solution.
    solve_time : ndarray (NT, J) — [s]
        Build and solve time over the Weber iterations and screening rounds.
    weber_iterations : ndarray (NT, J) of int
    compliance_time : ndarray (J,) — [s]
    n_segments : ndarray (J,) of int
        Segments in the largest problem of the roll.
    """

    force: np.ndarray
    load_per_length: np.ndarray
    pressure_max: np.ndarray
    half_width: np.ndarray
    contact: np.ndarray
    in_problem: np.ndarray
    state: np.ndarray
    rotation: np.ndarray
    residuals: dict[str, np.ndarray]
    found: np.ndarray
    status: np.ndarray
    solve_time: np.ndarray
    weber_iterations: np.ndarray
    compliance_time: np.ndarray
    n_segments: np.ndarray

    #: the per-segment results
    PER_SEGMENT: ClassVar[tuple[str, ...]] = (
        "force", "load_per_length", "pressure_max", "half_width", "contact", "in_problem",
        "state")

    @classmethod
    def empty(cls, n_torque: int, n_roll: int, n_pair: int, n_segment: int) -> RollResults:
        """Results of that size with nothing solved yet."""
        shape4, shape2 = (n_torque, n_roll, n_pair, n_segment), (n_torque, n_roll)
        return cls(
            force=np.full(shape4, np.nan), load_per_length=np.full(shape4, np.nan),
            pressure_max=np.full(shape4, np.nan), half_width=np.full(shape4, np.nan),
            contact=np.zeros(shape4, np.int8), in_problem=np.zeros(shape4, np.int8),
            state=np.zeros(shape4, np.int8), rotation=np.full(shape2, np.nan),
            residuals={r: np.full(shape2, np.nan) for r in RESIDUALS},
            found=np.zeros(shape2, np.int8), status=np.full(shape2, "", dtype=object),
            solve_time=np.zeros(shape2), weber_iterations=np.zeros(shape2, np.int64),
            compliance_time=np.zeros(n_roll), n_segments=np.zeros(n_roll, np.int64))

    def copy_roll(self, source: int, j: int) -> None:
        """Roll j's results are roll ``source``'s (rolls whole mesh cycles apart: the
        same segments, separations and contact problems)."""
        for arr in (*(getattr(self, k) for k in self.PER_SEGMENT), *self.residuals.values(),
                    self.rotation, self.found, self.status, self.weber_iterations):
            arr[:, j] = arr[:, source]
        self.n_segments[j] = self.n_segments[source]

    def record(self, it: int, j: int, solution: ContactSolution, iterations: int,
               n_segments: int) -> None:
        """The status, residuals and size (``n_segments`` in its problem) of the solution
        at torque ``it``, roll ``j``."""
        self.weber_iterations[it, j] = iterations
        self.n_segments[j] = max(self.n_segments[j], n_segments)
        self.found[it, j] = int(solution.found)
        self.status[it, j] = solution.status
        for r in RESIDUALS:
            self.residuals[r][it, j] = solution.residuals[r]

    def record_loads(self, it: int, j: int, solution: ContactSolution, pairs: np.ndarray,
                     segments: np.ndarray, length: np.ndarray, r_eq: np.ndarray,
                     modulus: float, plastic: np.ndarray | None = None) -> None:
        """The loads of a certified solution and their Hertz line contact
        (:func:`geometry.core.hertz.hertz_line_contact`, contact modulus ``modulus`` [MPa]) on
        the segments (N,) of lengths ``length`` and radii ``r_eq`` [mm]; ``plastic`` (N,)
        bool marks those at their force limit (:meth:`ContactSolution.at_limit`)."""
        F = solution.force
        self.rotation[it, j] = solution.rotation
        w = F / length
        # (the solved loads are finite, the radii the selection's, checked: the checks
        # not made again at every roll)
        hertz = hertz_line_contact_of_checked(np.maximum(w, 0.0), r_eq, float(modulus))
        at = (it, j, pairs, segments)
        self.force[at] = F
        self.load_per_length[at] = w
        self.half_width[at] = np.where(F > 0, hertz.half_width, 0.0)
        self.pressure_max[at] = np.where(F > 0, hertz.peak_pressure, 0.0)
        active = solution.active_set
        self.contact[at] = active.astype(np.int8)
        self.in_problem[at] = 1
        state = active.astype(np.int8)
        if plastic is not None:
            state[plastic] = 2
        self.state[at] = state

    def keep(self, keep: np.ndarray) -> RollResults:
        """The same results with only the segments ``keep`` (bool (S,))."""
        per = {k: getattr(self, k)[..., keep] for k in self.PER_SEGMENT}
        return RollResults(**per, rotation=self.rotation, residuals=self.residuals,
                           found=self.found, status=self.status, solve_time=self.solve_time,
                           weber_iterations=self.weber_iterations,
                           compliance_time=self.compliance_time, n_segments=self.n_segments)
