"""Contact problems with known answers or LTCA-like structure: the solver study's test set.

- :func:`hertz_sphere_problem` — a sphere pressed on a flat, discretised in square
  cells with Love's exact influence coefficients (answer: Hertz).
- :func:`hertz_cylinder_problem` — a cylinder on a flat in plane strain, strips with
  the exact strip influence coefficients (answer: Hertz).
- :func:`ltca_like_problem` — random instances with the structure of a hypoid
  mesh: two to four tooth pairs, each a contact line of segments; bending couples
  segments of the same tooth with an exponentially decaying kernel calibrated to
  ISO 6336-1's mesh stiffness c′ ≈ 14 N/(mm·µm), a Hertz-like diagonal, no
  coupling across teeth; separations from a parabolic ease-off plus the pair's
  unloaded-TE offset; moment arms of a gear of ~80 mm mean radius.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact.qp.halfspace import (
    hertz_line,
    hertz_point,
    rectangle_influence,
    strip_influence,
)
from contact.qp.problem import ContactProblem
from geometry.core.errors import InputError
from geometry.core.hertz import STEEL, contact_modulus, hertz_line_contact
from geometry.core.validation import integer, real

__all__ = [
    "STEEL_MODULUS",
    "TestProblem",
    "hertz_cylinder_problem",
    "hertz_sphere_problem",
    "ltca_like_problem",
    "standard_problem_set",
]

#: Steel on steel (:data:`geometry.core.hertz.STEEL`, E = 206 000 MPa, ν = 0.3): E* [MPa].
STEEL_MODULUS = contact_modulus(*STEEL, *STEEL)


@dataclass(frozen=True, eq=False)
class TestProblem:
    """A named contact problem with its reference answer where one exists.

    Attributes
    ----------
    name : str
    kind : str
        ``hertz_sphere``, ``hertz_cylinder`` or ``ltca_like``.
    problem : ContactProblem
    reference : dict
        Analytical values (Hertz) and the discretisation data needed to compare.
    """

    __test__ = False  # not a pytest class

    name: str
    kind: str
    problem: ContactProblem
    reference: dict[str, Any] = field(default_factory=dict)


def hertz_sphere_problem(
    cells_per_radius: int = 10,
    *,
    load: float = 1000.0,
    radius: float = 20.0,
    modulus: float = STEEL_MODULUS,
    domain: float = 1.25,
) -> TestProblem:
    """Sphere on a flat on a square grid of cells (Love 1929; Johnson Eq. 3.25, 4.22).

    Parameters
    ----------
    cells_per_radius : int
        Cells across the Hertz contact radius a (≥ 3).
    load : float — [N]
    radius : float — [mm]
    modulus : float — [MPa]
        Contact modulus E*.
    domain : float
        Half-side of the gridded square in units of a (> 1).

    Returns
    -------
    TestProblem
        ``problem``: compliance [mm/N], separation r²/(2R) [mm], moment arms 1 [mm],
        torque = load, so Θ is the approach [mm]; ``reference``: Hertz ``radius``,
        ``peak_pressure``, ``approach``, and ``cell_area`` [mm²], ``x``, ``y``.
    """
    integer("cells_per_radius", cells_per_radius, 3)
    real("domain", domain, unit="contact radii", low=1.0, low_open=True)
    hz = hertz_point(load, radius, modulus)
    h = hz["radius"] / cells_per_radius
    k = math.ceil(domain * cells_per_radius)
    g = h * np.arange(-k, k + 1)
    X, Y = np.meshgrid(g, g, indexing="ij")
    x, y = X.ravel(), Y.ravel()
    C = rectangle_influence(x, y, h / 2, h / 2, modulus)
    s = (x * x + y * y) / (2 * radius)
    prob = ContactProblem(C, s, np.ones_like(s), load, name=f"hertz_sphere_{x.size}")
    return TestProblem(
        prob.name, "hertz_sphere", prob, {**hz, "cell_area": h * h, "x": x, "y": y, "cell": h}
    )


def hertz_cylinder_problem(
    strips_per_half_width: int = 20,
    *,
    load_per_length: float = 500.0,
    radius: float = 20.0,
    modulus: float = STEEL_MODULUS,
    domain: float = 1.5,
    datum: float | None = None,
) -> TestProblem:
    """Cylinder on a flat in plane strain on uniform strips (Johnson Eq. 2.25, 4.43–4.45).

    Parameters
    ----------
    strips_per_half_width : int
        Strips across the Hertz half-width b (≥ 3).
    load_per_length : float — [N/mm]
    radius : float — [mm]
    modulus : float — [MPa]
    domain : float
        Half-width of the discretised band in units of b (> 1).
    datum : float, optional — [mm]
        Displacement datum distance; default 10 × the band width.

    Returns
    -------
    TestProblem
        Forces are per unit length [N/mm]; Θ is the approach [mm]; ``reference``:
        Hertz ``half_width``, ``peak_pressure``, ``approach``, and ``strip`` [mm], ``x``.
    """
    integer("strips_per_half_width", strips_per_half_width, 3)
    real("domain", domain, unit="half-widths", low=1.0, low_open=True)
    b0 = float(hertz_line_contact(load_per_length, radius, modulus).half_width)
    h = b0 / strips_per_half_width
    k = math.ceil(domain * strips_per_half_width)
    x = h * np.arange(-k, k + 1)
    d = 20 * k * h if datum is None else datum
    hz = hertz_line(load_per_length, radius, modulus, d)
    C = strip_influence(x, h / 2, modulus, d)
    s = x * x / (2 * radius)
    prob = ContactProblem(C, s, np.ones_like(s), load_per_length, name=f"hertz_cylinder_{x.size}")
    return TestProblem(prob.name, "hertz_cylinder", prob, {**hz, "strip": h, "x": x, "datum": d})


def ltca_like_problem(
    n_segments: int,
    *,
    seed: int = 0,
    n_pairs: int | None = None,
    torque: float | None = None,
) -> TestProblem:
    """A random contact problem with the structure of a hypoid-gear mesh.

    Parameters
    ----------
    n_segments : int
        Total number of segments N (≥ 6), split evenly over the tooth pairs.
    seed : int
        Random seed (the instance is reproducible).
    n_pairs : int, optional
        Tooth pairs sharing the load (default: 2–4 at random, at most N/3).
    torque : float, optional — [N·mm]
        Gear torque (default: random, 50–600 N·m).

    Returns
    -------
    TestProblem
        ``reference`` holds the pair index and face-width position of each segment.

    Notes
    -----
    Compliance of one tooth pair: C_ij = c_b exp(−|x_i − x_j|/λ) ℓ-scaled so that a
    uniform line load w gives a deflection w/c′ with c′ = 14 N/(mm·µm) (ISO 6336-1
    single stiffness order), λ ∈ [3, 8] mm; plus a diagonal contact term
    (20–40 % of the bending diagonal). The exponential (Ornstein–Uhlenbeck) kernel
    is positive definite, so C is SPD. Separations: a parabolic lengthwise crowning
    of 5–40 µm over the face plus 0–60 µm per neighbouring pair; moment arms
    70–90 mm with a linear variation along the line.
    """
    integer("n_segments", n_segments, 6)
    rng = np.random.default_rng(seed)
    pairs = int(n_pairs if n_pairs is not None else min(rng.integers(2, 5), n_segments // 3))
    if not 1 <= pairs <= n_segments // 3:
        raise InputError(f"n_pairs: must be in [1, {n_segments // 3}], got {pairs}")
    T = float(torque if torque is not None else rng.uniform(50e3, 600e3))
    sizes = np.full(pairs, n_segments // pairs)
    sizes[: n_segments - sizes.sum()] += 1
    C = np.zeros((n_segments, n_segments))
    s = np.empty(n_segments)
    R = np.empty(n_segments)
    pair_of = np.empty(n_segments, dtype=int)
    pos = np.empty(n_segments)
    c_mesh = 14.0e3  # N/mm per mm of face width (14 N/(mm·µm))
    start = 0
    centre = (pairs - 1) / 2
    for p, m in enumerate(sizes):
        L = rng.uniform(20.0, 40.0)  # contact line length [mm]
        x = np.linspace(-L / 2, L / 2, m)
        ell = L / m
        lam = rng.uniform(3.0, 8.0)
        c_b = 1.0 / (2 * lam * c_mesh)  # kernel amplitude [mm/N per mm] so that ∫ k = 1/c′
        K = c_b * np.exp(-np.abs(x[:, None] - x[None, :]) / lam)
        diag = np.diag(K) * rng.uniform(0.2, 0.4) * (lam / ell)
        sl = slice(start, start + m)
        C[sl, sl] = K + np.diag(diag)
        crown = rng.uniform(5e-3, 40e-3)
        offset = abs(p - centre) * rng.uniform(0.0, 60e-3)
        x0 = rng.uniform(-0.3, 0.3) * L
        s[sl] = crown * ((x - x0) / (L / 2)) ** 2 + offset
        R[sl] = rng.uniform(70.0, 90.0) + rng.uniform(-5, 5) * x / L
        pair_of[sl] = p
        pos[sl] = x
        start += m
    s -= s.min()
    prob = ContactProblem(C, s, R, T, name=f"ltca_like_{n_segments}_{seed}")
    return TestProblem(prob.name, "ltca_like", prob, {"pair": pair_of, "position": pos})


def standard_problem_set(quick: bool = False) -> list[TestProblem]:
    """The solver study's problem set.

    Parameters
    ----------
    quick : bool
        A small set (N ≲ 400) for a first look and the README command; otherwise
        Hertz problems at several grid sizes and LTCA-like instances with N from
        50 to ~2000.

    Returns
    -------
    list of TestProblem
    """
    if quick:
        return [
            hertz_sphere_problem(5),
            hertz_cylinder_problem(20),
            *(ltca_like_problem(n, seed=i) for i, n in enumerate((60, 120, 240))),
        ]
    return [
        *(hertz_sphere_problem(k) for k in (5, 8, 12, 16)),
        *(hertz_cylinder_problem(k) for k in (20, 80, 320)),
        *(
            ltca_like_problem(n, seed=i)
            for i, n in enumerate((50, 100, 240, 240, 240, 500, 1000, 2000))
        ),
    ]
