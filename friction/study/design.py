"""Condition designs of the friction study: the seed's Table 5.1 space.

The seed (§5.2.3, Table 5.1) ran its mixed-EHL model over the full factorial grid of
p_h ∈ {0.5 … 2.5} GPa (5 levels), R_eq ∈ {5, 20, 40} mm, V_r ∈ {1, 5, 10, 15, 20} m/s,
SR ∈ {0.025 … 1} (7 levels), T_oil ∈ {25, 50, 75, 100} °C and Rq₁, Rq₂ ∈ {0.1 … 1} µm
(5 levels each): 5·3·5·7·4 = 2100 conditions times the 15 *unordered* roughness pairs =
31,500, the number the seed states (the two surfaces' profiles enter the seed's groups
S_c and S_eq symmetrically). :func:`factorial_design` gives that grid (for a cluster);
:func:`space_filling_design` a seeded Sobol or Latin-hypercube sample of the same box
for a small machine, with p_h, T and the Rq uniform and R, u_e, SR log-uniform (the fit
is log-linear in them, so the sample is spread evenly in the regression's variables).

A design is a mapping of :data:`DESIGN_INPUTS` names to equal-length float arrays.
"""

from __future__ import annotations

import itertools
import math
import warnings
from collections.abc import Mapping
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray

from geometry.core.errors import InputError
from geometry.core.validation import integer, one_of

__all__ = ["DESIGN_BOXES", "DESIGN_BOX_TEXT", "DESIGN_INPUTS", "DESIGN_METHODS",
           "GEAR_CONTACT_RANGE", "GEAR_EDGE_RANGE", "GEAR_FLANK_RANGE", "TABLE_5_1",
           "TABLE_5_1_RANGE", "check_design", "design_box_of", "factorial_design",
           "inside_box", "space_filling_design"]

Array = NDArray[np.float64]

#: The inputs of a design point: name → (units, long_name).
DESIGN_INPUTS: Mapping[str, tuple[str, str]] = MappingProxyType({
    "hertz_pressure": ("MPa", "Hertz maximum pressure p_h"),
    "radius": ("mm", "equivalent radius of curvature R_eq"),
    "entraining_velocity": ("m/s", "entraining velocity u_e = (u1 + u2)/2"),
    "slide_to_roll": ("1", "slide-to-roll ratio SR = (u1 - u2)/u_e"),
    "temperature": ("degC", "inlet oil temperature"),
    "roughness_1": ("um", "RMS roughness Rq of surface 1"),
    "roughness_2": ("um", "RMS roughness Rq of surface 2"),
})

#: The seed's Table 5.1 levels (toolkit units: MPa, mm, m/s, 1, degC, µm).
TABLE_5_1: Mapping[str, tuple[float, ...]] = MappingProxyType({
    "hertz_pressure": (500.0, 1000.0, 1500.0, 2000.0, 2500.0),
    "radius": (5.0, 20.0, 40.0),
    "entraining_velocity": (1.0, 5.0, 10.0, 15.0, 20.0),
    "slide_to_roll": (0.025, 0.05, 0.1, 0.25, 0.5, 0.75, 1.0),
    "temperature": (25.0, 50.0, 75.0, 100.0),
    "roughness_1": (0.1, 0.35, 0.6, 0.85, 1.0),
    "roughness_2": (0.1, 0.35, 0.6, 0.85, 1.0),
})

#: The box of Table 5.1: name → (low, high, log-spaced in the space-filling designs).
TABLE_5_1_RANGE: Mapping[str, tuple[float, float, bool]] = MappingProxyType({
    "hertz_pressure": (500.0, 2500.0, False),
    "radius": (5.0, 40.0, True),
    "entraining_velocity": (1.0, 20.0, True),
    "slide_to_roll": (0.025, 1.0, True),
    "temperature": (25.0, 100.0, False),
    "roughness_1": (0.1, 1.0, False),
    "roughness_2": (0.1, 1.0, False),
})

