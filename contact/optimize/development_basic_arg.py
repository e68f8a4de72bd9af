"""The ``basic`` argument of :func:`contact.develop`: a basic design, or its file.

Issue 71, round 26d (branch api87): a script user who passed the basic file's path, as
``contact.run_analysis`` takes a case file's path, or the analysis case it wrote, got
``AttributeError: 'str' object has no attribute 'root_stress'`` from deep inside the
development. A path is now read as ``ltca synthesize FILE`` reads it; anything else is
refused naming the argument and what it takes.
"""

from __future__ import annotations

import os
from typing import Any

from geometry.core.errors import InputError
from geometry.synthesis.basic_design import BasicDesign, load_basic

__all__ = ["basic_design_of"]


def basic_design_of(basic: Any) -> BasicDesign:
    """``basic`` as a :class:`BasicDesign`.

    Parameters
    ----------
    basic : BasicDesign, str or path-like
        The design, or the path of its basic design file (read by
        :func:`geometry.synthesis.basic_design.load_basic`, as ``ltca synthesize FILE``).

    Returns
    -------
    BasicDesign

    Raises
    ------
    InputError
        ``basic`` of another type (an analysis case named as such: it is what the
        development writes, not what it starts from), or the file's own errors.
    """
    if isinstance(basic, BasicDesign):
        return basic
    if isinstance(basic, str | os.PathLike):
        return load_basic(basic)
    from geometry.case import Case

    got = (f"the analysis case {basic.name!r} (the development writes a case; it starts "
           "from the basic data)" if isinstance(basic, Case) else type(basic).__name__)
    raise InputError("basic: must be a BasicDesign (geometry.load_basic(FILE)) or a basic "
                     f"design file's path, got {got}")
