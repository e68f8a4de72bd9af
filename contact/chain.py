"""The analysis chain: the named steps :func:`contact.run_analysis` runs, after pvlib's
``ModelChain``.

One analysis of a case is a fixed sequence of steps (:data:`STEP_ORDER`)::

    geometry → utca → ltca → root_stress → mesh_interface → efficiency → load_capacity
             → lte_range

Each step is chosen by name from :data:`STEPS` (its implementations), given as a callable of
the user's, or — the optional ones, all but ``utca`` and ``ltca`` — skipped with ``None``.
:class:`AnalysisChain` holds one choice per step; its defaults are the one set of defaults
of the toolkit, the steps ``ltca run`` runs (so ``contact.run_analysis(case)`` and
``ltca run case`` write the same groups and variables)::

    from contact import AnalysisChain, run_analysis

    # the contact alone (a study's hot loop): no root stress, mesh interface, efficiency
    # or load capacity
    tree = run_analysis(None, [250.0], steps={"root_stress": None, "mesh_interface": None,
                                              "efficiency": None, "load_capacity": None})

A step is a function of one argument, the :class:`ChainState` of the analysis: it reads
what the earlier steps left there (the case as run, the torques, the ease-off, the groups
so far) and adds its group(s) to ``state.groups`` (paths such as ``"/ltca"``) — the same
contract for the built-in steps and a user's.

The step that writes ``/rating`` (load capacity) is chosen by the name of a method of the
load-capacity registry (:func:`contact.load_capacity.available_methods`: ``"iso10300"`` by
default, a plug-in's by its name) and rates through :func:`contact.load_capacity.rate`;
``"scuffing_micropitting"`` writes ``/scuffing_micropitting`` without a rating.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import os
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import xarray as xr

from contact.utca.conjugate_map import flank_nodes
from geometry.case import Case
from geometry.core.caches import Carried, Same, memoised
from geometry.core.conventions import assigned
from geometry.core.errors import InputError, LTCAError, ModelUnavailableError
from geometry.machine.flank import DEFAULT_GRID, flank_dataset

__all__ = [
    "OPTIONAL_STEPS",
    "STEPS",
    "STEP_ORDER",
    "AnalysisChain",
    "ChainState",
    "available_steps",
    "geometry_datasets",
    "resolve_chain",
    "scuffing_flash_temperature",
]

log = logging.getLogger(__name__)

#: the steps of one analysis, in the order they run
STEP_ORDER = ("geometry", "utca", "ltca", "root_stress", "mesh_interface", "efficiency",
              "load_capacity", "lte_range")
#: the steps that may be skipped (``None``); ``utca`` and ``ltca`` make the analysis
OPTIONAL_STEPS = ("geometry", "root_stress", "mesh_interface", "efficiency", "load_capacity",
                  "lte_range")

#: a step: a name of :data:`STEPS`, a callable ``f(state: ChainState) -> None`` or None
StepChoice = str | Callable[["ChainState"], None] | None


@dataclass
class ChainState:
    """What the steps of one analysis share: the inputs as run and the results so far.

    A step (built-in or a user's callable) reads the attributes it needs and adds its
    group(s) to :attr:`groups`; it may replace a group an earlier step made (the root
    stress step adds its variables to ``/ltca``). :func:`contact.run_analysis` makes it;
    each parameter is the attribute of the same name.

    Parameters
    ----------
    case : geometry.case.Case
        The case as run: its misalignment and its ``[operating]`` table the run's (torques,
        speed, oil, roughness; the file's ``inputs`` attribute is its TOML).
    torque : float or sequence of float — [N·m]
        The pinion torques, as given.
    flank : str or None
        ``"drive"``, ``"coast"``, a pinion flank name, or None (the drive flank).
    options : contact.ltca.LTCAOptions
        The LTCA's settings (solver, compliance model, roll positions, segments …).
    operating : friction.operating.OperatingConditions or None
        The efficiency step's conditions; None: no efficiency step.
    deviations : (SurfaceDeviation or None, SurfaceDeviation or None) or None
        The flanks' surface deviations (pinion, gear) [mm]; None: theoretical surfaces.
    theoretical : bool
        With deviations, also analyse the theoretical surfaces (``/theoretical``).
    progress : bool or "lines"
        Progress of the LTCA's rolls and of a first FE build.
    fe_options : contact.compliance.fe.FEOptions or None
        The root-stress step's FE model; None: the default one (with the FE compliance,
        the compliance's own).
    groups : dict of str to xarray.Dataset
        The analysis groups so far, by path (``"/geometry/pinion/concave"``, ``"/easeoff"``,
        ``"/utca"``, ``"/ltca"``, ``"/mesh_interface"``, ``"/friction"``, ``"/rating"`` …).
    times : dict of str to float — [s]
        Wall time per step (the file's ``time_<step>_s`` root attributes).
    easeoff : contact.utca.easeoff.EaseOff or None
        The ease-off the LTCA loads (the deviated surfaces' where there are deviations).
    transitions : tuple of float — [rad]
        The UTCA's roll angles where the contact passes to the next tooth pair.
    theoretical_easeoff : contact.utca.easeoff.EaseOff or None
        With deviations, the theoretical surfaces' ease-off (``/theoretical/ltca``).
    theoretical_transitions : tuple of float — [rad]
        Its UTCA's transition roll angles.
    roll_problems : list or None
        Filled by the LTCA with every roll position's problem and solution when a
        ``mesh_interface`` step follows (it linearises them), else None.
    not_run : dict of str to str
        Why an optional step gave no group (``"not requested (steps)"`` when the chain
        skips it; the file's ``<step>_not_run`` root attributes).
    prepared : dict of str to object
        What a built-in step computed from the inputs before any work (the rating, so
        that a bad ``[rating]`` table is refused before the LTCA).
    """

    case: Case
    torque: Any
    flank: str | None
    options: Any
    operating: Any = None
    deviations: tuple | None = None
    theoretical: bool = True
    progress: bool | str = False
    fe_options: Any = None
    groups: dict[str, xr.Dataset] = field(default_factory=dict)
    times: dict[str, float] = field(default_factory=dict)
    easeoff: Any = None
    transitions: tuple = ()
    theoretical_easeoff: Any = None
    theoretical_transitions: tuple = ()
    roll_problems: list | None = None
    not_run: dict[str, str] = field(default_factory=dict)
    prepared: dict[str, Any] = field(default_factory=dict)


# --------------------------------------------------------------------------- the steps

def geometry_datasets(case: Case) -> dict[tuple[str, str], xr.Dataset]:
    """The four flanks of a case as the ``/geometry`` group's Datasets, keyed by (member,
    flank): :func:`geometry.machine.flank.geometry_datasets` on its default grid, the
    flanks taken from the per-process memo of the teeth
    (:func:`contact.utca.conjugate_map.flank_nodes`), which the ease-off reads too.

    Parameters
    ----------
    case : geometry.case.Case

    Returns
    -------
    dict
        ``{("pinion", "concave"): Dataset, …}``, as
        :func:`geometry.machine.flank.geometry_datasets` (the same arrays: each flank is
        the same :func:`geometry.machine.flank.flank_surface` of the same grid; the gear's
        is solved once per analysis instead of twice — once here, once by the ease-off —
        and all four once per process for the analyses of the same teeth; issue 32).

    Raises
    ------
    InputError
        As :func:`geometry.machine.flank.flank_surface`.
    """
    out = {}
    for m in ("pinion", "gear"):
        for f in ("concave", "convex"):
            out[m, f] = flank_dataset(case, m, f, surface=flank_nodes(case, m, f,
                                                                      dict(DEFAULT_GRID)))
    return out


def geometry_flanks(state: ChainState) -> None:
    """``/geometry/<member>/<flank>``: the four generated flanks on the default grid
    (:func:`geometry_datasets`; seed ch. 2)."""
    for (m, f), ds in geometry_datasets(state.case).items():
        state.groups[f"/geometry/{m}/{f}"] = ds


def utca_easeoff(state: ChainState, *, curves: bool = True) -> None:
    """``/easeoff`` and ``/utca``: the ease-off and the unloaded TCA of the flank pair in
    contact (:func:`contact.utca.easeoff.ease_off`, :func:`contact.utca.unloaded_tca`; seed
    §2.3–2.4, ch. 3), of the deviated surfaces where there are deviations
    (:func:`contact.utca.deviations.apply_deviations`, seed ch. 4) with the theoretical
    ones under ``/theoretical`` and ``ease_off_change`` [µm] in ``/easeoff``.
    ``curves=False``: ``/utca`` without the contact curves (:func:`utca_ute`)."""
    from contact.utca import unloaded_tca
    from contact.utca.easeoff import ease_off

    c, flank = state.case, state.flank
    t0 = time.perf_counter()
    eo = ease_off(c, flank=flank)
    state.times["easeoff"] = time.perf_counter() - t0
    t_eo = None  # the theoretical surfaces' /easeoff dataset
    if state.deviations is not None:
        from contact.utca.deviations import apply_deviations

        t_eo, t_ut = unloaded_tca(c, flank=flank, easeoff=eo, curves=curves)
        if state.theoretical:
            state.groups["/theoretical/easeoff"] = t_eo
            state.groups["/theoretical/utca"] = t_ut
        state.theoretical_easeoff = eo
        state.theoretical_transitions = tuple(t_ut["transition_roll"].values)
        pin_dev, gear_dev = state.deviations
        eo = apply_deviations(eo, pinion=pin_dev, gear=gear_dev, case=c)
    t0 = time.perf_counter()
    eo_ds, utca_ds = unloaded_tca(c, flank=flank, easeoff=eo, curves=curves)
    state.times["utca"] = time.perf_counter() - t0
    if t_eo is not None:
        change = (eo_ds["ease_off"] - t_eo["ease_off"]).astype(float)
        eo_ds["ease_off_change"] = change.assign_attrs(
            units=eo_ds["ease_off"].attrs.get("units", "um"),
            long_name="ease-off change by the surface deviations (deviated - theoretical)",
        )
        eo_ds.attrs["deviations"] = (
            "pinion: " + ("yes" if state.deviations[0] is not None else "no")
            + ", gear: " + ("yes" if state.deviations[1] is not None else "no"))
    state.groups["/easeoff"] = eo_ds
    state.groups["/utca"] = utca_ds
    state.easeoff = eo
    state.transitions = tuple(utca_ds["transition_roll"].values)


def utca_ute(state: ChainState) -> None:
    """``/easeoff`` and ``/utca`` as :func:`utca_easeoff`, the ``/utca`` of the UTE alone
    (:func:`contact.utca.datasets.ute_dataset`: the pairs' and the actual UTE, the
    transitions, the peak-to-peak — the same values bit for bit — without the contact
    curves' flank points, separations, lines and paths). A study point's step
    (:func:`contact.study.engine.analyse_point`: its summary reads the UTE peak-to-peak,
    the LTCA the transitions; ≈ 9 ms of a ≈ 0.19 s point, issue 75)."""
    utca_easeoff(state, curves=False)


def ltca_qp(state: ChainState) -> None:
    """``/ltca``: the loaded TCA, the contact QP at every roll position
    (:func:`contact.ltca.loaded_tca`, seed Eq. 3.12–3.14), with the solver and the
    compliance model of ``state.options``; with deviations and ``theoretical``, also
    ``/theoretical/ltca``."""
    from contact.ltca import loaded_tca

    c = state.case
    if state.theoretical_easeoff is not None and state.theoretical:
        t0 = time.perf_counter()
        state.groups["/theoretical/ltca"] = loaded_tca(
            c, state.torque, flank=state.flank, options=state.options,
            easeoff=state.theoretical_easeoff, transitions=state.theoretical_transitions)
        state.times["theoretical_ltca"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    state.groups["/ltca"] = loaded_tca(
        c, state.torque, flank=state.flank, options=state.options, easeoff=state.easeoff,
        progress=state.progress, transitions=state.transitions,
        roll_problems=state.roll_problems)
    state.times["ltca"] = time.perf_counter() - t0


def lte_range_ltca(state: ChainState) -> None:
    """``lte_torque`` [N·m], ``lte_range_peak_to_peak`` [µrad] and ``lte_range_source``
    added to ``/ltca``: the LTE p-p at :data:`contact.ltca.lte_range.LTE_TORQUES` torques
    from the lightest analysed torque to the heaviest up to the rating's design torque
    (``/rating`` ``design_torque``; every torque without one), the contact alone
    (:func:`contact.ltca.loaded_tca` with the run's options, ease-off and transitions)
    analysed at those the run has not (:func:`contact.ltca.lte_range.lte_range`; issue
    71: an LTE that peaks between the run's torques is judged). Nothing is added where no
    torque is at or below the design torque."""
    from contact.ltca.lte_range import lte_range

    lt = state.groups["/ltca"]
    rating = state.groups.get("/rating")
    design = math.inf
    if rating is not None and "design_torque" in rating and rating["design_torque"].ndim == 0:
        design = float(rating["design_torque"])
        if not math.isfinite(design):
            design = math.inf
    t0 = time.perf_counter()
    found = lte_range(lt, state.case, design=design, flank=state.flank,
                      options=state.options, easeoff=state.easeoff,
                      transitions=state.transitions)
    state.times["lte_range"] = time.perf_counter() - t0
    if not found:
        return
    coords = {"lte_torque": found.pop("lte_torque")}
    state.groups["/ltca"] = assigned(lt, found, coords)


def root_stress_fe(state: ChainState) -> None:
    """``root_stress`` [MPa] (torque, roll, member, tooth, fillet_point) and
    ``root_stress_max`` [MPa] (torque, member) added to ``/ltca``: the fillet stress of both
    members superposed from FE influence coefficients and the LTCA's segment forces
    (:func:`contact.ltca.root_stress.root_stress`; docs/fe.md). The FE model is
    ``state.fe_options``, or with the FE compliance (``options.compliance == "fe"``) the
    compliance's own, else the default one. A design's first run builds its coefficients
    (~15–20 s per member), later runs read them from the cache."""
    from contact.ltca.root_stress import root_stress

    opts = state.options
    fe_options = state.fe_options
    if fe_options is None and opts.compliance == "fe":
        fe_options = opts.fe_options()
    lt = state.groups["/ltca"]
    try:
        rs = root_stress(state.case, state.easeoff, lt, fe_options, progress=state.progress)
    except (InputError, ModelUnavailableError):
        raise  # a wrong input or a missing solver is the user's to fix, said at once
    except LTCAError as exc:
        # the FE model of these teeth could not be built or solved (e.g. a fillet whose
        # mapped elements invert): root stress never sinks an analysis (issue 60) - the
        # rest is written, and the file and the console say why it is missing
        log.warning("root stress not computed: %s", exc)
        state.not_run["root_stress"] = (f"root stress not computed: the FE model failed "
                                        f"({exc})")
        return
    # lt.assign(root_stress=rs["root_stress"], root_stress_max=rs["root_stress_max"]):
    # the same dataset (the DataArrays bring their coordinates /ltca lacks, in their
    # order; torque and roll are /ltca's own), without the merge (issue 75)
    new_coords = [c for c in rs["root_stress"].coords if c not in lt.variables]
    state.groups["/ltca"] = assigned(
        lt, {name: rs.variables[name] for name in ("root_stress", "root_stress_max")},
        {c: rs.variables[c] for c in new_coords})


def mesh_interface_linearised(state: ChainState) -> None:
    """``/mesh_interface``: mesh point, line of action, mesh stiffness and transmission-
    error excitation for dynamic models, linearised from the LTCA's roll problems
    (:func:`contact.ltca.mesh_interface.mesh_interface`); the problems' compliance
    matrices are let go after it."""
    from contact.ltca.mesh_interface import mesh_interface

    state.groups["/mesh_interface"] = mesh_interface(state.groups["/ltca"],
                                                     state.roll_problems or [])
    state.roll_problems = None


def efficiency_local_friction(state: ChainState) -> None:
    """``/friction``: sliding and rolling velocities, film, friction coefficient, power
    loss and mechanical efficiency at every contact segment of ``/ltca``
    (:func:`friction.efficiency.efficiency_analysis`, seed ch. 5) at ``state.operating``;
    nothing where there are no conditions (pinion speed 0)."""
    if state.operating is None:
        state.not_run["efficiency"] = "no pinion speed (the [operating] pinion_speed is 0)"
        return
    from friction.efficiency import efficiency_analysis

    state.groups["/friction"] = efficiency_analysis(state.groups["/ltca"], state.operating)


def _rating_of(state: ChainState, method: str):
    """(``/rating`` dataset or None, why not): the load-capacity rating of the case as run
    by the registered ``method`` (:func:`contact.load_capacity.rate`) at the run's torques,
    pinion speed and flank. A case the method cannot rate although nothing in it is wrong
    (:attr:`contact.load_capacity.RatingMethod.missing`: ISO 10300 without a ``[design]`` or
    ``[rating]`` table) or a run without a pinion speed gives None and the reason; a table
    that is there but wrong is refused (InputError)."""
    return _rating_for(state.case, state.torque, state.flank, method, state.groups)


def _rating_for(c: Case, torque, flank, method: str, groups):
    """:func:`_rating_of` of the case ``c`` as run, the torques, flank and the analysis'
    ``groups`` so far."""
    from contact.load_capacity.methods import METHODS, rate

    entry = METHODS.get(method)
    why = "" if entry is None or entry.missing is None else entry.missing(c)
    if why:
        return None, why
    speed = c.operating.pinion_speed
    if not speed > 0.0:
        return None, (f"{method} rating not computed: no pinion speed (the case's "
                      "[operating] pinion_speed is 0; give --speed)")
    return rate(c, torque, speed, method=method, flank=flank, analysis=groups), ""


def _nominal_rating_of(state: ChainState, method: str, entry):
    """:func:`_rating_of` of a method that rates the nominal geometry from the case's
    tables alone (:attr:`contact.load_capacity.RatingMethod.nominal`, before any work), the
    same for the same case object, torques, pinion speed, flank and registered method: kept
    per process (:func:`_memo_nominal_rating`; ISO 10300's ~6 ms of a warm analysis, issue
    75) and handed out as a shallow copy (its own attributes and variables, the arrays
    shared), which the step may annotate."""
    c = state.case
    key = (Same(c), tuple(float(t) for t in np.atleast_1d(state.torque)),
           float(c.operating.pinion_speed), method, state.flank, Same(entry))
    try:
        hash(key)
    except TypeError:  # (a flank or method name that is not a plain value: as before)
        return _rating_of(state, method)
    rating, why = _memo_nominal_rating(*key, Carried(state.torque))
    return (None if rating is None else rating.copy(deep=False)), why


@memoised(maxsize=16)
def _memo_nominal_rating(case: Same, torque: tuple, speed: float, method: str, flank,
                         entry: Same, given: Carried):
    """(``/rating`` or None, why not) of :func:`_rating_for` before any work (no analysis
    dataset), by the case object, torques (``given``: as the caller gave them), speed,
    flank and method entry."""
    return _rating_for(case.obj, given.value, flank, method, {})


def _rating_step(method: str) -> Callable[[ChainState], None]:
    """The load-capacity step that rates by the registered ``method``, with its check
    before work (``before_work``, which :func:`run_chain` calls before any step)."""

    def rating_step(state: ChainState) -> None:
        """``/scuffing_micropitting`` (with ``/friction``), then ``/rating`` by the
        registered method (:func:`contact.load_capacity.rate`) and the companion results
        the method declares (:attr:`contact.load_capacity.RatingMethod.companions`; ISO
        10300's ``"flash_temperature"``: the standard's flash-temperature method on its
        virtual cylindrical gears, ``/rating/flash_temperature``,
        :func:`scuffing_flash_temperature`). Without the
        tables the method needs or a pinion speed there is no ``/rating``;
        ``state.not_run["load_capacity"]`` says why."""
        load_capacity_without_rating(state)
        rating, why = state.prepared.pop("load_capacity", None) or _rating_of(state, method)
        if rating is None:
            state.not_run["load_capacity"] = why
            return
        state.groups["/rating"] = rating
        from contact.load_capacity.methods import METHODS

        entry = METHODS.get(str(rating.attrs.get("rating_method", method)))
        # the results the method declares beside its rating (RatingMethod.companions)
        if entry is not None and "flash_temperature" in entry.companions:
            flash, why = _flash_temperature_or_reason(
                rating, state.groups.get("/friction"),
                None if state.operating is None else state.operating.oil())
            if flash is not None:  # stored beside the rating it is computed on
                state.groups["/rating/flash_temperature"] = flash
            else:  # the verdict's "not checked: scuffing_standard" says why
                rating.attrs["flash_temperature_not_run"] = why

    def inputs(state: ChainState) -> None:
        """Before any work: the rating of a method that rates the nominal geometry
        (:attr:`contact.load_capacity.RatingMethod.nominal`: ISO 10300, ANSI/AGMA 2003;
        analytic, < 0.5 s), so that a bad ``[rating]``, ``[agma2003]`` or ``[design]``
        table is refused before the LTCA, not after it. A method that rates from the
        analysis' datasets is left to its step."""
        from contact.load_capacity.methods import METHODS

        entry = METHODS.get(method)
        if entry is not None and entry.nominal:
            state.prepared["load_capacity"] = _nominal_rating_of(state, method, entry)

    rating_step.__name__ = rating_step.__qualname__ = f"rating_{method}"
    rating_step.before_work = inputs  # type: ignore[attr-defined]
    return rating_step


def load_capacity_without_rating(state: ChainState) -> None:
    """``/scuffing_micropitting`` alone (the ``load_capacity`` step's
    ``"scuffing_micropitting"`` implementation; ``ltca run --no-rating``): with
    ``/friction``, Blok's flash temperature, the contact temperature, λ_GF and the safeties
    S_B, S_λ on the LTCA's contact segments
    (:func:`contact.load_capacity.scuffing_micropitting.scuffing_micropitting`, from
    ``/ltca`` and ``/friction``; ISO/TS 6336-20, ISO/TS 6336-22); nothing without
    ``/friction``."""
    friction = state.groups.get("/friction")
    if friction is None:
        return
    from contact.load_capacity.scuffing_micropitting import scuffing_micropitting

    # the oil as the efficiency step read it (read once: OperatingConditions.oil)
    state.groups["/scuffing_micropitting"] = scuffing_micropitting(
        state.groups["/ltca"], friction,
        lubricant=None if state.operating is None else state.operating.oil())


def scuffing_flash_temperature(rating: xr.Dataset, friction: xr.Dataset | None,
                               lubricant: str | os.PathLike[str] | None = None
                               ) -> xr.Dataset | None:
    """The standard's flash-temperature method on the virtual cylindrical gears of a
    ``/rating`` dataset and its hypoid lengthwise-sliding variant, with the spread of S_B,
    at the efficiency step's oil, oil temperature [degC] and roughness Rq [µm]
    (:func:`contact.load_capacity.iso_flash_temperature.iso_flash_temperature_variants`;
    ISO/TS 6336-20).

    Parameters
    ----------
    rating : xarray.Dataset
        The ``/rating`` group.
    friction : xarray.Dataset or None
        The ``/friction`` group (its attributes ``lubricant``, ``inlet_temperature_degC``,
        ``roughness_rq_um``); None: no method.
    lubricant : str or path-like, optional
        The oil the efficiency step ran with (:attr:`friction.OperatingConditions.lubricant`:
        a bundled name or the oil file); default the ``/friction`` group's ``lubricant``
        attribute, which is the oil's *name* and finds a bundled oil only — an oil file of
        the user's is carried by its path, never looked up by its name.

    Returns
    -------
    xarray.Dataset or None
        The ``/rating/flash_temperature`` group; None without ``friction`` or where the
        method cannot be applied (the reason logged at INFO).
    """
    return _flash_temperature_or_reason(rating, friction, lubricant)[0]


def _flash_temperature_or_reason(rating: xr.Dataset, friction: xr.Dataset | None,
                                 lubricant: Any
                                 ) -> tuple[xr.Dataset | None, str]:
    """:func:`scuffing_flash_temperature`'s group, or None with the reason it could not be
    computed (the verdict's "not checked" says it: e.g. a virtual transverse contact ratio
    below 1, which the standard's method does not cover)."""
    if friction is None:
        return None, "the analysis ran without an efficiency stage"
    from contact.load_capacity.iso_flash_temperature import iso_flash_temperature_variants

    try:
        return iso_flash_temperature_variants(
            rating, lubricant=(str(friction.attrs["lubricant"]) if lubricant is None
                               else lubricant),
            temperature=float(friction.attrs["inlet_temperature_degC"]),
            roughness=float(friction.attrs["roughness_rq_um"])), ""
    except (InputError, ModelUnavailableError, KeyError) as exc:
        log.info("the standard's flash temperature method not applied: %s", exc)
        return None, f"the standard's method does not apply here ({exc})"


#: every step's implementations by name; the first of each is the default
STEPS: Mapping[str, Mapping[str, Callable[[ChainState], None]]] = {
    "geometry": {"flanks": geometry_flanks},
    "utca": {"easeoff": utca_easeoff, "ute": utca_ute},
    "ltca": {"qp": ltca_qp},
    "root_stress": {"fe": root_stress_fe},
    "mesh_interface": {"linearised": mesh_interface_linearised},
    "efficiency": {"local_friction": efficiency_local_friction},
    "load_capacity": {"iso10300": _rating_step("iso10300"),
                      "scuffing_micropitting": load_capacity_without_rating},
    "lte_range": {"ltca": lte_range_ltca},
}


def _implementations(step: str) -> Mapping[str, Callable[[ChainState], None]]:
    """``step``'s implementations by name, default first: :data:`STEPS`'s and, for the
    load-capacity step, every method of the load-capacity registry
    (:func:`contact.load_capacity.available_methods`, a plug-in's among them) by its name."""
    if step != "load_capacity":
        return STEPS[step]
    from contact.load_capacity.methods import available_methods

    return {**STEPS[step], **{m: _rating_step(m) for m in available_methods()
                              if m not in STEPS[step]}}


def available_steps() -> dict[str, tuple[str, ...]]:
    """The steps of the chain and the names each may be chosen by (default first).

    Returns
    -------
    dict of str to tuple of str
        ``{"geometry": ("flanks",), "utca": ("easeoff",), …}`` in :data:`STEP_ORDER`; the
        load-capacity step's names are the registry's rating methods
        (:func:`contact.load_capacity.available_methods`) and ``"scuffing_micropitting"``
        (no rating).
    """
    return {step: tuple(_implementations(step)) for step in STEP_ORDER}


def _default(step: str) -> str:
    return next(iter(STEPS[step]))


@dataclass(frozen=True)
class AnalysisChain:
    """One choice per step of the analysis (:data:`STEP_ORDER`): a name of
    :data:`STEPS`, a callable ``f(state: ChainState) -> None``, or None to skip an optional
    step (:data:`OPTIONAL_STEPS`). The defaults are the steps ``ltca run`` runs.

    Parameters
    ----------
    geometry : str, callable or None
        ``/geometry``: the four generated flanks (``"flanks"``, seed ch. 2).
    utca : str or callable
        ``/easeoff``, ``/utca``: ease-off and unloaded TCA (``"easeoff"``, seed §2.3–2.4,
        ch. 3; deviations ch. 4); ``"ute"``: the same with ``/utca`` of the UTE alone, no
        contact curves (a study point's, :func:`utca_ute`).
    ltca : str or callable
        ``/ltca``: the loaded TCA, the contact QP (``"qp"``, seed Eq. 3.12–3.14).
    root_stress : str, callable or None
        ``root_stress``, ``root_stress_max`` [MPa] in ``/ltca`` from FE influence
        coefficients (``"fe"``).
    mesh_interface : str, callable or None
        ``/mesh_interface``: mesh stiffness and TE excitation (``"linearised"``).
    efficiency : str, callable or None
        ``/friction``: friction, power loss, efficiency (``"local_friction"``, seed ch. 5).
    load_capacity : str, callable or None
        ``/scuffing_micropitting`` (Blok, ISO/TS 6336-20/-22 on the LTCA's contact),
        ``/rating`` and ``/rating/flash_temperature``: ISO 10300 Method B1 and ISO/TS
        6336-20 (``"iso10300"``), or the rating of another method of the load-capacity
        registry by its name (:func:`contact.load_capacity.available_methods`);
        ``"scuffing_micropitting"``: the first alone (no rating, ``ltca run --no-rating``).
    lte_range : str, callable or None
        ``lte_torque`` [N·m], ``lte_range_peak_to_peak`` [µrad] and ``lte_range_source``
        in ``/ltca``: the LTE p-p from the lightest torque to the heaviest up to the
        rating's design torque, the contact alone analysed between the run's torques
        (``"ltca"``, :func:`contact.ltca.lte_range.lte_range`; issue 71), which the
        verdict's ``lte`` check judges.
    fe_options : contact.compliance.fe.FEOptions or None
        The root-stress step's FE model (None: the default one, or with the FE compliance
        the compliance's own; :meth:`with_root_stress` sets it).

    Raises
    ------
    InputError
        An unknown name (the message lists the available ones), a value that is neither
        a name, a callable nor None, or None for ``utca`` or ``ltca``.

    Notes
    -----
    Named configurations (after pvlib's ``ModelChain.with_pvwatts``; issue 72):
    :meth:`analysis` (every step, ``ltca run``'s), :meth:`contact_only` (ease-off, UTCA,
    LTCA), and on either :meth:`with_root_stress`, :meth:`with_mesh_interface`,
    :meth:`with_geometry`, :meth:`with_efficiency`, :meth:`with_load_capacity`,
    :meth:`without`, :meth:`with_steps`, each returning a new chain.

    Examples
    --------
    >>> from contact import AnalysisChain
    >>> AnalysisChain(root_stress=None).root_stress is None
    True
    >>> AnalysisChain.contact_only().with_root_stress().describe()["root_stress"]
    'fe'
    """

    geometry: StepChoice = "flanks"
    utca: StepChoice = "easeoff"
    ltca: StepChoice = "qp"
    root_stress: StepChoice = "fe"
    mesh_interface: StepChoice = "linearised"
    efficiency: StepChoice = "local_friction"
    load_capacity: StepChoice = "iso10300"
    lte_range: StepChoice = "ltca"
    #: the root-stress step's FE model (contact.compliance.fe.FEOptions; None: the default
    #: one, or with the FE compliance the compliance's own)
    fe_options: Any = None

    def __post_init__(self) -> None:
        for step in STEP_ORDER:
            _check_choice(step, getattr(self, step))
        if self.fe_options is not None:
            from contact.compliance.fe import FEOptions
            from contact.compliance.fe.options import level_hint

            if not isinstance(self.fe_options, FEOptions):
                raise InputError("fe_options: must be a contact.compliance.fe.FEOptions or "
                                 f"None, got {type(self.fe_options).__name__}"
                                 f"{level_hint(self.fe_options)}")

    # ----------------------------------------------------------- named configurations
    # after pvlib's ModelChain.with_pvwatts: one way to say which steps a run makes
    # (issue 72 item 5), instead of run_analysis's on/off keywords

    @classmethod
    def analysis(cls) -> AnalysisChain:
        """Every step with its default implementation: what ``ltca run`` runs (geometry,
        ease-off and UTCA, LTCA, root stress, mesh interface, efficiency, ISO 10300
        load capacity)."""
        return cls()

    @classmethod
    def contact_only(cls) -> AnalysisChain:
        """The contact alone — ease-off, UTCA and LTCA — as a study's hot loop, an
        optimisation's objective or ``ltca mesh-interface`` start from: geometry, root
        stress, mesh interface, efficiency and load capacity skipped (add any back with
        the ``with_…`` methods)."""
        return cls(geometry=None, root_stress=None, mesh_interface=None, efficiency=None,
                   load_capacity=None, lte_range=None)

    def with_steps(self, **choices: StepChoice) -> AnalysisChain:
        """This chain with the given steps' choices replaced (a name, a callable
        ``f(state)`` or None); e.g. ``AnalysisChain.contact_only().with_steps(efficiency=f)``.

        Raises
        ------
        InputError
            A step name not among :data:`STEP_ORDER`, or a choice :class:`AnalysisChain`
            refuses.
        """
        unknown = [k for k in choices if k not in STEP_ORDER]
        if unknown:
            raise InputError(f"steps: unknown step {unknown[0]!r}; the steps are "
                             f"{', '.join(STEP_ORDER)}")
        return dataclasses.replace(self, **choices)

    def without(self, *steps: str) -> AnalysisChain:
        """This chain with ``steps`` skipped (each an optional step,
        :data:`OPTIONAL_STEPS`)."""
        return self.with_steps(**dict.fromkeys(steps))

    def _on(self, step: str, on: bool) -> AnalysisChain:
        if not isinstance(on, (bool, np.bool_)):
            raise InputError(f"{step}: must be True or False, got {on!r}")
        if not on:
            return self.with_steps(**{step: None})
        return self if getattr(self, step) is not None else self.with_steps(
            **{step: _default(step)})

    def with_root_stress(self, on: bool | Any = True) -> AnalysisChain:
        """This chain with the root-stress step (``"fe"``) on or off; an
        :class:`contact.compliance.fe.FEOptions` turns it on with that FE model."""
        if isinstance(on, (bool, np.bool_)):
            return self._on("root_stress", bool(on))
        from contact.compliance.fe import FEOptions
        from contact.compliance.fe.options import level_hint

        if not isinstance(on, FEOptions):
            raise InputError("root_stress: must be True, False or a contact.compliance.fe."
                             f"FEOptions, got {type(on).__name__} {on!r}{level_hint(on)}")
        return dataclasses.replace(self._on("root_stress", True), fe_options=on)

    def with_geometry(self, on: bool = True) -> AnalysisChain:
        """This chain with the ``/geometry`` step on or off."""
        return self._on("geometry", on)

    def with_mesh_interface(self, on: bool = True) -> AnalysisChain:
        """This chain with the ``/mesh_interface`` step on or off."""
        return self._on("mesh_interface", on)

    def with_efficiency(self, on: bool = True) -> AnalysisChain:
        """This chain with the efficiency step (``/friction``) on or off."""
        return self._on("efficiency", on)

    def with_load_capacity(self, method: str | None = "iso10300") -> AnalysisChain:
        """This chain with the load-capacity step by ``method`` (a method of the
        load-capacity registry or ``"scuffing_micropitting"``), or skipped (None)."""
        return self.with_steps(load_capacity=method)

    def function(self, step: str) -> Callable[[ChainState], None] | None:
        """The callable that runs ``step`` (None: skipped)."""
        choice = getattr(self, step)
        return _implementations(step)[choice] if isinstance(choice, str) else choice

    def describe(self) -> dict[str, str]:
        """Each step's choice as text: its name, ``"callable <qualified name>"`` or
        ``"skipped"``."""
        out = {}
        for step in STEP_ORDER:
            choice = getattr(self, step)
            out[step] = ("skipped" if choice is None else choice if isinstance(choice, str)
                         else f"callable {getattr(choice, '__qualname__', repr(choice))}")
        return out


def _check_choice(step: str, choice: StepChoice) -> None:
    names = ", ".join(_implementations(step))
    if choice is None:
        if step not in OPTIONAL_STEPS:
            raise InputError(f"steps.{step}: the analysis cannot skip it; give one of "
                             f"{names} or a callable f(state)")
        return
    if isinstance(choice, str):
        if choice not in _implementations(step):
            skip = ", or None to skip it" if step in OPTIONAL_STEPS else ""
            raise InputError(f"steps.{step}: unknown step {choice!r}; available: {names} "
                             f"(or a callable f(state){skip})")
        return
    if not callable(choice):
        raise InputError(f"steps.{step}: must be one of {names}, a callable f(state) or "
                         f"None, got {type(choice).__name__} {choice!r}")
    from contact.chain_contract import check_step_callable

    check_step_callable(step, choice)  # one argument, the state (issue 72)


def resolve_chain(steps: AnalysisChain | Mapping[str, StepChoice] | None = None,
                  **switches: bool | None) -> AnalysisChain:
    """The chain of :func:`contact.run_analysis`'s ``steps`` and on/off keywords.

    Parameters
    ----------
    steps : AnalysisChain, mapping of step name to choice, or None
        The chain, or the steps that differ from the defaults (:class:`AnalysisChain`).
    **switches : bool or None
        ``geometry``, ``root_stress``, ``mesh_interface``, ``efficiency``,
        ``load_capacity``: False skips the step, True runs it (its default implementation
        where ``steps`` skips it), None leaves ``steps``' choice.

    Returns
    -------
    AnalysisChain

    Raises
    ------
    InputError
        A step name not among :data:`STEP_ORDER` (listed), or as :class:`AnalysisChain`.
    """
    if steps is None:
        chain = AnalysisChain()
    elif isinstance(steps, AnalysisChain):
        chain = steps
    elif isinstance(steps, Mapping):
        unknown = [k for k in steps if k not in STEP_ORDER]
        if unknown:
            raise InputError(f"steps: unknown step {unknown[0]!r}; the steps are "
                             f"{', '.join(STEP_ORDER)}")
        chain = AnalysisChain(**steps)
    elif steps is AnalysisChain or getattr(steps, "__self__", None) is AnalysisChain:
        name = getattr(steps, "__qualname__", "AnalysisChain")
        raise InputError(f"steps: got {name} itself; call it: {name}() (a chain, e.g. "
                         "AnalysisChain.analysis() or AnalysisChain.contact_only())")
    else:
        raise InputError("steps: must be a contact.AnalysisChain, a mapping of step name to "
                         f"a name, callable or None, or None; got {type(steps).__name__}")
    change: dict[str, StepChoice] = {}
    for step, on in switches.items():
        if on is None:
            continue
        if on is False:
            change[step] = None
        elif getattr(chain, step) is None:
            change[step] = _default(step)
    return dataclasses.replace(chain, **change) if change else chain


def run_chain(chain: AnalysisChain, state: ChainState) -> ChainState:
    """Run the steps of ``chain`` on ``state`` in :data:`STEP_ORDER`; each step's wall time
    in ``state.times`` (the step's own entries kept), a skipped step's reason in
    ``state.not_run``. Checks the built-in steps make on their inputs run first, before
    any work."""
    functions = {step: chain.function(step) for step in STEP_ORDER}
    if functions["mesh_interface"] is not None:
        state.roll_problems = []
    for f in functions.values():  # a built-in step's checks of its inputs
        before_work = getattr(f, "before_work", None)
        if before_work is not None:
            before_work(state)
    from contact.chain_contract import run_step

    # the steps that run: a /friction is checked for the load-capacity step where it runs
    running = tuple(step for step, f in functions.items() if f is not None)
    for step, f in functions.items():
        if f is None:
            state.not_run[step] = "not requested (steps)"
            continue
        t0 = time.perf_counter()
        # a user's step: its exception and what it left refused naming it (issue 72)
        run_step(step, f, state, builtin=isinstance(getattr(chain, step), str),
                 order=running)
        key = "friction" if step == "efficiency" else step
        state.times.setdefault(key, time.perf_counter() - t0)
    return state
