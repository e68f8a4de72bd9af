"""The root-stress and local pitting capacity of a developed design (issue 71 item 2: one
design torque that holds).

The development's design torque is by default the ISO 10300 capacity, which rates the root
by torque-independent factors (Y_Fa·Y_Sa, K_Fβ of a nominal bearing) and the flank by the
nominal contact stress of the virtual cylindrical gears, whose face load factor
K_Hβ = 1.5·K_Hβ-be stands for a bearing that covers the face under full load. Two checks
judge the developed bearing itself, at ``ltca run``'s sampling:

* **root**: the verdict's FE root stress (:mod:`contact.study.verdict_checks`, "Root
  stress": S_F,FE = σ_FP / (σ_FE,max·K_A·K_v) against S_Fmin), with the same FE model
  ``ltca run`` builds by default (cached by the members' geometry, so ``ltca run``
  afterwards reads it);
* **pitting** (:func:`pitting_safety`): the local flank safety at long life,
  S_H,loc = σ_HP,∞ / (p_max·√(K_A·K_v)), the LTCA's peak flank pressure in place of
  ISO 10300-2's σ_H0·√(K_Hβ·K_Hα) — the load distribution along the face and between the
  tooth pairs taken from the loaded contact (ISO 10300-1:2014 Method A for K_Hβ and K_Hα),
  the permissible stress σ_HP,∞ = σ_Hlim Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp the rating's own at
  long life (its knee, the allowable the duty cycle's S–N curve has,
  :meth:`contact.load_capacity.durability.SNCurve.rated`), against S_Hmin.

:func:`root_capacity` lowers the design torque to the capacity :func:`root_capacity_step`
of whichever criterion fails, so that the design torque written is one that holds by the
judgements ``ltca run`` and ``ltca duty-cycle`` apply (a spectrum at or below it stays
at or below the S–N curve's knee stress). Imported by :mod:`contact.optimize.development`.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from contact.optimize.development_result import STATIC_MARGIN, case_torques, floor_torque
from geometry.core.errors import raise_if_interrupted
from geometry.core.text import plain_number

log = logging.getLogger(__name__)

#: most steps of :func:`root_capacity` (each an LTCA and the root stress at the new torques)
ROOT_STEPS = 3


def root_capacity_step(torque: float, safety: float, s_min: float,
                       margin: float = STATIC_MARGIN, exponent: float = 1.0) -> float:
    """The root-stress capacity [N·m] from a safety at one torque:
    T · (m · S_F,FE / S_Fmin)^(1/b), rounded down (``floor_torque``: 0.1 N·m, two
    significant digits below 1 N·m).

    With S_F,FE ∝ T^(−b): b = 1 where the FE root stress is linear in the load (the
    fillet's influence coefficients are linear; T·S_F,FE/S_Fmin). A localised bearing
    spreads its load over more of the face and more teeth as the torque grows, so the peak
    root stress grows more slowly than the torque (measured b ≈ 0.55 near the design
    torque of the 10×43 hypoid): :func:`root_capacity` measures b on the bearing. K_v
    depends weakly on the torque (ISO 10300-1 Method B: K_v − 1 ∝ 1/(F/b), it grows a
    little as the torque falls); it is in the measured S_F,FE, and the margin ``m``
    (default 0.99, :data:`STATIC_MARGIN`, as the flank capacity) covers the rest.

    Parameters
    ----------
    torque : float — [N·m] the pinion torque the safety was computed at (> 0)
    safety : float — [1] S_F,FE of the weaker member there
    s_min : float — [1] the rating's S_Fmin (> 0)
    margin : float — [1] in (0, 1]
    exponent : float — [1] b of S_F,FE ∝ T^(−b), in [0.2, 1.5]

    Returns
    -------
    float — [N·m]

    Raises
    ------
    ValueError
        A non-positive or non-finite input.
    """
    if not (torque > 0 and s_min > 0 and safety > 0 and 0 < margin <= 1
            and 0.2 <= exponent <= 1.5 and math.isfinite(torque * safety * s_min)):
        raise ValueError(f"root capacity: torque {torque}, S_F,FE {safety}, S_Fmin {s_min} "
                         f"and margin {margin} must be finite and > 0 (margin <= 1), "
                         f"exponent {exponent} in [0.2, 1.5]")
    t = torque * (margin * safety / s_min) ** (1.0 / exponent)
    return floor_torque(t)


def root_safety(tree) -> tuple[np.ndarray, float, str]:
    """(S_F,FE of the weaker member per torque [1], S_Fmin [1], its member) of an analysis
    with root stress and an ISO 10300 ``/rating`` at the same torques — the verdict's
    :func:`contact.study.verdict_checks.root_stress_safety`.

    Raises
    ------
    LookupError
        No ``root_stress_max`` or no ISO ``/rating`` at the same torques (the reason).
    """
    from contact.study.verdict_checks import has_iso_rating, member_names, root_stress_safety

    lt = tree["/ltca"].to_dataset()
    if "root_stress_max" not in lt:
        why = lt.attrs.get("root_stress_not_run", "") or "no root_stress_max"
        raise LookupError(f"no root stress ({why})")
    rt = tree["/rating"].to_dataset() if "/rating" in tree.groups else None
    rs = lt["root_stress_max"].transpose("torque", "member")
    if not has_iso_rating(rt) or not np.array_equal(rt["torque"].values, rs["torque"].values):
        raise LookupError("no ISO 10300 rating at the analysed torques (a pinion speed and a "
                          "[rating] material are needed)")
    s = root_stress_safety(np.asarray(rs.values, float), rt)
    j = int(np.nanargmin(s[-1]))
    return s[:, j], float(rt["S_Fmin"]), member_names(rs)[j]


#: the FE level a torque the root stress limits is decided on: the model the coarser
#: levels state their accuracy against (:data:`contact.compliance.fe.options.LEVEL_ACCURACY`)
DECIDING_LEVEL = "default"


def decided_case(case, setup: dict[str, Any]):
    """``case`` on the FE level the development's root checks read: ``setup["fe_level"]``
    where a root check on a coarser level set it (:func:`refined_for_root`), else ``case``
    itself (also where ``case`` is None).

    Parameters
    ----------
    case : geometry.case.Case or None
    setup : dict — the development's state (its optional ``"fe_level"``, a key of
        :data:`contact.compliance.fe.options.LEVELS`)

    Returns
    -------
    geometry.case.Case or None

    Raises
    ------
    InputError — an unknown level (:func:`contact.compliance.fe.options.with_fe_level`).
    """
    level = setup.get("fe_level")
    if case is None or level is None:
        return case
    from contact.compliance.fe.options import fe_level_of, with_fe_level

    return case if fe_level_of(case) == level else with_fe_level(case, level)


def at_decided_level(case, basic, setup: dict[str, Any]):
    """(``case``, ``basic``) on the FE level the development decided its root-limited
    torques on (:func:`decided_case`; the basic design's ``root_stress`` table naming it
    too), as given where no root check moved the level.

    Parameters
    ----------
    case : geometry.case.Case — the case written
    basic : geometry.synthesis.basic_design.BasicDesign — its basic design
    setup : dict — the development's state (its optional ``"fe_level"``)

    Returns
    -------
    (geometry.case.Case, BasicDesign)

    Raises
    ------
    InputError — an unknown level (:func:`decided_case`).
    """
    level = setup.get("fe_level")
    if level is None:
        return case, basic
    import dataclasses

    return (decided_case(case, setup),
            dataclasses.replace(basic, root_stress={"fe_level": level}))


def design_torque_kept(setup: dict[str, Any]) -> str:
    """The FE level's note (``setup["fe_level_why"]``, :func:`refined_for_root`) as the
    case written is read: where it names the design torque its coarse root check failed at
    (``setup["fe_level_torque"]``, :func:`root_capacity`) and the development wrote
    another (``setup["torques"][1]``, at the printed digits), that torque is named "the
    design torque then checked" and the one written beside it; else the note as it is
    ("" without one).

    Parameters
    ----------
    setup : dict — the development's state at its end

    Returns
    -------
    str

    Notes
    -----
    Source: issue 71, round 35 (helper unseen97): the FM hypoid 12×31 remedied (b2 36 mm)
    printed "note: the coarse10 FE level reads S_F,FE 1.12 < S_Fmin 1.3 at the design
    torque 753.2 N m" where the case's design torque is 643.8 N·m (the root-stress
    capacity of its developed bearing on the default model): 753.2 N·m was its ISO
    capacity, the torque the development started from.
    """
    why = str(setup.get("fe_level_why", ""))
    named = setup.get("fe_level_torque")
    if not why or named is None:
        return why
    written = plain_number(float(setup["torques"][1]))
    said = f"at the design torque {plain_number(float(named))} N m"
    if said not in why or written == plain_number(float(named)):
        return why
    return why.replace(said, f"at {plain_number(float(named))} N m, the design torque then "
                             f"checked (the design torque written: {written} N m)", 1)


def refined_for_root(case, setup: dict[str, Any], what: str, safety: float, s_min: float,
                     say: Callable[[str], None]):
    """Where the root check of ``case`` on a coarser FE level than
    :data:`DECIDING_LEVEL` fails (S_F,FE ``safety`` < S_Fmin ``s_min`` [1]) and so would
    limit a torque (``what``: the design torque or the coast design torque), the case on
    the default FE model: ``setup["fe_level"]`` and ``setup["fe_level_why"]`` set (every
    root check after reads that model, :func:`decided_case`, and the case written names
    it, :func:`contact.optimize.development.develop`), said through ``say``, both members'
    models of both flanks built (:func:`both_flanks_built`). None where ``case`` is None,
    already on the default model, or the check holds.

    Why: coarse10 reads the peak root stress −1.0 … +7.1 % of the default model's
    (docs/fe.md, "A coarse model for a new design"); where the root stress limits a
    torque, that reading is the torque's own error: on the face-hobbed 11×46 (2026-11-27)
    coarse10's S_F,FE 1.28 at the ISO capacity 1022 N·m cut it to 985.9 N·m (−3.5 %) and
    the coast design torque 733.6 → 694.7 N·m, while the default model holds 1022 N·m
    (S_F,FE 1.316). Designs whose torque the root stress does not limit keep the coarse
    level (no default build). docs/fe.md, "A root-limited torque decided on the default
    model".

    Returns
    -------
    geometry.case.Case or None
    """
    if case is None or not (math.isfinite(safety) and safety < s_min):
        return None
    from contact.compliance.fe.options import fe_level_of, with_fe_level

    level = fe_level_of(case)
    if level == DECIDING_LEVEL:
        return None
    from contact.study.verdicts import shown_below

    # what the coarse level reads, not "root stress limits the ...": the default model may
    # hold the torque (the FM 10x37 at Sigma 103 deg remedied, round 32 of issue 71: coarse10
    # 1.29 at 735 N m, the torque then cut by local pitting alone, S_F,FE 1.42 written)
    why = (f"the {level} FE level reads S_F,FE {shown_below(safety, s_min)} < S_Fmin "
           f"{s_min:g} at the {what}: the root stress there checked on the "
           f"{DECIDING_LEVEL} FE model, the one the torque is decided with (the {level} "
           f"level's peak root stress is -1.0 ... +7.1 % of the default model's, docs/fe.md)")
    setup.update(fe_level=DECIDING_LEVEL, fe_level_why=why)
    say(f"development: {why}")
    finer = with_fe_level(case, DECIDING_LEVEL)
    both_flanks_built(finer, None, say)
    return finer


def _in_worker_session(function: Callable) -> Callable:
    """``function`` run in a :func:`contact.compliance.fe.elasticity.worker_session`: the
    FE builds it makes share one solver worker (issue 75; imported when called)."""
    import functools

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        from contact.compliance.fe.elasticity import worker_session

        with worker_session():
            return function(*args, **kwargs)

    return wrapper


def _drive_cached(case, member: str) -> bool:
    """Whether the member's FE model of its drive flank (the case's level,
    :func:`contact.compliance.fe.options.case_fe_options`) has a cache entry (its
    file exists; :func:`contact.compliance.fe.contact_compliance.shared_coefficients`
    checks it when it reads it and builds it again where it fails a check)."""
    from contact.compliance.fe.cache import cache_key, cache_path
    from contact.compliance.fe.options import case_fe_options, member_flank

    try:
        key = cache_key(case.member(member), member_flank(case, member, "drive"),
                        case_fe_options(case))
        return cache_path(key).is_file()
    except OSError:
        return False


@_in_worker_session
def both_flanks_built(case, earlier=None,
                      say: Callable[[str], None] | None = None) -> dict[str, float]:
    """Both members' FE models of the written ``case`` (its level, ``[root_stress]
    fe_level``: :func:`contact.compliance.fe.options.case_fe_options`) built once for both flanks
    (:func:`contact.compliance.fe.influence_coefficients` with ``other_flank``: the coast
    flank's coefficients on the drive build's solid and factorisation, the same numbers as
    a build of their own), cached for the drive flank's root-stress check, the coast
    flank's and ``ltca run`` afterwards: 1.4–1.5 builds per member instead of 2 (issue 75).
    Where the drive flank's entry is cached, it is read into the process's memo the
    root-stress checks read it from (:func:`contact.compliance.fe.contact_compliance.
    shared_coefficients`), nothing built. A failure is logged and not raised: each check then
    builds (or fails to build) its own model and says so, as before.

    ``earlier``: the case whose models were built before (a re-synthesis of it is
    ``case``): a member whose FE load and stress points moved by no more than
    :data:`contact.compliance.fe.reuse.REUSE_DEPTH_FRACTION` of its whole depth keeps the
    earlier coefficients (:func:`contact.compliance.fe.reuse.reuse_near_model`, written
    under its new keys, so that ``ltca run`` reads them) instead of a build of its own
    (~28 s of CPU on a 9x41's pinion; the FE root stress within 0.8 % measured on four
    designs, docs/fe.md,
    "Coefficients kept for a re-synthesis").
    ``say`` (optional) gets one line per member compared: kept, or why not; and one
    before each member's build (a cold build is the longest stretch of ``ltca
    synthesize`` without a line: 85-138 s of wall time on a 9-fold loaded machine,
    docs/own_gear_set.md "Round 12").

    Returns
    -------
    dict — member → the largest node deviation [mm] of the members whose earlier
        coefficients were kept (empty where none)
    """
    from contact.compliance.fe import influence_coefficients
    from contact.compliance.fe.contact_compliance import (
        cached_entry,
        remember_written,
        shared_coefficients,
    )
    from contact.compliance.fe.options import case_fe_options
    from contact.compliance.fe.reuse import REUSE_DEPTH_FRACTION, reuse_near_model

    opt = case_fe_options(case)  # ltca run's model of the case written (its FE level)
    kept = {}
    for member in ("pinion", "gear"):
        if earlier is not None and earlier is not case:
            refused: list[str] = []
            try:
                # the earlier entries through the process's memo (built or read by the
                # first pass), the new ones kept there as written (issue 75)
                deviation = reuse_near_model(case, earlier, member, opt, refused=refused,
                                             read=cached_entry, written=remember_written)
            except Exception as exc:  # built below as before
                raise_if_interrupted(exc)
                log.info("development: the %s's earlier FE models not kept: %s", member, exc)
                deviation = None
            if deviation is not None and deviation > 0.0:
                kept[member] = deviation
                if say is not None:
                    say(f"development: the {member}'s FE models (both flanks) kept from the "
                        f"design checked before: its load and stress points within "
                        f"{1000.0 * deviation:.0f} um of them (<= "
                        f"{100.0 * REUSE_DEPTH_FRACTION:g} % of the whole depth; the FE root "
                        f"stress within 1 %, docs/fe.md)")
            elif refused and say is not None:
                say(f"development: the {member}'s FE models built again: {refused[0]}")
        try:
            if _drive_cached(case, member):
                # read once for the root-stress checks that follow (the process's memo of
                # contact.compliance.fe.contact_compliance.shared_coefficients): read
                # here and again there, ~0.25 s of CPU per file (issue 75)
                shared_coefficients(case, member, "drive", opt, progress=False)
            else:
                if say is not None:  # the longest stretch of a new design without a line
                    say(f"development: building the {member}'s FE models (both flanks) for "
                        "the root-stress checks, once per design and cached for `ltca "
                        "run` (~15-20 s of CPU per member, docs/fe.md)")
                # the four entries kept in the process's memo as written: the checks
                # that follow read none of them back from disk (issue 75)
                influence_coefficients(case, member, "drive", opt, progress=False,
                                       other_flank=True, written=remember_written)
        except Exception as exc:  # the checks build their own and report (never fatal)
            raise_if_interrupted(exc)
            log.info("development: the %s's FE models of both flanks not built: %s",
                     member, exc)
    return kept


def long_life_contact_allowable(rating):
    """σ_HP,∞ = σ_Hlim Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp [MPa] per member: the permissible
    contact stress at long life (Z_NT = 1) of an ISO 10300 rating dataset, the strength
    side of :func:`pitting_safety` and of
    :func:`contact.optimize.development_pitting.pitting_pressure_limit`.

    Parameters
    ----------
    rating : xarray.Dataset
        An ISO 10300 ``/rating`` (:func:`contact.load_capacity.iso10300.rating.iso10300_rating`)
        with ``sigma_Hlim`` [MPa] and the factors ``Z_X, Z_L, Z_speed, Z_R, Z_W, Z_K,
        Z_Hyp`` [1].

    Returns
    -------
    xarray.DataArray — [MPa], over ``member`` (and the factors' other dimensions)

    Raises
    ------
    KeyError
        A factor missing from ``rating``.

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 (Method B1), σ_HP = σ_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K
    Z_Hyp with Z_NT = 1 (ISO/TR 10300-30:2024 sample 1 checks the factors).
    """
    from contact.load_capacity.iso10300.allowable_factors import CONTACT_FACTORS

    allowable = rating["sigma_Hlim"]
    for name, _ in CONTACT_FACTORS:  # Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp, in this order
        allowable = allowable * rating[name]
    return allowable


def pitting_allowable_note(case, torque: float) -> str:
    """What the permissible contact stress at long life σ_HP,∞ of ``case``'s ISO 10300
    rating at ``torque`` is made of, naming its lowest factor — one phrase for the line
    that cuts the design torque to the local pitting capacity
    (:func:`contact.load_capacity.iso10300.allowable_factors.contact_allowable_text`);
    empty where the rating cannot be made (logged, never raised).

    Parameters
    ----------
    case : geometry.case.Case — with ``[design]`` and ``[rating]`` tables
    torque : float — [N·m] the pinion torque

    Returns
    -------
    str

    Notes
    -----
    Source: ISO 10300-2:2014 cl. 6 and 8, σ_HP = σ_Hlim Z_NT Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp
    (Z_NT = 1), at the case's ``[operating]`` pinion speed as
    :func:`contact.optimize.development_pitting.pitting_pressure_limit` rates it.

    Why: the unseen hypoid 11×43 at Σ 100°, a = 0.25 d_e2 (round 25) had its design torque
    cut to 0.81 of its ISO capacity against a local pitting limit of 998 MPa on σ_Hlim
    1500 MPa, and the line did not say that the hypoid factor Z_Hyp, at its lower bound
    0.6, made it (docs/own_gear_set.md, "The 11×43's local pitting limit").
    """
    from contact.load_capacity.iso10300.allowable_factors import contact_allowable_text
    from contact.load_capacity.iso10300.rating import iso10300_rating
    from geometry.core.operating_defaults import OPERATING_DEFAULTS

    try:
        table = {k: v for k, v in (case.extra.get("rating") or {}).items()
                 if k != "load_cycles"}
        speed = case.operating.pinion_speed or OPERATING_DEFAULTS["pinion_speed"]
        ds = iso10300_rating(case, torque=np.atleast_1d(float(torque)), pinion_speed=speed,
                             rating=table)
        return contact_allowable_text(ds)
    except Exception as exc:  # a phrase of a message: its absence is logged, not fatal
        raise_if_interrupted(exc)
        log.info("development: the local pitting limit's factors not said: %s", exc)
        return ""


def pitting_safety(tree) -> tuple[np.ndarray, float, str]:
    """(S_H,loc of the weaker member per torque [1], S_Hmin [1], its member) of an analysis
    with an ISO 10300 ``/rating`` at the LTCA's torques: the local flank safety at long life.

    S_H,loc = σ_HP,∞ / (p_max √(K_A K_v)), with p_max the LTCA's peak flank (contact-curve)
    pressure at each torque [MPa] (``/ltca/pressure_max_flank`` without the curves shorter
    than their contact width,
    :func:`contact.optimize.development_evaluate.flank_peak_pressure`; edge contact apart,
    as the duty cycle counts it), K_A and K_v the rating's, and σ_HP,∞ = σ_Hlim Z_X Z_L Z_v Z_R Z_W
    Z_K Z_Hyp per member [MPa] the rating's permissible stress at long life (Z_NT = 1,
    whatever ``load_cycles`` says).

    Parameters
    ----------
    tree : xarray.DataTree
        An analysis (:func:`contact.pipeline.run_analysis` with the load-capacity step).

    Returns
    -------
    (ndarray (torque,), float, str)

    Raises
    ------
    LookupError
        No ISO 10300 ``/rating`` at the LTCA's torques, or no flank pressure (the reason).

    Notes
    -----
    ISO 10300-2:2014 cl. 6 (Method B1): σ_H = σ_H0 √(K_A K_v K_Hβ K_Hα) with σ_H0 the
    mean-point Hertzian stress of the virtual cylindrical gears (Z_M-B, Z_LS: the decisive
    point and the sharing between the contact lines) and S_H = σ_HP / σ_H. ISO 10300-1:2014
    ranks Method A — factors from a comprehensive analysis of the loaded gear pair — above
    Method B; the LTCA's peak pressure is that analysis' σ_H0 √(K_Hβ K_Hα) of the developed
    bearing (its load along the face and between the pairs, at the decisive point it
    finds), so S_H,loc is S_H with the load distribution of the bearing itself; where the
    LTCA's pressure were σ_H0 √(K_Hβ K_Hα) it is S_H at long life (tested). The strength
    side keeps every factor of the rating, Z_K and Z_Hyp included (the empirical bevel and
    hypoid factors of the permissible stress, ISO/TR 10300-30:2024 sample 1); the same
    allowable is the knee of the duty cycle's S–N curve (ISO 6336-6:2019, Miner's rule on
    the curves of ISO 6336-2).
    """
    lt = tree["/ltca"].to_dataset()
    if "pressure_max_flank" not in lt:
        raise LookupError("no flank pressure in /ltca")
    rt = tree["/rating"].to_dataset() if "/rating" in tree.groups else None
    need = {"sigma_Hlim", "Z_X", "Z_L", "Z_speed", "Z_R", "Z_W", "Z_K", "Z_Hyp", "K_A", "K_v",
            "S_Hmin"}
    if rt is None or not need <= set(rt.variables):
        raise LookupError("no ISO 10300 rating (a pinion speed and a [rating] material are "
                          "needed)")
    from contact.optimize.development_evaluate import flank_peak_pressure

    # the contact curves' peak without those shorter than their contact width, as the
    # development's metrics read it (flank_peak_pressure: a curve clipped to a corner)
    p = flank_peak_pressure(lt)
    if not np.array_equal(np.asarray(rt["torque"].values, float),
                          np.asarray(lt["torque"].values, float)):
        raise LookupError("no ISO 10300 rating at the analysed torques")
    allow = long_life_contact_allowable(rt)
    members = [str(m) for m in allow["member"].values]
    k_v = np.broadcast_to(np.asarray(rt["K_v"].values, float), p.shape)
    load = p * np.sqrt(float(rt["K_A"]) * k_v)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.asarray(allow.values, float)[None, :] / load[:, None]  # (torque, member)
    j = int(np.nanargmin(s[-1])) if np.any(np.isfinite(s[-1])) else 0
    return s[:, j], float(rt["S_Hmin"]), members[j]


#: the criteria of :func:`root_capacity`: name → (safety of a tree, the safety's symbol,
#: its exponent's bounds and default: S ∝ T^(−b); the root stress grows about linearly
#: with the load, the Hertzian pressure as T^(1/3) at a point contact (Johnson 1985,
#: eq. 4.23) to T^(1/2) at a line contact)
CRITERIA: dict[str, tuple[Callable[[Any], tuple[np.ndarray, float, str]], str,
                          tuple[float, float, float]]] = {
    "root": (root_safety, "S_F,FE", (0.3, 1.0, 1.0)),
    "pitting": (pitting_safety, "S_H,loc", (0.2, 1.0, 1.0 / 3.0)),
}


def _safeties(tree, missing: dict[str, str] | None = None
              ) -> dict[str, tuple[np.ndarray, float, str]]:
    """Each criterion of :data:`CRITERIA` the analysis can give (the others said in the
    log and, where ``missing`` is given, put there: criterion → why)."""
    out = {}
    for name, (fn, _, _) in CRITERIA.items():
        try:
            out[name] = fn(tree)
        except LookupError as exc:
            log.info("development %s capacity not checked: %s", name, exc)
            if missing is not None:
                missing[name] = str(exc)
    return out


def _failing(safe: dict[str, tuple[np.ndarray, float, str]]) -> list[str]:
    """The criteria whose safety at the design torque (the last) is below its minimum."""
    return [k for k, (s, s_min, _) in safe.items()
            if math.isfinite(float(s[-1])) and float(s[-1]) < s_min]


def _root_tree(case, torques: list[float]):
    """``ltca run``'s drive-flank analysis of ``case`` at ``torques`` with the root stress
    (its default FE model) and the ISO 10300 rating, without the mesh interface (the
    efficiency stage is run: the rating takes the pinion speed from it, as in
    ``ltca run``)."""
    from contact.chain import AnalysisChain
    from contact.optimize.development import CHECK_LTCA
    from contact.pipeline import run_analysis

    steps = (AnalysisChain.contact_only().with_root_stress().with_efficiency()
             .with_load_capacity())
    return run_analysis(case, torques, flank="drive", options=CHECK_LTCA, deviations=False,
                        steps=steps)


def root_capacity(case, setup: dict[str, Any], light_load: float,
                  say: Callable[[str], None]) -> tuple[Any, float, str]:
    """Check the written ``case`` at the design torque (``setup["torques"][1]``) by the
    criteria of :data:`CRITERIA` — the FE root stress (S_F,FE >= S_Fmin) and the local
    pitting safety at long life (:func:`pitting_safety`, S_H,loc >= S_Hmin) — and lower the
    design torque to the capacity of the criteria that fail there: T ← the least
    :func:`root_capacity_step` over them, each with its exponent b of S ∝ T^(−b) measured
    between the light and the design torque, checked at the new light (``light_load`` ×
    T) and design torque and stepped again, b measured between the last two design
    torques, while one still fails (at most :data:`ROOT_STEPS`). ``setup`` gets the new
    torques, source and ``lowered`` where lowered. An analysis that fails is said through
    ``say`` and never raised (the torque last checked is kept). Where ``case``'s FE level
    is coarser than the default and its root check fails, the torque is decided on the
    default model (:func:`refined_for_root`: checked again there, and every check after).

    Returns
    -------
    (tree or None, S_F,FE, text)
        The analysis at the torques finally kept where the torque was lowered (its drive
        metrics replace the check's), else None; the weaker member's S_F,FE at the design
        torque written (NaN where not computed); one phrase for the case's records (empty
        where nothing was lowered).
    """
    torques = [float(t) for t in setup["torques"]]
    torque = torques[1]
    missing: dict[str, str] = {}
    try:
        case = decided_case(case, setup)
        safe = _safeties(_root_tree(case, torques), missing)
        if "root" in safe:  # a coarse level's failing root check: decided on the default
            s, s_min, _ = safe["root"]
            finer = refined_for_root(case, setup, f"design torque {plain_number(torque)} N m",
                                     float(s[-1]), s_min, say)
            if finer is not None:
                setup["fe_level_torque"] = torque  # the note's torque: design_torque_kept
                case, safe = finer, _safeties(_root_tree(finer, torques))
    except Exception as exc:  # reported, never fatal (ltca run says it)
        raise_if_interrupted(exc)
        log.info("development root stress check not made: %s", exc)
        say(f"development: root stress not checked ({exc}), nor the local pitting safety")
        return None, math.nan, ""
    if not safe:
        say("development: root stress and local pitting safety not checked (no FE root "
            "stress and no ISO 10300 rating)")
        return None, math.nan, ""
    for k, why in missing.items():  # one criterion alone not given: said, not only logged
        if k not in safe:
            say(f"development: {CRITERIA[k][1]} at {plain_number(torque)} N m not checked "
                f"({why}); the design torque decided without it")

    fails = _failing(safe)
    if not fails:
        say(f"development: at {plain_number(torque)} N m " + "; ".join(
            f"{CRITERIA[k][1]} {float(s[-1]):.2f} ({m}) >= {s_min:g}"
            for k, (s, s_min, m) in safe.items()))
        return None, _root_of(safe), ""
    first = {k: (float(safe[k][0][-1]), safe[k][1], safe[k][2]) for k in fails}
    # the exponent b of S ∝ T^(-b) first from the light and the design torque, then from
    # the last two design torques (the local slope)
    slope = {k: _exponent(torques[0], float(s[0]), torque, float(s[-1]),
                          CRITERIA[k][2][2], *CRITERIA[k][2][:2])
             for k, (s, _, _) in safe.items()}
    t, tree, used = torque, None, []
    for _ in range(ROOT_STEPS):
        steps = {k: root_capacity_step(t, float(safe[k][0][-1]), safe[k][1],
                                       exponent=slope[k]) for k in fails}
        why = min(steps, key=steps.get)
        new = steps[why]
        if new >= t:
            break
        checked = _checked_at(case, light_load, new, say)
        if checked is None:  # the last torque checked is kept
            break
        step, new_safe = checked
        tree, torques, used = step, case_torques(light_load, new), [*used, (why, slope[why])]
        slope = {k: _exponent(new, float(new_safe[k][0][-1]), t, float(safe[k][0][-1]),
                              slope[k], *CRITERIA[k][2][:2])
                 for k in new_safe if k in safe}
        bad = t
        t, safe = new, new_safe
        fails = _failing(safe)
        if not fails:
            break
    if tree is None:  # no lower torque checked
        return None, _root_of(safe), ""
    if not fails:  # back up inside the bracket where the step landed well below
        up = _back_up(case, light_load, t, bad, safe, slope, say)
        if up is not None:
            tree, torques, safe, t = up
            used = [*used, ("up", math.nan)]
    what = {"root": "its FE root stress gives", "pitting": "its LTCA peak flank pressure "
            "gives the local pitting safety at long life (sigma_HP / (p_max sqrt(K_A "
            "K_v)), ISO 10300 with the bearing's own load distribution)"}
    from contact.study.verdicts import shown_below

    factors = {"pitting": pitting_allowable_note(case, torque) if "pitting" in first else ""}
    was = "; ".join(f"{what[k]} {CRITERIA[k][1]} {shown_below(s, s_min)} ({m}) below "
                    f"{CRITERIA[k][1][:3]}"
                    f"min {s_min:g}" + (f" ({factors[k]})" if factors.get(k) else "")
                    for k, (s, s_min, m) in first.items())
    now = ", ".join(f"{CRITERIA[k][1]} ({m}) is "
                    + (f"{shown_below(float(s[-1]), s_min)} (still below)" if k in fails
                       else f"{float(s[-1]):.2f}")
                    for k, (s, s_min, m) in safe.items())
    symbols = "; ".join(dict.fromkeys(CRITERIA[k][1] for k, _ in used if k in CRITERIA))
    down = [u for u in used if u[0] in CRITERIA]
    up = len(down) < len(used)
    name = ("root-stress" if set(first) == {"root"} else
            "local pitting" if set(first) == {"pitting"} else "root-stress and local pitting")
    source = (f"the {name} capacity of the developed bearing: {was} at the design "
              f"torque {plain_number(torque)} N m ({setup['source'].split(',')[0].split(':')[0]}); "
              f"T (0.99 S/S_min)^(1/b) in {len(down)} step"
              f"{'s' if len(down) > 1 else ''}, b = "
              f"{'/'.join(f'{b:.2f}' for _, b in down)} measured ({symbols} ~ T^-b)"
              f"{', then one step back up with b measured between the two' if up else ''}"
              f" -> {plain_number(t)} N m, where {now}")
    say(f"  design torque {plain_number(torque)} -> {plain_number(t)} N m: {source}")
    setup.update(torques=torques, source=source, lowered=True)
    return tree, _root_of(safe), source


def given_torque_root(case, setup: dict[str, Any], say: Callable[[str], None]
                      ) -> tuple[float, str]:
    """The FE root stress of the written ``case`` at a design torque the basic file gives
    (``[synthesis]`` or ``[rating] design_torque``), checked as ``ltca run`` will judge it
    and said — the torque itself kept as given (:func:`root_capacity` lowers only the
    default design torque, the ISO 10300 capacity).

    Where the case's FE level is coarser than :data:`DECIDING_LEVEL` and its check fails,
    the torque is checked again on the default model (:func:`refined_for_root`:
    ``setup["fe_level"]`` set, so that the case written names it and ``ltca run`` reads
    it); where it fails there too, the returned sentence says so with an estimate of the
    torque the bearing carries: :func:`root_capacity_step` with the exponent b of
    S_F,FE ∝ T^(−b) measured between the light and the design torque (:func:`root_capacity`'s
    first step; not checked by an analysis).

    Why: a given torque skipped every root check, so the case kept the coarse level of the
    development (coarse10, whose peak root stress is −1.0 … +7.1 % of the default
    model's, docs/fe.md); the industrial spiral bevel 19×57 given 0.9 of its ISO capacity
    (2865.6 N·m; benchmarks/data/unseen_designs, round 20) then failed ``ltca run`` on
    coarse10's gear S_F,FE 1.28 < 1.3, while the default model reads 1.30 there
    (ATTENTION), and ``ltca synthesize`` had said nothing of the root.

    Parameters
    ----------
    case : geometry.case.Case — the case written (its ``[root_stress] fe_level``)
    setup : dict — the development's state: ``"torques"`` (light, design) [N·m]; gets
        ``"fe_level"`` and ``"fe_level_why"`` where the default model decided, and
        ``"given_root"`` (S_F,FE [1], S_Fmin [1], member) where S_F,FE < S_Fmin
    say : callable — one plain line per step (the CLI prints them)

    Returns
    -------
    safety : float — [1]
        S_F,FE of the weaker member at the design torque, on the model that decided; NaN
        where not computed (no FE root stress, no ISO 10300 rating, a failed analysis:
        said through ``say``, never raised).
    text : str
        Where S_F,FE < S_Fmin: the torque, the safety, that ``ltca run`` rates it FAIL and
        the torque the bearing carries; empty where it holds or was not computed.

    Raises
    ------
    KeyboardInterrupt
        Passed on (:func:`geometry.core.errors.raise_if_interrupted`); every other error
        of the analysis is said, not raised.

    Notes
    -----
    Source: the verdict's root-stress check (:func:`contact.study.verdict_checks.
    root_stress_safety`: S_F,FE = σ_FP / (σ_F,FE,max·K_A·K_v), ISO 10300-3's permissible
    stress on the FE peak fillet stress) at ``ltca run``'s sampling (:func:`_root_tree`).
    """
    from contact.study.verdicts import shown_below

    torques = [float(t) for t in setup["torques"]]
    torque = torques[1]
    try:
        case = decided_case(case, setup)
        s, s_min, member = root_safety(_root_tree(case, torques))
        finer = refined_for_root(case, setup, f"given design torque {plain_number(torque)} "
                                 f"N m", float(s[-1]), s_min, say)
        if finer is not None:
            s, s_min, member = root_safety(_root_tree(finer, torques))
    except Exception as exc:  # reported, never fatal (ltca run says it)
        raise_if_interrupted(exc)
        log.info("development root stress check at the given torque not made: %s", exc)
        say(f"development: root stress at the given design torque {plain_number(torque)} "
            f"N m not checked ({exc})")
        return math.nan, ""
    safety = float(s[-1])
    if not math.isfinite(safety):
        say(f"development: root stress at the given design torque {plain_number(torque)} "
            f"N m not computed (S_F,FE NaN)")
        return math.nan, ""
    if safety >= s_min:
        say(f"development: at the given design torque {plain_number(torque)} N m S_F,FE "
            f"{safety:.2f} ({member}) >= {s_min:g}")
        return safety, ""
    # for the bearing step that follows (development_given_root): the safety it starts
    # from, the minimum and the member
    setup["given_root"] = (safety, s_min, member)
    low, high, default = CRITERIA["root"][2]
    b = _exponent(torques[0], float(s[0]), torque, safety, default, low, high)
    holds = root_capacity_step(torque, safety, s_min, exponent=b)
    text = (f"the design torque {plain_number(torque)} N m the basic file gives is above "
            f"the developed bearing's root-stress capacity: its FE root stress gives S_F,FE "
            f"{shown_below(safety, s_min)} ({member}) below S_Fmin {s_min:g} there, which "
            f"`ltca run` rates FAIL; about {plain_number(holds)} N m would hold (T (0.99 "
            f"S_F,FE/S_Fmin)^(1/b), b = {b:.2f} measured between the light and the design "
            f"torque; an estimate, not analysed); without a given torque the development "
            f"lowers its design torque to the capacity it finds")
    say(f"development: {text}")
    return safety, text


def capacity_holds(case, torques, say: Callable[[str], None]) -> tuple[bool, str]:
    """Whether the written ``case`` holds every criterion of :data:`CRITERIA` at the design
    torque ``torques[1]`` — S_F,FE >= S_Fmin and S_H,loc >= S_Hmin, as :func:`root_capacity`
    judges them — the torque not changed: the check of a bearing developed at a torque
    below a capacity cut (``development._redeveloped_after_cut``), which may be kept only
    where its own capacity holds there.

    Parameters
    ----------
    case : geometry.case.Case
        The case written (on the FE level its development decided).
    torques : sequence of float, shape (2,) — [N·m]
        Its light and design torque.
    say : callable (str) → None
        Where a failed analysis is said.

    Returns
    -------
    holds : bool
        True where every criterion the analysis gives holds at the design torque; False
        where one fails, where the analysis fails or where it gives no criterion (nothing
        known: a bearing whose capacity is not known is not kept in place of one checked).
    text : str
        Each criterion with its safety, member and minimum ("S_F,FE 2.92 (gear) >= 1.3;
        S_H,loc 0.98 (pinion) < 1"), or why it was not checked.

    Raises
    ------
    KeyboardInterrupt
        Passed on; every other error of the analysis is said, not raised.

    Notes
    -----
    One analysis at ``ltca run``'s sampling with the root stress and the ISO 10300 rating
    (:func:`_root_tree`; the FE models are cached by the members' geometry). Source: the
    verdict's root-stress check and the local pitting safety of :func:`pitting_safety`
    (ISO 10300-2 with the LTCA's peak pressure); issue 71 ("one design torque that holds").
    """
    from contact.study.verdicts import shown_below

    ts = [float(t) for t in torques]
    try:
        safe = _safeties(_root_tree(case, ts))
    except Exception as exc:  # reported, never fatal
        raise_if_interrupted(exc)
        log.info("development capacity check at %g N m failed: %s", ts[1], exc)
        say(f"development: root stress at {plain_number(ts[1])} N m not computed ({exc})")
        return False, f"not checked ({exc})"
    if not safe:
        return False, "not checked (no FE root stress and no ISO 10300 rating)"
    fails = _failing(safe)
    text = "; ".join(
        f"{CRITERIA[k][1]} {shown_below(float(v[-1]), s_min)} ({m}) < {s_min:g}" if k in fails
        else f"{CRITERIA[k][1]} {float(v[-1]):.2f} ({m}) >= {s_min:g}"
        for k, (v, s_min, m) in safe.items())
    return not fails, text


def regained_capacity(case, setup: dict[str, Any], light_load: float, ceiling: float,
                      say: Callable[[str], None]
                      ) -> tuple[Any, list[float], float, float] | None:
    """The design torque raised back towards ``ceiling`` [N·m] where the written ``case``
    is a bearing developed *after* a capacity cut (:func:`root_capacity`): the cut was
    measured on the bearing before it, and the steps that followed at the lowered torques
    may have made one that carries more (the unseen hypoid 5×39 at a = 0.275 d_e2: cut
    72.2 → 47.4 N·m for local pitting, the bearing developed at 47.4 N·m then peaks at
    1095 MPa at 72.2 N·m against its local pitting limit 1089 MPa — S_H,loc 0.995, so it
    carries ≈ 70 N·m, not 47.4).

    The case is checked at ``ceiling`` by :data:`CRITERIA` (S_F,FE >= S_Fmin, S_H,loc >=
    S_Hmin); where every criterion holds there, the design torque is ``ceiling``. Else
    each failing criterion's exponent b of S ∝ T^(−b) is measured between the design
    torque (``setup["torques"][1]``) and ``ceiling`` (:func:`_exponent`, its bounds), the
    capacity estimated from ``ceiling`` by :func:`root_capacity_step` (margin 0.99) and
    checked there: kept where every criterion holds and it is above 1.01 × the design
    torque, else None (the torque written stays). At most three analyses; an analysis
    that fails is said through ``say``, never raised. ``setup`` is not changed: the caller
    re-scores the drive targets at the new torques and keeps them only where no target is
    lost.

    Parameters
    ----------
    case : Case — the written case (its FE models built: ``ltca run``'s)
    setup : dict — the development's state; ``setup["torques"]`` [N·m] (light, design)
    light_load : float — [1] the light torque's share of the design torque
    ceiling : float — [N·m] the torque before the cut (the rating's capacity or the
        static capacity), > the design torque

    Returns
    -------
    (tree, torques, torque, S_F,FE) or None
        The analysis at the new (light, design) torques [N·m], the design torque [N·m]
        and the weaker member's S_F,FE there [1] (NaN where not computed); None where the
        torque is not raised.

    Source: ISO 10300-2:2014 (S_H) and the FE root stress (S_F,FE), with the capacity
    step of :func:`root_capacity` (the issue-71 development, docs/synthesis.md
    "The design torque raised back on the final bearing").
    """
    torque = float(setup["torques"][1])
    if not (math.isfinite(ceiling) and ceiling > 1.01 * torque):
        return None
    case = decided_case(case, setup)  # the level the root-limited torque was decided on
    high = _checked_at(case, light_load, ceiling, say)
    if high is None:
        return None
    tree_hi, safe_hi = high
    if not safe_hi:
        return None
    fails = _failing(safe_hi)
    if not fails:
        return tree_hi, case_torques(light_load, ceiling), ceiling, _root_of(safe_hi)
    low = _checked_at(case, light_load, torque, say)
    if low is None:
        return None
    _, safe_lo = low
    if _failing(safe_lo):  # the written torque does not hold either: not this step's
        return None
    est = math.inf
    for k in fails:
        if k not in safe_lo:
            return None
        s_hi, s_min, _ = safe_hi[k]
        if not (float(s_hi[-1]) > 0 and math.isfinite(float(s_hi[-1]))):
            return None
        b = _exponent(torque, float(safe_lo[k][0][-1]), ceiling, float(s_hi[-1]),
                      CRITERIA[k][2][2], *CRITERIA[k][2][:2])
        est = min(est, root_capacity_step(ceiling, float(s_hi[-1]), s_min, exponent=b))
    new = floor_torque(min(est, ceiling))
    if not (1.01 * torque < new < ceiling):
        return None
    checked = _checked_at(case, light_load, new, say)
    if checked is None or not checked[1] or _failing(checked[1]):
        return None
    return checked[0], case_torques(light_load, new), new, _root_of(checked[1])


def _root_of(safe: dict) -> float:
    """The weaker member's S_F,FE at the design torque [1] of a safeties dict (NaN where
    the root stress was not computed)."""
    return float(safe["root"][0][-1]) if "root" in safe else math.nan


def _back_up(case, light_load: float, t: float, bad: float,
             safe: dict[str, tuple[np.ndarray, float, str]], slope: dict[str, float],
             say: Callable[[str], None]) -> tuple[Any, list[float], dict, float] | None:
    """One step back up from the torque ``t`` that holds towards ``bad`` (the last that
    failed): the least :func:`root_capacity_step` over the criteria from ``t``, with the
    exponents ``slope`` measured between the two, kept a tenth of the bracket's log-width
    inside it; analysed, and returned (tree, torques, safeties, torque) where every
    criterion holds there, else None. Not tried where the estimate is within 1 % of ``t``
    (the step landed at the capacity, to the margin): a design torque written well below
    what the bearing carries is a judgement as wrong as one above it."""
    est = min(root_capacity_step(t, float(s[-1]), s_min, exponent=slope.get(k, 1.0))
              for k, (s, s_min, _) in safe.items() if float(s[-1]) > 0)
    if not est > 1.01 * t:
        return None
    lo, hi = math.log(t), math.log(bad)
    x = min(max(math.log(est), lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo))
    new = floor_torque(math.exp(x))
    if not t < new < bad:
        return None
    checked = _checked_at(case, light_load, new, say)
    if checked is None or _failing(checked[1]):  # the torque that holds is kept
        return None
    return checked[0], case_torques(light_load, new), checked[1], new


def _checked_at(case, light_load: float, torque: float, say: Callable[[str], None]
                ) -> tuple[Any, dict[str, tuple[np.ndarray, float, str]]] | None:
    """The capacity check's analysis of ``case`` at ``torque`` [N·m] and its light torque
    (``light_load`` × it): (the analysis, its safeties of :data:`CRITERIA`), or None where
    it failed (logged and said, never raised)."""
    try:
        tree = _root_tree(case, case_torques(light_load, torque))
        return tree, _safeties(tree)
    except Exception as exc:  # reported, never fatal
        raise_if_interrupted(exc)
        log.info("development capacity check at %g N m failed: %s", torque, exc)
        say(f"development: root stress at {plain_number(torque)} N m not computed ({exc})")
        return None


def _exponent(t1: float, s1: float, t2: float, s2: float, default: float = 1.0,
              low: float = 0.3, high: float = 1.0) -> float:
    """b of S ∝ T^(−b) between two torques, bounded to [low, high] (``default`` where not
    measurable)."""
    if not (t1 > 0 and t2 > 0 and t1 != t2 and s1 > 0 and s2 > 0
            and math.isfinite(s1 * s2)):
        return default
    return min(high, max(low, math.log(s1 / s2) / math.log(t2 / t1)))


#: [1] the exponent b of S_H,loc ∝ T^(−b) :func:`pitting_capacity_bound` takes: a line
#: contact's (Hertz: p_max ∝ F^(1/2); a point contact's 1/3 and a pattern that grows
#: under load give less, hence a lower capacity than the bound)
BOUND_PITTING_EXPONENT = 0.5

#: [1] the range of the exponent b :func:`measured_pitting_exponent` measures on a bearing:
#: at most the line contact's :data:`BOUND_PITTING_EXPONENT` (a bearing's bound is never
#: above the Hertz one), at least the low end of the capacity step's pitting exponent
#: (:data:`CRITERIA`); measured between the light and the design torque on the eight
#: Formate bearings that set it: 0.268-0.467 (docs/own_gear_set.md, "The Formate gear's
#: cut foreseen with the bearing's own exponent")
MEASURED_PITTING_EXPONENT = (0.2, BOUND_PITTING_EXPONENT)


def measured_pitting_exponent(light_torque: float, light_safety: float, torque: float,
                              safety: float) -> float:
    """[1] The exponent b of S_H,loc ∝ T^(−b) between two torques one analysis of a
    bearing took, within :data:`MEASURED_PITTING_EXPONENT`.

    Parameters
    ----------
    light_torque, torque : float — [N·m]
        The analysis's light and design torque (any two distinct positive torques).
    light_safety, safety : float — [1]
        S_H,loc at each (:func:`pitting_safety`).

    Returns
    -------
    float
        b = ln(S_light / S) / ln(T / T_light), bounded to [0.2, 0.5];
        :data:`BOUND_PITTING_EXPONENT` where it cannot be measured (equal torques, a
        safety not finite or not positive).

    Notes
    -----
    Source: the power law the capacity steps take (:func:`root_capacity`, b measured
    between the light and the design torque); issue 71/75, branch cut85: the line
    contact's b = 1/2 left the 13x41 at Σ 62°'s Formate bound at 118.9 N·m against its
    final 86.6 N·m; b 0.338 measured gives 89.0 N·m.
    """
    low, high = MEASURED_PITTING_EXPONENT
    return _exponent(float(light_torque), float(light_safety), float(torque),
                     float(safety), BOUND_PITTING_EXPONENT, low, high)


def pitting_capacity_bound(case, torques: list[float], measured: bool = False) -> float:
    """[N·m] An upper estimate of the drive flank's local pitting capacity of ``case`` from
    one analysis at ``torques`` (light, design [N·m]) without the FE root stress (no FE
    model built): T · (S_H,loc / S_Hmin)^(1/b) with b = :data:`BOUND_PITTING_EXPONENT`
    (``measured``: b measured between the analysis's two torques,
    :func:`measured_pitting_exponent`, at most that) where S_H,loc at the design torque T
    is below S_Hmin (:func:`pitting_safety`), else inf; inf where the analysis fails
    (logged). :func:`root_capacity` lowers the design torque to at most its own estimate
    with b measured on the bearing (≤ 1, a lower capacity for b < 1/2) and never raises it
    above the torque it checked.

    Why: a second gear process's development (``outclassed_below``,
    :func:`contact.optimize.development_process.outclassing_torque`) stops here before its
    coast flank, its synthesis and its FE build where it could not end above the first
    one's design torque. Measured on the spiral bevel 13x37 at Σ 60° of
    benchmarks/data/unseen_designs (2026-11-26): its generated gear's drive design, S_H,loc
    0.68 at its static capacity 209.6 N m (bound 96.9 N m), ended at 18 N m after a coast
    development and an FE build (~70 s of CPU), below the Formate design's 110.4 N m. The
    measured exponent is the Formate foresight's
    (:func:`contact.optimize.development_process.cut_foreseen`, branch cut85): an estimate
    of where the development ends rather than a bound above it."""
    from contact.chain import AnalysisChain
    from contact.optimize.development import CHECK_LTCA
    from contact.pipeline import run_analysis

    try:
        tree = run_analysis(case, [float(t) for t in torques], flank="drive",
                            options=CHECK_LTCA, deviations=False,
                            steps=AnalysisChain.contact_only().with_efficiency()
                            .with_load_capacity())
        safety, s_min, _ = pitting_safety(tree)
    except Exception as exc:  # no bound: the development goes on
        raise_if_interrupted(exc)
        log.info("development: no local pitting bound: %s", exc)
        return math.inf
    safeties = np.asarray(safety, dtype=float)
    s = float(safeties[-1])
    b = BOUND_PITTING_EXPONENT
    if measured:
        b = measured_pitting_exponent(torques[0], float(safeties[0]), torques[-1], s)
    log.info("development: S_H,loc %.4f / %.4f at %.1f / %.1f N m (S_Hmin %g), b %.3f",
             float(safeties[0]), s, float(torques[0]), float(torques[-1]), s_min, b)
    if not (math.isfinite(s) and s > 0.0 and s_min > 0.0) or s >= s_min:
        return math.inf
    return float(torques[-1]) * (s / s_min) ** (1.0 / b)
