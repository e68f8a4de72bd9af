"""The default case's FE root stress against ISO 10300 and where each member's peak sits
(issue 62 item 1; docs/fe.md, "Root and slot bottom").

Slow: the default analysis with its FE root stress (about a minute on a warm FE cache,
several minutes on a cold one)."""

from __future__ import annotations

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.compliance.fe import influence_coefficients
from contact.pipeline import run_analysis

DEFAULT = "kolivand2009_fm_11x41_reference"


def _unit_load_peaks(coef, load_v: float = 0.525) -> np.ndarray:
    """(load_u,) [MPa/N] the largest tensile fillet stress of the loaded tooth's root
    (both fillets, every station) per unit load at each load_u of the row ``load_v``."""
    fm = coef["fillet_max_principal"].sel(tooth=0).sel(load_v=load_v, method="nearest")
    in_root = coef["fillet_in_root"].sel(tooth=0) > 0
    return fm.where(in_root).max(("side", "station", "arc")).values


@pytest.mark.slow  # the default analysis with FE root stress: ~1 min warm, ~5 min cold cache
def test_default_fe_root_stress_against_iso_and_the_pinion_heel():
    """FE peak / ISO 10300 σ_F of both members at 250 and 500 N·m lies in [0.7, 1.5] (the
    issue's band for a localised pattern: ISO spreads the load by K_Fβ over an assumed
    width, the FE takes the LTCA's; measured 1.26 / 1.06 pinion, 0.93 / 0.81 gear), and
    the pinion's peak stays on the heel side for a reason of its own, not an assumed slot
    bottom: a unit load at its heel end stresses its root ≥ 4× the least mid-face one
    and ≥ 2× its toe end (measured 6.3× and 2.6×: the drive flank meets the heel's back
    cone at an acute 48°), where the gear's weak end is its toe (measured 3.2× its heel;
    its drive flank meets the toe at 67°), while the heel tenth of the face carries
    11.5–15.6 % of the load at every torque."""
    tree = run_analysis(DEFAULT)
    lt, rating = tree["/ltca"], tree["/rating"]
    fe = lt["root_stress_max"].transpose("torque", "member")
    iso = rating["sigma_F"].transpose("torque", "member")
    torques = list(lt["torque"].values)
    for t in (250.0, 500.0):
        i = torques.index(t)
        ratio = fe.values[i] / iso.values[i]
        assert np.all((ratio >= 0.7) & (ratio <= 1.5)), (t, ratio)
    case = resolve_case(DEFAULT)
    pinion = _unit_load_peaks(influence_coefficients(case, "pinion", progress=False))
    gear = _unit_load_peaks(influence_coefficients(case, "gear", progress=False))
    assert pinion[-1] >= 4.0 * pinion.min() and pinion[-1] >= 2.0 * pinion[0], pinion
    assert gear[0] >= 2.0 * gear[-1], gear
