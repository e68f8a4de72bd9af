"""
A misalignment study
====================

How the loaded transmission error of the default design reacts to the offset (ΔE) and
pinion mounting (ΔP) errors: a 3 × 3 grid at 250 N·m, each point a whole loaded analysis
(``contact.sweep``; ``ltca sweep`` on the command line), run here in this process
(``scheduler="synchronous"``) at a coarse roll sampling. A study of a real design uses a
finer grid on a Dask cluster (docs/studies_at_scale.md).
"""

import contact

run = contact.StudyRun(scheduler="synchronous",
                       options=contact.LTCAOptions(rolls_per_cycle=8, segments=12))
study = contact.sweep(delta_E=[-0.1, 0.0, 0.1], delta_P=[-0.1, 0.0, 0.1], torque=250,
                      run=run)
assert (study["status"] == 0).all()
te_map = contact.map_figure(study, "lte_peak_to_peak", x="delta_E", y="delta_P",
                            heading="LTE peak-to-peak at 250 N·m")

# %%
# The loaded pattern's centre moves toward the toe as ΔE grows (toe 0 → heel 1):
print(study["pattern_centre_u"].sel(torque=250, delta_P=0.0).round(2).values)
