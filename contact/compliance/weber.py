"""Contact (Hertzian) deformation of a tooth pair by Weber's formula.

Seed section 3.2 (p. 78): "Closed-form formula of Weber [3.8] was used here for
computing the Hertzian deformations". Weber's formula gives the approach of a
point on the tooth centreline towards the contact of a line contact, per body and
per unit length of the contact line; it grows like w′ ln(1/w′), so the contact
compliance depends on the load.

Conventions (stated once, used everywhere in this module)
---------------------------------------------------------
* ``E*`` is the *contact modulus* of Johnson (*Contact Mechanics*, 1985, Eq. 4.22):
  1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (not the plane-strain modulus of one body, not
  twice it). For steel on steel (E = 206 000 MPa, ν = 0.3) E* = 113 187 MPa.
* Hertz half-width of a line contact (Johnson Eq. 4.43 with this E*):
  b = sqrt(4 w′ R_eq / (π E*)), R_eq = R₁R₂/(R₁ + R₂) (seed Eq. 2.13's R_eq).
* Weber (1949), per body i (NOTES.md; Weber & Banaschek 1953):
  δ_i = (2 w′ (1 − ν_i²)/(π E_i)) · [ln(2 h_i / b) − ν_i / (2 (1 − ν_i))],
  h_i the distance from the contact to the tooth centreline; the pair deforms by
  δ₁ + δ₂.
* Units: w′ [N/mm], lengths [mm], moduli [MPa] → δ [mm], compliance [mm/N].

How the LTCA uses it
--------------------
The contact term is diagonal (a segment's contact deformation depends on its own
load only) and load-dependent. Evaluate :func:`weber_compliance` at a reference
load per segment (e.g. the mean load T/(R·N)), add it to the diagonal of the
bending/base compliance, solve the contact QP, then re-evaluate at the computed
segment loads and re-solve until the loads stop changing (fixed point
F → C_H(F) → F). With the *secant* compliance δ(F)/F the converged loads satisfy
the nonlinear compatibility exactly; the *tangent* compliance dδ/dF is what a
Newton iteration needs. Segments that end with no load are evaluated at
``load_floor``; their compliance multiplies a zero force, so it does not enter
the solution.

Public API
----------
contact_modulus            E* [MPa]
hertz_half_width           b [mm] of a line contact
weber_deformation          δ_i [mm] of one body
weber_pair_deformation     δ₁ + δ₂ [mm]
weber_compliance           diagonal contact compliance [mm/N] of loaded segments
WeberSegments              segments validated once, their compliance at several loads
WEBER_COMPLIANCE_KINDS     registry: "secant", "tangent"

References
----------
Weber, C. (1949). The deformation of loaded gears and the effect on their
load-carrying capacity. Sponsored Research (Germany), British Dept. of Scientific
and Industrial Research, Report No. 3.
Weber, C., Banaschek, K. (1953). Formänderung und Profilrücknahme bei gerad- und
schrägverzahnten Rädern. Schriftenreihe Antriebstechnik 11, Vieweg.
Johnson, K. L. (1985). Contact Mechanics. Cambridge University Press.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from geometry.core.caches import memoised
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.hertz import contact_modulus, hertz_line_contact
from geometry.core.validation import positive, real, real_array

__all__ = [
    "WEBER_COMPLIANCE_KINDS",
    "WeberSegments",
    "contact_modulus",
    "hertz_half_width",
    "weber_compliance",
    "weber_deformation",
    "weber_pair_deformation",
]


def _modulus(name: str, value: float) -> float:
    return real(name, value, unit="MPa", low=0.0, low_open=True)


def _poisson(name: str, value: float) -> float:
    return real(name, value, unit="1", low=0.0, high=0.5, high_open=True)


def hertz_half_width(
    load_per_length: np.ndarray | float,
    r_eq: np.ndarray | float,
    e1: float,
    nu1: float,
    e2: float,
    nu2: float,
) -> np.ndarray:
    """Hertz half-width of a line contact [mm].

    Parameters
    ----------
    load_per_length : float or ndarray (N,) — [N/mm] w′ > 0
    r_eq : float or ndarray (N,) — [mm] equivalent radius R₁R₂/(R₁ + R₂) > 0
    e1, e2 : float — [MPa]; nu1, nu2 : float — [1]

    Returns
    -------
    ndarray — [mm] b = sqrt(4 w′ R_eq / (π E*)), broadcast shape of the inputs

    Raises
    ------
    InputError
        w′ or R_eq not finite and positive; bad material constants.

    Notes
    -----
    Johnson (1985) Eq. 4.43 with E* of :func:`contact_modulus`: the half-width of
    :func:`geometry.core.hertz.hertz_line_contact`, the toolkit's one Hertz line contact.
    """
    w = real_array("load_per_length", load_per_length, unit="N/mm", low=0.0, low_open=True)
    r = real_array("r_eq", r_eq, unit="mm", low=0.0, low_open=True)
    return hertz_line_contact(w, r, contact_modulus(e1, nu1, e2, nu2)).half_width


def _weber_bracket(depth: np.ndarray, half_width: np.ndarray, nu: float, name: str) -> np.ndarray:
    bracket = np.log(2.0 * depth / half_width) - nu / (2.0 * (1.0 - nu))
    if np.any(bracket <= 0.0):
        raise InputError(
            f"{name}: must exceed half the Hertz half-width times exp(nu/(2(1-nu))) [mm] "
            "(Weber's formula is for a contact much narrower than the tooth), got "
            f"{int(np.count_nonzero(bracket <= 0.0))} depth(s) below it"
        )
    return bracket


def weber_deformation(
    load_per_length: np.ndarray | float,
    half_width: np.ndarray | float,
    depth: np.ndarray | float,
    youngs_modulus: float,
    poisson_ratio: float,
) -> np.ndarray:
    """Weber's contact deformation of one body [mm].

    Parameters
    ----------
    load_per_length : float or ndarray — [N/mm] w′ > 0
    half_width : float or ndarray — [mm] Hertz half-width b > 0
    depth : float or ndarray — [mm] h, distance from the contact to the tooth
        centreline (> b/2 · e^(ν/(2(1−ν))))
    youngs_modulus : float — [MPa]; poisson_ratio : float — [1]

    Returns
    -------
    ndarray — [mm] δ = (2 w′ (1 − ν²)/(π E)) [ln(2h/b) − ν/(2(1 − ν))]

    Raises
    ------
    InputError
        Non-positive or non-finite inputs; a depth so small that the bracket is
        not positive.

    Notes
    -----
    Weber (1949); NOTES.md. Seed p. 78 cites Weber [3.8] without the formula.
    """
    w = real_array("load_per_length", load_per_length, unit="N/mm", low=0.0, low_open=True)
    b = real_array("half_width", half_width, unit="mm", low=0.0, low_open=True)
    h = real_array("depth", depth, unit="mm", low=0.0, low_open=True)
    e, nu = _modulus("youngs_modulus", youngs_modulus), _poisson("poisson_ratio", poisson_ratio)
    return 2.0 * w * (1.0 - nu**2) / (math.pi * e) * _weber_bracket(h, b, nu, "depth")


def weber_pair_deformation(
    load_per_length: np.ndarray | float,
    r_eq: np.ndarray | float,
    depth_1: np.ndarray | float,
    depth_2: np.ndarray | float,
    e1: float,
    nu1: float,
    e2: float,
    nu2: float,
) -> np.ndarray:
    """Contact deformation δ₁ + δ₂ of a tooth pair [mm] (Weber 1949 + Hertz b).

    Parameters
    ----------
    load_per_length : float or ndarray (N,) — [N/mm] w′
    r_eq : float or ndarray (N,) — [mm] equivalent radius of curvature
    depth_1, depth_2 : float or ndarray (N,) — [mm] contact-to-centreline distances
    e1, nu1, e2, nu2 : float — [MPa], [1] materials of members 1 and 2

    Returns
    -------
    ndarray — [mm]

    Raises
    ------
    InputError
        As :func:`weber_deformation` and :func:`hertz_half_width`.
    """
    b = hertz_half_width(load_per_length, r_eq, e1, nu1, e2, nu2)
    return weber_deformation(load_per_length, b, depth_1, e1, nu1) + weber_deformation(
        load_per_length, b, depth_2, e2, nu2
    )


def _secant(kb: np.ndarray, ks: np.ndarray) -> np.ndarray:
    return kb + 0.0 * ks


def _tangent(kb: np.ndarray, ks: np.ndarray) -> np.ndarray:
    # d/dw′ [w′ k (ln(2h/b) − c)] = k (ln(2h/b) − c) − k · dln b/dln w′
    return kb - ks


#: Kinds of contact compliance: ``"secant"`` δ(F)/F (fixed-point iteration) and
#: ``"tangent"`` dδ/dF (Newton). Each maps (Σ_i k_i B_i, Σ_i k_i · dln b/dln w′),
#: both [mm²/N], to the compliance times the segment length [mm²/N].
WEBER_COMPLIANCE_KINDS: dict[str, Callable[[np.ndarray, np.ndarray], np.ndarray]] = {
    "secant": _secant,
    "tangent": _tangent,
}


def weber_compliance(
    load: np.ndarray | float,
    length: np.ndarray | float,
    depth_1: np.ndarray | float,
    depth_2: np.ndarray | float,
    *,
    e1: float,
    nu1: float,
    e2: float,
    nu2: float,
    r_eq: np.ndarray | float | None = None,
    half_width_fn: Callable[[np.ndarray], np.ndarray] | None = None,
    kind: str | Sequence[str] = "secant",
    load_floor: float = 1.0,
) -> np.ndarray | tuple[np.ndarray, ...]:
    """Diagonal contact compliance of loaded contact segments [mm/N].

    Parameters
    ----------
    load : float or ndarray (N,) — [N] segment forces F ≥ 0
    length : float or ndarray (N,) — [mm] segment lengths L > 0; w′ = F / L
    depth_1, depth_2 : float or ndarray (N,) — [mm] contact-to-centreline
        distances of the two members at each segment
    e1, nu1, e2, nu2 : float — [MPa], [1] materials
    r_eq : float or ndarray (N,), optional — [mm] equivalent radius; gives the
        Hertz half-width of :func:`hertz_half_width`
    half_width_fn : callable, optional — w′ [N/mm] (N,) → b [mm] (N,), instead of
        ``r_eq`` (e.g. an elliptical-contact or EHL half-width); exactly one of
        ``r_eq`` and ``half_width_fn`` must be given
    kind : {"secant", "tangent"} or a sequence of them — see
        :data:`WEBER_COMPLIANCE_KINDS` (a sequence: one array per kind, from one
        evaluation, e.g. both for a Newton step)
    load_floor : float — [N/mm] w′ below this is evaluated at this value
        (unloaded segments; their compliance multiplies a zero force)

    Returns
    -------
    ndarray (N,) — [mm/N] the diagonal term to add to the compliance matrix:
        secant δ(F)/F or tangent dδ/dF along the contact normal (a tuple of them for
        a sequence of kinds)

    Raises
    ------
    InputError
        Negative or non-finite loads, non-positive lengths/depths/floor, both or
        neither of ``r_eq`` / ``half_width_fn``, a half-width function returning
        non-positive values, a depth too small for Weber's formula.
    ModelUnavailableError
        Unknown ``kind`` (lists the available ones).

    Notes
    -----
    With k_i = 2(1 − ν_i²)/(π E_i) and B_i = ln(2h_i/b) − ν_i/(2(1 − ν_i)) (Weber),
    δ = w′ Σ k_i B_i, so secant = Σ k_i B_i / L and tangent = Σ k_i (B_i − s) / L
    with s = d ln b / d ln w′ (½ for Hertz; by central difference for
    ``half_width_fn``). Usage in the LTCA: see the module docstring.
    """
    kinds = _kinds(kind)
    if r_eq is not None and half_width_fn is None:
        # the segments' data validated once: the LTCA's Weber iteration keeps them
        # (WeberSegments) and evaluates them at each iteration's loads
        return WeberSegments.of(length, depth_1, depth_2, e1=e1, nu1=nu1, e2=e2, nu2=nu2,
                                r_eq=r_eq).compliance(load, kind, load_floor)
    f = real_array("load", load, unit="N", low=0.0)
    length_a = real_array("length", length, unit="mm", low=0.0, low_open=True)
    floor = positive("load_floor", load_floor, "N/mm")
    w = np.maximum(f / length_a, floor)
    if (r_eq is None) == (half_width_fn is None):
        raise InputError("r_eq, half_width_fn: must be exactly one given (r_eq [mm] or "
                         "w' -> b), got "
                         f"{'both' if r_eq is not None else 'neither'}")
    if half_width_fn is None:
        b = hertz_half_width(w, r_eq, e1, nu1, e2, nu2)
        slope = np.full_like(b, 0.5)
    else:
        b = np.asarray(half_width_fn(w), dtype=float)
        if b.shape != w.shape:
            raise InputError("half_width_fn: must return one half-width per load, got shape "
                             f"{b.shape} for loads of shape {w.shape}")
        real_array("half_width_fn(w')", b, unit="mm", low=0.0, low_open=True)
        step = 1e-4
        bp = np.asarray(half_width_fn(w * (1.0 + step)), dtype=float)
        bm = np.asarray(half_width_fn(w * (1.0 - step)), dtype=float)
        slope = (np.log(bp) - np.log(bm)) / (math.log1p(step) - math.log1p(-step))
    e1f, nu1f = _modulus("e1", e1), _poisson("nu1", nu1)
    e2f, nu2f = _modulus("e2", e2), _poisson("nu2", nu2)
    h1 = real_array("depth_1", depth_1, unit="mm", low=0.0, low_open=True)
    h2 = real_array("depth_2", depth_2, unit="mm", low=0.0, low_open=True)
    k1 = 2.0 * (1.0 - nu1f**2) / (math.pi * e1f)
    k2 = 2.0 * (1.0 - nu2f**2) / (math.pi * e2f)
    kb = k1 * _weber_bracket(h1, b, nu1f, "depth_1") + k2 * _weber_bracket(h2, b, nu2f, "depth_2")
    shape = np.broadcast_shapes(w.shape, b.shape)
    out = tuple(np.broadcast_to(WEBER_COMPLIANCE_KINDS[k](kb, (k1 + k2) * slope) / length_a,
                                shape).copy() for k in kinds)
    return out[0] if isinstance(kind, str) else out


def _kinds(kind: str | Sequence[str]) -> tuple[str, ...]:
    """The kinds of :func:`weber_compliance` as a tuple (ModelUnavailableError for an
    unknown one, listing the available ones)."""
    kinds = (kind,) if isinstance(kind, str) else tuple(kind)
    for k in kinds:
        if k not in WEBER_COMPLIANCE_KINDS:
            raise ModelUnavailableError(
                f"kind {k!r} is not available; choose one of {sorted(WEBER_COMPLIANCE_KINDS)}"
            )
    return kinds


@dataclass(frozen=True, eq=False)
class WeberSegments:
    """Contact segments whose Weber compliance is evaluated at several loads.

    What does not change with the load — lengths, depths, equivalent radii, materials —
    is validated once (:meth:`of`); :meth:`compliance` then evaluates
    :func:`weber_compliance` at given loads (the same arithmetic, value for value). The
    LTCA's Weber iteration (:func:`contact.ltca.weber.weber_solve`) evaluates one roll's
    segments at each iteration's loads.

    Attributes
    ----------
    length : ndarray (N,) — [mm] segment lengths L > 0
    depth_1, depth_2 : ndarray (N,) — [mm] contact-to-centreline distances h_i > 0
    r_eq : ndarray (N,) — [mm] equivalent radii > 0 (Hertz half-width)
    e_star : float — [MPa] contact modulus E*
    nu1, nu2 : float — [1]
    k1, k2 : float — [mm²/N] 2 (1 − ν_i²)/(π E_i)
    """

    length: np.ndarray
    depth_1: np.ndarray
    depth_2: np.ndarray
    r_eq: np.ndarray
    e_star: float
    nu1: float
    nu2: float
    k1: float
    k2: float

    def __post_init__(self) -> None:
        # what secant_tangent takes at every Weber iteration, formed once: 2 h_i (exact,
        # a power of two) and ν_i/(2(1 − ν_i))
        object.__setattr__(self, "_twice_depth", (2.0 * self.depth_1, 2.0 * self.depth_2))
        object.__setattr__(self, "_poisson_terms", (self.nu1 / (2.0 * (1.0 - self.nu1)),
                                                    self.nu2 / (2.0 * (1.0 - self.nu2))))

    @classmethod
    def of(cls, length, depth_1, depth_2, *, e1: float, nu1: float, e2: float, nu2: float,
           r_eq) -> WeberSegments:
        """Validate the segments' data (parameters as :func:`weber_compliance`).

        Raises
        ------
        InputError
            Non-positive or non-finite lengths, depths or radii; bad material constants.
        """
        arrays = (length, depth_1, depth_2, r_eq)
        if (all(type(a) is np.ndarray and a.dtype == np.float64 for a in arrays)
                and all(type(m) is float for m in (e1, nu1, e2, nu2))):
            # the LTCA's every roll (issue 75): float arrays, checked finite and > 0 in one
            # pass each and copied, as real_array would; any failing goes the named way
            both = np.concatenate([a.ravel() for a in arrays])
            if bool(np.all((both > 0.0) & (both < np.inf))):
                e_star, nu1f, nu2f, k1, k2 = _materials(e1, nu1, e2, nu2)
                return cls(*(a.copy() for a in arrays), e_star, nu1f, nu2f, k1, k2)
        length_a = real_array("length", length, unit="mm", low=0.0, low_open=True)
        e1f, nu1f = _modulus("e1", e1), _poisson("nu1", nu1)
        e2f, nu2f = _modulus("e2", e2), _poisson("nu2", nu2)
        h1 = real_array("depth_1", depth_1, unit="mm", low=0.0, low_open=True)
        h2 = real_array("depth_2", depth_2, unit="mm", low=0.0, low_open=True)
        r = real_array("r_eq", r_eq, unit="mm", low=0.0, low_open=True)
        e_star = float(contact_modulus(e1f, nu1f, e2f, nu2f))
        return cls(length_a, h1, h2, r, e_star, nu1f, nu2f,
                   2.0 * (1.0 - nu1f**2) / (math.pi * e1f),
                   2.0 * (1.0 - nu2f**2) / (math.pi * e2f))

    def compliance(self, load, kind: str | Sequence[str] = "secant",
                   load_floor: float = 1.0) -> np.ndarray | tuple[np.ndarray, ...]:
        """:func:`weber_compliance` of the segments at the loads ``load`` (N,) [N].

        Returns
        -------
        ndarray (N,) or tuple of them — [mm/N]
            As :func:`weber_compliance` (seed p. 78; Weber 1949; Johnson Eq. 4.43).

        Raises
        ------
        InputError
            Negative or non-finite loads, a non-positive floor, a depth too small for
            Weber's formula.
        ModelUnavailableError
            Unknown ``kind``.
        """
        kinds = _kinds(kind)
        f = real_array("load", load, unit="N", low=0.0)
        floor = positive("load_floor", load_floor, "N/mm")
        return self._evaluated(f, kinds, floor, isinstance(kind, str))

    def secant_tangent(self, load: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``compliance(load, kind=("secant", "tangent"))`` of loads the caller has already
        made finite and ≥ 0 (N,) [N] (the Weber iteration's, clipped to [0, cap]): the same
        arithmetic without checking the loads again at every iteration (issue 75).

        Raises
        ------
        InputError
            A depth too small for Weber's formula at these loads.
        """
        f = np.asarray(load, dtype=float)
        if (WEBER_COMPLIANCE_KINDS["secant"] is not _secant
                or WEBER_COMPLIANCE_KINDS["tangent"] is not _tangent
                or f.shape != self.length.shape):  # a kind replaced, or loads broadcast
            return self._evaluated(f, ("secant", "tangent"), 1.0, False)
        # _evaluated's arithmetic for these two kinds, to the bit, in fewer array passes:
        # kb + 0·ks is kb, and ks = (k₁ + k₂)·½ for every segment (a scalar here)
        w = np.maximum(f / self.length, 1.0)
        b = np.sqrt(4.0 * w * self.r_eq / (math.pi * self.e_star))
        c1, c2 = self._poisson_terms
        twice_1, twice_2 = self._twice_depth
        bracket_1 = np.log(twice_1 / b) - c1
        bracket_2 = np.log(twice_2 / b) - c2
        if not (bracket_1.min() > 0.0 and bracket_2.min() > 0.0):
            _weber_bracket(self.depth_1, b, self.nu1, "depth_1")  # raises, naming it
            _weber_bracket(self.depth_2, b, self.nu2, "depth_2")
        kb = self.k1 * bracket_1 + self.k2 * bracket_2
        return kb / self.length, (kb - (self.k1 + self.k2) * 0.5) / self.length

    def _evaluated(self, f: np.ndarray, kinds, floor: float, single: bool):
        """:meth:`compliance`'s arithmetic on checked loads ``f`` [N] and floor [N/mm]."""
        w = np.maximum(f / self.length, floor)
        # Hertz half-width, Johnson Eq. 4.43 (geometry.core.hertz.hertz_line_contact)
        b = np.sqrt(4.0 * w * self.r_eq / (math.pi * self.e_star))
        slope = np.full_like(b, 0.5)
        kb = (self.k1 * _weber_bracket(self.depth_1, b, self.nu1, "depth_1")
              + self.k2 * _weber_bracket(self.depth_2, b, self.nu2, "depth_2"))
        shape = np.broadcast_shapes(w.shape, b.shape)
        out = tuple(_shaped(WEBER_COMPLIANCE_KINDS[k](kb, (self.k1 + self.k2) * slope)
                            / self.length, shape) for k in kinds)
        return out[0] if single else out


@memoised(maxsize=8)
def _materials(e1: float, nu1: float, e2: float, nu2: float
               ) -> tuple[float, float, float, float, float]:
    """(E* [MPa], ν₁, ν₂, k₁, k₂ [mm²/N]) of :meth:`WeberSegments.of`'s materials, checked
    (InputError naming the bad one) and worked out once per process for each set."""
    e1f, nu1f = _modulus("e1", e1), _poisson("nu1", nu1)
    e2f, nu2f = _modulus("e2", e2), _poisson("nu2", nu2)
    return (float(contact_modulus(e1f, nu1f, e2f, nu2f)), nu1f, nu2f,
            2.0 * (1.0 - nu1f**2) / (math.pi * e1f), 2.0 * (1.0 - nu2f**2) / (math.pi * e2f))


def _shaped(value: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """``value`` (a quotient just formed, so an array of its own) as an array of ``shape``:
    itself where it has that shape (the Weber iteration's every call), else broadcast and
    copied (a registered kind that returns fewer dimensions)."""
    if isinstance(value, np.ndarray) and value.shape == shape:
        return value
    return np.broadcast_to(value, shape).copy()
