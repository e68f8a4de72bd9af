"""Total compliance of the contact segments of a gear mesh at one roll position.

The LTCA (seed §3.3, Eq. 3.12–3.14; ``DESIGN.md``) needs at every pinion roll
position the N×N compliance C [mm/N] of the N contact segments of all tooth pairs
that may share the load. Seed §3.2 (p. 78, Fig. 3.2: "construct compliance matrix
for pinion and gear and calculate total compliance matrix") adds, along the
contact normal,

    C = C_pinion + C_gear            bending and shear, tapered shell (Eq. 3.1–3.11)
      + C_foundation,p + C_foundation,g   fillet foundation (Sainsot et al. 2004)
      + diag(c_Weber)               contact deformation (Weber 1949), secant at the loads

Loads on different tooth pairs do not couple (each tooth is its own shell on its
own foundation): C is block diagonal by tooth pair. Each member's tooth model is
measured and its shell stiffness factorised once per case and reused for every
roll position (:func:`pair_compliance_model`, memoised).

Public API
----------
ContactSegments       frozen dataclass: the segments of one roll position (pair frame)
PairComplianceModel   both members' tooth models and the shell settings
pair_compliance_model build (memoised per case text and settings)
clear_model_cache     forget the memoised models
model_cache_info      hits and misses of the memo
mesh_compliance       C and its parts
"""

from __future__ import annotations

import contextlib
import logging
import math
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from contact.compliance.tooth import (
    END_TOLERANCE,
    N_FACE,
    N_HEIGHT,
    ShellPoints,
    ToothModelData,
    member_foundations,
    shell_matrices,
    shell_points_many,
    shell_tooth_from_case,
    weber_depth,
)
from contact.compliance.weber import weber_compliance
from geometry.case import TeethKey
from geometry.core.caches import BatchedRows, Same, memoised, row_keys, rows_kept
from geometry.core.errors import InputError
from geometry.core.hertz import STEEL
from geometry.core.validation import integer, real, real_array
from geometry.machine.meshing import warm_seeds_active
from geometry.pair.assembly import case_transforms

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "ContactSegments",
    "PairComplianceModel",
    "clear_model_cache",
    "mesh_compliance",
    "mesh_compliance_many",
    "model_cache_info",
    "pair_compliance_model",
]

log = logging.getLogger(__name__)

_MEMO_SIZE = 4  # cases whose tooth models are kept by pair_compliance_model


def _array(name: str, value: Any, shape: tuple[int, ...], unit: str, *,
           low: float | None = None, low_open: bool = False) -> np.ndarray:
    a = real_array(name, value, unit=unit, low=low, low_open=low_open)
    if a.ndim == 0 and len(shape) == 1:
        a = np.full(shape, float(a))
    if a.shape != shape:
        raise InputError(f"{name}: must be of shape {shape} [{unit}], got {a.shape}")
    return a


#: the per-segment fields of :class:`ContactSegments` (its rows)
_ROW_FIELDS = ("midpoints", "ends", "normals", "length", "r_eq", "pair_index", "load")


