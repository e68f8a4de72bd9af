"""The ``/ltca`` dataset of a loaded TCA: loads, pressures, LTE and its summary.

Every variable carries ``units`` and ``long_name`` (the exchange names of DESIGN.md:
``transmission_error`` [µrad] over (``torque``, ``roll``); ``force`` [N] and
``pressure_max`` [MPa] over (``torque``, ``roll``, ``pair``, ``segment``); ``load_share``
[1] over (``torque``, ``roll``, ``pair``)); the state of every segment
(``segment_state``: free, elastic or plastic, CF flags), its force limit and the share of
the torque carried at the limit; the attributes record the solver, the transitions, the
options and the misalignment as JSON, the edge radii, the materials and their pressure
limits, and the members' axes (which the efficiency stage needs).

Public functions
----------------
ltca_dataset        assemble the ``/ltca`` Dataset
json_misalignment   a Misalignment as JSON text
"""

from __future__ import annotations

import json

import numpy as np
import xarray as xr

from contact.ltca.edges import EDGE_KINDS
from contact.ltca.options import LTCASetup, edge_radii, json_options
from contact.ltca.plastic import force_limits, pressure_limits
from contact.ltca.results import SEGMENT_STATES, RollResults
from contact.ltca.screening import Screening
from contact.ltca.segments import Segments
from contact.ltca.transmission_error import transmission_error_summary
from contact.qp.problem import RESIDUALS
from contact.qp.solvers import solver_name
from geometry import __version__
from geometry.core.conventions import binary_flag, dataset
from geometry.core.conventions import data_var as _var
from geometry.core.hertz import contact_modulus

__all__ = ["json_misalignment", "ltca_dataset"]

_DIMS4 = ("torque", "roll", "pair", "segment")
_DIMS3 = ("torque", "roll", "pair")
_DIMS2 = ("torque", "roll")
_SEGMENT_DIMS = ("roll", "pair", "segment")


def ltca_dataset(setup: LTCASetup, seg: Segments, screening: Screening,
                 results: RollResults, timing: dict[str, float], *,
                 force_limit: np.ndarray | None = None) -> xr.Dataset:
    """The ``/ltca`` Dataset of an analysis.

    Parameters
    ----------
    setup : LTCASetup
        Case, ease-off, options, torques (NT,) [N·m], roll positions (J,) [rad],
        transitions.
    seg : Segments
        The segments (J, K, S) the problems were built on.
    screening : Screening
        Their separations [mm] and each roll's UTE [rad].
    results : RollResults
        The solutions (NT, J, K, S).
    timing : dict
        ``easeoff`` and ``segments`` times [s]; ``compliance_asymmetry`` [1] (optional).
    force_limit : ndarray (J, K, S), optional — [N]
        The segments' force limits as the solves took them
        (:func:`contact.ltca.plastic.force_limits` of ``seg``, ``inf`` where a kind has
        none); default: computed here from ``seg`` (the same numbers, elementwise).

    Returns
    -------
    xarray.Dataset
        Dims ``torque``, ``roll``, ``pair``, ``segment``, ``harmonic``, ``u``, ``v``,
        ``xyz``; see the module docstring.
    """
    lte = (screening.ute[None, :] + results.rotation) * 1e6  # (NT, J) urad
    data = {
        **_load_vars(lte, screening, results),
        **_segment_vars(seg, screening),
        **_plastic_vars(setup, seg, results, force_limit),
        **_solution_vars(seg, results),
        **_summary_vars(setup, seg, results, lte),
    }
    return dataset(data, _coords(setup, seg), _attrs(setup, timing))


