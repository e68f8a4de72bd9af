"""The cradle-type generator: from machine settings and blades to tooth surfaces.

cutter         blades and their profile sections (seed Fig. 2.2–2.3)
cradle         the machine settings and the kinematic chain from cutter to blank (FM and FH,
               seed Eq. 2.1–2.7)
family         the generated family r_g(s, θ, q) with its derivatives and the meshing
               function (seed Eq. 2.7–2.8)
meshing        the equation of meshing solved for flank points (seed Eq. 2.8)
flank_point    flank points with tangents and curvature
flank          flank surfaces on the projection grid, trimmed by the blank
curvature      principal curvatures and directions (seed Eq. 2.9–2.13)
relief         profile relief by the blade's toprem and flankrem
convention     machine-setting conventions (ours, SpyGO)

The package exports what the module ``geometry.machine`` did (the cradle).
"""

from geometry.machine.cradle import (
    PROCESSES,
    MachineSettings,
    PoseSettings,
    cradle_pose,
    cutter_pose,
    indexing_ratio,
    machine_transform,
    mirror_settings,
    roll_angle,
    settings_from_poses,
    taylor_motion,
    work_rotation,
)
from geometry.machine.family import GeneratedFamily, generated_family, meshing_function

__all__ = [
    "PROCESSES",
    "GeneratedFamily",
    "MachineSettings",
    "PoseSettings",
    "cradle_pose",
    "cutter_pose",
    "generated_family",
    "indexing_ratio",
    "machine_transform",
    "meshing_function",
    "mirror_settings",
    "roll_angle",
    "settings_from_poses",
    "taylor_motion",
    "work_rotation",
]
