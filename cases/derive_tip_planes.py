"""Put the bundled pinions' blade tip planes on their root cones (face milling and hobbing).

Run from the repository root::

    python cases/derive_tip_planes.py [--check]

A separately cut (Generate) flank's blade tip plane sets how deep its cut goes and nothing
else: moved along the cutter axis with the cutting surface kept where it is
(:func:`geometry.synthesis.tip_plane.move_tip_plane`: point radius, profile and relief
heights; radial setting, cradle angle, swivel and sliding base), the flank is unchanged and
the root line moves. ``ltca synthesize`` now places each pinion cut's tip plane so that its
root line touches the pinion's root cone and lies nowhere above it (step 8,
:func:`geometry.synthesis.tip_plane.tip_plane_on_root_cone`). The bundled cases were
written before, by scripts whose other results have moved on since (re-running them would
change every setting), so this script applies step 8 alone to every bundled case with a
``[design]`` table and a Generate pinion and leaves every other line as it is. A
face-hobbed pinion's blade is placed in the head (phase, offset angle): its move also
turns the blade phase and the blade offset angle (the same rake plane through the new
reference point, :func:`geometry.synthesis.tip_plane.move_tip_plane`).

Run it again after a script that rewrites a bundled case's pinion tables without the
synthesis (``derive_basic_settings.py``, ``derive_iso10300_samples.py``,
``deviations/make_wear_case.py``); tests/test_generated_root.py runs ``--check``.
``--check`` writes nothing and exits with status 1 if a file would change.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

from geometry.case import FLANKS, load_case
from geometry.core.atomic_files import atomic_path
from geometry.synthesis.tip_plane import tip_plane_on_root_cone

CASES = Path(__file__).resolve().parent
_HEADER = re.compile(r"^\[pinion\.(cutter|machine)\.(concave|convex)\]\s*$")
_NOTE = "# tip planes: placed on the pinion's root cone by cases/derive_tip_planes.py."
#: [mm] a move below this leaves the file as it is (the placement's own tolerance is 1e-9)
_MOVE_TOL = 1e-7


def placed_values(case) -> dict[tuple[str, str], dict[str, float]]:
    """{(table, flank): {key: value in the case file's units}} of the moved tip planes of a
    loaded case's pinion ("cutter"/"machine" tables); empty where nothing moves."""
    out: dict[tuple[str, str], dict[str, float]] = {}
    mem = case.pinion
    if mem.process != "Generate":
        return out
    for flank in FLANKS:
        tool = mem.flank(flank)
        p = tip_plane_on_root_cone(tool.blade, tool.machine, mem.blank, mem.hand)
        if abs(p.moved) < _MOVE_TOL:
            continue
        b, s = p.blade, p.settings
        out[("cutter", flank)] = {"point_radius": b.point_radius,
                                  "profile_reference_height": b.profile_reference_height,
                                  "toprem_height": b.toprem_height,
                                  "flankrem_height": b.flankrem_height}
        if tool.blade.placed:
            out[("cutter", flank)] |= {"blade_phase": math.degrees(b.blade_phase),
                                       "blade_offset_angle":
                                           math.degrees(b.blade_offset_angle)}
        out[("machine", flank)] = {"radial_setting": s.radial_setting,
                                   "cradle_angle": math.degrees(s.cradle_angle),
                                   "swivel": math.degrees(s.swivel),
                                   "sliding_base": s.sliding_base}
    return out


def with_values(text: str, values: dict[tuple[str, str], dict[str, float]]) -> str:
    """The case text with the given keys of the pinion's cutter and machine tables
    replaced (a key not already in its table is left out: a straight profile has no
    reference height, a blade without toprem no toprem height), other lines unchanged."""
    out: list[str] = []
    table = None
    for line in text.splitlines():
        if line.startswith("["):
            m = _HEADER.match(line)
            table = (m.group(1), m.group(2)) if m else None
        elif table in values and "=" in line:
            key = line.split("=", 1)[0].strip()
            if key in values[table]:
                line = f"{key} = {values[table][key]!r}"
        out.append(line)
    if values and _NOTE not in out:
        first = next(i for i, ln in enumerate(out) if not ln.startswith("#"))
        out.insert(first, _NOTE)
    return "\n".join(out) + "\n"


def main(argv: list[str]) -> int:
    check = "--check" in argv
    changed = []
    for path in sorted(CASES.glob("*.toml")):
        case = load_case(path)
        if "design" not in case.extra:
            continue
        text = path.read_text(encoding="utf-8")
        new = with_values(text, placed_values(case))
        if new != text:
            changed.append(path.name)
            if not check:
                with atomic_path(path) as tmp:
                    tmp.write_text(new, encoding="utf-8")
    verb = "would change" if check else "wrote"
    print(f"{verb} {len(changed)} case(s): {', '.join(changed) or 'none'}")
    return 1 if check and changed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
