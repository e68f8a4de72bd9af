"""Plausibility of a loaded TCA: the causes a run's numbers should not be trusted for.

A certified solution of the contact problem can still describe a mesh no gear engineer
would believe: contact that the material cannot carry elastically, or a transmission error
that swings by as much as its mean. :func:`plausibility_warnings` reads the ``/ltca``
dataset alone and names each such cause with the torques where it occurs; ``ltca run``
prints them as ``WARNING:`` lines.

The checks and their stated thresholds:

* **plastic contact** — segments at their force limit (``segment_state`` plastic: their
  Hertz pressure at the material's contact-pressure limit, :mod:`contact.ltca.plastic`)
  carry more than :data:`PLASTIC_SHARE_LIMIT` (5 %) of the torque at some roll position.
  5 % is the edge share the reference design was optimised to at 500 N·m (the issue-37
  limits: edges ≤ 1 % of the torque at 50 N·m, ≤ 5 % at 500); beyond it the edges (or
  flanks) would flatten in running, and the result is that of a gear whose contact has
  already changed shape.
* **flank above the limit** — with the flank limit off (the default), a flank peak
  pressure above the material's contact-pressure limit (the edges' limit,
  ``edge_pressure_limit_MPa``): the flank would yield, which the elastic flank model does
  not follow (``LTCAOptions.flank_pressure_limit`` bounds it).
* **LTE spread** — the LTE peak-to-peak exceeds :data:`LTE_SPREAD_LIMIT` (0.5) times its
  mean. In a mesh that carries its load on the flanks the LTE varies about its mean by the
  mesh-stiffness variation and the unloaded TE: peak-to-peak / mean is 0.12/0.055/0.037 in
  the seed's Table 3.1 and Fig. 3.6 at 50/250/500 N·m (13/110, 16/290, 22/600 µrad) and at
  most 0.16 on every bundled case at 50–500 N·m; 0.5 is three times that. The check
  applies where the mean LTE exceeds the unloaded TE's peak-to-peak: at lighter loads the
  LTE is the unloaded TE's own shape — parabolic pair TEs from their common minimum, whose
  peak-to-peak is 2–3 times their mean — and its ratio says nothing of the mesh.

Public functions
----------------
PLASTIC_SHARE_LIMIT    the torque share at the limit beyond which a run is flagged [1]
LTE_SPREAD_LIMIT       the LTE peak-to-peak / mean beyond which a run is flagged [1]
plausibility_warnings  the causes, one sentence each
"""

from __future__ import annotations

import numpy as np
import xarray as xr

__all__ = ["LTE_SPREAD_LIMIT", "PLASTIC_SHARE_LIMIT", "plausibility_warnings"]

#: [1] largest share of the gear torque that segments at their force limit may carry at a
#: roll position before a run is flagged (module docstring)
PLASTIC_SHARE_LIMIT = 0.05

#: [1] largest LTE peak-to-peak / mean LTE of a load-dominated run (module docstring)
LTE_SPREAD_LIMIT = 0.5


def _slashed(values: np.ndarray, fmt: str = "{:g}") -> str:
    """'12.3/4.5'-style text of values, one per flagged torque."""
    return "/".join(fmt.format(v) for v in values)


def plausibility_warnings(ltca: xr.Dataset) -> list[str]:
    """The causes for which a loaded TCA is implausible, one sentence each.

    Parameters
    ----------
    ltca : xarray.Dataset
        The ``/ltca`` dataset of an analysis (:func:`contact.ltca.loaded_tca`). Files
        written before a variable existed simply skip its check.

    Returns
    -------
    list of str
        Empty when the run is plausible; otherwise, for each cause of the module
        docstring that occurs, a sentence naming it, the torques [N·m] where it occurs,
        the numbers and the threshold.

    Notes
    -----
    Thresholds and their justification: module docstring. Checked in
    tests/test_plausibility.py on the default case (plausible) and at ΔE = 5 mm (every
    cause).
    """
    out = []
    torque = np.asarray(ltca["torque"].values, float)
    if "plastic_load_share" in ltca:
        share = np.nanmax(np.nan_to_num(ltca["plastic_load_share"].values, nan=0.0), axis=1)
        bad = share > PLASTIC_SHARE_LIMIT
        if np.any(bad):
            out.append(
                "plastic contact: segments at the material's contact-pressure limit carry "
                f"up to {_slashed(100 * share[bad], '{:.1f}')} % of the torque at "
                f"{_slashed(torque[bad])} N m (more than {100 * PLASTIC_SHARE_LIMIT:g} % at "
                "some roll position); the edges (or flanks) would flatten in running, so "
                "these are the results of a contact that cannot last (/ltca/segment_state)")
    limit = float(ltca.attrs.get("edge_pressure_limit_MPa", np.nan))
    flank_limit = float(ltca.attrs.get("flank_pressure_limit_MPa", np.nan))
    if "pressure_max_flank" in ltca and np.isfinite(limit) and not np.isfinite(flank_limit):
        p = np.asarray(ltca["pressure_max_flank"].values, float)
        bad = p > limit
        if np.any(bad):
            out.append(
                f"flank above the material's limit: flank peak pressure "
                f"{_slashed(p[bad], '{:.0f}')} MPa at {_slashed(torque[bad])} N m, above the "
                f"contact-pressure limit {limit:.0f} MPa; the flank would yield, which the "
                "elastic flank model does not follow (LTCAOptions.flank_pressure_limit "
                "bounds it)")
    if {"lte_peak_to_peak", "lte_mean", "unloaded_transmission_error"} <= set(ltca):
        pp = np.asarray(ltca["lte_peak_to_peak"].values, float)
        mean = np.asarray(ltca["lte_mean"].values, float)
        ute = np.asarray(ltca["unloaded_transmission_error"].values, float)
        ute_pp = float(np.nanmax(ute) - np.nanmin(ute)) if np.any(np.isfinite(ute)) else 0.0
        with np.errstate(invalid="ignore", divide="ignore"):
            ratio = pp / mean
        bad = (mean > ute_pp) & (ratio > LTE_SPREAD_LIMIT)
        if np.any(bad):
            out.append(
                f"LTE spread: LTE peak-to-peak {_slashed(ratio[bad], '{:.2f}')} times its "
                f"mean at {_slashed(torque[bad])} N m (more than {LTE_SPREAD_LIMIT:g}); a mesh "
                "that carries its load on the flanks varies far less (seed Table 3.1: "
                "0.04-0.12): edge contact or loss of contact over part of the mesh cycle")
    return out