@dataclass(frozen=True, eq=False)
class ContactSegments:
    """Contact segments of one roll position, in the pair frame.

    Parameters
    ----------
    midpoints : array_like (N, 3) — [mm] segment midpoints (load points)
    ends : array_like (N, 2, 3) — [mm] the two end points of each straight segment
    normals : array_like (N, 3) — [1] unit contact normal at each midpoint, pointing
        OUT of the pinion flank (into the gear); the gear's outward normal is −n
    length : array_like (N,) or float — [mm] segment length L > 0 (w′ = F/L for Weber)
    r_eq : array_like (N,) or float — [mm] equivalent radius of curvature R_eq > 0
        (seed Eq. 2.13) along the segment's normal section across the contact line
    pair_index : array_like (N,) of int — [1] tooth pair of each segment (−1, 0, 1 …)
    load : array_like (N,) or float — [N] segment loads F ≥ 0 at which Weber's
        contact compliance is linearised (secant δ(F)/F)
    pinion_rotation, gear_rotation : float — [rad] member rotations of this roll
        position about their own axes, as in :func:`geometry.pair.assembly.case_transforms`

    Raises
    ------
    InputError
        Wrong shapes, non-finite values, non-unit normals, L or R_eq ≤ 0, F < 0,
        a non-integer pair index.
    """

    midpoints: np.ndarray
    ends: np.ndarray
    normals: np.ndarray
    length: np.ndarray
    r_eq: np.ndarray
    pair_index: np.ndarray
    load: np.ndarray
    pinion_rotation: float = 0.0
    gear_rotation: float = 0.0

    def __post_init__(self) -> None:
        if self._set_if_checked():
            return
        mid = real_array("midpoints", self.midpoints, unit="mm")
        if mid.ndim != 2 or mid.shape[1] != 3 or mid.shape[0] == 0:
            raise InputError(f"midpoints: must be of shape (N, 3), N >= 1 [mm], got {mid.shape}")
        n = mid.shape[0]
        mid = _array("midpoints", mid, (n, 3), "mm")
        ends = _array("ends", self.ends, (n, 2, 3), "mm")
        nrm = _array("normals", self.normals, (n, 3), "1")
        if np.any(np.abs(np.linalg.norm(nrm, axis=1) - 1.0) > 1e-6):
            raise InputError("normals: must be unit vectors (|n| = 1 within 1e-6) [1], got "
                             f"|n| - 1 up to {np.max(np.abs(np.linalg.norm(nrm, axis=1) - 1)):.3g}")
        length = _array("length", self.length, (n,), "mm", low=0.0, low_open=True)
        r_eq = _array("r_eq", self.r_eq, (n,), "mm", low=0.0, low_open=True)
        load = _array("load", self.load, (n,), "N", low=0.0)
        pairs = real_array("pair_index", self.pair_index)
        if pairs.shape != (n,) or np.any(pairs % 1 != 0):
            raise InputError(f"pair_index: must be ({n},) integers, got shape {pairs.shape}")
        rot = [real(name, getattr(self, name), unit="rad")
               for name in ("pinion_rotation", "gear_rotation")]
        for name, val in (("midpoints", mid), ("ends", ends), ("normals", nrm),
                          ("length", length), ("r_eq", r_eq), ("load", load),
                          ("pair_index", pairs.astype(int)), ("pinion_rotation", rot[0]),
                          ("gear_rotation", rot[1])):
            object.__setattr__(self, name, val)

    def _set_if_checked(self) -> bool:
        """The check of :meth:`__post_init__` where every field is already what it
        accepts — float64 arrays of the exact shapes (int arrays for ``pair_index``),
        finite, within their bounds, Python floats for the rotations, as the LTCA builds
        them for every roll (issue 75: ~40 a study point, ~190 µs each through the
        general checks) — storing the same values (copies, as the general path); False
        (nothing set) where anything is otherwise: the general path then converts or
        refuses with its messages."""
        mid, ends, nrm = self.midpoints, self.ends, self.normals
        length, r_eq, load, pairs = self.length, self.r_eq, self.load, self.pair_index
        if not (type(mid) is np.ndarray and mid.dtype == np.float64 and mid.ndim == 2
                and mid.shape[1] == 3 and mid.shape[0] > 0):
            return False
        n = mid.shape[0]
        for a, shape in ((ends, (n, 2, 3)), (nrm, (n, 3)), (length, (n,)), (r_eq, (n,)),
                         (load, (n,))):
            if not (type(a) is np.ndarray and a.dtype == np.float64 and a.shape == shape):
                return False
        if not (type(pairs) is np.ndarray and pairs.dtype.kind == "i" and pairs.shape == (n,)
                and all(type(getattr(self, r)) is float
                        for r in ("pinion_rotation", "gear_rotation"))):
            return False
        # a finite sum of each array: every entry finite (a NaN or an infinity makes the
        # sum non-finite; a finite sum's overflow only sends the general path); the
        # least length and R_eq > 0 and load ≥ 0 (False for a NaN)
        if not (all(math.isfinite(float(np.add.reduce(a, axis=None)))
                    for a in (mid, ends, nrm))
                and float(length.min()) > 0.0 and float(r_eq.min()) > 0.0
                and float(load.min()) >= 0.0
                and math.isfinite(self.pinion_rotation)
                and math.isfinite(self.gear_rotation)):
            return False
        if np.any(np.abs(np.linalg.norm(nrm, axis=1) - 1.0) > 1e-6):
            return False  # the general path's message
        # (|pair_index| < 2**53: the general path's float round trip keeps the values)
        for name, val in (("midpoints", mid.copy()), ("ends", ends.copy()),
                          ("normals", nrm.copy()), ("length", length.copy()),
                          ("r_eq", r_eq.copy()), ("load", load.copy()),
                          ("pair_index", pairs.astype(int))):
            object.__setattr__(self, name, val)
        return True

    @property
    def size(self) -> int:
        """Number of segments N."""
        return int(self.midpoints.shape[0])

    @classmethod
    def of_rolls(cls, counts, pinion_rotation, gear_rotation,
                 **fields: Any) -> list[ContactSegments]:
        """The segments of several roll positions from their rows concatenated, checked
        in one pass.

        Parameters
        ----------
        counts : array_like (R,) of int — [1] segments of each roll position (≥ 1)
        pinion_rotation, gear_rotation : array_like (R,) — [rad] each roll position's
            member rotations
        **fields
            ``midpoints`` (N, 3) [mm], ``ends`` (N, 2, 3) [mm], ``normals`` (N, 3) [1],
            ``length`` (N,) [mm], ``r_eq`` (N,) [mm], ``pair_index`` (N,) [1], ``load``
            (N,) [N]: as the class takes them, the R roll positions' rows one after the
            other (N = Σ counts).

        Returns
        -------
        list of ContactSegments (R,)
            Roll r's the rows of its segments, with its rotations: equal, field by field,
            to ``ContactSegments`` of those rows (its arrays views of one checked copy of
            all rows instead of a copy each).

        Raises
        ------
        InputError
            As the class, with the message of the first roll position it refuses (a
            count < 1: that roll's N ≥ 1); counts that do not match the rotations or
            add up to another number of rows than the fields have.

        Notes
        -----
        The LTCA's pool of segments of every computed roll (:mod:`contact.ltca.pool`)
        hands its rolls over in one batch (:func:`mesh_compliance_many`): its fields
        gathered for all rolls at once and checked once, where a roll at a time paid the
        checks and copies per roll (issue 75 item 4).
        """
        counts = np.asarray(counts)
        pin = np.asarray(pinion_rotation, dtype=float)
        gear = np.asarray(gear_rotation, dtype=float)
        if (counts.ndim != 1 or counts.dtype.kind not in "iu" or pin.shape != counts.shape
                or gear.shape != counts.shape):
            raise InputError(f"counts: must be (R,) integers with (R,) pinion_rotation and "
                             f"gear_rotation, got shapes {counts.shape}, {pin.shape}, "
                             f"{gear.shape}")
        at = np.concatenate([[0], np.cumsum(counts)]).tolist()
        whole = None
        if (counts.size and int(counts.min()) >= 1 and np.all(np.isfinite(pin))
                and np.all(np.isfinite(gear))):
            with contextlib.suppress(InputError):  # (refused: roll by roll, to name it)
                whole = cls(**fields)
        if whole is None or whole.size != at[-1]:
            if whole is not None:
                raise InputError(f"counts: must add up to the {whole.size} segments given, "
                                 f"got {at[-1]}")
            # roll by roll: each roll's checks and messages (the first refused raises)
            rows = {k: np.asarray(v) for k, v in fields.items()}
            return [cls(**{k: v[at[r]:at[r + 1]] if v.ndim else v for k, v in rows.items()},
                        pinion_rotation=float(pin[r]), gear_rotation=float(gear[r]))
                    for r in range(counts.size)]
        values = [(name, getattr(whole, name)) for name in _ROW_FIELDS]
        out = []
        for r, (p_r, g_r) in enumerate(zip(pin.tolist(), gear.tolist(), strict=True)):
            seg = object.__new__(cls)
            for name, value in values:
                object.__setattr__(seg, name, value[at[r]:at[r + 1]])
            object.__setattr__(seg, "pinion_rotation", p_r)
            object.__setattr__(seg, "gear_rotation", g_r)
            out.append(seg)
        return out


