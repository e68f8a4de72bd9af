"""What the toolkit's registries of interchangeable models share: names, signatures, plug-ins.

Three things are chosen by name and may be a user's own (docs/extending.md): the contact
solver (:func:`contact.qp.solvers.register_backend`), the friction-coefficient model
(:func:`friction.coefficient.register_friction_model`) and the tooth compliance model
(:func:`contact.ltca.compliance_models.register_compliance_model`). Each registry checks a
new entry the same way, with the helpers here, and refuses a bad one with an
:class:`~geometry.core.errors.InputError` that names the field, the value and what is
accepted.

Public functions
----------------
check_model_name      a registry name: a non-empty string without white space
callable_name         the name a callable passed in place of a registered name is known by
keyword_parameters    a callable's parameters, checked to be passable by keyword
entry_point_objects   the objects of an entry-point group of the installed distributions
"""

from __future__ import annotations

import inspect
import logging
from collections.abc import Callable
from importlib import metadata
from typing import Any

from geometry.core.errors import InputError

__all__ = ["callable_name", "check_model_name", "entry_point_objects", "keyword_parameters"]

log = logging.getLogger(__name__)


def check_model_name(field: str, name: Any) -> str:
    """A registry name: a non-empty string without white space (it is written into netCDF
    attributes and typed on the command line).

    Parameters
    ----------
    field : str
        The argument's name, for the message.
    name : object

    Returns
    -------
    str

    Raises
    ------
    InputError
        Not a string, empty, or with white space.
    """
    if not isinstance(name, str) or not name or any(c.isspace() for c in name):
        raise InputError(f"{field}: must be a non-empty name without spaces, got {name!r}")
    return name


def callable_name(function: Callable[..., Any]) -> str:
    """The name a callable given in place of a registered name is recorded by (in the
    results' attributes): its ``__name__`` (``functools.partial``: its function's)."""
    target = getattr(function, "func", function)
    return str(getattr(target, "__name__", None) or type(target).__name__)


def keyword_parameters(field: str, function: Any, *, positional: int = 0,
                       var_keyword: bool = True) -> tuple[tuple[str, ...], tuple[str, ...],
                                                          bool]:
    """The parameters of a model function, checked to be passable the way the registry
    calls it: ``positional`` leading arguments by position, all others by keyword.

    Parameters
    ----------
    field : str
        The argument's name, for the message.
    function : callable
    positional : int
        Leading parameters the registry passes by position (a solver's problem: 1).
    var_keyword : bool
        Whether ``**kwargs`` is accepted (a friction model's function: no, its inputs are
        read from its parameters).

    Returns
    -------
    (required, optional, takes_var_keyword)
        Names of the keyword parameters without and with a default (the positional ones
        left out), and whether it takes ``**kwargs``.

    Raises
    ------
    InputError
        Not callable, a signature that cannot be read, ``*args``, fewer positional
        parameters than ``positional``, a positional-only parameter beyond them, or a
        ``**kwargs`` where none is accepted.
    """
    if not callable(function):
        raise InputError(f"{field}: must be callable, got {function!r}")
    try:
        params = list(inspect.signature(function).parameters.values())
    except (TypeError, ValueError) as exc:
        raise InputError(f"{field}: the signature of {function!r} cannot be read ({exc})"
                         ) from None
    kinds = inspect.Parameter
    lead = [p for p in params if p.kind in (kinds.POSITIONAL_ONLY, kinds.POSITIONAL_OR_KEYWORD)]
    if len(lead) < positional:
        raise InputError(f"{field}: {callable_name(function)}{inspect.signature(function)} "
                         f"must take {positional} positional argument(s)")
    rest = [p for p in params if p not in lead[:positional]]
    required, optional, takes_var = [], [], False
    for p in rest:
        if p.kind is kinds.VAR_POSITIONAL:
            raise InputError(f"{field}: {callable_name(function)} takes *{p.name}; its "
                             "inputs are passed by keyword only")
        if p.kind is kinds.POSITIONAL_ONLY:
            raise InputError(f"{field}: parameter {p.name!r} of {callable_name(function)} is "
                             "positional-only; its inputs are passed by keyword")
        if p.kind is kinds.VAR_KEYWORD:
            if not var_keyword:
                raise InputError(f"{field}: {callable_name(function)} takes **{p.name}; "
                                 "name its inputs as parameters instead")
            takes_var = True
            continue
        (required if p.default is kinds.empty else optional).append(p.name)
    return tuple(required), tuple(optional), takes_var


def entry_point_objects(group: str) -> dict[str, Any]:
    """The objects the installed distributions advertise in an entry-point group.

    Parameters
    ----------
    group : str
        E.g. ``"hypoid_ltca.solvers"``.

    Returns
    -------
    dict of str to object
        Entry-point name → the loaded object. One that fails to load is left out with a
        warning (a broken plug-in must not break the toolkit).

    Notes
    -----
    Source: :func:`importlib.metadata.entry_points` (the packaging specification's entry
    points, ``[project.entry-points."<group>"]`` in a plug-in's ``pyproject.toml``).
    """
    out: dict[str, Any] = {}
    for ep in metadata.entry_points(group=group):
        try:
            out[ep.name] = ep.load()
        except Exception as exc:  # a plug-in's import error is its own, not ours
            log.warning("entry point %s = %s of group %s could not be loaded: %s: %s",
                        ep.name, ep.value, group, type(exc).__name__, exc)
    return out
