"""Tooth compliance (seed section 3.2, Eq. 3.1–3.11).

Three parts add up to a tooth pair's compliance along the contact normal:

* :mod:`contact.compliance.shell` — bending and shear of each tooth, a Rayleigh–Ritz
  model of a tapered cylindrical shell (seed Eq. 3.1–3.11), N×N per tooth;
* :mod:`contact.compliance.weber` — contact deformation by Weber (1949), diagonal,
  load-dependent;
* :mod:`contact.compliance.foundation` — fillet-foundation deflection by Sainsot, Velex &
  Duverger (2004), rank ≤ 3 per tooth;
* :mod:`contact.compliance.tooth` — the shell idealisation fitted to a generated tooth
  and the mapping of flank points to shell coordinates;
* :mod:`contact.compliance.mesh` — the total compliance of the contact segments of a
  roll position (both members, contact, foundation; block-diagonal by tooth pair).
"""

from contact.compliance.foundation import (
    SAINSOT_COEFFICIENTS,
    ToothFoundation,
    foundation_compliance,
    foundation_matrix,
    load_angle_from_normals,
    load_line_height,
    sainsot_coefficients,
)
from contact.compliance.mesh import (
    ContactSegments,
    PairComplianceModel,
    mesh_compliance,
    pair_compliance_model,
)
from contact.compliance.shell import (
    THEORIES,
    ComplianceMatrix,
    ShellModel,
    ShellTooth,
    build_shell_model,
    compliance_matrix,
    flank_normals,
    shell_deflection,
)
from contact.compliance.tooth import (
    ToothModelData,
    member_compliance,
    shell_coordinates,
    shell_tooth_from_case,
)
from contact.compliance.weber import (
    WEBER_COMPLIANCE_KINDS,
    contact_modulus,
    hertz_half_width,
    weber_compliance,
    weber_deformation,
    weber_pair_deformation,
)

__all__ = [
    "SAINSOT_COEFFICIENTS",
    "THEORIES",
    "WEBER_COMPLIANCE_KINDS",
    "ComplianceMatrix",
    "ContactSegments",
    "PairComplianceModel",
    "ShellModel",
    "ShellTooth",
    "ToothFoundation",
    "ToothModelData",
    "build_shell_model",
    "compliance_matrix",
    "contact_modulus",
    "flank_normals",
    "foundation_compliance",
    "foundation_matrix",
    "hertz_half_width",
    "load_angle_from_normals",
    "load_line_height",
    "member_compliance",
    "mesh_compliance",
    "pair_compliance_model",
    "sainsot_coefficients",
    "shell_coordinates",
    "shell_deflection",
    "shell_tooth_from_case",
    "weber_compliance",
    "weber_deformation",
    "weber_pair_deformation",
]
