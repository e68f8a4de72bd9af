"""Discretisation and solution settings of the LTCA (:class:`LTCAOptions`).

Public functions
----------------
LTCAOptions      frozen dataclass of the settings, validated on construction
LTCASetup        what one analysis is run on: case, ease-off, options, torques, rolls
edge_radii       the (pinion, gear) edge rounding radii an analysis uses
json_options     the options as JSON text (netCDF-safe)
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from contact.ltca.compliance_models import (
    DEFAULT_COMPLIANCE,
    ComplianceModel,
    compliance_model_name,
    get_compliance_model,
)
from contact.qp.solvers import DEFAULT_SOLVER, SolverLike, get_backend, solver_name
from contact.utca import CURVE_SPACINGS, EaseOff
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.hertz import STEEL
from geometry.core.materials import CONTACT_PRESSURE_LIMITS
from geometry.core.validation import integer, one_of, positive, real

if TYPE_CHECKING:
    from contact.compliance.fe import FEOptions
    from geometry.case import Case

__all__ = ["LTCAOptions", "LTCASetup", "edge_radii", "json_options"]


@dataclass(frozen=True)
class LTCAOptions:
    """Discretisation and solution settings of the LTCA.

    Parameters
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
    solver : str, contact.qp.solvers.Backend or callable
        Registered solver name (default our exact ``active_set``;
        :func:`contact.qp.available_solvers`), or a Backend or solve function of one's own
        (:func:`contact.qp.solvers.as_backend`; recorded by its name).
    weber_tolerance : float — [µrad]
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
    edge_pressure_limit : str or None
        The elastic–perfectly-plastic limit of the edge segments, a name of
        :data:`geometry.core.materials.CONTACT_PRESSURE_LIMITS`: an edge segment carries at
        most the force F_max = L π R_eq p₀²/E* at which its Hertz peak pressure reaches
        the limit p₀ of the softer member's material (the case's ``[<member>] material``),
        and the load beyond passes to its neighbours (the contact QP's bound F ≤ F_max).
        Default ``"shakedown"`` (p₀ = 4 k: 5.26 GPa for case-carburised steel at 60 HRC;
        why this limit: :mod:`geometry.core.materials`); ``"first_yield"``; None: elastic to
        any pressure (the former edge model).
    flank_pressure_limit : str or None
        The same bound on the contact-curve (flank) segments; default None (off: the
        flank's Hertz pressure is reported as computed).
    youngs_modulus, poisson_ratio : float — [MPa], [1]
        Steel for both members (default 206 000 MPa, 0.3).
    theory : str
        Shell theory of the shell model (default ``"seed"``;
        :func:`contact.compliance.pair_compliance_model`).
    n_height, n_face : int
        The shell model's shape functions over the tooth height (1–20, default 6) and the
        face width (1–30, default 21). With ``compliance="fe"`` the shell tooth's
        measurement still gives Weber's depths.
    compliance : str, ComplianceModel or callable
        The teeth's bending, shear and base compliance, a model of the registry
        :mod:`contact.ltca.compliance_models`: ``"shell"`` (default; the seed's model),
        ``"fe"`` (the FE influence coefficients of both members, built once per member and
        design and then read from the disk cache: docs/fe.md), a name registered with
        :func:`~contact.ltca.compliance_models.register_compliance_model`, or a model's
        preparation function itself (recorded by its name). Weber's contact term is the
        same in all.
    fe : contact.compliance.fe.FEOptions or None
        The FE model of ``compliance="fe"`` (default None: ``FEOptions()`` with this
        analysis' material); its material must be the analysis' (``youngs_modulus``,
        ``poisson_ratio``). Refused with the shell compliance (it would be unused).

    Raises
    ------
    InputError
        A field out of its range (named, with the range): counts, ``spacing``, ``pairs``
        without the reference pair 0, non-positive lengths or limits, an unknown model;
        ``fe`` with another material or a ``load_row_step`` other than 1.
    """

    cycles: int = 2
    rolls_per_cycle: int = 20
    pairs: tuple[int, ...] = (-1, 0, 1, 2)
    segments: int = 24
    spacing: str = "cosine"
    separation_limit: float | None = None
    solver: SolverLike = DEFAULT_SOLVER
    weber_tolerance: float = 1e-3
    max_weber_iterations: int = 12
    edge_contact: bool = True
    edge_radius: float | None = None
    edge_step: float = 0.25
    edge_pressure_limit: str | None = "shakedown"
    flank_pressure_limit: str | None = None
    youngs_modulus: float = STEEL[0]
    poisson_ratio: float = STEEL[1]
    theory: str = "seed"
    n_height: int = 6
    n_face: int = 21
    compliance: str | ComplianceModel | Callable[..., Any] = DEFAULT_COMPLIANCE
    fe: FEOptions | None = None

    def __post_init__(self) -> None:
        for name, lo, hi in (("cycles", 1, 20), ("rolls_per_cycle", 4, 400),
                             ("segments", 4, 400), ("max_weber_iterations", 1, 100),
                             ("n_height", 1, 20), ("n_face", 1, 30)):
            integer(name, getattr(self, name), lo, hi)
        one_of("spacing", self.spacing, CURVE_SPACINGS)
        if not self.pairs or 0 not in self.pairs:
            raise InputError(f"pairs: must contain the reference pair 0, got {self.pairs!r}")
        for k in self.pairs:
            integer("pairs", k)
        if self.separation_limit is not None:
            positive("separation_limit", self.separation_limit, "mm")
        if self.edge_radius is not None:
            positive("edge_radius", self.edge_radius, "mm", high=50.0)
        positive("edge_step", self.edge_step, "mm", high=50.0)
        if not isinstance(self.edge_contact, bool):
            raise InputError(f"edge_contact: must be True or False, got {self.edge_contact!r}")
        for name in ("edge_pressure_limit", "flank_pressure_limit"):
            if getattr(self, name) is not None:
                one_of(name, getattr(self, name), tuple(CONTACT_PRESSURE_LIMITS))
        positive("weber_tolerance", self.weber_tolerance, "urad")
        positive("youngs_modulus", self.youngs_modulus, "MPa")
        real("poisson_ratio", self.poisson_ratio, unit="1", low=0.0, high=0.5, high_open=True)
        get_backend(self.solver)
        try:
            get_compliance_model(self.compliance)
        except ModelUnavailableError as exc:
            raise InputError(f"compliance: {exc}") from None
        if self.fe is not None:
            self._check_fe()

    def _check_fe(self) -> None:
        from contact.compliance.fe import FEOptions
        from contact.compliance.fe.options import level_hint

        if not isinstance(self.fe, FEOptions):
            raise InputError(f"fe: must be a contact.compliance.fe.FEOptions or None, got a "
                             f"{type(self.fe).__name__}{level_hint(self.fe)}")
        if self.compliance != "fe":
            raise InputError(f"fe: FE options are used only with compliance='fe', got "
                             f"compliance={self.compliance!r}")
        if self.fe.load_row_step != 1:
            raise InputError(f"fe: load_row_step must be 1 for the FE-compliance LTCA (its "
                             f"compliance is read at every load row; the step is a root-"
                             f"stress screening option), got {self.fe.load_row_step}")
        if (self.fe.youngs_modulus, self.fe.poisson_ratio) != (self.youngs_modulus,
                                                                self.poisson_ratio):
            raise InputError(
                f"fe: the FE model's material (E {self.fe.youngs_modulus:g} MPa, ν "
                f"{self.fe.poisson_ratio:g}) must be the analysis' (youngs_modulus "
                f"{self.youngs_modulus:g} MPa, poisson_ratio {self.poisson_ratio:g})")

    def fe_options(self) -> FEOptions:
        """The FE model of ``compliance="fe"``: ``fe``, or ``FEOptions()`` with this
        analysis' material."""
        from contact.compliance.fe import FEOptions

        if self.fe is not None:
            return self.fe
        return FEOptions(youngs_modulus=self.youngs_modulus, poisson_ratio=self.poisson_ratio)


@dataclass(frozen=True, eq=False)
class LTCASetup:
    """What one loaded TCA is run on (:func:`contact.ltca.loaded_tca` builds it).

    Attributes
    ----------
    case : geometry.case.Case
        The case, with the misalignment analysed.
    easeoff : contact.utca.EaseOff
        Its ease-off (same flank and misalignment).
    options : LTCAOptions
    torques : ndarray (NT,) — [N·m]
        Pinion torques.
    roll : ndarray (J,) — [rad]
        Pinion roll positions (Q units, driving sense), from the transition M1.
    transitions : (float, float) — [rad]
        The transition rolls (M1, M2) of the ease-off (NaN where none).
    """

    case: Case
    easeoff: EaseOff
    options: LTCAOptions
    torques: np.ndarray
    roll: np.ndarray
    transitions: tuple[float, float]

    @property
    def gear_torques(self) -> np.ndarray:
        """(NT,) [N·mm] gear torque T_g = T_p z_g/z_p of each pinion torque (lossless)."""
        return self.torques * self.easeoff.ratio * 1e3


def edge_radii(case, opts: LTCAOptions) -> tuple[float, float]:
    """(pinion, gear) rounding radii of the tooth edges [mm]: ``opts.edge_radius`` if set,
    else each member's blank ``edge_break_radius``."""
    if opts.edge_radius is not None:
        return float(opts.edge_radius), float(opts.edge_radius)
    return (float(case.pinion.blank.edge_break_radius),
            float(case.gear.blank.edge_break_radius))


def json_options(opts: LTCAOptions) -> str:
    """The options as JSON text (netCDF-safe).

    ``compliance`` and ``fe`` are written only with a compliance other than the default
    shell (an analysis with the shell compliance writes the same text as before the FE
    compliance existed, so its files, the golden file among them, are unchanged); ``fe``
    as the dict of the FE options used (:meth:`LTCAOptions.fe_options`). A solver or
    compliance model given as an object is written by its name.
    """
    d = {f.name: getattr(opts, f.name) for f in dataclasses.fields(opts)}
    d["solver"] = solver_name(opts.solver)
    d["compliance"] = compliance_model_name(opts.compliance)
    if opts.compliance == "fe":
        d["fe"] = opts.fe_options().as_dict()
    elif d["compliance"] == DEFAULT_COMPLIANCE:
        del d["compliance"], d["fe"]
    else:
        del d["fe"]
    return json.dumps(d, sort_keys=True)