@dataclass(frozen=True, eq=False)
class PairComplianceModel:
    """Both members' tooth models of one case, with the shell settings.

    Attributes
    ----------
    pinion, gear : ToothModelData — :func:`contact.compliance.tooth.shell_tooth_from_case`
    theory : str — shell kinematics; n_height, n_face : int — Ritz modes
    build_time : float — [s] measuring both teeth and factorising both shells
    """

    pinion: ToothModelData
    gear: ToothModelData
    theory: str
    n_height: int
    n_face: int
    build_time: float

    def member(self, name: str) -> ToothModelData:
        """The tooth model of ``"pinion"`` or ``"gear"``."""
        if name not in ("pinion", "gear"):
            raise InputError(f"member: must be 'pinion' or 'gear', got {name!r}")
        return getattr(self, name)


def _build_pair(case: Case, theory: str, n_height: int, n_face: int,
                materials: tuple[float, float, float, float],
                bores: tuple[float | None, float | None]) -> PairComplianceModel:
    t0 = time.perf_counter()
    teeth = {}
    for k, name in enumerate(("pinion", "gear")):
        data = shell_tooth_from_case(case, name, youngs_modulus=materials[2 * k],
                                     poisson_ratio=materials[2 * k + 1], bore_radius=bores[k])
        data.shell_model(theory, n_height, n_face)  # factorise now, once
        teeth[name] = data
    return PairComplianceModel(pinion=teeth["pinion"], gear=teeth["gear"], theory=theory,
                               n_height=n_height, n_face=n_face,
                               build_time=time.perf_counter() - t0)


@memoised(maxsize=_MEMO_SIZE)
def _memo_pair(teeth: TeethKey, theory: str, n_height: int, n_face: int,
               materials: tuple[float, float, float, float],
               bores: tuple[float | None, float | None]) -> PairComplianceModel:
    return _build_pair(teeth.case, theory, n_height, n_face, materials, bores)


def pair_compliance_model(
    case: Case,
    *,
    theory: str = "seed",
    n_height: int = N_HEIGHT,
    n_face: int = N_FACE,
    pinion_material: tuple[float, float] = STEEL,
    gear_material: tuple[float, float] = STEEL,
    pinion_bore: float | None = None,
    gear_bore: float | None = None,
) -> PairComplianceModel:
    """Tooth models and factorised shells of both members, built once per case.

    Parameters
    ----------
    case : geometry.case.Case
    theory : str — shell kinematics (:data:`contact.compliance.shell.THEORIES`)
    n_height, n_face : int — [1] Ritz modes (default 6 × 21, see
        :data:`contact.compliance.tooth.N_FACE`)
    pinion_material, gear_material : (float, float) — ([MPa], [1]) E and ν
    pinion_bore, gear_bore : float, optional — [mm] bore radii for the Sainsot
        foundation (default: half the mean root radius, see
        :func:`contact.compliance.tooth.shell_tooth_from_case`)

    Returns
    -------
    PairComplianceModel
        Memoised: a second call with an equal case (the same teeth, Case.teeth_key) and equal
        settings returns the same object without measuring or factorising again
        (the last 4 cases are kept).

    Raises
    ------
    InputError, ModelUnavailableError, LTCAError
        As :func:`contact.compliance.tooth.shell_tooth_from_case` and
        :func:`contact.compliance.shell.build_shell_model`.

    Notes
    -----
    Seed Fig. 3.2: the Ritz coefficients are computed once and are "valid for all
    mesh positions". The memo (``functools.lru_cache`` of 4 entries, the only state
    of this module; :func:`clear_model_cache` empties it) is keyed by
    :meth:`geometry.case.Case.teeth_key`: the case without its misalignment and
    deviations (neither changes a tooth in its member's frame), compared to the last
    bit of every field, so two cases that differ only in how they are assembled share one
    model — a misalignment sweep builds it once per worker process. A caller that
    keeps the model (e.g. the LTCA pipeline) can pass it to :func:`mesh_compliance`
    and need not rely on the memo.
    """
    materials = []
    for name, mat in (("pinion_material", pinion_material), ("gear_material", gear_material)):
        try:
            e, nu = mat
        except (TypeError, ValueError):
            raise InputError(f"{name}: must be (youngs_modulus [MPa], poisson_ratio [1]), got "
                             f"{mat!r}") from None
        materials += [real(f"{name}[0]", e, unit="MPa"), real(f"{name}[1]", nu, unit="1")]
    bores = tuple(None if b is None else float(b) for b in (pinion_bore, gear_bore))
    n_height, n_face = integer("n_height", n_height), integer("n_face", n_face)
    # the teeth live in their members' frames: the misalignment and the surface
    # deviations of the case change the assembly, not the shells, so they are left out of
    # the memo's key (a misalignment sweep builds the shells once per process)
    return _memo_pair(case.teeth_key(), str(theory), n_height, n_face, tuple(materials),
                      bores)


