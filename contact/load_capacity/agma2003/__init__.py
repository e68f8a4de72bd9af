"""ANSI/AGMA 2003-D19: pitting resistance and bending strength of generated straight, Zerol
and spiral bevel gear teeth (the registry's ``"agma2003"`` method).

* :mod:`~contact.load_capacity.agma2003.factors` — the rating factors of clauses 10–20
  (K_v, C_s, K_s, K_m, C_xc, K_x, C_L, K_L, K_T, C_R, K_R, C_p);
* :mod:`~contact.load_capacity.agma2003.stresses` — the stress numbers s_c, s_t, the
  permissible s_wc, s_wt and the power ratings P_ac, P_at of clause 5;
* :mod:`~contact.load_capacity.agma2003.allowables` — s_ac, s_at by metallurgical grade
  from the material table (clause 21);
* :mod:`~contact.load_capacity.agma2003.inputs` — the ``[agma2003]`` table and the
  geometry of the ``[design]`` table (no hypoid offset);
* :mod:`~contact.load_capacity.agma2003.method` — the registry's ``rate``, ``tables`` and
  ``missing``.

The geometry factors I and J are inputs (the standard's Annex D charts or another
calculation); Annex C(M) is not computed. Checked against the standard's Annex E
(tests/test_rating_agma2003.py; docs/rating.md).
"""

from contact.load_capacity.agma2003.inputs import FIELDS, AGMAGeometry, AGMAInputs
from contact.load_capacity.agma2003.method import agma2003_rating, missing, rate, tables

__all__ = ["FIELDS", "AGMAGeometry", "AGMAInputs", "agma2003_rating", "missing", "rate",
           "tables"]
