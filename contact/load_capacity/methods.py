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

import logging
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from geometry.core.errors import InputError, ModelUnavailableError, PluginError
from geometry.core.renamed import renamed_keywords

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = ["DEFAULT_METHOD", "METHODS", "RatingMethod", "available_methods",
           "available_rating_methods", "rate", "rate_load_capacity", "register_method",
           "register_rating_method", "unregister_method", "unregister_rating_method"]

log = logging.getLogger(__name__)

#: the method :func:`rate` uses when none is named (``ltca rate``'s default)
DEFAULT_METHOD = "iso10300"


@dataclass(frozen=True)
class RatingMethod:
    """One load-capacity rating method of the registry.

    Attributes
    ----------
    name : str
        The registry name (``ltca rate --method NAME``), lower case.
    function : callable
        ``function(case, torque, speed, *, flank=None, datasets=None, **options) ->
        xarray.Dataset``: ``case`` a :class:`geometry.case.Case`, ``torque`` the pinion
        torques [N·m] (1-D float array), ``speed`` the pinion speed [rpm] (float > 0),
        ``flank`` the pinion flank the analysis loads (None: the case's drive flank),
        ``datasets`` the analysis' groups by path (``{"/ltca": …, "/friction": …}``, empty
        without an analysis); ``options`` the method's own keywords. It returns the
        ``/rating`` dataset (every variable with ``units`` and ``long_name``) and raises
        :class:`geometry.core.errors.InputError` naming a bad input.
    title : str
        What the method is, one line (the standard and its method).
    source : str
        The standard (edition) and the worked example it is checked against.
    tables : callable, optional
        ``tables(dataset) -> str``: the rating as text in the standard's layout, what
        ``ltca rate`` prints; None: one line per variable
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
    """

    name: str
    function: Callable[..., xr.Dataset]
    title: str
    source: str
    tables: Callable[[xr.Dataset], str] | None = None
    missing: Callable[[Any], str] | None = None
    nominal: bool = False


def _iso10300() -> RatingMethod:
    from contact.load_capacity.iso10300.method import missing_tables, tables
    from contact.load_capacity.iso10300.method import rate as iso10300_rate

    return RatingMethod(
        "iso10300", iso10300_rate,
        "ISO 10300-1/-2/-3:2014 Method B1 (pitting and tooth root strength of bevel and "
        "hypoid gears)",
        "ISO 10300-1/-2/-3:2014; checked against ISO/TR 10300-30:2024 samples 1-3 "
        "(tests/test_rating_iso10300.py)", tables, missing_tables, nominal=True)


def _agma2003() -> RatingMethod:
    from contact.load_capacity.agma2003.method import missing, tables
    from contact.load_capacity.agma2003.method import rate as agma2003_rate

    return RatingMethod(
        "agma2003", agma2003_rate,
        "ANSI/AGMA 2003-D19 (pitting resistance and bending strength of generated "
        "straight, Zerol and spiral bevel gear teeth)",
        "ANSI/AGMA 2003-D19 clauses 5-21 (SI equations); checked against its Annex E "
        "worked example (tests/test_rating_agma2003.py)", tables, missing, nominal=True)


#: name → :class:`RatingMethod`: every method that imported (one module each, imported
#: under try/except as qpsolvers' backends, so a method whose module fails to import is
#: absent with a warning in the log instead of breaking the package)
METHODS: dict[str, RatingMethod] = {}
for _entry in (_iso10300, _agma2003):
    try:
        _method = _entry()
    except ImportError as _exc:  # pragma: no cover - the bundled methods import
        log.warning("load-capacity method %s unavailable: %s", _entry.__name__, _exc)
    else:
        METHODS[_method.name] = _method


def available_methods() -> list[str]:
    """The names of the registered load-capacity rating methods, sorted.

    Returns
    -------
    list of str
        Names :func:`rate` and ``ltca rate --method`` accept (``"iso10300"`` …).
    """
    return sorted(METHODS)


def register_method(name: str, function: Callable[..., xr.Dataset], *, title: str,
                    source: str, tables: Callable[[xr.Dataset], str] | None = None,
                    missing: Callable[[Any], str] | None = None,
                    nominal: bool = False, replace: bool = False) -> RatingMethod:
    """Add a rating method to the registry (a plug-in's; the bundled ones are entries of
    :data:`METHODS`).

    Parameters
    ----------
    name : str
        Registry name: lower-case letters, digits and underscores, starting with a letter.
    function : callable
        The method, of the protocol of :attr:`RatingMethod.function`.
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

    Returns
    -------
    RatingMethod
        The registered entry.

    Raises
    ------
    PluginError
        A bad name, a function that is not callable, empty title or source, or a name
        already registered without ``replace``.
    """
    if not (isinstance(name, str) and name[:1].isalpha() and name == name.lower()
            and name.replace("_", "").isalnum()):
        raise PluginError(f"name: a method name is lower-case letters, digits and "
                          f"underscores starting with a letter, got {name!r}")
    if not callable(function):
        raise PluginError(f"function: must be callable, got {function!r}")
    if not (isinstance(title, str) and title.strip() and isinstance(source, str)
            and source.strip()):
        raise PluginError("title, source: a method states what it is and what it is "
                          "checked against (non-empty text)")
    if name in METHODS and not replace:
        raise PluginError(f"name: the load-capacity method {name!r} is registered already "
                          "(replace=True replaces it)")
    if tables is not None and not callable(tables):
        raise PluginError(f"tables: must be callable or None, got {tables!r}")
    if missing is not None and not callable(missing):
        raise PluginError(f"missing: must be callable or None, got {missing!r}")
    METHODS[name] = RatingMethod(name, function, title, source, tables, missing,
                                 bool(nominal))
    return METHODS[name]


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
    del METHODS[name]


def _method(name: str) -> RatingMethod:
    """The registered method ``name``, or ModelUnavailableError listing the available."""
    if not isinstance(name, str) or name not in METHODS:
        raise ModelUnavailableError(
            f"method: unknown load-capacity rating method {name!r}; available: "
            f"{', '.join(available_methods()) or 'none'} (contact.load_capacity."
            "register_method adds one; docs/extending.md)")
    return METHODS[name]


@renamed_keywords(speed="pinion_speed")
def rate(case: Case | str | os.PathLike[str] | None, torque: Any = None,
         pinion_speed: float | None = None, *, method: str = DEFAULT_METHOD,
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
    method : str
        A name of :func:`available_methods` (default :data:`DEFAULT_METHOD`).
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
        The method's ``/rating`` dataset, with the attributes ``rating_method`` (the
        registry name) and ``rating_method_title``.

    Raises
    ------
    ModelUnavailableError
        ``method`` is not registered (the message lists the available ones).
    InputError
        A bad case, torque, speed, flank or option (named), or a method that returned
        something other than a Dataset.

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

    entry = _method(method)
    c = resolve_case(case)
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
    out = entry.function(c, np.atleast_1d(np.asarray(torque, float)), float(pinion_speed),
                         flank=flank, datasets=datasets, **options)
    if not isinstance(out, xr.Dataset):
        raise InputError(f"method: {entry.name} returned {type(out).__name__}, not an "
                         "xarray.Dataset (the /rating group)")
    return out.assign_attrs(rating_method=entry.name, rating_method_title=entry.title)


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