def model_cache_info() -> tuple[int, int, int | None, int]:
    """Hits, misses and size of the memo of :func:`pair_compliance_model` in this process
    (a study asks its workers, to show the tooth models are built once per worker)."""
    return _memo_pair.cache_info()


def clear_model_cache() -> None:
    """Forget the memoised tooth models of :func:`pair_compliance_model` (frees memory)."""
    _memo_pair.cache_clear()


def _take(sp: ShellPoints, idx: np.ndarray) -> ShellPoints:
    return ShellPoints(*(None if a is None else a[idx] for a in sp))


def _distinct_ends(ends: np.ndarray, breaks: np.ndarray | None = None
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Segment ends (N, 2, 3) [mm] without the repeats of consecutive segments.

    Returns the distinct points (D, 3) and the index (2N,) of each of the first N then
    second N ends among them: where segment k ends exactly (bit for bit) where segment
    k + 1 starts, as along one contact curve, that point is listed once (D ≈ N + curves
    instead of 2N). ``breaks`` (int array): segments whose second end is listed whatever
    the next segment's start (the last segment of each roll where several rolls'
    segments are concatenated: :func:`_distinct_ends_of_rolls`).
    """
    n = ends.shape[0]
    starts = ends[:, 0]
    shared = np.zeros(n, dtype=bool)
    a, b = ends[:-1, 1], ends[1:, 0]
    # (the three coordinates compared element-wise: the same as np.all along the length-3
    # axis, without numpy's slow reduction there)
    shared[:-1] = (a[:, 0] == b[:, 0]) & (a[:, 1] == b[:, 1]) & (a[:, 2] == b[:, 2])
    if breaks is not None:
        shared[breaks] = False
    own = np.flatnonzero(~shared)
    second = np.empty(n, dtype=int)
    second[:-1] = np.arange(1, n)
    second[own] = n + np.arange(own.size)
    return (np.concatenate([starts, ends[own, 1]]),
            np.concatenate([np.arange(n), second]))


def _distinct_ends_of_rolls(ends: np.ndarray, counts: np.ndarray
                            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`_distinct_ends` of every roll, the rolls' segments concatenated in ``ends``
    (N, 2, 3) [mm], ``counts`` (R,) segments a roll: in one pass over all rolls.

    Returns the distinct points (D, 3), roll by roll (each roll's as
    :func:`_distinct_ends` of its segments alone lists them: its starts, then its own
    second ends), their start in it per roll (R + 1,), and the index (2N,) of the
    rolls' first ends (N, roll by roll) then second ends among them: the points and index
    of the rolls one by one, concatenated, to the bit (no end is shared across rolls).
    """
    last = np.cumsum(counts) - 1
    points, index = _distinct_ends(ends, last[counts > 0])
    n = ends.shape[0]
    roll = np.repeat(np.arange(counts.size), counts)  # (N,) each segment's roll
    # each distinct point's roll: the starts', then the own second ends' (in segment order)
    roll_d = np.concatenate([roll, roll[index[n:] >= n]])
    # roll by roll: a stable sort by roll keeps each roll's starts before its own ends
    order = np.argsort(roll_d, kind="stable")
    place = np.empty_like(order)
    place[order] = np.arange(order.size)
    at = np.concatenate([[0], np.cumsum(np.bincount(roll_d, minlength=counts.size))])
    return points[order], at, place[index]


