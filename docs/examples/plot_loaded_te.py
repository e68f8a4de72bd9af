"""
Loaded transmission error of the default design
===============================================

The whole chain on the bundled default case (the reference design of the seed's 11×41
face-milled hypoid pair at its Table 3.1 misalignment): geometry from machine settings,
ease-off UTCA and the loaded TCA at three pinion torques; the loaded transmission error
over two mesh cycles, as the seed's Fig. 3.8.
"""

import matplotlib.pyplot as plt

import contact

steps = contact.AnalysisChain.analysis().without("efficiency", "geometry", "mesh_interface")
tree = contact.run_analysis(None, [50.0, 250.0, 500.0], steps=steps)
ltca = tree["ltca"].to_dataset()

fig, ax = plt.subplots(figsize=(6, 3.5))
for torque in ltca["torque"].values:
    lte = ltca["transmission_error"].sel(torque=torque)
    ax.plot(lte["roll"], lte, label=f"{torque:g} N·m")
ax.set_xlabel(f"pinion roll angle [{ltca['roll'].attrs.get('units', '')}]")
ax.set_ylabel(f"loaded TE [{ltca['transmission_error'].attrs['units']}]")
ax.legend(title="pinion torque")
fig.tight_layout()

# %%
# The peak-to-peak LTE per torque [µrad]:
for torque, p2p in zip(ltca["torque"].values, ltca["lte_peak_to_peak"].values,
                       strict=True):
    print(f"{torque:5g} N·m: {p2p:5.1f} µrad")
