"""Segment screening: which segments a roll's contact problem must take (seed §3.3).

A segment left out of a roll's problem whose gap C F + s − R Θ stays open (≥ 0) at the
solution changes nothing: the solution on the other segments is that of all of them
(complementarity holds for it with F = 0). So each problem takes the segments with

    s < 1.1 R Θ̂ + 1 µm

Θ̂ the rotation of the last computed roll at that torque carried over by the UTE
difference; after the solve the gaps of the segments left out are checked — exactly for
those whose compliance is assembled, by s ≥ R Θ for the others (enough, as the
compliance matrix has no negative entries: the gap is ≥ s − R Θ) — and any that would
close is added and the roll solved again (:meth:`Screening.missed`). Before any rotation
is known, a generous limit (:func:`generous_limit`) bounds the first roll's pool and the
edge segments worked out. A fixed ``LTCAOptions.separation_limit`` replaces the screening
by a plain limit. tests/test_ltca.py compares the screened solution with that of all
segments.

Public functions
----------------
Screening        the separations of an analysis' segments and the selection rules
generous_limit   a separation limit that holds every loaded segment, before any rotation
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact.ltca.segments import Segments
from geometry.core.errors import InputError

__all__ = ["SCREEN_MARGIN", "SCREEN_PAD", "SCREEN_ROUNDS", "Screening",
           "generous_limit"]

#: segment screening (LTCAOptions.separation_limit None): a roll's problem takes the
#: segments with s < margin · R Θ̂ + pad, Θ̂ the loaded rotation expected there; after the
#: solve every segment left out must keep its gap open (else it is added and the roll
#: solved again, at most SCREEN_ROUNDS times). [1], [mm]
SCREEN_MARGIN = 1.1
SCREEN_PAD = 1e-3
SCREEN_ROUNDS = 6


def generous_limit(torque: float, ratio: float) -> float:
    """A separation limit [mm] that holds every loaded segment of the seed's cases.

    Parameters
    ----------
    torque : float — [N·m]
        The largest pinion torque of the analysis.
    ratio : float — [1]
        z_g / z_p.

    Returns
    -------
    float — [mm]
        0.05 mm + 0.15 mm per 1000 N·m of gear torque: it bounds the edge segments worked
        out and the first roll's pool before any rotation is known (the analysis checks
        it against the solution's R Θ and repeats with a wider one if it was too tight).
    """
    return 0.05 + 0.15 * torque * ratio / 1000.0


@dataclass(frozen=True, eq=False)
class Screening:
    """The separations of an analysis' segments and the rules that select a roll's.

    Attributes
    ----------
    ute : ndarray (J,) — [rad]
        Each roll's unloaded transmission error (the least over its pairs).
    separation : ndarray (J, K, S) — [mm]
        Initial separation s = R (lag − UTE) of every segment.
    usable : ndarray (J, K, S) of bool
        Segments with the data of a contact problem: finite s and R_eq, a part inside the
        blanks.
    moment_arm : ndarray (J, K, S) — [mm]
    generous : float — [mm]
        :func:`generous_limit` of the analysis' largest torque.
    fixed : float or None — [mm]
        A fixed separation limit (``LTCAOptions.separation_limit``), or None to screen.

    Notes
    -----
    Source: the complementarity of the seed's Eq. 3.12–3.13 (a segment whose gap stays open
    carries nothing); module docstring.
    """

    ute: np.ndarray
    separation: np.ndarray
    usable: np.ndarray
    moment_arm: np.ndarray
    generous: float
    fixed: float | None

    @classmethod
    def of(cls, seg: Segments, largest_torque: float, ratio: float,
           fixed: float | None) -> Screening:
        """The screening of segments ``seg`` for an analysis up to ``largest_torque``
        [N·m] (pinion) with ratio z_g/z_p and an optional fixed limit [mm].

        Raises
        ------
        InputError
            If some roll position has no tooth pair in contact.
        """
        # a roll without a pair in contact is said before numpy's "All-NaN slice"
        # warning reaches the user (the 12x12 miter of round 17's development trials)
        if np.any(np.all(np.isnan(seg.ute), axis=1)):
            raise InputError("no tooth pair is in contact at some roll position (check the "
                             "case)")
        ute = np.nanmin(seg.ute, axis=1)  # (J,)
        if not np.all(np.isfinite(ute)):
            raise InputError("no tooth pair is in contact at some roll position (check the "
                             "case)")
        # separation s = R (lag − UTE) [mm] of every segment; ``usable``: the segments with
        # the data of a contact problem (finite s and R_eq, a part inside the blanks)
        arm = seg.moment_arm
        sep = arm * (seg.lag - ute[:, None, None])
        usable = np.isfinite(sep) & np.isfinite(seg.r_eq) & (seg.length > 0)
        return cls(ute, sep, usable, arm, generous_limit(largest_torque, ratio), fixed)

    def first_pool(self, j: int) -> np.ndarray:
        """(K, S) the segments of roll j within the generous limit (before any rotation is
        known) or the fixed limit."""
        limit = self.generous if self.fixed is None else self.fixed
        return self.usable[j] & (self.separation[j] <= limit)

    def near(self, j: int, theta: float) -> np.ndarray:
        """(K, S) the segments of roll j a loaded rotation θ [rad] may close: s < R θ
        with the screening's margin."""
        return self.usable[j] & (self.separation[j] < SCREEN_MARGIN * self.moment_arm[j]
                                 * max(theta, 0.0) + SCREEN_PAD)

    def missed(self, j: int, selected: np.ndarray, pool: np.ndarray, coupling: np.ndarray,
               force: np.ndarray, rotation: float) -> np.ndarray:
        """(K, S) the segments left out of roll j's problem whose gap would close.

        Parameters
        ----------
        j : int
            Roll index.
        selected, pool : ndarray (K, S) of bool
            The problem's segments and those whose compliance is assembled.
        coupling : ndarray (P − N, N) — [mm/N]
            Compliance of the pool's segments left out (rows, in pool order) under the
            selected ones' loads (columns).
        force : ndarray (N,) — [N]
            The solution's forces of the selected segments (row-major order of
            ``selected``).
        rotation : float — [rad]
            The solution's loaded rotation Θ.

        Returns
        -------
        ndarray (K, S) of bool
            Within the pool: the gap s + C F − R Θ < 0 exactly; beyond it: s < R Θ
            (enough, the compliance having no negative entries).
        """
        rest = pool & ~selected
        missed = (self.usable[j] & ~selected & ~pool
                  & (self.separation[j] < self.moment_arm[j] * rotation))
        if rest.any():
            gap = (self.separation[j][rest] - self.moment_arm[j][rest] * rotation
                   + coupling @ force)
            missed[rest] = gap < 0.0
        return missed
