"""Identities every loaded-contact result must satisfy, shared by the LTCA test modules."""

from __future__ import annotations

import numpy as np


def assert_equilibrium_and_complementarity(ds, case) -> None:
    """From a ``/ltca`` dataset's stored forces, arms and separations, at every roll and
    torque: torque equilibrium Σ F R = T_g to 1e-9 relative (the exact solver reaches
    round-off, ~1e-15), F ≥ 0, no load where the gap stays open (s_i > R_i Θ ⇒ F_i = 0: the
    compliance C is entrywise ≥ 0), contact flags exactly where F > 0, and the solver's own
    residuals < 1e-9."""
    assert bool(ds["found"].all())
    ratio = case.gear.blank.teeth / case.pinion.blank.teeth
    F = ds["force"].fillna(0.0)
    moment = (F * ds["moment_arm"].fillna(0.0)).sum(("pair", "segment"))  # N·mm
    target = ds["torque"] * ratio * 1e3
    np.testing.assert_array_less(np.abs(moment / target - 1.0).values, 1e-9)
    assert float(ds["force"].min()) >= 0.0
    theta = ds["loaded_rotation"] * 1e-6
    open_gap = ds["separation"] > ds["moment_arm"] * theta * (1 + 1e-9) + 1e-12
    assert float(F.where(open_gap, 0.0).max()) == 0.0
    assert bool(((ds["contact"] > 0) == (F > 0)).all())
    assert float(ds["residual_equilibrium"].max()) < 1e-9
    assert float(ds["residual_complementarity"].max()) < 1e-9


#: the cvxpy backend that stands for cvxpy's own path (canonicalisation, dual recovery)
#: in the CI run; every cvxpy backend runs with ``-m slow``
CVXPY_IN_CI = "cvxpy:CLARABEL"


def solver_params() -> list:
    """Every registered solver as a pytest parameter; the cvxpy backends but one marked
    slow. They repeat cvxpy's canonicalisation on solvers that CI already runs natively
    through qpsolvers (daqp, proxqp, qpalm, ecos, clarabel …), at 10–25 s each in a full
    run: the equality of every backend's LTE is kept in ``pytest -m slow`` and
    ``benchmarks/solvers.py``."""
    import pytest

    from contact import available_solvers

    return [pytest.param(s, marks=pytest.mark.slow)
            if s.startswith("cvxpy:") and s != CVXPY_IN_CI else s
            for s in available_solvers()]

