"""Discretisation and solution settings of the LTCA (:class:`LTCAOptions`).

Public functions
----------------
LTCAOptions    frozen dataclass of the settings, validated on construction
edge_radii     the (pinion, gear) edge rounding radii an analysis uses
json_options   the options as JSON text (netCDF-safe)
"""

from __future__ import annotations

import dataclasses
import json
import math
from dataclasses import dataclass

from contact.qp.solvers import DEFAULT_SOLVER, get_backend
from contact.utca import CURVE_SPACINGS
from geometry.errors import InputError

__all__ = ["LTCAOptions", "edge_radii", "json_options"]


@dataclass(frozen=True)
class LTCAOptions:
    """Discretisation and solution settings of the LTCA.

    Attributes
    ----------
    cycles : int
        Mesh cycles analysed (≥ 1; default 2).
    rolls_per_cycle : int
        Roll positions per mesh cycle (≥ 4; default 20).
    pairs : tuple of int
        Tooth-pair offsets considered, relative to the pair that takes over at the
        start of each mesh cycle (default −1, 0, 1, 2; see :func:`segment_geometry`).
        Widened by one on a side whose outermost pair is loaded at its end of the window
        (the lowest at a cycle's last roll, the highest at its first), where the next
        pair may be loaded too, up to 8 pairs.
    segments : int
        Segments per contact curve (≥ 4; default 24).
    spacing : str
        Placing of the segment ends along a curve (:data:`contact.utca.CURVE_SPACINGS`):
        ``"cosine"`` (default) grades them towards the curve ends, where the load rises
        into a flank edge (the entering pair at the gear tip, the leaving pair at the
        pinion tip): the end segments are ~π²/(4 S²) of the curve, so the load at the
        edge converges at second order in 1/S (uniform spacing: first order);
        ``"uniform"``: equal steps in the lengthwise fraction.
    separation_limit : float or None — [mm]
        A fixed limit: segments separated by more are left out (a warning is logged if
        one of them would touch). Default None: the screening of the module docstring,
        which leaves out only segments whose gap stays open (s ≥ R Θ).
    solver : str
        Registered solver name (default our exact ``active_set``).
    weber_tolerance : float — [urad]
        Stop the Weber load iteration when the LTE changes by less, or its next Newton
        step is foretold to be ten times smaller (default 1e-3).
    max_weber_iterations : int
        Cap on the Weber iteration (default 12).
    edge_contact : bool
        Also the contact of the flank boundary beyond the curves' ends (default True;
        :mod:`contact.edge`): the gear's tip edge and ends and the pinion's tip edge and
        ends where a pair's curve passes outside the contact region (an entering pair at
        the flank's corner before its curve emerges). False: the seed's line model, load
        on the curves only.
    edge_radius : float or None — [mm]
        Rounding radius of the tooth edges, across which an edge segment is in Hertz
        line contact with the mating flank. Default None: each member's own, the case's
        ``[<member>.blank] edge_break_radius`` (default 0.5 mm, a light edge break); a
        value in (0, 50] overrides both (e.g. a sensitivity study).
    edge_step : float — [mm]
        Largest edge segment along the boundary (> 0; default 0.25 mm: halving it moves
        the LTE by < 0.1 µrad and the edge pressure by < 1 % on the seed case).
    youngs_modulus, poisson_ratio : float — [MPa], [1]
        Steel for both members (default 206 000 MPa, 0.3).
    theory, n_height, n_face
        Shell-model settings (:func:`contact.compliance.pair_compliance_model`).
    """

    cycles: int = 2
    rolls_per_cycle: int = 20
    pairs: tuple[int, ...] = (-1, 0, 1, 2)
    segments: int = 24
    spacing: str = "cosine"
    separation_limit: float | None = None
    solver: str = DEFAULT_SOLVER
    weber_tolerance: float = 1e-3
    max_weber_iterations: int = 12
    edge_contact: bool = True
    edge_radius: float | None = None
    edge_step: float = 0.25
    youngs_modulus: float = 206_000.0
    poisson_ratio: float = 0.3
    theory: str = "seed"
    n_height: int = 6
    n_face: int = 21

    def __post_init__(self) -> None:
        checks = (
            ("cycles", self.cycles, 1, 20),
            ("rolls_per_cycle", self.rolls_per_cycle, 4, 400),
            ("segments", self.segments, 4, 400),
            ("max_weber_iterations", self.max_weber_iterations, 1, 100),
        )
        for name, val, lo, hi in checks:
            if not (isinstance(val, int) and lo <= val <= hi):
                raise InputError(f"{name}: must be an integer in [{lo}, {hi}], got {val!r}")
        if self.spacing not in CURVE_SPACINGS:
            raise InputError(f"spacing: must be one of {sorted(CURVE_SPACINGS)}, got "
                             f"{self.spacing!r}")
        if not self.pairs or 0 not in self.pairs:
            raise InputError(f"pairs: must contain the reference pair 0, got {self.pairs!r}")
        if self.separation_limit is not None and not self.separation_limit > 0:
            raise InputError(
                f"separation_limit: must be > 0 [mm] or None, got {self.separation_limit!r}"
            )
        for name in ("edge_radius", "edge_step"):
            val = getattr(self, name)
            if name == "edge_radius" and val is None:
                continue
            if not (isinstance(val, (int, float)) and not isinstance(val, bool)
                    and math.isfinite(val) and 0 < val <= 50):
                extra = " or None" if name == "edge_radius" else ""
                raise InputError(f"{name}: must be a length in (0, 50] [mm]{extra}, got "
                                 f"{val!r}")
        if not isinstance(self.edge_contact, bool):
            raise InputError(f"edge_contact: must be True or False, got {self.edge_contact!r}")
        if not self.weber_tolerance > 0:
            raise InputError(f"weber_tolerance: must be > 0 [urad], got {self.weber_tolerance}")
        get_backend(self.solver)


def edge_radii(case, opts: LTCAOptions) -> tuple[float, float]:
    """(pinion, gear) rounding radii of the tooth edges [mm]: ``opts.edge_radius`` if set,
    else each member's blank ``edge_break_radius``."""
    if opts.edge_radius is not None:
        return float(opts.edge_radius), float(opts.edge_radius)
    return (float(case.pinion.blank.edge_break_radius),
            float(case.gear.blank.edge_break_radius))


def json_options(opts: LTCAOptions) -> str:
    """The options as JSON text (netCDF-safe)."""

    return json.dumps(dataclasses.asdict(opts), sort_keys=True)
