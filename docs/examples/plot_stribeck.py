"""
A Stribeck curve from the friction model
========================================

The friction-coefficient model ``kolivand2009`` (the seed's Eq. 5.11 form, refitted to the
toolkit's stochastic mixed-EHL solver; the default until issue 61, now ``mixed_ehl``) at a
hypoid flank's conditions: 0.5 GPa Hertz pressure, slide-to-roll ratio 0.3, 75W90 at 50
and 90 °C, R 20 mm, superfinished flanks of Rq 0.1 µm, over the entraining speed. The
friction coefficient falls from the boundary regime as the film builds up and rises again
with the film's shear at higher speed: the Stribeck minimum (at 1 GPa and above the
thermal film's μ keeps falling up to 20 m/s: docs/ehl.md, the regime map).
"""

import matplotlib.pyplot as plt
import numpy as np

from friction import friction_coefficient, load_lubricant, pressure_viscosity_coefficient, viscosity

oil = load_lubricant("75W90")
speed = np.geomspace(0.05, 20.0, 40)  # m/s
fig, ax = plt.subplots(figsize=(6, 3.5))
for temperature in (50.0, 90.0):  # degC
    mu = friction_coefficient(
        "kolivand2009", hertz_pressure=500.0, slide_to_roll=0.3, entraining_velocity=speed,
        viscosity=viscosity(oil, temperature),
        pressure_viscosity=pressure_viscosity_coefficient(oil, temperature),
        radius=20.0, roughness_1=0.1, roughness_2=0.1)
    ax.semilogx(speed, mu, label=f"{temperature:g} °C")
    print(f"{temperature:g} °C: μ from {mu.max():.3f} (boundary side) to a minimum of "
          f"{mu.min():.4f} at {speed[np.argmin(mu)]:.2g} m/s")
    assert 0.0 < mu.min() < mu[0] and np.argmin(mu) < speed.size - 1  # a Stribeck minimum
ax.legend(title="oil inlet")
ax.set_xlabel("entraining speed u_e [m/s]")
ax.set_ylabel("friction coefficient μ [1]")
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