#: A wider box for a fit that covers a hypoid gear's loaded flank segments (issue 34: 54 %
#: of the default case's segments lay outside Table 5.1's box, with R_eq up to ~100 mm,
#: p_h above 2.5 GPa at 500 N·m and SR from 0 at the pitch point to ~1.3 at the tips;
#: issue 51 widened it to the low speeds, rough and smooth flanks and long radii of a
#: gear's efficiency map and the chapter-5 study): p_h 0.3–3 GPa, R_eq 5–150 mm, u_e
#: 0.05–20 m/s, SR 0.01–2, oil 25–110 °C, Rq 0.05–1.5 µm.
GEAR_CONTACT_RANGE: Mapping[str, tuple[float, float, bool]] = MappingProxyType({
    "hertz_pressure": (300.0, 3000.0, False),
    "radius": (5.0, 150.0, True),
    "entraining_velocity": (0.05, 20.0, True),
    "slide_to_roll": (0.01, 2.0, True),
    "temperature": (25.0, 110.0, False),
    "roughness_1": (0.05, 1.5, False),
    "roughness_2": (0.05, 1.5, False),
})

#: The gear box widened to every flank (contact-curve) segment of the default case and of
#: Table 5.4's A and B at the seed's operating points (1500 rpm, 500 N·m, 90 °C, Rq 0.8 µm),
#: measured: p_h down to ~100 MPa (0.3–1 % of the flank segments lie lower, at the
#: contact curves' light-load ends, under 0.005 % of the load: a Hertz zone narrower than
#: the ground profile's wavelengths), SR down to 1e-4 at the pitch line, R from 4.8 mm;
#: p_h log-uniform here. Points outside :data:`GEAR_CONTACT_RANGE` (``exclude``) extend the
#: study already run in it.
GEAR_FLANK_RANGE: Mapping[str, tuple[float, float, bool]] = MappingProxyType({
    "hertz_pressure": (100.0, 3000.0, True),
    "radius": (4.0, 150.0, True),
    "entraining_velocity": (0.05, 20.0, True),
    "slide_to_roll": (1e-4, 2.0, True),
    "temperature": (25.0, 110.0, False),
    "roughness_1": (0.05, 1.5, False),
    "roughness_2": (0.05, 1.5, False),
})

#: The contacts of a rounded tooth edge on the mating flank (the LTCA's edge segments:
#: R_eq ≈ the edge radius, 0.45–0.5 mm on the bundled cases; p_h up to the shakedown limit
#: 5.26 GPa; |SR| 0.3–2.4, u_e 0.5–4 m/s, λ 0.011–0.11 at 1500 rpm, 90 °C, Rq 0.8 µm,
#: measured on the default case and Table 5.4's A and B): R 0.3–1 mm, p_h 0.5–5.3 GPa,
#: u_e 0.3–5 m/s, SR 0.2–2 (the solver's limit).
GEAR_EDGE_RANGE: Mapping[str, tuple[float, float, bool]] = MappingProxyType({
    "hertz_pressure": (500.0, 5300.0, False),
    "radius": (0.3, 1.0, True),
    "entraining_velocity": (0.3, 5.0, True),
    "slide_to_roll": (0.2, 2.0, True),
    "temperature": (25.0, 110.0, False),
    "roughness_1": (0.05, 1.5, False),
    "roughness_2": (0.05, 1.5, False),
})

#: Named boxes of :func:`space_filling_design` (``ltca friction-study --box``).
DESIGN_BOXES: Mapping[str, Mapping[str, tuple[float, float, bool]]] = MappingProxyType({
    "table_5_1": TABLE_5_1_RANGE,
    "gear": GEAR_CONTACT_RANGE,
    "gear_flank": GEAR_FLANK_RANGE,
    "gear_edge": GEAR_EDGE_RANGE,
})

