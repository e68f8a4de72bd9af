"""The registry of load-capacity rating methods (after qpsolvers' solver registry).

A rating method rates a gear pair by a standard: from the case (its ``[design]`` basic data
and ``[rating]`` table), the pinion torques and speed — and, where the method uses them,
the analysis' datasets (``/ltca``, ``/friction`` …) — it returns one labelled
``xarray.Dataset``, the ``/rating`` group of an analysis. :data:`METHODS` maps each name to
its :class:`RatingMethod`; :func:`available_methods` lists them; :func:`rate` is the one
entry point and stamps the dataset's ``rating_method`` attribute with the name that made
it. An unknown name is refused with the list of available ones.

The methods
-----------
``iso10300``
    ISO 10300-1/-2/-3:2014 Method B1 (:func:`contact.load_capacity.iso10300.method.rate`),
    checked against ISO/TR 10300-30:2024's three worked samples.
``agma2003``
    ANSI/AGMA 2003-D19 (:func:`contact.load_capacity.agma2003.method.rate`), straight,
    Zerol and spiral bevel gears without offset, checked against the standard's Annex E.

Adding a method is one module with a function of the protocol of
:class:`RatingMethod` and one entry in :data:`METHODS` (or :func:`register_method` from
outside the toolkit): docs/extending.md, "A load-capacity rating method".
"""

from __future__ import annotations

import dataclasses
import logging
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from geometry.core.errors import InputError, ModelUnavailableError, PluginError, UnknownNameError
from geometry.core.registries import Registry, callable_name
from geometry.core.renamed import renamed_keywords

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = ["COMPANIONS", "DEFAULT_METHOD", "ENTRY_POINT_GROUP", "METHODS", "RatingMethod",
           "available_methods", "available_rating_methods", "case_method", "rate",
           "rate_load_capacity", "register_method", "register_rating_method", "unregister_method",
           "unregister_rating_method"]

log = logging.getLogger(__name__)

#: the method :func:`rate` uses when none is named (``ltca rate``'s default)
DEFAULT_METHOD = "iso10300"

#: the results a method may ask the analysis chain to compute beside its rating
#: (:attr:`RatingMethod.companions`): ``"flash_temperature"``, ISO/TS 6336-20's flash
#: temperature method on the virtual cylindrical gears of an ISO 10300 ``/rating``
#: (``/rating/flash_temperature``)
COMPANIONS = ("flash_temperature",)


@dataclass(frozen=True)
class RatingMethod:
    """One load-capacity rating method of the registry.

    Attributes
    ----------
    name : str
        The registry name (``ltca rate --method NAME``, ``ltca run --rating-method NAME``),
        lower case.
    function : callable
        ``function(case, torque, speed, *, flank=None, datasets=None, **options) ->
        xarray.Dataset``: ``case`` a :class:`geometry.case.Case`, ``torque`` the pinion
        torques [N·m] (1-D float array), ``speed`` the pinion speed [rpm] (float > 0),
        ``flank`` the pinion flank the analysis loads (None: the case's drive flank),
        ``datasets`` the analysis' groups by path (``{"/ltca": …, "/friction": …}``, empty
        without an analysis); ``options`` the method's own keywords. It returns the
        ``/rating`` dataset (every variable with ``units`` and ``long_name``) holding the
        result contract (:mod:`contact.load_capacity.contract`: ``pitting_safety``,
        ``pitting_safety_min``, ``bending_safety``, ``bending_safety_min`` over torque and
        member) and raises :class:`geometry.core.errors.InputError` naming a bad input.
    title : str
        What the method is, one line (the standard and its method).
    source : str
        The standard (edition) and the worked example it is checked against.
    tables : callable, optional
        ``tables(dataset) -> str``: the rating as text in the standard's layout, what
        ``ltca rate`` prints, every factor it uses; None: one line per variable
        (:func:`contact.commands.rate.variable_lines`).
    missing : callable, optional
        ``missing(case) -> str``: why the method cannot rate this case although nothing in
        it is wrong (a table the method needs is absent), or ``""``. An analysis then
        records the reason and goes on without ``/rating`` (the analysis chain's
        load-capacity step), where :func:`rate` itself would refuse the case. None: every
        case can be rated.
    nominal : bool
        True: the method rates the nominal geometry from the case's tables alone (it reads
        no analysis dataset), so the analysis chain rates it before any work and a bad
        table is refused before the contact analysis, not after it (ISO 10300 Method B1,
        ANSI/AGMA 2003). False (default, a plug-in's unless it says so): rated in its step,
        after the analysis whose datasets it may read.
    standard : str
        The standard the findings name (``"ISO 10300"``); default the title.
    worked_example : str
        The worked example the method is checked against; default the source.
    companions : tuple of str
        Results the analysis chain computes beside this rating from it (names of
        :data:`COMPANIONS`: ``"flash_temperature"``, ISO/TS 6336-20's flash temperature
        method on ISO 10300's virtual cylindrical gears, ``/rating/flash_temperature``,
        :func:`contact.chain.scuffing_flash_temperature`); default none.
    """

    name: str
    function: Callable[..., xr.Dataset]
    title: str
    source: str
    tables: Callable[[xr.Dataset], str] | None = None
    missing: Callable[[Any], str] | None = None
    nominal: bool = False
    standard: str = ""
    worked_example: str = ""
    companions: tuple[str, ...] = ()


