"""Summaries of an ``/ltca`` dataset that more than one layer reports.

Public functions
----------------
edge_load_share   the share of the gear torque the edge segments carry, per torque
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from geometry.core.errors import InputError

__all__ = ["edge_load_share"]


def edge_load_share(ltca: xr.Dataset) -> np.ndarray:
    """[1] Per torque, the share of the gear torque carried by the edge segments over the
    mesh cycles: Σ F·R over the edge segments / Σ F·R over all (seed Eq. 3.14's moments;
    :mod:`contact.ltca.edges`).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca``: ``force`` (torque, roll, pair, segment) [N], ``moment_arm`` (roll, pair,
        segment) [mm], ``segment_kind`` (segment).

    Returns
    -------
    ndarray (NT,)
        NaN where no segment carries load.

    Raises
    ------
    InputError
        If ``ltca`` lacks one of the variables.
    """
    missing = [k for k in ("force", "moment_arm", "segment_kind") if k not in ltca.variables]
    if missing:
        raise InputError(f"ltca: lacks {', '.join(missing)} (not an /ltca dataset)")
    moment = np.nan_to_num(ltca["force"].values) * np.nan_to_num(ltca["moment_arm"].values)[None]
    edge = np.asarray(ltca["segment_kind"].values != "curve")
    total = moment.sum(axis=(1, 2, 3))
    on_edges = moment[..., edge].sum(axis=(1, 2, 3))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(total > 0, on_edges / total, np.nan)
