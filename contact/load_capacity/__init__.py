"""Load capacity of a gear pair: rating methods, durability, scuffing and micropitting.

The load-capacity package reads the chain's datasets (the case, ``/ltca``, ``/friction``)
and writes its own groups; ``friction`` never reads them (tests/test_layers.py). Layout:

* :mod:`~contact.load_capacity.methods` — the registry of rating methods (:data:`METHODS`,
  :func:`available_methods`, :func:`rate`, :func:`register_method`), after qpsolvers';
* :mod:`~contact.load_capacity.iso10300` — ISO 10300-1/-2/-3:2014 Method B1 (the
  ``"iso10300"`` method: virtual cylindrical gears, load factors, pitting and tooth root
  stress, capacity and design torque, the rating beside the LTCA's stresses);
* :mod:`~contact.load_capacity.durability` — S–N curves of ISO 6336-2/-3, Miner's rule,
  damage and life over a duty cycle;
* :mod:`~contact.load_capacity.flash_temperature` — Blok's flash temperature, bulk
  temperature, scuffing temperature and safety;
* :mod:`~contact.load_capacity.iso_flash_temperature` — ISO/TS 6336-20's flash temperature
  method on the virtual cylindrical gears of ``/rating`` (``/rating/flash_temperature``);
* :mod:`~contact.load_capacity.micropitting` — specific film thickness and the safety
  against micropitting (ISO/TS 6336-22);
* :mod:`~contact.load_capacity.scuffing_micropitting` — both on the LTCA's contact
  segments from ``/ltca`` and ``/friction`` (the ``/scuffing_micropitting`` group).

Rate a case by a named method::

    from contact.load_capacity import available_methods, rate

    ds = rate("iso10300_30_sample1", method="iso10300")   # the /rating dataset
    ds.attrs["rating_method"]                              # 'iso10300'
"""

from geometry.core.lazy import lazy_exports

__all__ = [
    "DEFAULT_METHOD",
    "METHODS",
    "RatingMethod",
    "ScuffingConditions",
    "available_methods",
    "blok_flash_temperature",
    "micropitting_safety",
    "rate",
    "register_method",
    "scuffing_micropitting",
    "scuffing_safety",
    "specific_film_thickness",
    "unregister_method",
]

#: the public names and the module each comes from, imported when first used (PEP 562)
_LAZY = {
    **dict.fromkeys(("DEFAULT_METHOD", "METHODS", "RatingMethod", "available_methods", "rate",
                     "register_method", "unregister_method"), "contact.load_capacity.methods"),
    **dict.fromkeys(("ScuffingConditions", "blok_flash_temperature", "scuffing_safety"),
                    "contact.load_capacity.flash_temperature"),
    **dict.fromkeys(("micropitting_safety", "specific_film_thickness"),
                    "contact.load_capacity.micropitting"),
    "scuffing_micropitting": "contact.load_capacity.scuffing_micropitting",
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