#: How a study file's ``design_box`` attribute names each box (``ltca friction-study``
#: writes it, :func:`design_box_of` reads it back for ``ltca friction-fit --box auto``).
DESIGN_BOX_TEXT: Mapping[str, str] = MappingProxyType({
    "table_5_1": "seed Table 5.1; R, u_e, SR log-uniform",
    "gear": "gear contacts (friction.study.design.GEAR_CONTACT_RANGE); R, u_e, SR "
            "log-uniform",
    "gear_flank": "gear flank contacts (friction.study.design.GEAR_FLANK_RANGE); p_h, R, u_e, "
                  "SR log-uniform",
    "gear_edge": "tooth-edge contacts (friction.study.design.GEAR_EDGE_RANGE); R, u_e, SR "
                 "log-uniform",
})

#: Space-filling samplers of :func:`space_filling_design` (scipy.stats.qmc).
DESIGN_METHODS = ("sobol", "lhs")


def check_design(design: Mapping[str, object], lubricant=None) -> dict[str, Array]:
    """A design as float arrays, every input of :data:`DESIGN_INPUTS`, finite, in range.

    Parameters
    ----------
    design : mapping of str to array (n,)
        Inputs in the units of :data:`DESIGN_INPUTS`.
    lubricant : str or friction.lubricant.Lubricant, optional
        The study's oil: given, it must be a bundled name or a valid oil file, and every
        temperature must lie inside its data's range
        (:func:`friction.lubricant.temperature_range`).

    Returns
    -------
    dict of str to array (n,)

    Raises
    ------
    InputError
        A missing or unknown input, unequal lengths, no points, a value outside the
        solvers' accepted range (p_h in (0, 6000] MPa, R in [0.01, 5000] mm, u_e in
        (0, 100] m/s, |SR| ≤ 2, Rq in [0, 50] µm: :mod:`friction.ehl.line_contact`), an
        unknown or invalid oil, or a temperature outside its data, naming the input, the
        first value outside and the range.
    """
    from friction.ehl.line_contact import (
        MAX_ENTRAINING_VELOCITY,
        MAX_HERTZ_PRESSURE,
        RADIUS_RANGE,
        lubricant_of,
    )
    from friction.lubricant import temperature_range

    missing = sorted(set(DESIGN_INPUTS) - set(design))
    unknown = sorted(set(design) - set(DESIGN_INPUTS))
    if missing or unknown:
        raise InputError(f"design: inputs must be {sorted(DESIGN_INPUTS)}; missing {missing},"
                         f" unknown {unknown}")
    out = {k: np.atleast_1d(np.asarray(design[k], dtype=float)) for k in DESIGN_INPUTS}
    sizes = {k: v.size for k, v in out.items()}
    if len(set(sizes.values())) != 1 or any(v.ndim != 1 for v in out.values()):
        raise InputError(f"design: every input must be a 1-d array of one length, got {sizes}")
    if not next(iter(sizes.values())):
        raise InputError("design: a study needs at least one point")
    bounds = {"hertz_pressure": (0.0, MAX_HERTZ_PRESSURE),
              "radius": (RADIUS_RANGE[0], RADIUS_RANGE[1]),
              "entraining_velocity": (0.0, MAX_ENTRAINING_VELOCITY),
              "temperature": (-50.0, 300.0),
              "roughness_1": (-1.0, 50.0), "roughness_2": (-1.0, 50.0)}
    if lubricant is not None:
        oil = lubricant_of(lubricant)
        bounds["temperature"] = temperature_range(oil)
    for name, v in out.items():
        if not np.all(np.isfinite(v)):
            raise InputError(f"{name}: must be finite [{DESIGN_INPUTS[name][0]}]")
        if name == "slide_to_roll":
            if np.any(np.abs(v) > 2.0):
                raise InputError("slide_to_roll: must be in [-2, 2] [1], got "
                                 f"{v[np.abs(v) > 2][0]:g}")
            continue
        low, high = bounds[name]
        closed = name in ("radius", "temperature")
        bad = (v < low) if closed else (v <= low)
        if name.startswith("roughness"):
            bad = v < 0.0
        if high is not None:
            bad |= v > high
        if np.any(bad):
            rng = f"> {low:g}" if high is None else f"in ({low:g}, {high:g}]"
            if closed:
                rng = f"in [{low:g}, {high:g}]"
            if name.startswith("roughness"):
                rng = "in [0, 50]"
            raise InputError(f"{name}: must be {rng} [{DESIGN_INPUTS[name][0]}], got "
                             f"{v[bad][0]:g}")
    return out


