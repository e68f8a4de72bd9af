"""Machine settings from basic design data, and corrective settings from measured flanks.

The synthesis of a pair (:func:`synthesize`, ``docs/synthesis.md``), one module per step:

basic_design     the basic design file: ISO 23509 data, targets, synthesis options
gear             step 2, the gear's Formate tools (FM and FH), and the case blanks
mean_point       step 3, the mesh position of the gear's mean point M
local            step 4, the local synthesis of the pinion's shape at M
pinion           step 5, the pinion's Generate tools (face milling)
face_hobbing     step 5, the pinion's tools of a face-hobbed pair
modified_roll    step 6, the modified roll that puts the TE on its parabola
case_synthesis   the driver: basic design → complete case and report
correction       corrective machine settings from measured flank deviations
setting_variables  the machine settings as named variables (correction, optimisation)

The package exports what the module ``geometry.synthesis`` did.
"""

from geometry.machine.flank_point import FlankPoint
from geometry.pair.design_point import design_point, design_point_of_case, mean_addendum
from geometry.synthesis.case_synthesis import FlankSynthesis, SynthesisReport, synthesize
from geometry.synthesis.face_hobbing import face_hobbing_pinion_tools
from geometry.synthesis.gear import GearTools, case_blank, gear_formate_tools
from geometry.synthesis.local import LocalSynthesis, local_synthesis
from geometry.synthesis.mean_point import MeanPoint, mean_point
from geometry.synthesis.pinion import PinionTools, pinion_generate_tools, shift_roll_origin

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
