"""The structural compliance of the segments a roll's problems may take: the pool.

Per computed roll, the shells' and foundations' compliance (:mod:`contact.compliance`) of
a pool of segments is assembled once — all rolls' segments mapped onto the shells in one
batch (:func:`contact.compliance.mesh.mesh_compliance_many`) — and each torque's problem
takes the sub-matrix of its selection. Weber's contact compliance, which depends on the
load, is left out here and added by the Weber iteration (:mod:`contact.ltca.weber`); the
depths it needs are kept.

The structural compliance is the model ``LTCAOptions.compliance`` names, from the one
registry :mod:`contact.ltca.compliance_models` (the shells, the FE influence coefficients,
or a user's model): its preparation runs once per analysis and returns the batch assembler.
The FE model's coupling between neighbouring teeth has small negative entries (an unloaded
neighbour moves away, ≤ 9 % of the diagonal), which the screening's bound for segments
outside the pool (s ≥ R Θ) neglects: ~1 µm at 500 N·m against the pool's generous limit of
tenths of a millimetre (docs/fe.md).

Every model returns the total with Weber's term, which the pool takes out again (the
iteration adds it at the loads), and Weber's depths; the pool checks that it does.

Public functions
----------------
CompliancePool          the pool of every computed roll: masks, structural compliance, depths
"""

from __future__ import annotations

from typing import Any

import numpy as np

from contact.compliance.mesh import ContactSegments
from contact.ltca.compliance_models import (
    ComplianceModelError,
    compliance_model_name,
    get_compliance_model,
)
from contact.ltca.options import LTCAOptions
from contact.ltca.segments import Segments
from contact.utca import EaseOff
from geometry.core.errors import InputError, LTCAError

__all__ = ["CompliancePool"]

#: what every assembler's ``info`` must hold (contact.ltca.compliance_models)
REQUIRED_INFO = ("weber", "weber_depth", "time", "asymmetry")


def _checked(name: str, jobs: list, mats: Any) -> list[tuple[np.ndarray, dict[str, Any]]]:
    """A model's assembled matrices, checked against its contract: one (C, info) per roll,
    C (P, P) finite, info with :data:`REQUIRED_INFO` of the right shapes.

    Raises
    ------
    ComplianceModelError
        What breaks the contract, naming the model.
    """
    def fail(what: str) -> ComplianceModelError:
        return ComplianceModelError(f"compliance: model {name!r} {what} "
                                    "(contact.ltca.compliance_models)")

    if not isinstance(mats, (list, tuple)) or len(mats) != len(jobs):
        got = (f"{type(mats).__name__} of {len(mats)}" if isinstance(mats, (list, tuple))
               else type(mats).__name__)
        raise fail(f"must return one (C, info) per roll position ({len(jobs)}), got {got}")
    out = []
    for (_, mask), item in zip(jobs, mats, strict=True):
        p = int(np.count_nonzero(mask))
        try:
            c, info = item
        except (TypeError, ValueError):
            raise fail("must return (C, info) pairs") from None
        missing = [k for k in REQUIRED_INFO if not isinstance(info, dict) or k not in info]
        if missing:
            raise fail(f"gave no {missing} in its info")
        # numbers where numbers go: a string or an object there failed inside NumPy or the
        # pool's sums, a ValueError naming neither the model nor the field (api83)
        arrays = {}
        for field, value in (("C", c), ("weber", info["weber"]),
                             ("weber_depth", info["weber_depth"]),
                             ("time", info["time"]), ("asymmetry", info["asymmetry"])):
            try:
                arrays[field] = np.asarray(value, dtype=float)
            except (TypeError, ValueError):
                raise fail(f"gave {field} {type(value).__name__} {str(value)[:40]!r}; "
                           "it must be numbers ([mm/N] for C and weber, [mm] weber_depth, "
                           "[s] time, [1] asymmetry)") from None
        for field in ("time", "asymmetry"):
            x = arrays[field]
            if x.ndim != 0 or not (np.isfinite(x) and x >= 0.0):
                raise fail(f"gave info[{field!r}] {info[field]!r}; it must be one finite "
                           f"number >= 0 ({'[s]' if field == 'time' else '[1]'})")
        c = arrays["C"]
        if (c.shape != (p, p) or np.shape(info["weber"]) != (p, p)
                or np.shape(info["weber_depth"]) != (p, 2)):
            raise fail(f"gave C {c.shape}, weber {np.shape(info['weber'])}, weber_depth "
                       f"{np.shape(info['weber_depth'])} for {p} segments; expected ({p}, "
                       f"{p}), ({p}, {p}), ({p}, 2)")
        if not np.all(np.isfinite(c)):
            raise fail("gave a compliance that is not finite")
        if p and not np.all(np.diag(c) > 0.0):  # a segment that moves against its load
            raise fail(f"gave a compliance with a diagonal entry <= 0 (least "
                       f"{float(np.min(np.diag(c))):.3g} mm/N); a segment's own compliance "
                       "is > 0 (positive strain energy)")
        out.append((c, info))
    return out


def _plugin_call(name: str, what: str, function: Any, *args: Any) -> Any:
    """``function(*args)`` of the compliance model ``name``: an exception of the toolkit's
    family passes as it is (a bundled model's refusal), any other becomes a
    :class:`ComplianceModelError` naming the model, the call and what it raised (a user's
    model that fails at call time, not only at registration; docs/extending.md)."""
    try:
        return function(*args)
    except LTCAError:
        raise
    except Exception as exc:
        text = str(exc).splitlines()[0] if str(exc) else ""
        raise ComplianceModelError(f"compliance: model {name!r} raised {type(exc).__name__} "
                                   f"in {what}: {text} (contact.ltca.compliance_models)"
                                   ) from exc