def _iso10300() -> RatingMethod:
    from contact.load_capacity.iso10300.method import missing_tables, tables
    from contact.load_capacity.iso10300.method import rate as iso10300_rate

    return RatingMethod(
        "iso10300", iso10300_rate,
        "ISO 10300-1/-2/-3:2014 Method B1 (pitting and tooth root strength of bevel and "
        "hypoid gears)",
        "ISO 10300-1/-2/-3:2014; checked against ISO/TR 10300-30:2024 samples 1-3 "
        "(tests/test_rating_iso10300.py)", tables, missing_tables, nominal=True,
        standard="ISO 10300", worked_example="ISO/TR 10300-30:2024 samples 1-3",
        companions=("flash_temperature",))


def _agma2003() -> RatingMethod:
    from contact.load_capacity.agma2003.method import missing, tables
    from contact.load_capacity.agma2003.method import rate as agma2003_rate

    return RatingMethod(
        "agma2003", agma2003_rate,
        "ANSI/AGMA 2003-D19 (pitting resistance and bending strength of generated "
        "straight, Zerol and spiral bevel gear teeth)",
        "ANSI/AGMA 2003-D19 clauses 5-21 (SI equations); checked against its Annex E "
        "worked example (tests/test_rating_agma2003.py)", tables, missing, nominal=True,
        standard="ANSI/AGMA 2003-D19", worked_example="ANSI/AGMA 2003-D19 Annex E")


#: the entry-point group in which an installed distribution advertises rating methods: each
#: entry a :class:`RatingMethod` or a rating function (registered under the entry's name,
#: ``title`` and ``source`` its docstring's first line), e.g. in its ``pyproject.toml``::
#:
#:     [project.entry-points."hypoid_ltca.rating_methods"]
#:     my_method = "my_package.rating:rate"
ENTRY_POINT_GROUP = "hypoid_ltca.rating_methods"


def _adapt(name: str, obj: Any) -> RatingMethod:
    """An entry-point object as a :class:`RatingMethod` (a function is wrapped)."""
    if isinstance(obj, RatingMethod):
        return obj if obj.name == name else dataclasses.replace(obj, name=name)
    if not callable(obj):
        raise InputError(f"function: must be callable, got {obj!r}")
    doc = (getattr(obj, "__doc__", None) or "").strip().splitlines()
    line = doc[0] if doc else f"plug-in rating method {name}"
    return _entry(name, obj, title=line, source=line)


#: name → :class:`RatingMethod`: the bundled methods (one module each, imported under
#: try/except as qpsolvers' backends, so a method whose module fails to import is absent
#: with a warning in the log instead of breaking the package), the plug-ins' of
#: :data:`ENTRY_POINT_GROUP`, and those of :func:`register_method`
#: (:class:`geometry.core.registries.Registry`, a read-only mapping)
METHODS: Registry[RatingMethod] = Registry(
    "load-capacity rating method", ENTRY_POINT_GROUP, (_iso10300, _agma2003),
    name_of=lambda m: m.name, adapt=_adapt,
    hint="contact.load_capacity.register_method or the entry-point group "
         f"{ENTRY_POINT_GROUP} adds one; docs/extending.md")


