"""The optimisers of :func:`contact.optimize.optimize` by name.

In a module of its own (no NumPy, SciPy or analysis in it), so that ``ltca optimize
--help`` lists them without importing the optimisation.

Public names
------------
METHODS   optimiser name → what it is
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

__all__ = ["METHODS"]

#: optimisers: name → what it is
METHODS: Mapping[str, str] = MappingProxyType({
    "differential_evolution": "scipy.optimize.differential_evolution (best1bin, deferred "
                              "updating, a generation analysed in parallel)",
    "powell": "scipy.optimize.minimize(method='Powell') with bounds (sequential)",
})