def factorial_design(levels: Mapping[str, tuple[float, ...]] = TABLE_5_1, *,
                     unordered_roughness: bool = True) -> dict[str, Array]:
    """The full factorial grid of Table 5.1 (31,500 conditions with the default levels).

    Parameters
    ----------
    levels : mapping of str to tuple of float
        Levels of every :data:`DESIGN_INPUTS` input (their units); default the seed's.
    unordered_roughness : bool
        Keep each pair of roughness levels once (Rq₁ ≤ Rq₂), as the seed's count implies.

    Returns
    -------
    dict of str to array (n,)
        n = Π(levels) (ordered) or, unordered, Π(other levels)·k(k+1)/2 for k roughness
        levels when both surfaces share them.

    Raises
    ------
    InputError
        Missing or empty levels, or levels outside the accepted ranges (named).

    Notes
    -----
    Source: seed Table 5.1 and §5.2.3 ("a total of 31,500 contact conditions as a result of
    all combinations of the parameter values listed in Table 5.1"): 2100 × 15 = 31,500.
    """
    missing = sorted(set(DESIGN_INPUTS) - set(levels))
    if missing:
        raise InputError(f"levels: missing {missing}")
    for k in DESIGN_INPUTS:
        if len(levels[k]) == 0:
            raise InputError(f"levels.{k}: needs at least one level")
    names = list(DESIGN_INPUTS)
    rows = [r for r in itertools.product(*(levels[k] for k in names))
            if not unordered_roughness or r[-2] <= r[-1]]
    arr = np.asarray(rows, dtype=float)
    return check_design({k: arr[:, i] for i, k in enumerate(names)})


def design_box_of(design_box: str) -> str:
    """The name of the box a study's ``design_box`` attribute names (:data:`DESIGN_BOXES`).

    Parameters
    ----------
    design_box : str
        The attribute (of one study, or of several joined by ``"; "``).

    Returns
    -------
    str
        The first of ``gear_flank``, ``gear``, ``gear_edge`` whose text
        (:data:`DESIGN_BOX_TEXT`, up to its first ``";"``) it contains — the widest first,
        so a flank shell ``outside`` the gear box, or a gear study joined with its flank
        shell, is ``gear_flank`` — else ``table_5_1``.
    """
    for name in ("gear_flank", "gear", "gear_edge"):
        if DESIGN_BOX_TEXT[name].split(";")[0] in design_box:
            return name
    return "table_5_1"


def inside_box(design: Mapping[str, Array],
               box: Mapping[str, tuple[float, float, bool]]) -> NDArray[np.bool_]:
    """Which points of a design lie inside a box (every input within its closed range).

    Parameters
    ----------
    design : mapping of str to array (n,)
        Inputs of :data:`DESIGN_INPUTS` (their units).
    box : mapping of str to (low, high, log)
        Ranges; inputs the box does not name are not checked.

    Returns
    -------
    array of bool (n,)
    """
    n = next(iter(design.values())).size
    inside = np.ones(n, dtype=bool)
    for k, (lo, hi, _) in box.items():
        if k in design:
            v = np.asarray(design[k], dtype=float)
            inside &= (v >= lo) & (v <= hi)
    return inside


