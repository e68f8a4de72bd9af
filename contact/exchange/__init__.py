"""Exchange with the tools gear engineers already use (issue 73).

* :mod:`contact.exchange.rexs` — REXS bevel stages out and in, checked against FVA's
  schema and attribute database (optional extra ``[exchange]`` for the schema validators).
* :mod:`contact.exchange.step` — both members as closed B-rep solids in a STEP file
  (optional extra ``[step]``: OpenCASCADE through ``cadquery-ocp-novtk``).
"""
