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
Registry              a registry of named entries: bundled, a plug-in's (entry points), a
                      user's (registered in the process), refused by one rule

:class:`Registry` is the shared class (issue 72): the load-capacity rating methods
(:data:`contact.load_capacity.methods.METHODS`, group ``hypoid_ltca.rating_methods``) are
kept on it; the solver, friction-model and compliance-model registries keep their own
dictionaries with the helpers above (the same three layers: bundled, plug-ins, the user's),
to be moved onto it without changing their public functions.
"""

from __future__ import annotations

import inspect
import logging
from collections.abc import Callable, Iterator, Mapping
from importlib import metadata
from typing import Any, Generic, TypeVar

from geometry.core.caches import memoised
from geometry.core.errors import InputError, PluginError, UnknownNameError

__all__ = ["Registry", "callable_name", "check_model_name", "entry_point_objects",
           "keyword_parameters"]

T = TypeVar("T")

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


@memoised(maxsize=None)
def _group_objects(group: str) -> dict[str, Any]:
    """The entry-point objects of ``group``, found once per process
    (:func:`geometry.core.caches.clear_caches` forgets them, so that a package installed
    meanwhile is seen)."""
    return entry_point_objects(group)


class Registry(Mapping[str, T], Generic[T]):
    """Named entries of one kind — bundled, advertised by installed distributions in an
    entry-point group, registered in the process — read as one mapping (name → entry).

    Parameters
    ----------
    kind : str
        What an entry is, for messages (``"load-capacity rating method"``).
    group : str
        The entry-point group plug-ins advertise entries in (``"hypoid_ltca.rating_methods"``;
        ``[project.entry-points."<group>"]`` in a plug-in's ``pyproject.toml``).
    bundled : iterable of callable
        Each returns one bundled entry (imported when called: one that raises ImportError
        is left out with a warning, as a missing optional backend).
    name_of : callable
        ``name_of(entry) -> str``: the registry name of an entry.
    adapt : callable
        ``adapt(name, obj) -> entry``: an entry-point object as an entry (an entry itself,
        or a function the registry wraps); raises :class:`InputError` for what is none.
    hint : str
        Where the message of an unknown name says entries come from.

    Notes
    -----
    Order: the bundled entries, then the plug-ins' (a plug-in shadowing a bundled name is
    left out with a warning), then the user's (:meth:`register`, which may replace only
    with ``replace=True``). A plug-in that fails to load or adapt is left out with a
    warning (:func:`entry_point_objects`): a broken plug-in must not break the toolkit.
    """

    def __init__(self, kind: str, group: str, bundled: tuple[Callable[[], T], ...],
                 name_of: Callable[[T], str], adapt: Callable[[str, Any], T],
                 hint: str = "") -> None:
        self.kind, self.group, self.hint = kind, group, hint
        self._name_of, self._adapt = name_of, adapt
        self._bundled: dict[str, T] = {}
        for make in bundled:
            try:
                entry = make()
            except ImportError as exc:  # pragma: no cover - the bundled entries import
                log.warning("%s %s unavailable: %s", kind, getattr(make, "__name__", make),
                            exc)
                continue
            self._bundled[name_of(entry)] = entry
        self._plugins: tuple[object, dict[str, T]] | None = None
        self._user: dict[str, T] = {}
        self._dropped: set[str] = set()

    def plugins(self) -> dict[str, T]:
        """The entries of the installed distributions' entry points (:attr:`group`), found
        once per process (until :func:`geometry.core.caches.clear_caches`)."""
        objects = _group_objects(self.group)
        if self._plugins is None or self._plugins[0] is not objects:
            out: dict[str, T] = {}
            for name, obj in objects.items():
                if name in self._bundled:
                    log.warning("entry point %s of group %s shadows a bundled %s: left out",
                                name, self.group, self.kind)
                    continue
                try:
                    out[name] = self._adapt(name, obj)
                except InputError as exc:
                    log.warning("entry point %s of group %s is not a %s: %s", name,
                                self.group, self.kind, exc)
            self._plugins = (objects, out)
        return {k: v for k, v in self._plugins[1].items() if k not in self._dropped}

    def _all(self) -> dict[str, T]:
        return {**self._bundled, **self.plugins(), **self._user}

    def __getitem__(self, name: str) -> T:
        return self._all()[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._all())

    def __len__(self) -> int:
        return len(self._all())

    def entry(self, name: Any) -> T:
        """The entry ``name``.

        Raises
        ------
        UnknownNameError
            ``name`` is not registered (the message lists the available names; an
            InputError and a ModelUnavailableError).
        """
        entries = self._all()
        if not isinstance(name, str) or name not in entries:
            raise UnknownNameError(
                f"unknown {self.kind} {name!r}; available: "
                f"{', '.join(sorted(entries)) or 'none'}" + (f" ({self.hint})" if self.hint
                                                              else ""))
        return entries[name]

    def register(self, entry: T, *, replace: bool = False) -> T:
        """Add ``entry`` under its name for the running process.

        Raises
        ------
        PluginError
            The name is registered already (bundled, a plug-in's or the user's) and
            ``replace`` is False.
        """
        name = self._name_of(entry)
        if name in self._all() and not replace:
            raise PluginError(f"name: the {self.kind} {name!r} is registered already "
                              "(replace=True replaces it)")
        self._user[name] = entry
        self._dropped.discard(name)
        return entry

    def unregister(self, name: str) -> None:
        """Remove the entry ``name`` (a user's, a plug-in's or a bundled one) from the
        running process.

        Raises
        ------
        UnknownNameError
            ``name`` is not registered (listed as :meth:`entry`).
        """
        self.entry(name)
        self._user.pop(name, None)
        self._bundled.pop(name, None)
        if name in self.plugins():
            self._dropped.add(name)
