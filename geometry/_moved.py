"""Old module paths of ``geometry`` that keep working for one release (issue 31).

``geometry/`` was 26 flat modules; they now live in subpackages named for what they
compute (``core``, ``iso23509``, ``machine``, ``pair``, ``synthesis``). An import by an old
path — ``import geometry.errors``, ``from geometry.blank import blank_geometry`` — still
gives the module at its new place, with a :class:`DeprecationWarning` naming it
(:mod:`geometry.core.moved`). ``geometry.machine`` and ``geometry.synthesis`` kept their
names (now packages that export what the modules did); ``geometry.case`` and
``geometry.plot`` did not move.
"""

from __future__ import annotations

from geometry.core import moved

__all__ = ["MOVED", "install"]

#: old module path → new module path
MOVED: dict[str, str] = {
    "geometry._version": "geometry.core.version",
    "geometry.errors": "geometry.core.errors",
    "geometry.validation": "geometry.core.validation",
    "geometry.conventions": "geometry.core.conventions",
    "geometry.atomic_files": "geometry.core.atomic_files",
    "geometry.hertz": "geometry.core.hertz",
    "geometry.pitch_cone": "geometry.iso23509.pitch_cone",
    "geometry.blank": "geometry.iso23509.blank",
    "geometry.cutter": "geometry.machine.cutter",
    "geometry.meshing": "geometry.machine.meshing",
    "geometry.flank": "geometry.machine.flank",
    "geometry.flank_point": "geometry.machine.flank_point",
    "geometry.curvature": "geometry.machine.curvature",
    "geometry.relief": "geometry.machine.relief",
    "geometry.machine_convention": "geometry.machine.convention",
    "geometry.assembly": "geometry.pair.assembly",
    "geometry.design_point": "geometry.pair.design_point",
    "geometry.pitch_contact": "geometry.pair.pitch_contact",
    "geometry.conventional_tca": "geometry.pair.conventional_tca",
    "geometry.basic_design": "geometry.synthesis.basic_design",
    "geometry.correction": "geometry.synthesis.correction",
}


def install() -> None:
    """Put the finder of :data:`MOVED` on ``sys.meta_path`` (once)."""
    moved.install(MOVED)
