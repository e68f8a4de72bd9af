"""The contract of a chain step, checked where a step is given and after it runs (issue 72
item 4): a misused extension point is refused in one sentence naming the step, never a
traceback from inside :mod:`contact.chain` or :mod:`contact.pipeline`.

A step of :class:`contact.AnalysisChain` is a callable ``f(state)`` of one positional
argument, the :class:`contact.chain.ChainState`, that adds its group(s) to
``state.groups`` and returns None (docs/extending.md, "A step of the analysis chain").
Checked:

* **when it is given** (:func:`check_step_callable`): it must be callable with one
  positional argument — ``lambda: …``, ``def f(state, extra)`` (no default) or a class
  are refused with the signature they have;
* **after it runs** (:func:`check_step_output`): it returned None (a step that returns
  its dataset instead of storing it would lose it silently); ``state.groups`` is still a
  dict whose keys are paths (``"/name"``) and whose values are ``xarray.Dataset``; the
  groups the later steps read exist: ``/easeoff`` and ``/utca`` after the ``utca`` step,
  ``/ltca`` (with its ``torque`` dimension) from the ``ltca`` step on — a step that deletes
  ``/ltca`` is named, not the ``KeyError`` of the step after it; a ``/friction`` group
  holds ``efficiency_mean`` over ``torque`` (as ``/ltca``), finite, 0 < η <= 1
  (:func:`check_efficiency`; issue 71: a NaN printed as a blank, a per-roll array
  printed as its first value); where the load-capacity step runs after it, the
  ``/friction`` variables and attributes that step reads (:data:`LOAD_CAPACITY_READS`:
  μ, the speeds, the film) present, over the LTCA's dims, finite and in range on the
  loaded segments (:func:`check_load_capacity_inputs`; issue 71, notchecked83);
* **when it raises** (:func:`run_step`): a user's step's exception is re-raised as a
  :class:`geometry.core.errors.PluginError` naming the step and the callable, the original
  chained as its cause (``raise … from exc``); the built-in steps' own errors pass
  unchanged (they name their field already).

Public names
------------
check_step_callable  refuse a step callable that cannot take the state
check_step_output    refuse what a step left in the state
check_efficiency     refuse a /friction group without a printable efficiency_mean
check_load_capacity_inputs  refuse a /friction group the load-capacity step cannot read
LOAD_CAPACITY_READS  the /friction variables the load-capacity step reads, with their bounds
run_step             run one step, its misuse and its exceptions said with its name
READS                the groups each built-in step reads
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import xarray as xr

from geometry.core.errors import PluginError

__all__ = ["LOAD_CAPACITY_READS", "READS", "check_efficiency", "check_load_capacity_inputs",
           "check_step_callable", "check_step_output", "run_step"]

#: the groups each step leaves for the steps after it (a step's output is checked for
#: those of its own and of every earlier step; the ``ltca`` step's ``/ltca`` is read by
#: every later built-in step and by :func:`contact.run_analysis` itself)
MAKES: Mapping[str, tuple[str, ...]] = {
    "utca": ("/easeoff", "/utca"),
    "ltca": ("/ltca",),
}

#: the groups each built-in step reads (contact/chain.py)
READS: Mapping[str, tuple[str, ...]] = {
    "ltca": (),
    "root_stress": ("/ltca",),
    "mesh_interface": ("/ltca",),
    "efficiency": ("/ltca",),
    "load_capacity": ("/ltca",),
    "lte_range": ("/ltca",),
}


def _name(f: Any) -> str:
    return str(getattr(f, "__qualname__", None) or getattr(f, "__name__", None)
               or type(f).__name__)


def check_step_callable(step: str, f: Callable[..., Any]) -> None:
    """Refuse a step callable that cannot be called as ``f(state)``.

    Parameters
    ----------
    step : str
        The step it is given for (:data:`contact.chain.STEP_ORDER`).
    f : callable
        The user's callable.

    Raises
    ------
    InputError (PluginError)
        ``f`` is a class (a step is a function of the state, not a type), or its
        signature does not accept exactly one positional argument (the message gives the
        signature it has). A callable whose signature Python cannot inspect (some
        built-ins) is accepted and checked when it runs.
    """
    name = _name(f)
    if inspect.isclass(f):
        raise PluginError(f"steps.{step}: {name} is a class; a step is a callable f(state) "
                          "of the contact.chain.ChainState that adds its groups to "
                          "state.groups (docs/extending.md)")
    try:
        sig = inspect.signature(f)
    except (TypeError, ValueError):
        return
    try:
        sig.bind(object())
    except TypeError:
        raise PluginError(f"steps.{step}: the callable {name}{sig} cannot be called as "
                          "f(state): a step takes one argument, the contact.chain.ChainState "
                          "(docs/extending.md)") from None


def check_step_output(step: str, f: Callable[..., Any], state: Any, returned: Any,
                      order: tuple[str, ...]) -> None:
    """Refuse what step ``step`` left in ``state`` where the steps after it could not read
    it, naming the step.

    Parameters
    ----------
    step : str
        The step that just ran.
    f : callable
        Its callable (named in the message).
    state : contact.chain.ChainState
        The state after it.
    returned : object
        What it returned (must be None).
    order : tuple of str
        The steps in the order they run (:data:`contact.chain.STEP_ORDER`, the skipped
        ones left out or not: a ``"load_capacity"`` after ``step`` means that step will
        read ``/friction``).

    Raises
    ------
    PluginError
        A value returned; ``state.groups`` no dict; a key that is no path ``"/…"``; a value
        that is no ``xarray.Dataset`` (a list, a dict, a DataTree); a group the later steps
        read (:data:`MAKES` of this and every earlier step) missing; ``/ltca`` without its
        ``torque`` dimension; a ``/friction`` group refused by :func:`check_efficiency`,
        or, with ``"load_capacity"`` later in ``order``, by
        :func:`check_load_capacity_inputs`.
    """
    who = f"steps.{step}: the callable {_name(f)}"
    if returned is not None:
        raise PluginError(f"{who} returned {type(returned).__name__}; a step adds its groups "
                          "to state.groups (e.g. state.groups['/name'] = dataset) and returns "
                          "None (docs/extending.md)")
    groups = state.groups
    if not isinstance(groups, dict):
        raise PluginError(f"{who} left state.groups as {type(groups).__name__}; it must stay "
                          "a dict of path to xarray.Dataset")
    for path, ds in groups.items():
        if not (isinstance(path, str) and path.startswith("/")):
            raise PluginError(f"{who} wrote state.groups[{path!r}]: a group's key is its path, "
                              "a str starting with '/' (e.g. '/friction')")
        if not isinstance(ds, xr.Dataset):
            raise PluginError(f"{who} wrote state.groups[{path!r}] as {type(ds).__name__}; a "
                              "group must be an xarray.Dataset")
    done = order[:order.index(step) + 1]
    for earlier in done:
        for path in MAKES.get(earlier, ()):
            if path not in groups:
                made = "it should make" if earlier == step else f"the {earlier} step made"
                raise PluginError(f"{who} left no {path} group ({made} it and the later "
                                  "steps read it)")
    if "ltca" in done and "torque" not in groups["/ltca"].dims:
        raise PluginError(f"{who} left a /ltca group without the dimension 'torque' (the "
                          "later steps and the file read the LTCA per torque)")
    if "/friction" in groups and "/ltca" in groups:
        check_efficiency(who, groups["/friction"], groups["/ltca"].sizes["torque"],
                         uncertified_torques(groups["/ltca"]))
        if "load_capacity" in order[order.index(step) + 1:]:
            check_load_capacity_inputs(who, groups["/friction"], groups["/ltca"])


def uncertified_torques(ltca: xr.Dataset) -> np.ndarray:
    """Per torque of ``ltca``, whether a roll position has no certified contact solution
    (``found`` 0): there the built-in friction step writes a NaN efficiency with its reason
    (never the loss-free 100 %), which :func:`check_efficiency` accepts.

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` group, over ``torque``; without ``found`` every torque counts as
        certified.

    Returns
    -------
    numpy.ndarray of bool, shape (n_torque,)
    """
    from contact.ltca.summary import certification

    if "found" not in ltca.variables:
        return np.zeros(ltca.sizes["torque"], dtype=bool)
    cert = certification(ltca)
    return np.asarray(cert.certified) < cert.rolls


def check_efficiency(who: str, friction: xr.Dataset, n_torque: int,
                     uncertified: np.ndarray | None = None) -> None:
    """Refuse a ``/friction`` group whose ``efficiency_mean`` the report and the summary
    table could not print as the mean mechanical efficiency per torque (issue 71).

    Parameters
    ----------
    who : str
        The step and callable that left it (the message's subject).
    friction : xarray.Dataset
        The ``/friction`` group.
    n_torque : int
        The number of torques of ``/ltca``.
    uncertified : numpy.ndarray of bool, shape (n_torque,), optional
        Torques whose loaded contact has an uncertified roll (:func:`uncertified_torques`):
        a NaN efficiency is accepted there (the analysis failed and says so; issue 71).

    Raises
    ------
    PluginError
        ``efficiency_mean`` [1] missing, not over the one dimension ``torque`` of
        ``n_torque`` values, or a value NaN, infinite or outside 0 < η <= 1 (a mechanical
        efficiency is the output power over the input power, seed Eq. 5.1).
    """
    where = f"{who} left /friction with efficiency_mean"
    if "efficiency_mean" not in friction:
        raise PluginError(f"{who} left /friction without efficiency_mean (the mean mechanical "
                          "efficiency [1] per torque the report and ltca run print; "
                          "docs/extending.md)")
    eff = friction["efficiency_mean"]
    if eff.dims != ("torque",) or eff.size != n_torque:
        raise PluginError(f"{where} over {eff.dims} (shape {eff.shape}); it must be over "
                          f"('torque',) with the /ltca group's {n_torque} torque(s)")
    try:
        values = np.asarray(eff.values, dtype=float)
    except (TypeError, ValueError):
        raise PluginError(f"{where} of dtype {eff.dtype}; it must be numbers [1]") from None
    bad = ~(np.isfinite(values) & (values > 0.0) & (values <= 1.0))
    if uncertified is not None:
        bad &= ~(np.isnan(values) & np.asarray(uncertified, dtype=bool).reshape(values.shape))
    if np.any(bad):
        raise PluginError(f"{where} {float(values[bad][0]):.6g} at {int(np.count_nonzero(bad))} of "
                          f"{values.size} torque(s); accepted a finite 0 < efficiency_mean "
                          "<= 1 [1] (a fraction, not %)")


#: the ``/friction`` variables the load-capacity step reads
#: (:func:`contact.load_capacity.scuffing_micropitting.scuffing_micropitting`: Blok's flash
#: temperature from μ and the flanks' speeds across the line, λ_GF from the film), each
#: with its unit and the closed range a loaded segment's value must lie in: μ within the
#: friction models' bound [0, MU_MAX] (:data:`friction.coefficient.MU_MAX`); the speeds
#: are magnitudes (friction/kinematics.py: ``norm``, ``abs``), so >= 0; the film >= 0.
#: ``slide_to_roll_total`` = abs(V_s)/V_r may be +inf (pure sliding), never NaN or < 0.
LOAD_CAPACITY_READS: Mapping[str, tuple[str, float, float]] = {
    "friction_coefficient": ("1", 0.0, 1.0),
    "sliding_velocity": ("m/s", 0.0, np.inf),
    "rolling_velocity": ("m/s", 0.0, np.inf),
    "slide_to_roll_total": ("1", 0.0, np.inf),
    "film_thickness": ("um", 0.0, np.inf),
    "surface_speed": ("m/s", 0.0, np.inf),
}

#: the ``/friction`` attributes it reads: the oil, its inlet temperature [degC], Rq [µm]
_LOAD_CAPACITY_ATTRS = ("lubricant", "inlet_temperature_degC", "roughness_rq_um")

_SEGMENT_DIMS = ("torque", "roll", "pair", "segment")


def check_load_capacity_inputs(who: str, friction: xr.Dataset, ltca: xr.Dataset) -> None:
    """Refuse a ``/friction`` group whose friction coefficient, speeds or film the
    load-capacity step (scuffing, micropitting, the flash temperature) could not read as
    the efficiency step's, naming the step that left it and the variable (issue 71).

    Parameters
    ----------
    who : str
        The step and callable that left it (the message's subject).
    friction : xarray.Dataset
        The ``/friction`` group.
    ltca : xarray.Dataset
        The ``/ltca`` group: its ``force`` [N] over (torque, roll, pair, segment) gives the
        loaded segments (finite and > 0) and the shape; without ``force`` the dims alone
        are checked against its ``torque`` and the values that are not NaN.

    Raises
    ------
    PluginError
        A variable of :data:`LOAD_CAPACITY_READS` missing; not over (``torque``, ``roll``,
        ``pair``, ``segment``) (``surface_speed``: with ``member`` of 2 first) of the
        LTCA's shape; on a loaded segment NaN, or infinite (but ``slide_to_roll_total``),
        or outside its range (μ in [0, ``friction.coefficient.MU_MAX``] = [0, 1]; speeds,
        film, slide-to-roll >= 0); an attribute ``lubricant``, ``inlet_temperature_degC``
        [degC] or ``roughness_rq_um`` [µm] missing, the last two not finite or Rq <= 0.

    Notes
    -----
    Source: the inputs of ISO/TS 6336-20 (Blok's flash temperature: μ, the flanks' speeds)
    and ISO/TS 6336-22 (λ_GF: the film) as
    :mod:`contact.load_capacity.scuffing_micropitting` reads them; μ's bound is
    :data:`friction.coefficient.MU_MAX`'s (issue 71, plugin83).
    """
    from friction.coefficient import MU_MAX

    reader = "the load-capacity step reads it"
    force = ltca["force"] if "force" in ltca else None
    shape = (None if force is None or force.dims != _SEGMENT_DIMS
             else tuple(force.shape))
    loaded = (None if shape is None
              else np.isfinite(force.values) & (force.values > 0.0))
    for name, (unit, low, high) in LOAD_CAPACITY_READS.items():
        high = MU_MAX if name == "friction_coefficient" else high
        where = f"{who} left /friction with {name}"
        if name not in friction:
            raise PluginError(f"{who} left /friction without {name} [{unit}] ({reader}; "
                              "docs/extending.md)")
        var = friction[name]
        dims = ("member", *_SEGMENT_DIMS) if name == "surface_speed" else _SEGMENT_DIMS
        want = None if shape is None else ((2, *shape) if name == "surface_speed" else shape)
        if var.dims != dims or (want is not None and tuple(var.shape) != want) or (
                want is None and var.sizes["torque"] != ltca.sizes.get("torque", -1)):
            raise PluginError(f"{where} over {var.dims} (shape {var.shape}); {reader} over "
                              f"{dims}" + (f" of shape {want}, the /ltca force's"
                                           if want is not None else " with /ltca's torques"))
        try:
            values = np.asarray(var.values, dtype=float)
        except (TypeError, ValueError):
            raise PluginError(f"{where} of dtype {var.dtype}; {reader} as numbers "
                              f"[{unit}]") from None
        if loaded is None:
            on = values[~np.isnan(values)]
        else:
            on = values[:, loaded] if name == "surface_speed" else values[loaded]
        ok = ~np.isnan(on) & (on >= low) & (on <= high)
        if name != "slide_to_roll_total":
            ok &= np.isfinite(on)
        if not np.all(ok):
            bad = on[~ok]
            raise PluginError(
                f"{where} {float(bad[0]):.6g} [{unit}] at {bad.size} of {on.size} loaded "
                f"value(s); {reader}: accepted a finite {low:g} <= {name} <= {high:g}"
                if np.isfinite(high) else
                f"{where} {float(bad[0]):.6g} [{unit}] at {bad.size} of {on.size} loaded "
                f"value(s); {reader}: accepted {name} >= {low:g}"
                + ("" if name == "slide_to_roll_total" else ", finite")
                + " (a magnitude)")
    for attr in _LOAD_CAPACITY_ATTRS:
        if attr not in friction.attrs:
            raise PluginError(f"{who} left /friction without the attribute {attr} ({reader}: "
                              "the oil, its inlet temperature [degC], the roughness Rq [um])")
    try:
        temp = float(friction.attrs["inlet_temperature_degC"])
        rq = float(friction.attrs["roughness_rq_um"])
    except (TypeError, ValueError):
        raise PluginError(f"{who} left /friction with inlet_temperature_degC "
                          f"{friction.attrs['inlet_temperature_degC']!r} and roughness_rq_um "
                          f"{friction.attrs['roughness_rq_um']!r}; {reader}: numbers") from None
    if not (np.isfinite(temp) and np.isfinite(rq) and rq > 0.0):
        raise PluginError(f"{who} left /friction with inlet_temperature_degC {temp:g} and "
                          f"roughness_rq_um {rq:g}; {reader}: a finite temperature [degC] and "
                          "a finite Rq > 0 [um]")


def run_step(step: str, f: Callable[..., Any], state: Any, *, builtin: bool,
             order: tuple[str, ...]) -> None:
    """Run one step on ``state`` and check what it left (:func:`check_step_output`).

    Parameters
    ----------
    step : str
        The step's name.
    f : callable
        Its callable.
    state : contact.chain.ChainState
    builtin : bool
        A built-in step (contact/chain.py or a registered method): its exceptions pass
        unchanged; a user's are wrapped.
    order : tuple of str
        :data:`contact.chain.STEP_ORDER`.

    Raises
    ------
    PluginError
        A user's step raised (the message names the step, the callable, the exception's
        type and text; the exception is chained as ``__cause__``), or left the state where
        the later steps cannot read it.
    """
    if builtin:
        returned = f(state)
    else:
        try:
            returned = f(state)
        except Exception as exc:
            first = str(exc).splitlines()[0] if str(exc) else ""
            raise PluginError(f"steps.{step}: the callable {_name(f)} raised "
                              f"{type(exc).__name__}" + (f": {first}" if first else "")) from exc
    check_step_output(step, f, state, returned, order)
