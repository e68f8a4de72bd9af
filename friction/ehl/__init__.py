"""Mixed-EHL line-contact solver (the seed's §5.2.2 model; issue 33).

One module per physical step: :mod:`.rheology` (viscosity, density, film shear),
:mod:`.kernel` (half-space deflection by DC-FFT), :mod:`.reynolds` (the unified Reynolds
equation), :mod:`.line_contact` (one condition: load balance, friction, dataset),
:mod:`.roughness` (measured-like ground profiles). Equations and validity: ``docs/ehl.md``.
"""
