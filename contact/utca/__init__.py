"""Unloaded tooth contact analysis by the ease-off method (seed §2.3.2, §2.4, ch. 4).

The layer between the generated flanks (:mod:`geometry`) and the loaded analysis
(:mod:`contact.ltca`):

* :mod:`contact.utca.action_surface` — mesh kinematics, the surface of action and the
  conjugate points of the ideal motion (seed Eq. 2.19–2.20);
* :mod:`contact.utca.easeoff` — the surface of roll angle Q and the ease-off on the gear
  projection-plane grid (:class:`EaseOff`, :func:`ease_off`);
* :mod:`contact.utca.fields` — the ease-off fields as splines over the grid and the tests
  of the contact region (:class:`EaseOffFields`);
* :mod:`contact.utca.contact_curves` — instantaneous contact curves, the unloaded
  transmission error (UTE) of each pair and the transitions M1, M2;
* :mod:`contact.utca.datasets` — the contact of the tooth pairs over one mesh cycle
  (:func:`unloaded_cycle`) and the whole UTCA of a case as the ``/easeoff`` and ``/utca``
  datasets (:func:`unloaded_tca`);
* :mod:`contact.utca.deviations` — measured or wear deviations of the flanks and the
  ease-off they give (seed ch. 4).

It uses ``geometry`` only: no compliance, no contact problem, no solver.
"""

from contact.utca.action_surface import MeshKinematics, mesh_kinematics
from contact.utca.contact_curves import (
    CURVE_SPACINGS,
    DEFAULT_SEPARATION,
    UTE_METHODS,
    ContactCurves,
    contact_curves,
    pair_transmission_error,
)
from contact.utca.datasets import (
    UnloadedCycle,
    easeoff_dataset,
    unloaded_cycle,
    unloaded_tca,
    utca_dataset,
)
from contact.utca.easeoff import FLANK_ROLES, MATING_FLANK, EaseOff, ease_off
from contact.utca.fields import EaseOffFields
from contact.utca.transitions import transitions

__all__ = [
    "CURVE_SPACINGS",
    "DEFAULT_SEPARATION",
    "FLANK_ROLES",
    "MATING_FLANK",
    "UTE_METHODS",
    "ContactCurves",
    "EaseOff",
    "EaseOffFields",
    "MeshKinematics",
    "UnloadedCycle",
    "contact_curves",
    "ease_off",
    "easeoff_dataset",
    "mesh_kinematics",
    "pair_transmission_error",
    "transitions",
    "unloaded_cycle",
    "unloaded_tca",
    "utca_dataset",
]