def mesh_compliance(
    case: Case,
    contact_segments: ContactSegments,
    *,
    model: PairComplianceModel | None = None,
    weber_kind: str = "secant",
    load_floor: float = 1.0,
    **model_options: Any,
) -> tuple[np.ndarray, dict[str, Any]]:
    """Total compliance of the contact segments of one roll position [mm/N].

    Parameters
    ----------
    case : geometry.case.Case — the gear pair (misalignments from ``case.misalignment``)
    contact_segments : ContactSegments — N segments in the pair frame
    model : PairComplianceModel, optional — both members' tooth models; default
        :func:`pair_compliance_model` of the case (memoised: built on the first call,
        reused afterwards) with ``model_options``
    weber_kind : {"secant", "tangent"} — Weber linearisation
        (:data:`contact.compliance.weber.WEBER_COMPLIANCE_KINDS`)
    load_floor : float — [N/mm] w′ below this is evaluated at this value
    **model_options — ``theory``, ``n_height``, ``n_face``, ``pinion_material``,
        ``gear_material``, ``pinion_bore``, ``gear_bore`` of :func:`pair_compliance_model`

    Returns
    -------
    C : ndarray (N, N) — [mm/N] total compliance along the contact normals,
        symmetric, block diagonal by ``pair_index`` (order of the segments kept)
    info : dict
        ``"pinion_shell"``, ``"gear_shell"`` (N, N) [mm/N] bending and shear;
        ``"pinion_foundation"``, ``"gear_foundation"`` (N, N) [mm/N] Sainsot;
        ``"weber"`` (N, N) [mm/N] diagonal contact compliance; ``"asymmetry"`` [1]
        largest ‖C − Cᵀ‖/‖C‖ of the shell blocks before symmetrisation;
        ``"pinion_points"``, ``"gear_points"`` (:class:`ShellPoints`);
        ``"weber_depth"`` (N, 2) [mm]; ``"blocks"`` {pair: segment indices};
        ``"model"`` the PairComplianceModel; ``"time"`` [s].

    Raises
    ------
    InputError
        Midpoints off a member's tooth (segment ends may overhang by
        :data:`contact.compliance.tooth.END_TOLERANCE` and are clipped), normals
        pointing into the pinion (the contact normal must point out of the pinion),
        bad Weber inputs.
    ModelUnavailableError
        Unknown shell theory or Weber kind.

    Notes
    -----
    Seed §3.2 (Eq. 3.11 per member, Fig. 3.2 "calculate total compliance matrix")
    and p. 78 (Weber [3.8]; base effects — Sainsot et al. 2004 here, as the seed's
    Stegemiller interpolation is not published). Per member the segments are
    mapped to its shell by :func:`contact.compliance.tooth.shell_coordinates`
    with the member's transform at this roll position; each pinion load acts
    along −n on the pinion flank, each gear load along +n on the gear flank, so
    the four flexibilities add up as approaches along the contact normal. Weber's
    depths are the members' contact-to-centreline distances
    (:func:`contact.compliance.tooth.weber_depth`).
    """
    return mesh_compliance_many(case, [contact_segments], model=model, weber_kind=weber_kind,
                                load_floor=load_floor, **model_options)[0]


def mesh_compliance_many(
    case: Case,
    segments: list[ContactSegments],
    *,
    model: PairComplianceModel | None = None,
    weber_kind: str = "secant",
    load_floor: float = 1.0,
    **model_options: Any,
) -> list[tuple[np.ndarray, dict[str, Any]]]:
    """:func:`mesh_compliance` of several roll positions at once.

    The segments of all roll positions (each with its own member rotations) are mapped
    onto both members' shells in ONE batch (the mapping's cost is mostly per call, not
    per point); the matrices are then assembled per roll position. Each result equals
    :func:`mesh_compliance` of that roll position to round-off.

    Parameters
    ----------
    case : geometry.case.Case
    segments : list of ContactSegments — one per roll position
    model, weber_kind, load_floor, **model_options
        As :func:`mesh_compliance`.

    Returns
    -------
    list of (C, info)
        As :func:`mesh_compliance`, one per roll position; ``info["time"]`` [s] is the
        batch's time shared evenly among them.

    Raises
    ------
    InputError
        As :func:`mesh_compliance` (the message names the point within its roll).

    Notes
    -----
    The model is :func:`mesh_compliance`'s (seed §3.2, Eq. 3.11; Weber 1949; Sainsot et
    al. 2004); only the batching differs. Tested equal to it per roll to 1e-12
    (tests/test_compliance_fast_paths.py).
    """
    t0 = time.perf_counter()
    if not all(isinstance(seg, ContactSegments) for seg in segments):
        bad = next(type(seg).__name__ for seg in segments
                   if not isinstance(seg, ContactSegments))
        raise InputError(f"contact_segments: must be ContactSegments, got a {bad}")
    if model is None:
        model = pair_compliance_model(case, **model_options)
    elif model_options:
        raise InputError(f"give either model or model options, not both: {sorted(model_options)}")
    # midpoints may overhang slightly too: the LTCA takes them on the gear side, and the
    # pinion mate differs by the ease-off (≤ tens of µm) along the normal; they are
    # clipped onto the tooth like segment ends. Midpoints and ends of every roll position
    # in one job per member, both members in one batch (shell_points_many); an end shared
    # by consecutive segments is mapped once.
    if not segments:
        return []
    names = ("pinion", "gear")
    try:
        points, mids, both = _map_members(case, segments, model)
    except InputError:
        # the mapping refused a point: map roll by roll as jobs of their own, whose
        # message names the point within its roll (raises; the batch's own error if not)
        _map_rolls(case, segments, model)
        raise
    # the shell matrices of every tooth pair of every roll position: one set of load
    # vectors and one triangular solve per member (the shell's stiffness does not depend
    # on the roll position), one block per (roll, pair)
    offsets = np.concatenate([[0], np.cumsum([seg.size for seg in segments])])
    blocks, flat_blocks = _pair_blocks(segments, offsets)
    shell, found = {}, {}
    for name in names:
        shell[name] = shell_matrices(model.member(name), mids[name], both[name],
                                     model.theory, model.n_height, model.n_face, flat_blocks)
        # the fillet foundation of every tooth of every roll position in one batch
        found[name] = member_foundations(model.member(name), mids[name], flat_blocks)
    # Weber's depths and compliance of every segment of every roll position at once (each
    # segment's own; the batch changes nothing but the number of calls)
    depth = np.column_stack([weber_depth(model.pinion, mids["pinion"]),
                             weber_depth(model.gear, mids["gear"])])
    tp, tg = model.pinion.tooth, model.gear.tooth
    c_w = weber_compliance(np.concatenate([seg.load for seg in segments]),
                           np.concatenate([seg.length for seg in segments]),
                           depth[:, 0], depth[:, 1], e1=tp.youngs_modulus,
                           nu1=tp.poisson_ratio, e2=tg.youngs_modulus, nu2=tg.poisson_ratio,
                           r_eq=np.concatenate([seg.r_eq for seg in segments]),
                           kind=weber_kind, load_floor=load_floor)
    out = _assemble_rolls(segments, model, points, blocks, shell, found, depth, c_w, offsets)
    share = (time.perf_counter() - t0) / max(len(segments), 1)
    for _, info in out:
        info["time"] = share
        log.debug("mesh compliance: %d segments in %d tooth pairs, %.4f s",
                  len(info["weber_depth"]), len(info["blocks"]), share)
    return out


