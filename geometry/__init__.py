"""Tooth-surface geometry of face-milled and face-hobbed hypoid and spiral bevel gears.

Case files, blank geometry, cutter and machine kinematics, equation of meshing,
normals and curvatures, assembly with misalignments (seed chapter 2).
"""

from geometry._version import __version__
from geometry.case import Case, load_case
from geometry.errors import InputError, LTCAError, ModelUnavailableError

__all__ = ["Case", "InputError", "LTCAError", "ModelUnavailableError", "__version__", "load_case"]
