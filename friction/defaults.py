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
#: without ``--friction-model``): ``kolivand2009``, the seed's Eq. 5.11 method done again
#: with the toolkit's mixed-EHL solver (docs/friction.md, "Which model is the default").
DEFAULT_FRICTION_MODEL = "kolivand2009"