def available_methods() -> list[str]:
    """The names of the registered load-capacity rating methods, sorted.

    Returns
    -------
    list of str
        Names :func:`rate` and ``ltca rate --method`` accept (``"iso10300"`` …): the
        bundled ones, the plug-ins' (:data:`ENTRY_POINT_GROUP`) and the registered ones.
    """
    return sorted(METHODS)


def _entry(name: str, function: Callable[..., xr.Dataset], *, title: str, source: str,
           tables: Callable[[xr.Dataset], str] | None = None,
           missing: Callable[[Any], str] | None = None, nominal: bool = False,
           standard: str | None = None, worked_example: str | None = None,
           companions: tuple[str, ...] = ()) -> RatingMethod:
    """A checked :class:`RatingMethod` (the rules of :func:`register_method`)."""
    if not (isinstance(name, str) and name[:1].isalpha() and name == name.lower()
            and name.replace("_", "").isalnum()):
        raise PluginError(f"name: a method name is lower-case letters, digits and "
                          f"underscores starting with a letter, got {name!r}")
    if not callable(function):
        raise PluginError(f"function: must be callable, got {function!r}")
    _check_signature(name, function)
    if not (isinstance(title, str) and title.strip() and isinstance(source, str)
            and source.strip()):
        raise PluginError("title, source: a method states what it is and what it is "
                          "checked against (non-empty text)")
    for field, text in (("standard", standard), ("worked_example", worked_example)):
        if text is not None and not (isinstance(text, str) and text.strip()):
            raise PluginError(f"{field}: must be non-empty text naming the "
                              f"{field.replace('_', ' ')}, got {text!r}")
    if tables is not None and not callable(tables):
        raise PluginError(f"tables: must be callable or None, got {tables!r}")
    if missing is not None and not callable(missing):
        raise PluginError(f"missing: must be callable or None, got {missing!r}")
    companions = tuple(companions)
    unknown = [c for c in companions if c not in COMPANIONS]
    if unknown:
        raise PluginError(f"companions: unknown companion result {unknown[0]!r} of method "
                          f"{name!r}; available: {', '.join(COMPANIONS)}")
    return RatingMethod(name, function, title, source, tables, missing, bool(nominal),
                        standard or title, worked_example or source, companions)


#: the keywords :func:`rate` passes a method besides the caller's options
CALL_KEYWORDS = ("flank", "datasets")


def _check_signature(name: str, function: Callable[..., Any]) -> None:
    """Refuse a method function :func:`rate` cannot call: it takes ``(case, torque, speed)``
    by position and ``flank``, ``datasets`` by keyword (:attr:`RatingMethod.function`),
    checked when it is registered rather than deep in the first rating (issue 71, branch
    api82: ``lambda: …`` was registered and failed at its first use). A callable whose
    signature cannot be read (a builtin) is let through: its first call says it."""
    import inspect

    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        return
    try:
        signature.bind(None, None, None, **dict.fromkeys(CALL_KEYWORDS))
    except TypeError as exc:
        raise PluginError(f"function: {callable_name(function)}{signature} of method "
                          f"{name!r} cannot be called as function(case, torque, speed, *, "
                          f"flank=None, datasets=None, **options) ({exc})") from None