def _load_vars(lte: np.ndarray, screening: Screening, results: RollResults) -> dict:
    """The LTE (NT, J) [µrad], the loaded rotation, the UTE and the per-segment loads."""
    return {
        "transmission_error": _var(_DIMS2, lte, "urad",
                                   "loaded transmission error (gear lag, UTE + loaded rotation)"),
        "loaded_rotation": _var(_DIMS2, results.rotation * 1e6, "urad",
                                "loaded rotation Theta of the contact problem"),
        "unloaded_transmission_error": _var(("roll",), screening.ute * 1e6, "urad",
                                            "unloaded transmission error (lower envelope)"),
        "force": _var(_DIMS4, results.force, "N", "segment force"),
        "load_per_length": _var(_DIMS4, results.load_per_length, "N/mm",
                                "load per unit length"),
        "pressure_max": _var(_DIMS4, results.pressure_max, "MPa",
                             "maximum Hertzian pressure (line contact)"),
        "half_width": _var(_DIMS4, results.half_width, "mm", "Hertzian half-width"),
        "contact": _var(_DIMS4, results.contact, "1", "segment in contact (1) or open (0)",
                        **binary_flag("open", "in_contact")),
        "in_problem": _var(_DIMS4, results.in_problem, "1",
                           "segment in the contact problem (1) or left out, its gap open "
                           "(0)", **binary_flag("left_out", "in_problem")),
    }


def _segment_vars(seg: Segments, screening: Screening) -> dict:
    """The geometry of the segments over (roll, pair, segment)."""
    d = _SEGMENT_DIMS
    return {
        "separation": _var(d, screening.separation, "mm",
                           "initial separation (ease-off relative to the UTE)"),
        "moment_arm": _var(d, seg.moment_arm, "mm",
                           "moment arm of the contact normal about the gear axis"),
        "segment_length": _var(d, seg.length, "mm", "segment length"),
        "equivalent_radius": _var(d, seg.r_eq, "mm",
                                  "equivalent radius across the contact line"),
        "segment_u": _var(d, seg.u, "1",
                          "gear lengthwise fraction of the segment midpoint (toe 0, heel 1)"),
        "segment_v": _var(d, seg.v, "1",
                          "gear profile fraction of the segment midpoint (root 0, tip 1)"),
        "segment_position": _var((*d, "xyz"), seg.midpoint, "mm",
                                 "segment midpoint on the reference gear tooth, gear frame"),
        "contact_point": _var((*d, "xyz"), seg.midpoint_pair, "mm",
                              "segment midpoint in the pair frame at the roll position"),
        "contact_normal": _var((*d, "xyz"), seg.normal_pair, "1",
                               "contact normal (out of the pinion) in the pair frame"),
        "contact_tangent": _var((*d, "xyz"), seg.tangent_pair, "1",
                                "unit tangent of the contact line in the pair frame"),
    }


def _plastic_vars(setup: LTCASetup, seg: Segments, results: RollResults,
                  limit: np.ndarray | None = None) -> dict:
    """The segments' states (free, elastic, plastic), their force limits (``limit``, the
    solves', else computed here) and the share of the torque carried at the limits."""
    if limit is None:
        opts = setup.options
        modulus = contact_modulus(opts.youngs_modulus, opts.poisson_ratio,
                                  opts.youngs_modulus, opts.poisson_ratio)
        limit = force_limits(seg.kind[None, None, :], seg.length, seg.r_eq,
                             pressure_limits(setup.case, opts), modulus)
    limit = (np.full(seg.shape, np.nan) if limit is None
             else np.where(np.isfinite(limit), limit, np.nan))
    plastic = results.state == 2
    torque = np.nan_to_num(results.force) * np.nan_to_num(seg.moment_arm)[None]
    total = np.sum(torque, axis=(-2, -1))
    share = np.sum(np.where(plastic, torque, 0.0), axis=(-2, -1)) / np.where(
        total > 0, total, 1.0)
    share = np.where(results.found > 0, share, np.nan)
    return {
        "segment_state": _var(_DIMS4, results.state, "1",
                              "segment state: unloaded (free), loaded below its force limit "
                              "(elastic), at its limit (plastic)",
                              flag_values=np.arange(len(SEGMENT_STATES), dtype=np.int8),
                              flag_meanings=" ".join(SEGMENT_STATES)),
        "force_limit": _var(_SEGMENT_DIMS, limit, "N",
                            "largest force of the segment: its Hertz line contact at the "
                            "material's contact-pressure limit (NaN: no limit)"),
        "plastic_load_share": _var(_DIMS2, share, "1",
                                   "share of the gear torque carried by segments at their "
                                   "force limit"),
        "plastic_segments": _var(("torque",), np.sum(plastic, axis=(1, 2, 3)), "1",
                                 "segments at their force limit, counted over the roll "
                                 "positions"),
    }


