"""Loaded tooth contact analysis over the mesh cycle (seed §3.3–3.4, Eq. 3.12–3.14).

The layer that turns the unloaded contact (:mod:`contact.utca`) and the tooth compliance
(:mod:`contact.compliance`) into the loaded-contact problems of every roll position and
solves them (:mod:`contact.qp`):

* :mod:`contact.ltca.options` — :class:`LTCAOptions`, the discretisation and solution
  settings, and :class:`~contact.ltca.options.LTCASetup`, what one analysis runs on;
* :mod:`contact.ltca.segments` — the contact segments of every (roll, pair)
  (:func:`segment_geometry` → :class:`~contact.ltca.segments.Segments`), built from
  :mod:`contact.ltca.discretisation` (the segment quadratic, blank clipping),
  :mod:`contact.ltca.curvature` (R_eq) and :mod:`contact.ltca.edges` (the flank boundary
  as edge contact);
* :mod:`contact.ltca.screening` — which segments a roll's problem must take;
* :mod:`contact.ltca.pool` — their structural compliance, assembled once per roll, by the
  compliance model the options name (the one registry
  :mod:`contact.ltca.compliance_models`: the shells, the FE influence coefficients, or a
  user's model registered with :func:`register_compliance_model`);
* :mod:`contact.ltca.plastic` — the elastic–perfectly-plastic segments' pressure and
  force limits (the bound F ≤ F_max of the contact QP);
* :mod:`contact.ltca.weber` — one roll's problem with Weber's compliance iterated
  (Newton) to the loads;
* :mod:`contact.ltca.roll_loop` — the loop over roll positions and torques, accumulating
  :class:`~contact.ltca.results.RollResults` (:mod:`contact.ltca.results`);
* :mod:`contact.ltca.dataset` — the ``/ltca`` dataset;
* :mod:`contact.ltca.transmission_error` — the LTE summary over the mesh cycles;
* :mod:`contact.ltca.plausibility` — the causes that make a result implausible (plastic
  contact, a flank above the material's limit, a large LTE spread);
* :mod:`contact.ltca.mesh_cycle` — :func:`loaded_tca`, the whole analysis of a case.
"""

from contact.ltca.compliance_models import (
    available_compliance_models,
    register_compliance_model,
    unregister_compliance_model,
)
from contact.ltca.edges import EDGE_KINDS, FlankBoundary, flank_boundary
from contact.ltca.mesh_cycle import loaded_tca, ltca_problems
from contact.ltca.options import LTCAOptions, LTCASetup
from contact.ltca.roll_loop import RollProblem
from contact.ltca.segments import Segments, segment_geometry
from contact.ltca.transmission_error import mesh_harmonics, transmission_error_summary

__all__ = [
    "EDGE_KINDS",
    "FlankBoundary",
    "LTCAOptions",
    "LTCASetup",
    "RollProblem",
    "Segments",
    "available_compliance_models",
    "flank_boundary",
    "loaded_tca",
    "ltca_problems",
    "mesh_harmonics",
    "register_compliance_model",
    "segment_geometry",
    "transmission_error_summary",
    "unregister_compliance_model",
]