def _pair_blocks(segments: list[ContactSegments], offsets: np.ndarray
                 ) -> tuple[list[dict[int, np.ndarray]], list]:
    """Each roll's tooth-pair blocks {pair: its segments' indices in the roll}, pairs
    ascending, and the same blocks of all rolls in one list, rolls in order, as indices
    into the rolls' concatenated segments (``offsets`` (R + 1,) each roll's first): a
    slice where a block's segments are consecutive (a roll's segments ordered by pair, as
    the LTCA gives them: the rows the shell and foundation products then take as views,
    not copies), else the index array.

    Where every roll's segments are ordered by pair the blocks are the runs of equal
    (roll, pair) over all rolls, found in one pass; else each roll's pairs are looked up
    on their own (the same blocks)."""
    counts = np.diff(offsets)
    pairs = np.concatenate([seg.pair_index for seg in segments])
    roll = np.repeat(np.arange(len(segments)), counts)
    same_roll = roll[1:] == roll[:-1]
    if np.all(pairs[1:][same_roll] >= pairs[:-1][same_roll]):
        new = np.ones(pairs.size, dtype=bool)
        new[1:] = ~same_roll | (pairs[1:] != pairs[:-1])
        start = np.flatnonzero(new)
        stop = np.append(start[1:], pairs.size)
        blocks: list[dict[int, np.ndarray]] = [{} for _ in segments]
        flat = []
        for a, b, r, pair in zip(start.tolist(), stop.tolist(), roll[start].tolist(),
                                 pairs[start].tolist(), strict=True):
            first = a - int(offsets[r])
            blocks[r][pair] = np.arange(first, first + b - a)
            flat.append(slice(a, b))
        return blocks, flat
    blocks = [{int(pair): np.flatnonzero(seg.pair_index == pair)
               for pair in np.unique(seg.pair_index)} for seg in segments]
    flat = []
    for r, b in enumerate(blocks):
        for idx in b.values():
            rows, _ = _block(offsets[r] + idx)
            flat.append(rows if isinstance(rows, slice) else offsets[r] + idx)
    return blocks, flat


def _map_rolls(case: Case, segments: list[ContactSegments],
               model: PairComplianceModel) -> list[list[ShellPoints]]:
    """The segments' midpoints and distinct ends mapped onto both shells with one job per
    (roll, member), each in its own pair → member transform (the checks' messages name
    the point within its roll)."""
    jobs = []
    for seg in segments:
        t_p, t_g = case_transforms(case, seg.pinion_rotation, seg.gear_rotation)
        ends_flat, _ = _distinct_ends(seg.ends)
        jobs += [(model.member(name), seg.midpoints, sign * seg.normals, transform, ends_flat)
                 for name, transform, sign in zip(("pinion", "gear"), (t_p, t_g), (1.0, -1.0),
                                                  strict=True)]
    return shell_points_many(jobs, END_TOLERANCE)


