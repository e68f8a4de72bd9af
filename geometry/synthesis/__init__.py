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

from geometry.core.lazy import lazy_exports

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

#: the public names and their modules, imported when first used (PEP 562): importing one
#: module of the package (e.g. ``setting_variables`` for ``ltca correct --help``) does not
#: import the whole synthesis
_LAZY = {
    "FlankPoint": "geometry.machine.flank_point",
    "design_point": "geometry.pair.design_point",
    "design_point_of_case": "geometry.pair.design_point",
    "mean_addendum": "geometry.pair.design_point",
    "FlankSynthesis": "geometry.synthesis.case_synthesis",
    "SynthesisReport": "geometry.synthesis.case_synthesis",
    "synthesize": "geometry.synthesis.case_synthesis",
    "face_hobbing_pinion_tools": "geometry.synthesis.face_hobbing",
    "GearTools": "geometry.synthesis.gear",
    "case_blank": "geometry.synthesis.gear",
    "gear_formate_tools": "geometry.synthesis.gear",
    "LocalSynthesis": "geometry.synthesis.local",
    "local_synthesis": "geometry.synthesis.local",
    "MeanPoint": "geometry.synthesis.mean_point",
    "mean_point": "geometry.synthesis.mean_point",
    "PinionTools": "geometry.synthesis.pinion",
    "pinion_generate_tools": "geometry.synthesis.pinion",
    "shift_roll_origin": "geometry.synthesis.pinion",
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
