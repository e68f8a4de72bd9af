"""Write the blade point widths into the bundled cases.

Run from the repository root::

    python cases/derive_point_widths.py [--check]

The point width W of a blade is the width of its flat tip, from the point (the nominal
profile line at the tip plane, radius r_p) across the slot; the tip cuts the slot bottom
(``docs/cases.md``, blade table). The bundled cases were written before the case schema held
it, by scripts whose other results have moved on since (re-running ``ltca synthesize`` or
``ltca optimize`` would change every setting), so this script adds only ``point_width``,
derived by the relations ``ltca synthesize`` now uses, and leaves every other line as it is:

* a member whose two flanks are cut by one head in one setting (a spread-blade Formate
  gear): face milling, W = r_OB − r_IB, the outside minus the inside blade's point radius
  (the definition of a spread-blade cutter's point width); face hobbing, the slot width at
  the mean root below;
* a member whose flanks are cut separately (a generated pinion): each blade spans the slot
  width at the mean root, W = π m_mn − s_mn − h_fm (tan α_IB + tan α_OB)
  (:func:`geometry.synthesis.gear.slot_width_at_root`, from the case's ``[design]`` table
  through ISO 23509, with the case's own blade angles).

A ``point_width`` line already present is replaced. ``--check`` writes nothing and exits
with status 1 if a file would change by more than round-off (:data:`ROUND_OFF`); a file
whose widths differ by round-off alone is neither rewritten nor reported.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

from geometry.case import FLANKS, load_case
from geometry.core.atomic_files import atomic_path
from geometry.iso23509.blank import blank_geometry
from geometry.iso23509.design_data import BevelGearDesign
from geometry.synthesis.gear import slot_width_at_root

CASES = Path(__file__).resolve().parent
_HEADER = re.compile(r"^\[(pinion|gear)\.cutter\.(concave|convex)\]\s*$")
_NOTE = "# point_width: written by cases/derive_point_widths.py (see its docstring)."


def point_widths(case) -> dict[tuple[str, str], float]:
    """{(member, flank): W [mm]} of a loaded case with a ``[design]`` table."""
    geom = blank_geometry(BevelGearDesign.from_degrees(**case.extra["design"]))
    out = {}
    for mem in (case.pinion, case.gear):
        concave, convex = mem.flank("concave").blade, mem.flank("convex").blade
        one_cut = mem.concave.machine == mem.convex.machine
        if one_cut and not (concave.placed or convex.placed):
            w = concave.point_radius - convex.point_radius
        else:
            w = slot_width_at_root(getattr(geom, mem.name), geom.m_mn, convex.blade_angle,
                                   concave.blade_angle)
        for flank in FLANKS:
            out[(mem.name, flank)] = float(w)
    return out


def with_point_widths(text: str, widths: dict[tuple[str, str], float]) -> str:
    """The case text with a ``point_width`` line in each blade table (after its
    ``edge_radius`` line, else first), other lines unchanged."""
    lines = text.splitlines()
    out: list[str] = []
    table = None
    pending = False
    anchor = 0
    for line in lines:
        m = _HEADER.match(line)
        if line.startswith("["):
            if pending:  # a blade table without an edge_radius line
                out.insert(anchor, f"point_width = {widths[table]!r}")
            table, pending = ((m.group(1), m.group(2)), True) if m else (None, False)
            out.append(line)
            anchor = len(out)
            continue
        if table is not None and line.startswith("point_width"):
            continue
        out.append(line)
        if pending and line.startswith("edge_radius"):
            out.append(f"point_width = {widths[table]!r}")
            pending = False
    if pending:
        out.insert(anchor, f"point_width = {widths[table]!r}")
    if _NOTE not in out:
        first = next(i for i, ln in enumerate(out) if not ln.startswith("#"))
        out.insert(first, _NOTE)
    return "\n".join(out) + "\n"


#: relative difference of a derived point width that is round-off, not a change: the ISO
#: 23509 chain gives the widths to ~1e-15 relative, and its last digit moves with the
#: NumPy/SciPy build (1.2412878285717923 against ...914 mm, numpy 2.4)
ROUND_OFF = 1e-12


def _same(new: str, old: str) -> bool:
    """The two texts equal but for ``point_width`` values within :data:`ROUND_OFF`."""
    a, b = new.splitlines(), old.splitlines()
    if len(a) != len(b):
        return False
    for x, y in zip(a, b, strict=True):
        if x == y:
            continue
        if not (x.startswith("point_width = ") and y.startswith("point_width = ")):
            return False
        vx, vy = float(x.split("=", 1)[1]), float(y.split("=", 1)[1])
        if abs(vx - vy) > ROUND_OFF * max(abs(vx), abs(vy)):
            return False
    return True


def main(argv: list[str]) -> int:
    check = "--check" in argv
    changed = []
    for path in sorted(CASES.glob("*.toml")):
        case = load_case(path)
        if "design" not in case.extra:
            continue
        text = path.read_text(encoding="utf-8")
        new = with_point_widths(text, point_widths(case))
        if not _same(new, text):
            changed.append(path.name)
            if not check:
                with atomic_path(path) as tmp:
                    tmp.write_text(new, encoding="utf-8")
    verb = "would change" if check else "wrote"
    print(f"{verb} {len(changed)} case(s): {', '.join(changed) or 'none'}")
    return 1 if check and changed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
