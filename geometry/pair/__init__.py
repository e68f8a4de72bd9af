"""The gear pair in mesh.

assembly           the pinion and gear in the global frame, misalignments ΔE, ΔP, ΔG, ΔΣ
design_point       the mean contact point M on a gear flank
pitch_contact      the pitch point and contact of the pitch cones
conventional_tca   the conventional TCA of seed Eq. 2.14 (the independent check)
"""
