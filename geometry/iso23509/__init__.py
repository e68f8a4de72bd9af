"""Bevel and hypoid gear blanks by ISO 23509:2016.

pitch_cone   the pitch cone by clause 5 (Methods 0–3, face milling and face hobbing,
             input data types I and II): :class:`BevelGearDesign`, :func:`pitch_cone`
blank        the blank dimensions by clause 6: :func:`blank_geometry`
"""
