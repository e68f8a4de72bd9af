"""Simulated wear of the flanks: Archard's law integrated over load cycles (seed ch. 6 (v)).

archard      the physics: the depth of one passage of the loaded band, k w |V_s| / c, the
             contact line's speed over each flank, the depths on a deviation grid
simulation   the loop: each step analyses the worn surfaces (ease-off updated by the
             deviation grids, UTCA, LTCA), wears them by the step's load cycles, repeats

The package exports what the module ``contact.wear`` did.
"""

from contact.wear.archard import (
    archard_depth,
    contact_line_speed,
    depth_on_grid,
    flank_line_speeds,
    passage_wear,
)
from contact.wear.simulation import WEAR_GRID, final_deviations, simulate_wear

__all__ = [
    "WEAR_GRID",
    "archard_depth",
    "contact_line_speed",
    "depth_on_grid",
    "final_deviations",
    "flank_line_speeds",
    "passage_wear",
    "simulate_wear",
]
