"""Finite-element models of a member's generated teeth and their influence coefficients.

The teeth of one member — the loaded tooth and its neighbours, both flanks, the root
fillets the blades' edge radii generate, the slot bottoms, the face, front and back cones
and a rim — are meshed with quadratic hexahedra straight from the generated surfaces and
solved with scikit-fem and a sparse direct solver (docs/fe.md):

* :mod:`~contact.compliance.fe.options` — :class:`FEOptions`, every input of the model;
* :mod:`~contact.compliance.fe.section` — transverse sections of the generated tooth;
* :mod:`~contact.compliance.fe.mapped_mesh` — structured meshes mapped from a parameter box;
* :mod:`~contact.compliance.fe.solid` — the meshed solid of the teeth;
* :mod:`~contact.compliance.fe.elasticity` — stiffness, stresses, direct solvers;
* :mod:`~contact.compliance.fe.influence` — influence coefficients (compliance of the
  flank, stress in the fillets), cached on disk (:mod:`~contact.compliance.fe.cache`);
* :mod:`~contact.compliance.fe.superposition` — the compliance matrix between contact
  points and the fillet stress of contact forces, from the coefficients;
* :mod:`~contact.compliance.fe.contact_compliance` — the contact compliance of a mesh's
  segments from both members' coefficients plus Weber's term: the FE-compliance LTCA
  (``LTCAOptions(compliance="fe")``; imported by its module path, not re-exported here);
* :mod:`~contact.compliance.fe.export` — the solid's boundary as STL (STEP with gmsh).
"""

from contact.compliance.fe.cache import (
    CACHE_ENV,
    cache_directory,
    cache_key,
    cache_path,
    prime_cache,
)
from contact.compliance.fe.elasticity import SOLVERS, elastic_model, factorise
from contact.compliance.fe.influence import (
    InfluenceModel,
    build_influence_model,
    hat_weights,
    influence_coefficients,
    influence_dataset,
    principal_stresses,
)
from contact.compliance.fe.options import CONSTRAINTS, ELEMENTS, FEOptions, member_flank
from contact.compliance.fe.solid import ToothSolid, build_tooth_solid
from contact.compliance.fe.superposition import (
    FlankPoints,
    fe_compliance_matrix,
    fillet_stress,
    locate_flank_points,
)

__all__ = [
    "CACHE_ENV",
    "CONSTRAINTS",
    "ELEMENTS",
    "SOLVERS",
    "FEOptions",
    "FlankPoints",
    "InfluenceModel",
    "ToothSolid",
    "build_influence_model",
    "build_tooth_solid",
    "cache_directory",
    "cache_key",
    "cache_path",
    "elastic_model",
    "factorise",
    "fe_compliance_matrix",
    "fillet_stress",
    "hat_weights",
    "influence_coefficients",
    "influence_dataset",
    "locate_flank_points",
    "member_flank",
    "prime_cache",
    "principal_stresses",
]
