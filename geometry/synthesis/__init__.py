"""Machine settings from basic design data, and corrective settings from measured flanks.

basic_design      the basic design file: ISO 23509 data, targets, synthesis options
flank_synthesis   the local synthesis of both members' settings (FM and FH)
correction        corrective machine settings from measured flank deviations

The package exports what the module ``geometry.synthesis`` did.
"""

from geometry.synthesis.flank_synthesis import (
    FlankPoint,
    FlankSynthesis,
    GearTools,
    LocalSynthesis,
    MeanPoint,
    PinionTools,
    SynthesisReport,
    case_blank,
    design_point,
    design_point_of_case,
    face_hobbing_pinion_tools,
    gear_formate_tools,
    local_synthesis,
    mean_addendum,
    mean_point,
    pinion_generate_tools,
    shift_roll_origin,
    synthesize,
)

__all__ = [
    "FlankPoint",
    "FlankSynthesis",
    "GearTools",
    "LocalSynthesis",
    "MeanPoint",
    "PinionTools",
    "SynthesisReport",
    "case_blank",
    "design_point",
    "design_point_of_case",
    "face_hobbing_pinion_tools",
    "gear_formate_tools",
    "local_synthesis",
    "mean_addendum",
    "mean_point",
    "pinion_generate_tools",
    "shift_roll_origin",
    "synthesize",
]
