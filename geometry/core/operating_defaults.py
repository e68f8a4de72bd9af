"""The toolkit's default operating point, in a module that imports nothing heavy.

The commands' help shows these values (``ltca run --help``), and the help imports no
NumPy (tests/test_startup.py); :mod:`geometry.case` re-exports them as
:data:`geometry.case.OPERATING_DEFAULTS`.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType
from typing import Any

__all__ = ["OPERATING_DEFAULTS"]

#: The toolkit's operating point where a case's ``[operating]`` table gives none (one
#: place: :class:`friction.operating.OperatingConditions` takes its defaults from here):
#: the seed's Table 3.1 torques [N·m], pinion speed [rpm], the seed's Table 5.2 oil, oil
#: inlet temperature [degC], RMS roughness Rq [µm]. The friction-coefficient model's
#: default is the friction package's (:data:`friction.defaults.DEFAULT_FRICTION_MODEL`):
#: a case that names none leaves the choice to the efficiency stage.
OPERATING_DEFAULTS: Mapping[str, Any] = MappingProxyType({
    "torque": (50.0, 250.0, 500.0),
    "pinion_speed": 1500.0,
    "lubricant": "75W90",
    "temperature": 90.0,
    "roughness": 0.8,
})