def _solution_vars(seg: Segments, results: RollResults) -> dict:
    """Load sharing, edge contact, certification, solver status, residuals and times."""
    F = np.nan_to_num(results.force)
    R = np.nan_to_num(seg.moment_arm)[None]
    pair_torque = np.sum(F * R, axis=-1)  # (NT, J, K) N·mm
    share = pair_torque / np.maximum(pair_torque.sum(axis=-1, keepdims=True), 1e-300)
    share = np.where(results.found[..., None] > 0, share, np.nan)
    # edge contact: the first or last segment of a curve (on the flank boundary: the gear
    # blank's edge where the curve ends, the pinion blank's edge where it is clipped) or an
    # edge segment loaded
    loaded = results.contact > 0
    curve = seg.kind == 0
    valid = np.isfinite(seg.r_eq) & (seg.length > 0)
    edge = (_edge_loaded(loaded[..., curve], valid[..., curve])
            | np.any(loaded[..., ~curve], axis=-1)).astype(np.int8)
    pairs_in_contact = np.sum(np.any(loaded, axis=-1), axis=-1)
    return {
        "load_share": _var(_DIMS3, share, "1", "share of the gear torque carried by the pair"),
        "edge_contact": _var(_DIMS3, edge, "1",
                             "load reaches the end of the pair's contact curve (flank edge)",
                             **binary_flag("within_flank", "edge_contact")),
        "pairs_in_contact": _var(_DIMS2, pairs_in_contact, "1", "number of pairs in contact"),
        "found": _var(_DIMS2, results.found, "1", "certified solution found (1) or not (0)",
                      **binary_flag("not_found", "found")),
        "status": _var(_DIMS2, results.status.astype(str), None, "solver status"),
        "solve_time": _var(_DIMS2, results.solve_time, "s",
                           "solver time over the Weber iterations"),
        "weber_iterations": _var(_DIMS2, results.weber_iterations, "1",
                                 "Weber linearisation iterations"),
        "compliance_time": _var(("roll",), results.compliance_time, "s",
                                "compliance assembly time"),
        "n_segments": _var(("roll",), results.n_segments, "1",
                           "segments in the contact problem"),
        **{f"residual_{r}": _var(_DIMS2, results.residuals[r], "1", f"relative {r} residual")
           for r in RESIDUALS},
    }


def _summary_vars(setup: LTCASetup, seg: Segments, results: RollResults,
                  lte: np.ndarray) -> dict:
    """The summary of the LTE (NT, J) [µrad] over the mesh cycles, the peak pressures and
    the loaded pattern."""
    summ, harm = _lte_summary(setup, lte)
    curve = seg.kind == 0
    return {
        "lte_mean": _var(("torque",), summ["mean"], "urad", "mean loaded transmission error"),
        "lte_peak_to_peak": _var(("torque",), summ["peak_to_peak"], "urad",
                                 "peak-to-peak loaded transmission error"),
        "lte_harmonics": _var(("torque", "harmonic"), harm, "urad",
                              "amplitude of the mesh harmonics of the LTE"),
        "lte_rms": _var(("torque",), summ["rms"], "urad", "RMS of the LTE about its mean"),
        "lte_harmonic_rss": _var(("torque",), summ["harmonic_rss"], "urad",
                                 "root-sum-square of the first three harmonic amplitudes "
                                 "(the seed's Table 3.1 RMS)"),
        "pressure_max_flank": _var(("torque",), _peak(results.pressure_max, curve), "MPa",
                                   "peak Hertzian pressure on the contact curves (line "
                                   "contact of the flanks)"),
        "pressure_max_edge": _var(("torque",), _peak(results.pressure_max, ~curve), "MPa",
                                  "peak Hertzian pressure of the edge contact (edge rounding "
                                  "on the mating flank; 0 where none)"),
        "pressure_envelope": _var(("torque", "u", "v"),
                                  _pressure_envelope(setup, seg, results.pressure_max), "MPa",
                                  "loaded contact pattern: envelope of the maximum pressure "
                                  "over the roll positions, on the gear grid"),
    }


