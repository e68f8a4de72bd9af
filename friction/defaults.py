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
#: without ``--friction-model``): ``mixed_ehl`` since issue 61 — Johnson, Greenwood & Poon's
#: load sharing with Greenwood–Tripp asperities, an Eyring film and boundary friction
#: (:mod:`friction.mixed_ehl`). Chosen by measurement: on the default case's flanks its μ is
#: 0.77–0.83× ISO/TR 14179-2's (Schlenk's FZG gear measurements) at 50–500 N·m and rises
#: with torque as that correlation does, where ``kolivand2009`` (the seed's Eq. 5.11 fitted
#: to the stochastic solver, the default of issues 34–61) was 1.5–2.5× and fell
#: (docs/friction.md, "Which model is the default, and why").
DEFAULT_FRICTION_MODEL = "mixed_ehl"
