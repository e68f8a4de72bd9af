"""The ``/ltca`` dataset of a loaded TCA: loads, pressures, LTE and its summary.

Public functions
----------------
ltca_dataset        assemble the ``/ltca`` Dataset
json_misalignment   a Misalignment as JSON text
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import xarray as xr

from contact.ltca.edges import EDGE_KINDS
from contact.ltca.options import edge_radii, json_options
from contact.ltca.transmission_error import transmission_error_summary
from contact.qp.problem import RESIDUALS
from geometry import __version__
from geometry.conventions import data_var as _var

__all__ = ["json_misalignment", "ltca_dataset"]


def ltca_dataset(case, eo, opts, torques, roll, seg, sep_all, ute_env, out, contact,
                  in_problem, rotation, resid, found, status, solve_time, weber_iters,
                  compliance_time, n_seg, m1, m2, timing) -> xr.Dataset:
    NT, _J, _K, S = out["force"].shape
    F = np.nan_to_num(out["force"])
    R = np.nan_to_num(seg["moment_arm"])[None]
    pair_torque = np.sum(F * R, axis=-1)  # (NT, J, K) N·mm
    share = pair_torque / np.maximum(pair_torque.sum(axis=-1, keepdims=True), 1e-300)
    share = np.where(found[..., None] > 0, share, np.nan)
    lte = (ute_env[None, :] + rotation) * 1e6  # urad
    # edge contact: the first or last segment of a curve (on the flank boundary: the gear
    # blank's edge where the curve ends, the pinion blank's edge where it is clipped) or an
    # edge segment loaded
    loaded = contact > 0
    curve = seg["kind"] == 0
    valid = np.isfinite(seg["r_eq"]) & (seg["length"] > 0)
    edge = (_edge_loaded(loaded[..., curve], valid[..., curve])
            | np.any(loaded[..., ~curve], axis=-1)).astype(np.int8)
    pairs_in_contact = np.sum(np.any(loaded, axis=-1), axis=-1)
    # LTE summary over the mesh cycles
    harm = np.full((NT, 3), np.nan)
    summ = {k: np.full(NT, np.nan) for k in ("mean", "peak_to_peak", "rms", "harmonic_rss")}
    # harmonics the roll sampling resolves: 2n + 1 ≤ samples per cycle (else NaN)
    n_h = min(3, (roll.size // max(opts.cycles, 1) - 1) // 2)
    for it in range(NT):
        if np.all(np.isfinite(lte[it])) and n_h >= 1:
            s = transmission_error_summary(roll, lte[it], eo.pitch, n_h)
            harm[it, :n_h] = s["harmonics"]
            for k in summ:
                summ[k][it] = s[k]
    # loaded contact pattern: envelope of the maximum pressure on the gear grid nodes
    nu, nv = eo.u.size, eo.v.size
    env = np.zeros((NT, nu, nv))
    # the ease-off grid fractions are uniform in [u0, u1] × [v0, v1]: nearest node
    u0, u1 = float(eo.u[0]), float(eo.u[-1])
    v0, v1 = float(eo.v[0]), float(eo.v[-1])
    ui = np.rint((seg["u"] - u0) / (u1 - u0) * (nu - 1))
    vi = np.rint((seg["v"] - v0) / (v1 - v0) * (nv - 1))
    good = np.isfinite(ui) & np.isfinite(vi)
    uu = np.clip(np.where(good, ui, 0), 0, nu - 1).astype(int)
    vv = np.clip(np.where(good, vi, 0), 0, nv - 1).astype(int)
    for it in range(NT):
        p = np.nan_to_num(out["pressure_max"][it])
        np.maximum.at(env[it], (uu[good], vv[good]), p[good])
    pairs = np.asarray(opts.pairs)
    dims4 = ("torque", "roll", "pair", "segment")
    dims3 = ("torque", "roll", "pair")
    dims2 = ("torque", "roll")
    data = {
        "transmission_error": _var(dims2, lte, "urad",
                                   "loaded transmission error (gear lag, UTE + loaded rotation)"),
        "loaded_rotation": _var(dims2, rotation * 1e6, "urad",
                                "loaded rotation Theta of the contact problem"),
        "unloaded_transmission_error": _var(("roll",), ute_env * 1e6, "urad",
                                            "unloaded transmission error (lower envelope)"),
        "force": _var(dims4, out["force"], "N", "segment force"),
        "load_per_length": _var(dims4, out["load_per_length"], "N/mm", "load per unit length"),
        "pressure_max": _var(dims4, out["pressure_max"], "MPa",
                             "maximum Hertzian pressure (line contact)"),
        "half_width": _var(dims4, out["half_width"], "mm", "Hertzian half-width"),
        "contact": _var(dims4, contact, "1", "segment in contact (1) or open (0)"),
        "in_problem": _var(dims4, in_problem, "1",
                           "segment in the contact problem (1) or left out, its gap open "
                           "(0)"),
        "separation": _var(("roll", "pair", "segment"), sep_all, "mm",
                           "initial separation (ease-off relative to the UTE)"),
        "moment_arm": _var(("roll", "pair", "segment"), seg["moment_arm"], "mm",
                           "moment arm of the contact normal about the gear axis"),
        "segment_length": _var(("roll", "pair", "segment"), seg["length"], "mm",
                               "segment length"),
        "equivalent_radius": _var(("roll", "pair", "segment"), seg["r_eq"], "mm",
                                  "equivalent radius across the contact line"),
        "segment_u": _var(("roll", "pair", "segment"), seg["u"], "1",
                          "gear lengthwise fraction of the segment midpoint (toe 0, heel 1)"),
        "segment_v": _var(("roll", "pair", "segment"), seg["v"], "1",
                          "gear profile fraction of the segment midpoint (root 0, tip 1)"),
        "segment_position": _var(("roll", "pair", "segment", "xyz"), seg["midpoint"], "mm",
                                 "segment midpoint on the reference gear tooth, gear frame"),
        "contact_point": _var(("roll", "pair", "segment", "xyz"), seg["midpoint_pair"], "mm",
                              "segment midpoint in the pair frame at the roll position"),
        "contact_normal": _var(("roll", "pair", "segment", "xyz"), seg["normal_pair"], "1",
                               "contact normal (out of the pinion) in the pair frame"),
        "contact_tangent": _var(("roll", "pair", "segment", "xyz"), seg["tangent_pair"], "1",
                                "unit tangent of the contact line in the pair frame"),
        "load_share": _var(dims3, share, "1", "share of the gear torque carried by the pair"),
        "edge_contact": _var(dims3, edge, "1",
                             "load reaches the end of the pair's contact curve (flank edge)"),
        "pairs_in_contact": _var(dims2, pairs_in_contact, "1", "number of pairs in contact"),
        "found": _var(dims2, found, "1", "certified solution found (1) or not (0)"),
        "status": _var(dims2, status.astype(str), None, "solver status"),
        "solve_time": _var(dims2, solve_time, "s", "solver time over the Weber iterations"),
        "weber_iterations": _var(dims2, weber_iters, "1", "Weber linearisation iterations"),
        "compliance_time": _var(("roll",), compliance_time, "s", "compliance assembly time"),
        "n_segments": _var(("roll",), n_seg, "1", "segments in the contact problem"),
        **{f"residual_{r}": _var(dims2, resid[r], "1", f"relative {r} residual")
           for r in RESIDUALS},
        "lte_mean": _var(("torque",), summ["mean"], "urad", "mean loaded transmission error"),
        "lte_peak_to_peak": _var(("torque",), summ["peak_to_peak"], "urad",
                                 "peak-to-peak loaded transmission error"),
        "lte_harmonics": _var(("torque", "harmonic"), harm, "urad",
                              "amplitude of the mesh harmonics of the LTE"),
        "lte_rms": _var(("torque",), summ["rms"], "urad", "RMS of the LTE about its mean"),
        "lte_harmonic_rss": _var(("torque",), summ["harmonic_rss"], "urad",
                                 "root-sum-square of the first three harmonic amplitudes "
                                 "(the seed's Table 3.1 RMS)"),
        "pressure_max_flank": _var(("torque",), _peak(out["pressure_max"], curve), "MPa",
                                   "peak Hertzian pressure on the contact curves (line "
                                   "contact of the flanks)"),
        "pressure_max_edge": _var(("torque",), _peak(out["pressure_max"], ~curve), "MPa",
                                  "peak Hertzian pressure of the edge contact (edge rounding "
                                  "on the mating flank; 0 where none)"),
        "pressure_envelope": _var(("torque", "u", "v"), env, "MPa",
                                  "loaded contact pattern: envelope of the maximum pressure "
                                  "over the roll positions, on the gear grid"),
    }
    coords = {
        "torque": ("torque", torques, {"units": "N m", "long_name": "pinion torque"}),
        "gear_torque": ("torque", torques * eo.ratio,
                        {"units": "N m", "long_name": "gear torque (lossless)"}),
        "roll": ("roll", roll, {"units": "rad",
                                "long_name": "pinion roll angle (Q units, driving sense)"}),
        "pair": ("pair", pairs, {"units": "1", "long_name": "tooth-pair offset"}),
        "segment": ("segment", np.arange(S), {"units": "1", "long_name": "segment index"}),
        "segment_kind": ("segment", np.array(("curve", *EDGE_KINDS))[seg["kind"]],
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
    attrs = {
        "title": "loaded tooth contact analysis",
        "case": case.name,
        "toolkit_version": __version__,
        "pinion_flank": eo.pinion_flank,
        "gear_flank": eo.gear_flank,
        "solver": opts.solver,
        "mesh_period_rad": eo.pitch,
        "transition_M1_rad": float(m1),
        "transition_M2_rad": float(m2),
        "options": json_options(opts),
        "time_easeoff_s": timing["easeoff"],
        "time_segments_s": timing["segments"],
        "misalignment": json_misalignment(case.misalignment),
        "ratio": float(eo.ratio),
        "edge_radius_pinion_mm": edge_radii(case, opts)[0] if opts.edge_contact else np.nan,
        "edge_radius_gear_mm": edge_radii(case, opts)[1] if opts.edge_contact else np.nan,
        "pinion_axis": np.asarray(eo.kinematics.pinion_axis, float),
        "pinion_origin_mm": np.asarray(eo.kinematics.pinion_origin, float),
        "gear_axis": np.asarray(eo.kinematics.gear_axis, float),
        "gear_origin_mm": np.asarray(eo.kinematics.gear_origin, float),
    }
    return xr.Dataset(data, coords=coords, attrs=attrs)


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
    """A Misalignment as JSON text (ΔE, ΔP, ΔG [mm], ΔΣ [rad])."""

    return json.dumps(dataclasses.asdict(m), sort_keys=True, default=float)