def register_method(name: str, function: Callable[..., xr.Dataset], *, title: str,
                    source: str, tables: Callable[[xr.Dataset], str] | None = None,
                    missing: Callable[[Any], str] | None = None,
                    nominal: bool = False, replace: bool = False,
                    standard: str | None = None, worked_example: str | None = None,
                    companions: tuple[str, ...] = ()) -> RatingMethod:
    """Add a rating method to the registry for the running process (a plug-in's; the
    bundled ones are entries of :data:`METHODS`, an installed distribution's come from the
    entry-point group :data:`ENTRY_POINT_GROUP`).

    Parameters
    ----------
    name : str
        Registry name: lower-case letters, digits and underscores, starting with a letter.
    function : callable
        The method, of the protocol of :attr:`RatingMethod.function`; its result must hold
        the result contract (:mod:`contact.load_capacity.contract`), checked at each call.
    title, source : str
        One line on what the method is, and the standard and worked example it is checked
        against (non-empty).
    tables : callable, optional
        The rating as text for ``ltca rate`` (:attr:`RatingMethod.tables`).
    missing : callable, optional
        Why a case cannot be rated although nothing in it is wrong, or ``""``
        (:attr:`RatingMethod.missing`).
    nominal : bool
        The method reads no analysis dataset, so the analysis chain rates it before any
        work (:attr:`RatingMethod.nominal`; default False).
    replace : bool
        Allow replacing a registered method of the same name (default False).
    standard, worked_example : str, optional
        The standard the findings name and the worked example (default the title and the
        source).
    companions : tuple of str
        Results the analysis chain computes beside the rating (:attr:`RatingMethod.
        companions`).

    Returns
    -------
    RatingMethod
        The registered entry.

    Raises
    ------
    PluginError
        A bad name, a function that is not callable or of another signature than
        ``function(case, torque, speed, *, flank=None, datasets=None, **options)``, empty
        title or source, an unknown companion, or a name already registered without
        ``replace`` (an InputError naming the field).
    """
    return METHODS.register(_entry(name, function, title=title, source=source,
                                   tables=tables, missing=missing, nominal=nominal,
                                   standard=standard, worked_example=worked_example,
                                   companions=companions), replace=replace)


def unregister_method(name: str) -> None:
    """Remove a rating method from the registry (a plug-in's, e.g. at a test's end).

    Parameters
    ----------
    name : str
        A registered name.

    Raises
    ------
    ModelUnavailableError
        ``name`` is not registered (the message lists those that are).
    """
    _method(name)
    METHODS.unregister(name)


def _method(name: str) -> RatingMethod:
    """The registered method ``name``, or ModelUnavailableError listing the available."""
    try:
        return METHODS.entry(name)
    except ModelUnavailableError as exc:
        raise UnknownNameError(f"method: {exc}") from None


def case_method(case: Any) -> str | None:
    """The load-capacity rating method a case chooses: its ``[rating] method`` field.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    str or None
        A registered method's name, or None where the case names none.

    Raises
    ------
    ModelUnavailableError
        The case names a method that is not registered (``rating.method: …``, the
        available ones listed).
    """
    table = getattr(case, "extra", {}).get("rating")
    name = table.get("method") if isinstance(table, Mapping) else None
    if name is None:
        return None
    try:
        return METHODS.entry(name).name
    except ModelUnavailableError as exc:
        raise UnknownNameError(f"rating.method: {exc}") from None