def _map_members(case: Case, segments: list[ContactSegments], model: PairComplianceModel
                 ) -> tuple[list[dict[str, ShellPoints]], dict[str, ShellPoints],
                            dict[str, ShellPoints]]:
    """Midpoints and segment ends of every roll position on both members' shells: one
    job per member (all rolls' points turned into the member's frame first, each roll by
    its own transform, then mapped in one batch, :func:`shell_points_many`).

    Returns each roll's midpoints per member (ShellPoints, frames in the pair frame), and
    per member all rolls' midpoints and the ends in :func:`shell_matrices`' order (the
    first ends of all rolls, then their second ends). The same arithmetic per point as
    :func:`_map_rolls`' jobs (the transforms' products, the mapping point by point), so
    the same results to round-off.

    Raises
    ------
    InputError
        A point off its tooth (the message's point index counts over all rolls:
        the caller maps again roll by roll to name it within its roll).
    """
    rolls = len(segments)
    t_p, t_g = case_transforms(case, np.array([s.pinion_rotation for s in segments]),
                               np.array([s.gear_rotation for s in segments]))
    rot = np.stack([t_p[:, :3, :3], t_g[:, :3, :3]])  # (member, roll, 3, 3)
    if not np.allclose(np.einsum("mrji,mrjk->mrik", rot, rot), np.eye(3), atol=1e-9):
        raise InputError("transform: must be a rigid motion (orthonormal rotation block)")
    off = np.stack([t_p[:, :3, 3], t_g[:, :3, 3]])  # (member, roll, 3)
    n_mid = np.array([seg.size for seg in segments])
    mid_at = np.concatenate([[0], np.cumsum(n_mid)])
    # every roll's distinct ends (roll by roll) in one pass, and each roll's first then
    # second ends among them
    distinct, end_at, take = _distinct_ends_of_rolls(
        np.concatenate([seg.ends for seg in segments]), n_mid)
    jobs = []
    for i, (name, sign) in enumerate((("pinion", 1.0), ("gear", -1.0))):
        mid = np.empty((int(mid_at[-1]), 3))
        nrm = np.empty_like(mid)
        ends = np.empty((int(end_at[-1]), 3))
        for r, seg in enumerate(segments):  # (p − o) R: the member frame's coordinates
            rows, rows_e = slice(mid_at[r], mid_at[r + 1]), slice(end_at[r], end_at[r + 1])
            mid[rows] = (seg.midpoints - off[i, r]) @ rot[i, r]
            nrm[rows] = (sign * seg.normals) @ rot[i, r]
            ends[rows_e] = (distinct[rows_e] - off[i, r]) @ rot[i, r]
        jobs.append((model.member(name), mid, nrm, None, ends))
    mapped = _kept_mapping(jobs)
    mids, both = {}, {}
    per_roll: list[dict[str, ShellPoints]] = [{} for _ in range(rolls)]
    for i, name in enumerate(("pinion", "gear")):
        sp_mid, sp_end = mapped[i]
        # the midpoints' frames back in the pair frame (rows e_x, e_θ, e_z: e R^T)
        rot_t = np.repeat(np.swapaxes(rot[i], 1, 2), n_mid, axis=0)
        mids[name] = sp_mid._replace(frame=np.matmul(sp_mid.frame, rot_t))
        both[name] = _take(sp_end, take)
        for r in range(rolls):
            per_roll[r][name] = _take(mids[name], slice(mid_at[r], mid_at[r + 1]))
    return per_roll, mids, both


#: points whose shell coordinates :func:`_kept_mapping` keeps per tooth model (the default
#: case's analysis maps ~3,000 midpoints and ends a member)
POINTS_KEPT = 16384

_SHELL_FIELDS = ("x", "theta", "u", "v", "side", "offset", "frame")


class _PointStore(BatchedRows):
    """The shell coordinates kept for one tooth model (:func:`_point_store`): a
    :class:`~geometry.core.caches.BatchedRows` whose batches are ShellPoints (read-only)."""

    __slots__ = ()

    def add(self, sp: ShellPoints, keys: list[bytes]) -> None:
        """Keep the points ``keys`` (in the order of ``sp``'s rows), made read-only."""
        for a in sp:
            if isinstance(a, np.ndarray):
                a.flags.writeable = False
        super().add(sp, keys)

    def gather(self, keys: list[bytes], normal: bool) -> ShellPoints:
        """The kept shell coordinates of the points ``keys`` as one ShellPoints."""
        code = np.fromiter(map(self.rows.__getitem__, keys), dtype=np.int64, count=len(keys))
        batch, row = code >> 32, code & 0xFFFFFFFF
        names = (*_SHELL_FIELDS, *(("normal",) if normal else ()))
        fields: dict[str, np.ndarray | None] = {"normal": None}
        ids = np.unique(batch)
        for b in ids.tolist():
            sp = self.batches[b]
            if ids.size == 1:  # one batch: a take of its rows
                fields.update({name: getattr(sp, name)[row] for name in names})
                break
            sel = batch == b
            for name in names:
                part = getattr(sp, name)
                if name not in fields or fields[name] is None:
                    fields[name] = np.empty((len(keys), *part.shape[1:]), dtype=part.dtype)
                fields[name][sel] = part[row[sel]]
        return ShellPoints(**fields)


@memoised(maxsize=4)
def _point_store(data: Same) -> _PointStore:
    """The shell coordinates of the points mapped so far onto the tooth model
    ``data.obj``, by the point's bytes (member frame; a midpoint with its normal): one
    store per tooth model, emptied with the memo (``clear_caches``); the last
    :data:`POINTS_KEPT` points are kept (the oldest dropped first)."""
    return _PointStore()


def _missing(kept: dict, keys: list[bytes]) -> list[int]:
    """The indices of the ``keys`` not in ``kept``."""
    return np.flatnonzero(~np.fromiter(map(kept.__contains__, keys), dtype=bool,
                                       count=len(keys))).tolist()


def _kept_mapping(jobs: list) -> list[list[ShellPoints]]:
    """:func:`contact.compliance.tooth.shell_points_many` of jobs (data, midpoints (N, 3),
    normals (N, 3), None, ends (D, 3)) in their members' frames, each point's shell
    coordinates kept per process and tooth model (:func:`_point_store`): the analyses of a
    torque series or one repeated at one misalignment map the same segments (the memoised
    curve segments, :mod:`contact.ltca.segments`). Only the points not kept are mapped, in
    one batch as before (a point's coordinates are its own to round-off: the batch
    iterates until its slowest point converged); a point the mapping refuses raises as
    there and is not kept."""
    # a development's trial (its teeth new at every trial), a study point (its segments
    # new at every point, geometry.core.caches.rows_not_kept): nothing kept
    if warm_seeds_active() or not rows_kept():
        return shell_points_many(jobs, END_TOLERANCE)
    stores = [_point_store(Same(job[0])) for job in jobs]
    with contextlib.ExitStack() as held:
        for store in {id(st): st for st in stores}.values():
            held.enter_context(store.lock)
        return _kept_mapping_held(jobs, stores)