def space_filling_design(n: int, *, method: str = "sobol", seed: int = 2009, skip: int = 0,
                         box: Mapping[str, tuple[float, float, bool]] = TABLE_5_1_RANGE,
                         exclude: Mapping[str, tuple[float, float, bool]] | None = None,
                         ) -> dict[str, Array]:
    """A seeded space-filling sample of the Table 5.1 box.

    Parameters
    ----------
    n : int
        Number of conditions, 1 … 1,000,000 (Sobol: a power of two keeps its balance).
    method : {"sobol", "lhs"}
        ``scipy.stats.qmc.Sobol`` (scrambled) or ``LatinHypercube`` (optimised by random
        CD): use another ``seed`` (and method) for held-out points.
    seed : int
        Seed of the sampler (same seed, same design).
    skip : int
        Sobol only: the first ``skip`` points of the sequence are passed over, so
        ``skip=128, n=128`` continues a design of ``n=128`` (points 128 … 255).
    box : mapping of str to (low, high, log)
        Range of each input, log-uniform where ``log``; default :data:`TABLE_5_1_RANGE`.
    exclude : mapping of str to (low, high, log), optional
        A box inside ``box`` whose points are passed over: the design fills the shell
        between them (a study that extends one already run in ``exclude``). Sobol: the
        sequence continues until ``n`` points lie outside; LHS: further hypercubes of ``n``
        points (seeds ``[seed, 1]``, ``[seed, 2]``, …) are drawn until they do.

    Returns
    -------
    dict of str to array (n,)

    Raises
    ------
    InputError
        Bad ``n``, ``method``, ``seed``, ``skip`` or box (named); an ``exclude`` box that
        leaves less than 1 % of ``box`` outside it.

    Notes
    -----
    Source: Sobol' (1967), Owen scrambling; McKay, Beckman & Conover (1979) Latin
    hypercube (``scipy.stats.qmc``). The box is the seed's Table 5.1.
    """
    from scipy.stats import qmc

    n = integer("n", n, low=1, high=1_000_000)
    one_of("method", method, DESIGN_METHODS)
    integer("seed", seed, low=0)
    skip = integer("skip", skip, low=0)
    names = list(DESIGN_INPUTS)
    for k in names:
        if k not in box:
            raise InputError(f"box: missing {k}")
        lo, hi, log = box[k]
        if not (math.isfinite(lo) and math.isfinite(hi) and hi >= lo) or (log and lo <= 0):
            raise InputError(f"box.{k}: must be finite, low <= high (low > 0 if log), got "
                             f"({lo}, {hi})")
    if method != "sobol" and skip:
        raise InputError("skip: only the Sobol sequence can be continued (method 'sobol')")

    def scaled(u: Array) -> dict[str, Array]:
        out = {}
        for i, k in enumerate(names):
            lo, hi, log = box[k]
            out[k] = (np.exp(np.log(lo) + u[:, i] * (np.log(hi) - np.log(lo))) if log
                      else lo + u[:, i] * (hi - lo))
        return out

    if method == "sobol":
        sampler = qmc.Sobol(d=len(names), scramble=True, seed=seed)
        if skip:
            sampler.fast_forward(skip)

        def draw(_: int) -> Array:
            with warnings.catch_warnings():  # the balance note for n not a power of two
                warnings.simplefilter("ignore", UserWarning)
                return sampler.random(n)
    else:
        def draw(k: int) -> Array:
            rng = seed if k == 0 else np.random.default_rng([seed, k])
            return qmc.LatinHypercube(d=len(names), seed=rng,
                                      optimization="random-cd").random(n)

    if exclude is None:
        return check_design(scaled(draw(0)))
    kept: list[dict[str, Array]] = []
    found = 0
    for k in range(100):
        part = scaled(draw(k))
        keep = ~inside_box(part, exclude)
        kept.append({name: v[keep] for name, v in part.items()})
        found += int(keep.sum())
        if found >= n:
            return check_design({name: np.concatenate([p[name] for p in kept])[:n]
                                 for name in names})
    raise InputError(f"exclude: leaves {found} of {100 * n} points of the box outside it; "
                     "it must leave at least 1 % of the box")