def _lte_summary(setup: LTCASetup, lte: np.ndarray) -> tuple[dict, np.ndarray]:
    """Mean, peak-to-peak, RMS and harmonic RSS (NT,) and the first three harmonic
    amplitudes (NT, 3) [µrad] of the LTE (NT, J) over the mesh cycles (NaN where a roll
    has no solution or the sampling does not resolve a harmonic: 2n + 1 ≤ samples per
    cycle)."""
    NT = lte.shape[0]
    roll, cycles = setup.roll, setup.options.cycles
    harm = np.full((NT, 3), np.nan)
    summ = {k: np.full(NT, np.nan) for k in ("mean", "peak_to_peak", "rms", "harmonic_rss")}
    n_h = min(3, (roll.size // max(cycles, 1) - 1) // 2)
    for it in range(NT):
        if np.all(np.isfinite(lte[it])) and n_h >= 1:
            s = transmission_error_summary(roll, lte[it], setup.easeoff.pitch, n_h)
            harm[it, :n_h] = s["harmonics"]
            for k in summ:
                summ[k][it] = s[k]
    return summ, harm


def _pressure_envelope(setup: LTCASetup, seg: Segments, pressure: np.ndarray) -> np.ndarray:
    """(NT, nu, nv) [MPa] the loaded contact pattern: the envelope of the maximum pressure
    (NT, J, K, S) over the roll positions, on the nearest gear grid nodes."""
    eo = setup.easeoff
    nu, nv = eo.u.size, eo.v.size
    env = np.zeros((pressure.shape[0], nu, nv))
    # the ease-off grid fractions are uniform in [u0, u1] × [v0, v1]: nearest node
    u0, u1 = float(eo.u[0]), float(eo.u[-1])
    v0, v1 = float(eo.v[0]), float(eo.v[-1])
    ui = np.rint((seg.u - u0) / (u1 - u0) * (nu - 1))
    vi = np.rint((seg.v - v0) / (v1 - v0) * (nv - 1))
    good = np.isfinite(ui) & np.isfinite(vi)
    uu = np.clip(np.where(good, ui, 0), 0, nu - 1).astype(int)
    vv = np.clip(np.where(good, vi, 0), 0, nv - 1).astype(int)
    for it in range(pressure.shape[0]):
        p = np.nan_to_num(pressure[it])
        np.maximum.at(env[it], (uu[good], vv[good]), p[good])
    return env


def _coords(setup: LTCASetup, seg: Segments) -> dict:
    eo, roll = setup.easeoff, setup.roll
    return {
        "torque": ("torque", setup.torques, {"units": "N m", "long_name": "pinion torque"}),
        "gear_torque": ("torque", setup.torques * eo.ratio,
                        {"units": "N m", "long_name": "gear torque (lossless)"}),
        "roll": ("roll", roll, {"units": "rad",
                                "long_name": "pinion roll angle (Q units, driving sense)"}),
        "pair": ("pair", np.asarray(setup.options.pairs),
                 {"units": "1", "long_name": "tooth-pair offset"}),
        "segment": ("segment", np.arange(seg.shape[2]),
                    {"units": "1", "long_name": "segment index"}),
        "segment_kind": ("segment", np.array(("curve", *EDGE_KINDS))[seg.kind],
                         {"long_name": "contact curve segment, or the flank edge of an edge "
                                       "segment (contact.ltca.EDGE_KINDS)"}),
        "harmonic": ("harmonic", np.arange(1, 4), {"units": "1",
                                                   "long_name": "mesh harmonic order"}),
        "u": ("u", np.asarray(eo.u), {"units": "1", "long_name": "gear lengthwise fraction"}),
        "v": ("v", np.asarray(eo.v), {"units": "1", "long_name": "gear profile fraction"}),
        "xyz": ("xyz", ["x", "y", "z"], {"long_name": "Cartesian component"}),
        "mesh_cycle": ("roll", (roll - roll[0]) / eo.pitch,
                       {"units": "1", "long_name": "mesh cycles from the first roll position"}),
    }


def _attrs(setup: LTCASetup, timing: dict[str, float]) -> dict:
    case, eo, opts = setup.case, setup.easeoff, setup.options
    m1, m2 = setup.transitions
    radii = edge_radii(case, opts) if opts.edge_contact else (np.nan, np.nan)
    p_edge, p_flank = (p if np.isfinite(p) else np.nan for p in pressure_limits(case, opts))
    return {
        "title": "loaded tooth contact analysis",
        "case": case.name,
        "toolkit_version": __version__,
        "pinion_flank": eo.pinion_flank,
        "gear_flank": eo.gear_flank,
        "solver": solver_name(opts.solver),
        "mesh_period_rad": eo.pitch,
        "transition_M1_rad": float(m1),
        "transition_M2_rad": float(m2),
        "options": json_options(opts),
        "time_easeoff_s": timing["easeoff"],
        "time_segments_s": timing["segments"],
        # largest relative asymmetry of the compliance blocks before symmetrisation (the
        # limit: contact.errors.ASYMMETRY_LIMIT; Maxwell–Betti)
        "compliance_asymmetry": float(timing.get("compliance_asymmetry", 0.0)),
        "misalignment": json_misalignment(case.misalignment),
        "ratio": float(eo.ratio),
        "edge_radius_pinion_mm": radii[0],
        "edge_radius_gear_mm": radii[1],
        "material_pinion": case.pinion.material,
        "material_gear": case.gear.material,
        # the contact-pressure limits (peak Hertz pressure) of the edge and flank segments
        # (NaN: off; LTCAOptions.edge_pressure_limit, flank_pressure_limit)
        "edge_pressure_limit_MPa": float(p_edge),
        "flank_pressure_limit_MPa": float(p_flank),
        "pinion_axis": np.asarray(eo.kinematics.pinion_axis, float),
        "pinion_origin_mm": np.asarray(eo.kinematics.pinion_origin, float),
        "gear_axis": np.asarray(eo.kinematics.gear_axis, float),
        "gear_origin_mm": np.asarray(eo.kinematics.gear_origin, float),
    }


def _peak(p: np.ndarray, which: np.ndarray) -> np.ndarray:
    """(NT,) largest of p (NT, J, K, S) over the segments ``which`` (0 where none)."""
    sel = np.nan_to_num(p[..., which])
    return sel.max(axis=(1, 2, 3)) if sel.size else np.zeros(p.shape[0])


def _edge_loaded(loaded: np.ndarray, valid: np.ndarray) -> np.ndarray:
    """(..., K) whether the first or last valid segment of each curve is loaded.

    ``loaded`` (NT, J, K, S) contact flags; ``valid`` (J, K, S) the segments of each
    curve (its ends lie on the flank boundary).
    """
    S = valid.shape[-1]
    have = valid.any(axis=-1)
    first = np.argmax(valid, axis=-1)
    last = S - 1 - np.argmax(valid[..., ::-1], axis=-1)
    at_first = np.take_along_axis(loaded, np.broadcast_to(first[None, ..., None],
                                                          (*loaded.shape[:-1], 1)), -1)
    at_last = np.take_along_axis(loaded, np.broadcast_to(last[None, ..., None],
                                                         (*loaded.shape[:-1], 1)), -1)
    return (at_first[..., 0] | at_last[..., 0]) & have[None]


def json_misalignment(m) -> str:
    """A Misalignment as JSON text, names with units (ΔE, ΔP, ΔG [mm], ΔΣ [deg]:
    :meth:`geometry.pair.assembly.Misalignment.labelled`), as the UTCA datasets record it."""

    return json.dumps(m.labelled())