class CompliancePool:
    """The assembled structural compliance of each computed roll's pool of segments.

    Parameters
    ----------
    case : geometry.case.Case
    seg : Segments
        The analysis' segments (J, K, S).
    options : LTCAOptions
        The compliance model (``compliance``; the shell's ``theory``, ``n_height``,
        ``n_face``; the FE model ``fe``), materials, the pairs and the fixed separation
        limit (named in the error when it takes in segments off the mating tooth).
    easeoff : contact.utca.EaseOff, optional
        The analysis' ease-off: its working flanks choose the FE coefficients (needed
        with ``compliance="fe"``).

    Attributes
    ----------
    time : ndarray (J,) — [s]
        Compliance assembly time per roll.
    asymmetry : float — [1]
        Largest relative asymmetry ‖C − Cᵀ‖_F/‖C‖_F of the shell blocks (or the members'
        FE matrices) assembled (they are symmetrised; above
        :data:`contact.errors.ASYMMETRY_LIMIT` shell blocks are refused).

    Notes
    -----
    Source: the members' tooth compliance matrices C_p, C_g of seed Eq. (3.11), the
    structural part of the total compliance C = C_p + C_g + C_h of seed Eq. (3.12): the
    shell model of §3.2 (Eq. 3.1–3.10) on its foundation, or the FE influence coefficients
    (docs/fe.md); the Hertzian C_h (Weber's closed form, seed ref. [3.8]) is added at the
    loads (:mod:`contact.ltca.weber`). A matrix that comes out slightly non-symmetric is
    symmetrised (Maxwell–Betti reciprocity) and its asymmetry reported.
    """

    def __init__(self, case, seg: Segments, options: LTCAOptions,
                 easeoff: EaseOff | None = None):
        self.case = case
        self.seg = seg
        self.options = options
        model = get_compliance_model(options.compliance)
        self._model_name = compliance_model_name(model)
        self._assembler = _plugin_call(self._model_name, "prepare", model.prepare, case,
                                       easeoff, options)
        if not callable(self._assembler):
            raise ComplianceModelError(
                f"compliance: model {self._model_name!r} prepare returned "
                f"{type(self._assembler).__name__} {self._assembler!r:.60}, not an assembler "
                "(a function of the segments of several rolls; contact.ltca.compliance_models)")
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
        # every roll's pool gathered at once: (roll of the batch, pair, segment) of all
        # rolls' segments, each roll's in its mask's row-major order
        rolls = np.array([j for j, _ in jobs], dtype=int)
        rr, wk, ws = np.nonzero(np.stack([mask for _, mask in jobs]))
        jj = rolls[rr]
        length = seg.length[jj, wk, ws]
        batch = ContactSegments.of_rolls(
            np.bincount(rr, minlength=len(jobs)), seg.pinion_rotation[rolls],
            seg.gear_rotation[rolls],
            midpoints=seg.midpoint_pair[jj, wk, ws],
            ends=seg.ends_pair[jj, wk, ws],
            normals=seg.normal_pair[jj, wk, ws],
            length=length,
            r_eq=seg.r_eq[jj, wk, ws],
            pair_index=np.asarray(self.options.pairs)[wk],
            # (Weber's part is replaced by the iteration; a unit line load keeps it
            # defined)
            load=length,
        )
        fixed = self.options.separation_limit
        try:
            mats = _plugin_call(self._model_name, "its assembler", self._assembler, batch)
        except InputError as exc:
            if fixed is None:
                raise
            raise InputError(
                f"separation_limit: {fixed:g} mm takes in segments so far from contact that "
                "their points lie off the mating tooth (far pairs' edges); use a smaller "
                f"limit or the default screening (None): {exc}") from exc
        mats = _checked(self._model_name, jobs, mats)
        for (j, mask), (c_full, info) in zip(jobs, mats, strict=True):
            self._masks[j] = mask
            structural = c_full - info["weber"]
            structural.setflags(write=False)  # handed out whole (restricted)
            self._structural[j] = structural
            self._depth[j] = info["weber_depth"]
            self.time[j] += info["time"]
            self.asymmetry = max(self.asymmetry, float(info["asymmetry"]))

    def restricted(self, j: int, selected: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The structural compliance (N, N) [mm/N] and Weber depths (N, 2) [mm] of the
        pool's segments ``selected`` (K, S) of roll j (row-major order); the compliance
        read-only (where the whole pool is selected, the pool's own matrix)."""
        in_pool = selected[self._masks[j]]
        if in_pool.all():  # the whole pool (most rolls' every round): the matrix itself
            return self._structural[j], self._depth[j][in_pool]
        sub = np.flatnonzero(in_pool)  # the selection's places in the pool
        return self._structural[j][np.ix_(sub, sub)], self._depth[j][sub]

    def coupling(self, j: int, rows: np.ndarray, columns: np.ndarray) -> np.ndarray:
        """Structural compliance [mm/N] of the pool's segments ``rows`` under loads on its
        segments ``columns`` (both (K, S) of bool, subsets of the pool) of roll j."""
        mask = self._masks[j]
        return self._structural[j][np.ix_(np.flatnonzero(rows[mask]),
                                          np.flatnonzero(columns[mask]))]
