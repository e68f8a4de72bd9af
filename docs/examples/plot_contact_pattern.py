"""
Contact pattern of the default design
=====================================

The unloaded and loaded contact patterns of the bundled default case on the gear flank
(the normalised tooth, toe → heel × root → tip), as the seed's Figs. 2.10 and 3.7 draw
them: the unloaded pattern and its path of contact, then the loaded pattern at 250 N·m.
A coarse roll sampling keeps the example quick; ``ltca run --plots DIR`` draws the same
figure at the full resolution.
"""

import contact

options = contact.LTCAOptions(rolls_per_cycle=8, segments=12)
steps = contact.AnalysisChain.analysis().without("efficiency", "geometry", "mesh_interface",
                                                 "root_stress")
tree = contact.run_analysis(None, [250.0], options=options, steps=steps)
pattern = contact.contact_pattern_figure(tree["easeoff"].to_dataset(),
                                         tree["utca"].to_dataset(),
                                         tree["ltca"].to_dataset())

# %%
# The loaded numbers behind the pattern at 250 N·m:
ltca = tree["ltca"].to_dataset()
for name in ("lte_peak_to_peak", "pressure_max_flank", "edge_load_share"):
    if name in ltca:
        print(f"{name}: {float(ltca[name][0]):.3g} {ltca[name].attrs['units']}")
