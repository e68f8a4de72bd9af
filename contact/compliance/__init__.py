"""Tooth compliance (seed section 3.2, Eq. 3.1–3.11).

Three parts add up to a tooth pair's compliance along the contact normal:

* :mod:`contact.compliance.shell` — bending and shear of each tooth, a Rayleigh–Ritz
  model of a tapered cylindrical shell (seed Eq. 3.1–3.11), N×N per tooth;
* :mod:`contact.compliance.hertz` — contact deformation by Weber (1949), diagonal,
  load-dependent;
* :mod:`contact.compliance.base` — fillet-foundation deflection by Sainsot, Velex &
  Duverger (2004), rank ≤ 3 per tooth.
"""

from contact.compliance.base import (
    SAINSOT_COEFFICIENTS,
    ToothFoundation,
    foundation_compliance,
    foundation_matrix,
    load_angle_from_normals,
    load_line_height,
    sainsot_coefficients,
)
from contact.compliance.hertz import (
    WEBER_COMPLIANCE_KINDS,
    contact_modulus,
    hertz_half_width,
    weber_compliance,
    weber_deformation,
    weber_pair_deformation,
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

__all__ = [
    "SAINSOT_COEFFICIENTS",
    "THEORIES",
    "WEBER_COMPLIANCE_KINDS",
    "ComplianceMatrix",
    "ShellModel",
    "ShellTooth",
    "ToothFoundation",
    "build_shell_model",
    "compliance_matrix",
    "contact_modulus",
    "flank_normals",
    "foundation_compliance",
    "foundation_matrix",
    "hertz_half_width",
    "load_angle_from_normals",
    "load_line_height",
    "sainsot_coefficients",
    "shell_deflection",
    "weber_compliance",
    "weber_deformation",
    "weber_pair_deformation",
]
