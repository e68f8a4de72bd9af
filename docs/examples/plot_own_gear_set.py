"""
Your own gear set: basic data to a developed, rated design
==========================================================

A passenger-car hypoid that is not bundled (10×43, ring gear d_e2 210 mm, b2 32 mm,
offset 25 mm, β_m1 46°, 7-in cutter, 22.5/22.5° pressure angles, face milling) from its
ISO 23509 basic data alone: the synthesis of the machine settings with the development of
the bearing under load (every input at its default), then the loaded analysis with the
ISO 10300 rating at the light and the design torque, and the verdict — the steps of
"Analyse your own gear set" (``ltca synthesize``, ``ltca run``) from Python.
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

import contact
import geometry

BASIC = """
name = "pc_hypoid_10x43"
source = "gallery example: passenger-car hypoid 10x43, de2 210 mm, b2 32 mm, a 25 mm"

[design]
method = 1
Sigma = 90.0
a = 25.0
z1 = 10
z2 = 43
de2 = 210.0
b2 = 32.0
beta_m = 46.0
rc0 = 88.9
alpha_dD = 22.5
alpha_dC = 22.5
f_alim = 1.0
c_ham = 0.25
k_d = 2.0
k_c = 0.125
k_t = 0.1
backlash = "j_et2"
backlash_value = 0.15
theta_a2 = 1.0
theta_f2 = 4.0
hand = "left"
"""

with tempfile.TemporaryDirectory() as tmp:
    path = Path(tmp) / "pc_hypoid_10x43.toml"
    path.write_text(BASIC, encoding="utf-8")
    basic = geometry.load_basic(path)

# %%
# Synthesis and development of the bearing: each candidate is a local synthesis of the
# drive flank analysed by a coarse LTCA at the light and the design torque, the best
# checked at the default sampling; the design torque is the ISO 10300 capacity at long life
# (the basic file gives none), lowered to the bearing's static flank capacity where the
# flank peak pressure there would exceed the static strength. Then the coast flank, which
# carries the full torque in reverse gear: checked at the same torques, and developed the
# same way on its own prescriptions where it misses a target.
developed = contact.develop(basic)
# the case `ltca synthesize` writes (its design torques in [rating], the light and design
# torque as its operating torques): `developed.case` is the synthesised case before them
case = developed.written_case()
light, design = case.operating.torque
print(developed.headline())
print(f"light load {light:.0f} N·m, design torque {design:.0f} N·m ({developed.torque_source})")

# %%
# The loaded analysis of the developed case at both torques with its ISO 10300 rating
# (the case carries the ``[design]`` and ``[rating]`` tables the synthesis wrote; the
# chain's rating step rates it at the case's pinion speed and adds the standard's flash
# temperature beside it — ``ltca run``'s steps but the flank geometry and the mesh
# interface), and the verdict: PASS or ATTENTION with its reasons for a development that
# met its targets.
steps = contact.AnalysisChain.analysis().without("geometry", "mesh_interface")
tree = contact.run_analysis(case, None, steps=steps)  # its operating torques, as `ltca run`
ltca = tree["ltca"].to_dataset()
for t, p2p, edge in zip(ltca["torque"].values, ltca["lte_peak_to_peak"].values,
                        ltca["pressure_max_edge"].values, strict=True):
    print(f"{t:6.0f} N·m: LTE p-p {p2p:5.1f} µrad, peak edge pressure {edge:5.0f} MPa")
print("S_H (pinion, gear) at the design torque:",
      tree["rating"]["S_H"].sel(torque=design).round(2).values)
print("\n".join(contact.verdict(tree).lines(6)))

# %%
# The loaded pattern on the gear flank (projection plane: toe → heel, root → tip) at the
# light and the design torque.
fig, axes = plt.subplots(1, 2, figsize=(8, 3.2), sharey=True)
env = ltca["pressure_envelope"]
for ax, t in zip(axes, env["torque"].values, strict=True):
    m = ax.pcolormesh(env["u"], env["v"], env.sel(torque=t).transpose("v", "u"),
                      shading="auto", cmap="viridis")
    ax.set_title(f"{t:.0f} N·m")
    ax.set_xlabel("u (toe 0, heel 1)")
axes[0].set_ylabel("v (root 0, tip 1)")
fig.colorbar(m, ax=axes, label=f"contact pressure [{env.attrs.get('units', 'MPa')}]")
