"""The friction package's defaults, in a module that imports nothing (``ltca --help`` shows
them and imports no NumPy, tests/test_startup.py).

Public names
------------
DEFAULT_FRICTION_MODEL   the friction-coefficient model of the efficiency stage by default
"""

from __future__ import annotations

__all__ = ["DEFAULT_FRICTION_MODEL"]

#: The efficiency stage's friction-coefficient model where none is named (a case's
#: ``[operating]`` table without ``friction_model``, ``OperatingConditions()``, ``ltca run``
#: without ``--friction-model``): ``thermal_eyring`` since issue 74 — Zhou & Hoeprich's
#: (1991) asperity load share of deterministic contacts of ground profiles, boundary
#: friction on the asperities and a thermal Eyring film (:mod:`friction.thermal_eyring`).
#: Chosen by measurement against ISO/TR 14179-2 (Schlenk's FZG gear measurements) and Xu et
#: al. (2007): it ranks surface finishes, oils and temperatures as those do (all 19 of issue
#: 74's rows on Table 5.4's A and B, most of which ``mixed_ehl`` — the default of issues
#: 61–74 — misses), and its flank μ on the default case is 0.81–1.40× ISO/TR 14179-2 at 50–90 °C
#: (1.54× at 100 °C and 50 N·m), rising with torque (docs/friction.md, "Which model is the
#: default, and why").
DEFAULT_FRICTION_MODEL = "thermal_eyring"
