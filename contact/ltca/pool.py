"""The structural compliance of the segments a roll's problems may take: the pool.

Per computed roll, the shells' and foundations' compliance (:mod:`contact.compliance`) of
a pool of segments is assembled once — all rolls' segments mapped onto the shells in one
batch (:func:`contact.compliance.mesh.mesh_compliance_many`) — and each torque's problem
takes the sub-matrix of its selection. Weber's contact compliance, which depends on the
load, is left out here and added by the Weber iteration (:mod:`contact.ltca.weber`); the
depths it needs are kept.

Public functions
----------------
CompliancePool   the pool of every computed roll: masks, structural compliance, depths
"""

from __future__ import annotations

import numpy as np

from contact.compliance.mesh import ContactSegments, mesh_compliance_many, pair_compliance_model
from contact.ltca.options import LTCAOptions
from contact.ltca.segments import Segments
from geometry.core.errors import InputError

__all__ = ["CompliancePool"]


class CompliancePool:
    """The assembled structural compliance of each computed roll's pool of segments.

    Parameters
    ----------
    case : geometry.case.Case
    seg : Segments
        The analysis' segments (J, K, S).
    options : LTCAOptions
        Shell model (``theory``, ``n_height``, ``n_face``), materials, the pairs and the
        fixed separation limit (named in the error when it takes in segments off the
        mating tooth).

    Attributes
    ----------
    time : ndarray (J,) — [s]
        Compliance assembly time per roll.
    asymmetry : float — [1]
        Largest relative asymmetry ‖C − Cᵀ‖_F/‖C‖_F of the shell blocks assembled (they
        are symmetrised; above :data:`contact.errors.ASYMMETRY_LIMIT` they are refused).
    """

    def __init__(self, case, seg: Segments, options: LTCAOptions):
        self.case = case
        self.seg = seg
        self.options = options
        material = (options.youngs_modulus, options.poisson_ratio)
        self.model = pair_compliance_model(
            case, theory=options.theory, n_height=options.n_height, n_face=options.n_face,
            pinion_material=material, gear_material=material)
        self._masks: dict[int, np.ndarray] = {}  # (K, S) the segments assembled
        self._structural: dict[int, np.ndarray] = {}  # (P, P) [mm/N] without Weber
        self._depth: dict[int, np.ndarray] = {}  # (P, 2) [mm] Weber's depths
        self.time = np.zeros(seg.shape[0])
        self.asymmetry = 0.0  # largest relative asymmetry of a shell block, symmetrised

    def mask(self, j: int) -> np.ndarray | None:
        """(K, S) the segments of roll j in the pool (None before it is assembled)."""
        return self._masks.get(j)

    def assemble(self, jobs: list[tuple[int, np.ndarray]]) -> None:
        """Assemble the pools of several rolls in one batch (replacing earlier ones).

        Parameters
        ----------
        jobs : list of (int, ndarray (K, S) of bool)
            Roll index and the segments of its pool.

        Raises
        ------
        InputError
            From the shell mapping; with a fixed separation limit, naming
            ``separation_limit`` (a limit so wide that far pairs' points lie off the
            mating tooth).
        """
        seg = self.seg
        batch = []
        for j, mask in jobs:
            wk, ws = np.nonzero(mask)
            batch.append(ContactSegments(
                midpoints=seg.midpoint_pair[j, wk, ws],
                ends=seg.ends_pair[j, wk, ws],
                normals=seg.normal_pair[j, wk, ws],
                length=seg.length[j, wk, ws],
                r_eq=seg.r_eq[j, wk, ws],
                pair_index=np.asarray(self.options.pairs)[wk],
                # (Weber's part is replaced by the iteration; a unit line load keeps it
                # defined)
                load=seg.length[j, wk, ws],
                pinion_rotation=float(seg.pinion_rotation[j]),
                gear_rotation=float(seg.gear_rotation[j]),
            ))
        fixed = self.options.separation_limit
        try:
            mats = mesh_compliance_many(self.case, batch, model=self.model)
        except InputError as exc:
            if fixed is None:
                raise
            raise InputError(
                f"separation_limit: {fixed:g} mm takes in segments so far from contact that "
                "their points lie off the mating tooth (far pairs' edges); use a smaller "
                f"limit or the default screening (None): {exc}") from exc
        for (j, mask), (c_full, info) in zip(jobs, mats, strict=True):
            self._masks[j] = mask
            self._structural[j] = c_full - info["weber"]
            self._depth[j] = info["weber_depth"]
            self.time[j] += info["time"]
            self.asymmetry = max(self.asymmetry, float(info["asymmetry"]))

    def restricted(self, j: int, selected: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The structural compliance (N, N) [mm/N] and Weber depths (N, 2) [mm] of the
        pool's segments ``selected`` (K, S) of roll j (row-major order)."""
        sub = np.flatnonzero(selected[self._masks[j]])  # the selection's places in the pool
        return self._structural[j][np.ix_(sub, sub)], self._depth[j][sub]

    def coupling(self, j: int, rows: np.ndarray, columns: np.ndarray) -> np.ndarray:
        """Structural compliance [mm/N] of the pool's segments ``rows`` under loads on its
        segments ``columns`` (both (K, S) of bool, subsets of the pool) of roll j."""
        mask = self._masks[j]
        return self._structural[j][np.ix_(np.flatnonzero(rows[mask]),
                                          np.flatnonzero(columns[mask]))]
