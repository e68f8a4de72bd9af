"""ISO 10300 Method B1 load capacity rating of bevel and hypoid gears (issue 52).

A gear engineer judges a pair by the standard rating beside the LTCA's local stresses:
ISO 10300-1 (virtual cylindrical gears, load factors), -2 (pitting) and -3 (tooth root
strength), Method B1, from the pair's ISO 23509 blank and the case's ``[rating]`` table.

Modules, each a set of plain functions over arrays (one per factor), all under
``contact.load_capacity.iso10300``:

* :mod:`~.virtual_gears` — the virtual cylindrical gears (ISO 10300-1 Annex A);
* :mod:`~.factors` — forces, K_v, K_Hβ, K_Fβ, K_Hα, K_Fα (ISO 10300-1);
* :mod:`~.pitting` — σ_H0, σ_H, σ_HP and their Z factors (ISO 10300-2);
* :mod:`~.bending` — σ_F0, σ_F, σ_FP and their Y factors (ISO 10300-3);
* :mod:`~.inputs` — :class:`GearData`, :class:`RatingInputs`;
* :mod:`~.materials` — the material numbers from the material table;
* :mod:`~.rating` — :func:`iso10300_rating`, the entry point (the ``/rating`` dataset),
  and :func:`rate_pair`;
* :mod:`~.beside` — :func:`analysis_rating` (the rating of an analysis, or why there is
  none) and :func:`rating_beside_ltca` (its stresses beside the LTCA's);
* :mod:`~.capacity` — the long-life capacity and the design torque;
* :mod:`~.face_contact` — the face contact ratio of a basic design and the face width or
  spiral angle that raise it to 1.25 (:func:`~.face_contact.overlap_text`).

It is the ``iso10300`` method of the load-capacity registry
(:func:`contact.load_capacity.rate`).

Checked against ISO/TR 10300-30:2024 (three worked samples, every printed intermediate
value; tests/test_rating_iso10300.py); docs/rating.md gives the equations and the
comparison.
"""

from contact.load_capacity.iso10300.beside import analysis_rating, bin_ratings, rating_beside_ltca
from contact.load_capacity.iso10300.inputs import GearData, RatingInputs, gear_data_from_blank
from contact.load_capacity.iso10300.rating import (
    case_gear_data,
    case_rating_inputs,
    iso10300_rating,
    rate_pair,
)

__all__ = ["GearData", "RatingInputs", "analysis_rating", "bin_ratings", "case_gear_data",
           "case_rating_inputs", "gear_data_from_blank", "iso10300_rating", "rate_pair",
           "rating_beside_ltca"]
