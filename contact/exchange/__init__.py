"""Exchange with the tools gear engineers already use (issue 73).

* :mod:`contact.exchange.step` — both members as closed B-rep solids in a STEP file
  (optional extra ``[step]``: OpenCASCADE through ``cadquery-ocp-novtk``).
"""
