"""Step 6 of the synthesis: the modified roll that puts the TE on its parabola.

The local synthesis fixes the transmission error only to second order at M; the modified
roll coefficients 6D and 24E put it on the prescribed parabola at ±pitch/4: the contact is
followed from M in a few roll steps with the conventional TCA's system of seed Eq. 2.14
(:class:`geometry.pair.conventional_tca.ToothPair`, scipy Levenberg–Marquardt per roll),
with a Newton–Broyden iteration on 6D and 24E.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from geometry.core.errors import InputError
from geometry.pair.assembly import member_transform
from geometry.pair.conventional_tca import ToothPair
from geometry.synthesis.mean_point import pair_kw
from geometry.synthesis.pinion import PinionTools


# --------------------------------------------------------------------------- TE shape
def nominal_transforms(shaft_angle: float, offset: float, gear_hand: str):
    """Member → pair transforms (φ_p, φ_g) → (T_p, T_g) of the aligned assembly."""
    kw = pair_kw(shaft_angle, offset, gear_hand)

    def transforms(phi_p, phi_g):
        return (member_transform("pinion", rotation=phi_p, **kw),
                member_transform("gear", rotation=phi_g, **kw))

    return transforms


def _te_at(pair: ToothPair, start: np.ndarray, rate: np.ndarray, *, phi_p0: float,
           pinion_sense: int, gear_sense: int, ratio: float, rolls: tuple[float, ...],
           steps: int = 4) -> dict[float, float]:
    """Transmission error (gear lag, :mod:`geometry.pair.conventional_tca` convention) at rolls.

    Continuation from M (``start`` = x at roll 0, ``rate`` = dx/droll there) in ``steps``
    steps per side, each roll solved by :meth:`~geometry.pair.conventional_tca.ToothPair.solve_one`
    (at most 50 evaluations); raises InputError if a step leaves a residual of seed Eq. 2.14
    above 1e-7 mm.
    """
    out = {}
    for side in (1.0, -1.0):
        targets = sorted((r for r in rolls if r * side > 0), key=abs)
        if not targets:
            continue
        far = abs(targets[-1])
        grid = sorted(set([far * k / steps for k in range(1, steps + 1)]
                          + [abs(r) for r in targets]))
        prev_r, prev_x = [0.0], [start]
        for a in grid:
            r = side * a
            if len(prev_r) == 1:
                x0 = start + rate * r
            else:
                t = (r - prev_r[-1]) / (prev_r[-1] - prev_r[-2])
                x0 = prev_x[-1] + t * (prev_x[-1] - prev_x[-2])
            phi = phi_p0 + pinion_sense * r
            x = pair.solve_one(phi, x0, max_nfev=50)
            f, _, ok, _ = pair.residual(np.array([phi]), x[None])
            res = float(np.abs(f[0]).max()) if ok[0] else math.inf
            if res > 1e-7:
                raise InputError("synthesis: the contact near the mean point could not be "
                                 f"followed to roll {r:.4g} rad (residual {res:.3g})")
            prev_r.append(r)
            prev_x.append(x)
            if any(abs(r - t_) < 1e-15 for t_ in targets):
                out[r] = ratio * r - gear_sense * (x[4] - start[4])
    return out


def tune_roll(tools: PinionTools, pair: ToothPair, start, rate, *, a21: float,
               pitch: float, **kw) -> PinionTools:
    """Modified roll 6D, 24E that put the TE at ±pitch/4 on the prescribed parabola.

    Newton iteration with a finite-difference Jacobian (the TE is nearly linear in 6D and
    24E, which do not change the surface to second order at M, where q = 0); tolerance 0.5 %
    of the level a21 (pitch/4)²/2. At ±pitch/4 the contact stays well inside the flank (with
    a profile contact ratio near 1 it reaches the tooth tips near ±pitch/2).
    """
    h = 0.25 * pitch
    level = 0.5 * a21 * h * h
    rolls = (h, -h)

    def g(coef):
        settings = replace(tools.settings, modified_roll=(0.0, *coef))
        tuned = ToothPair(pair.pinion._replace(machine=settings), pair.gear, pair.transforms)
        te = _te_at(tuned, start, rate, rolls=rolls, **kw)
        return np.array([te[h] - level, te[-h] - level])

    x = np.zeros(2)
    g0 = g(x)
    steps = np.array([0.05, 0.5])
    jac = np.column_stack([(g(x + steps[i] * np.eye(2)[i]) - g0) / steps[i] for i in range(2)])
    for _ in range(6):
        if np.abs(g0).max() < 5e-3 * level:
            break
        dx = np.linalg.solve(jac, -g0)
        x_new = x + dx
        g_new = g(x_new)
        # Broyden update of the Jacobian
        jac = jac + np.outer(g_new - g0 - jac @ dx, dx) / (dx @ dx)
        x, g0 = x_new, g_new
    else:
        raise InputError("synthesis: the modified roll could not put the TE on the prescribed "
                         f"parabola (miss {np.abs(g0).max() * 1e6:.3g} urad)")
    return tools._replace(settings=replace(tools.settings, modified_roll=(0.0, *x)))