def _kept_mapping_held(jobs: list, stores: list[_PointStore]) -> list[list[ShellPoints]]:
    """:func:`_kept_mapping` with the jobs' stores (their locks held)."""
    keys, todo = [], []
    for (_, mid, nrm, _, ends), store in zip(jobs, stores, strict=True):
        k_mid = row_keys(np.concatenate([mid, nrm], axis=1), b"m")
        k_end = row_keys(ends, b"e")
        todo.append((_missing(store.rows, k_mid), _missing(store.rows, k_end)))
        keys.append((k_mid, k_end))
    run = [i for i, (mm, me) in enumerate(todo) if mm or me]
    fresh: dict[int, list[ShellPoints]] = {}
    if run:
        new = shell_points_many([(jobs[i][0], jobs[i][1][todo[i][0]], jobs[i][2][todo[i][0]],
                                  None, jobs[i][4][todo[i][1]]) for i in run], END_TOLERANCE)
        for i, (sp_mid, sp_end) in zip(run, new, strict=True):
            (k_mid, k_end), (miss_mid, miss_end) = keys[i], todo[i]
            stores[i].add(sp_mid, [k_mid[j] for j in miss_mid])
            stores[i].add(sp_end, [k_end[j] for j in miss_end])
            if len(miss_mid) == len(k_mid) and len(miss_end) == len(k_end):
                fresh[i] = [sp_mid, sp_end]  # nothing kept: the batch's own result
    out = []
    for i, store in enumerate(stores):
        k_mid, k_end = keys[i]
        out.append(fresh[i] if i in fresh else [store.gather(k_mid, normal=True),
                                                store.gather(k_end, normal=False)])
    for store in stores:
        store.trim(POINTS_KEPT)
    return out


def _block(idx: np.ndarray):
    """The (rows, columns) index of a block of segments ``idx`` in a matrix: two slices
    where the segments are consecutive (a view), else ``np.ix_``."""
    if idx.size and int(idx[-1]) - int(idx[0]) == idx.size - 1:
        sl = slice(int(idx[0]), int(idx[-1]) + 1)
        return sl, sl
    return np.ix_(idx, idx)


def _assemble_rolls(segments: list[ContactSegments], model: PairComplianceModel,
                    points: list[dict], blocks: list[dict], shell: dict, found: dict,
                    depth: np.ndarray, c_w: np.ndarray, offsets: np.ndarray
                    ) -> list[tuple[np.ndarray, dict]]:
    """The compliance matrices of every roll position from its mapped shell points
    (``points[r]``), its tooth pairs' blocks (``blocks[r]``), the shell and foundation
    matrices of all rolls' blocks in order (``shell[member]``: ComplianceMatrix,
    ``found[member]``: ndarray, one per block of every roll), Weber's depths (N, 2) [mm]
    and compliances (N,) [mm/N] of all rolls' segments (roll r's rows
    ``offsets[r]:offsets[r + 1]``).

    Each roll's parts are (n, n) views of one buffer for all rolls (allocated and summed
    once: C = shell_p + shell_g + foundation_p + foundation_g + Weber, block by block, in
    that order), then symmetrised roll by roll; the same matrices as one roll at a time
    (its parts summed in the same order), to the bit."""
    sizes = np.diff(offsets)
    at = np.concatenate([[0], np.cumsum(sizes * sizes)])
    buf = np.zeros((4, int(at[-1])))  # pinion shell, gear shell, pinion and gear foundation
    views = [buf[:, at[r]:at[r + 1]].reshape(4, int(n), int(n))
             for r, n in enumerate(sizes.tolist())]
    k = 0
    asym = []
    for r, roll_blocks in enumerate(blocks):
        parts, a = views[r], 0.0
        for idx in roll_blocks.values():
            cp, cg = shell["pinion"][k], shell["gear"][k]
            ix = _block(idx)
            parts[0][ix] = cp.matrix
            parts[1][ix] = cg.matrix
            parts[2][ix] = found["pinion"][k]
            parts[3][ix] = found["gear"][k]
            a = max(a, cp.asymmetry, cg.asymmetry)
            k += 1
        asym.append(a)
    # the total of all rolls at once (zero between tooth pairs), each diagonal with Weber's
    total = buf[0] + buf[1]
    total += buf[2]
    total += buf[3]
    roll = np.repeat(np.arange(sizes.size), sizes)
    local = np.arange(int(offsets[-1])) - offsets[roll]
    total[at[roll] + local * (sizes[roll] + 1)] += c_w
    out = []
    for r, seg in enumerate(segments):
        n = seg.size
        c = total[at[r]:at[r + 1]].reshape(n, n)
        rows = slice(offsets[r], offsets[r + 1])
        parts = views[r]
        info: dict[str, Any] = {"pinion_shell": parts[0], "gear_shell": parts[1],
                                "pinion_foundation": parts[2], "gear_foundation": parts[3],
                                "weber": np.diag(c_w[rows])}
        info.update(asymmetry=asym[r], pinion_points=points[r]["pinion"],
                    gear_points=points[r]["gear"], weber_depth=depth[rows],
                    blocks=blocks[r], model=model)
        out.append((0.5 * (c + c.T), info))
    return out