@renamed_keywords(speed="pinion_speed")
def rate(case: Case | str | os.PathLike[str] | None, torque: Any = None,
         pinion_speed: float | None = None, *, method: str | None = None,
         flank: str | None = None,
         analysis: xr.DataTree | Mapping[str, xr.Dataset] | None = None,
         **options: Any) -> xr.Dataset:
    """Rate a gear pair's load capacity by a registered method: the ``/rating`` dataset.

    Parameters
    ----------
    case : geometry.case.Case, str or path-like
        The case (a Case, a case file or a bundled name,
        :func:`contact.catalogue.resolve_case`), with the tables the method needs
        (ISO 10300: ``[design]`` and ``[rating]``, docs/rating.md).
    torque : array_like, shape (n,) — [N·m], optional
        Pinion torques; default the analysis' (its ``/ltca`` torque coordinate), else the
        case's ``[operating]`` torques.
    pinion_speed : float — [rpm], optional
        Pinion speed (> 0; old name ``speed``, deprecated); default the analysis'
        efficiency stage's
        (``/friction`` attribute ``pinion_speed_rpm``), else the case's ``[operating]
        pinion_speed``.
    method : str, optional
        A name of :func:`available_methods`; default the case's ``[rating] method``
        (:func:`case_method`), else :data:`DEFAULT_METHOD` — as ``ltca rate`` and
        :func:`contact.run_analysis` choose it (issue 71, branch api82: the API rated
        by ISO 10300 a case whose file names another method).
    flank : {"concave", "convex", "drive", "coast"}, optional
        The pinion flank the analysis loads; default the case's drive flank.
    analysis : xarray.DataTree or mapping of str to xarray.Dataset, optional
        The analysis the rating goes with: a DataTree (:func:`contact.run_analysis`, a file
        read back) or its groups by path (``{"/ltca": …, "/friction": …}``); the method
        takes what it uses from it (ISO 10300 Method B1 uses none of it: it rates the
        nominal geometry).
    **options
        The method's own keywords (ISO 10300: ``rating``, a mapping or RatingInputs that
        replaces the case's ``[rating]`` table).

    Returns
    -------
    xarray.Dataset
        The method's ``/rating`` dataset, holding the result contract, with the
        attributes ``rating_method`` (the registry name), ``rating_method_title``,
        ``rating_standard`` and ``rating_worked_example``.

    Raises
    ------
    ModelUnavailableError
        ``method`` is not registered (the message lists the available ones).
    InputError
        A bad case, torque, speed, flank or option (named).
    PluginError
        The method raised (its name and exception said), or its result breaks the result
        contract (:func:`contact.load_capacity.contract.check_result`: the method and the
        variable named).

    Notes
    -----
    The rating is the method's: ``"iso10300"`` is ISO 10300-1/-2/-3:2014 Method B1,
    checked against ISO/TR 10300-30:2024's three worked samples; each method's ``source``
    (:class:`RatingMethod`) names its standard and worked example.

    Examples
    --------
    >>> from contact.load_capacity import available_methods, rate
    >>> "iso10300" in available_methods()
    True
    >>> ds = rate("iso10300_30_sample1", method="iso10300")  # doctest: +SKIP
    >>> ds.attrs["rating_method"]  # doctest: +SKIP
    'iso10300'
    """
    from contact.catalogue import resolve_case
    from contact.load_capacity.contract import check_result

    c = resolve_case(case)
    entry = _method(case_method(c) or DEFAULT_METHOD if method is None else method)
    datasets = _datasets(analysis)
    if torque is None:
        ltca = datasets.get("/ltca")
        torque = (ltca["torque"].values if ltca is not None and "torque" in ltca.coords
                  else c.operating.torque)
    if pinion_speed is None:
        friction = datasets.get("/friction")
        pinion_speed = (float(friction.attrs["pinion_speed_rpm"]) if friction is not None
                        and "pinion_speed_rpm" in friction.attrs else c.operating.pinion_speed)
    if flank is not None and flank not in ("concave", "convex", "drive", "coast"):
        raise InputError(f"flank: must be concave, convex, drive or coast, got {flank!r}")
    log.info("rating %s by %s", c.name, entry.name)
    torques = np.atleast_1d(np.asarray(torque, float))
    try:
        out = entry.function(c, torques, float(pinion_speed), flank=flank,
                             datasets=datasets, **options)
    except InputError:
        raise  # names its field
    except Exception as exc:  # a method's own failure, said with its name
        raise PluginError(f"load-capacity method {entry.name!r} raised {type(exc).__name__}: "
                          f"{exc}") from exc
    check_result(entry.name, out, torques)
    return out.assign_attrs(rating_method=entry.name, rating_method_title=entry.title,
                            rating_standard=entry.standard,
                            rating_worked_example=entry.worked_example)


def _datasets(analysis: Any) -> dict[str, xr.Dataset]:
    """The analysis' groups by absolute path (``"/ltca"``): from a DataTree, a mapping of
    paths (with or without the leading slash) to datasets, or None (none)."""
    if analysis is None:
        return {}
    if isinstance(analysis, xr.DataTree):
        return {node.path: node.to_dataset() for node in analysis.subtree
                if node.path != "/"}
    if isinstance(analysis, Mapping):
        out = {}
        for key, value in analysis.items():
            if not isinstance(value, xr.Dataset):
                raise InputError(f"analysis: the group {key!r} must be an xarray.Dataset, "
                                 f"got {type(value).__name__}")
            out["/" + str(key).lstrip("/")] = value
        return out
    raise InputError("analysis: must be an xarray.DataTree, a mapping of group paths to "
                     f"datasets or None, got {type(analysis).__name__}")


# the names :mod:`contact` exports at its top (``contact.rate_load_capacity`` …), where
# ``rate`` alone would not say what is rated
rate_load_capacity = rate
available_rating_methods = available_methods
register_rating_method = register_method
unregister_rating_method = unregister_method
