"""Tooth-surface geometry of face-milled and face-hobbed hypoid and spiral bevel gears.

Case files, blank geometry, cutter and machine kinematics, equation of meshing,
normals and curvatures, assembly with misalignments (seed chapter 2). Subpackages, each
named for what it computes:

* :mod:`geometry.core` — the toolkit-wide low layer (no gear in it): errors, validation,
  dataset conventions and netCDF files, atomic files, TOML files, Hertz line contact,
  version, caches, registries' helpers;
* :mod:`geometry.iso23509` — the blank by ISO 23509: pitch cone (clause 5), blank
  dimensions (clause 6), input data types I and II;
* :mod:`geometry.machine` — the cradle-type generator: cutter and blades, the machine's
  kinematic chain (FM and FH), equation of meshing, flank points and surfaces, curvatures,
  profile relief, machine-setting conventions;
* :mod:`geometry.pair` — the pair in mesh: assembly with misalignments, the design point,
  pitch contact, the conventional TCA (seed Eq. 2.14);
* :mod:`geometry.synthesis` — machine settings from basic design data (local synthesis,
  FM and FH) and corrective settings from measured flanks;
* :mod:`geometry.case` — case files; :mod:`geometry.plot` — geometry figures.
"""

from geometry.core.errors import InputError, LTCAError, ModelUnavailableError
from geometry.core.lazy import lazy_exports
from geometry.core.version import __version__

__all__ = ["BevelGearDesign", "Case", "InputError", "LTCAError", "Misalignment",
           "ModelUnavailableError", "__version__", "blank_geometry", "corrected_case",
           "corrective_settings", "load_basic", "load_case", "synthesize"]

# the case schema pulls in NumPy and the machine: imported when first used, so that what
# needs only the version or the exceptions (``ltca --help``) starts quickly. These names
# are the package's public, stable surface (issue 54).
__getattr__, __dir__ = lazy_exports(__name__, {
    "Case": "geometry.case",
    "load_case": "geometry.case",
    "Misalignment": "geometry.pair.assembly",
    "BevelGearDesign": "geometry.iso23509.design_data",
    "blank_geometry": "geometry.iso23509.blank",
    "load_basic": "geometry.synthesis.basic_design",
    "synthesize": "geometry.synthesis.case_synthesis",
    "corrective_settings": "geometry.synthesis.correction",
    "corrected_case": "geometry.synthesis.correction",
}, globals())
