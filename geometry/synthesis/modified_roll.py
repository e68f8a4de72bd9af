"""Step 6 of the synthesis: the modified roll that puts the TE on its parabola.

The local synthesis fixes the transmission error only to second order at M; the modified
roll coefficients 6D and 24E put it on the prescribed parabola at ±pitch/4: the contact is
followed from M in a few roll steps with the conventional TCA's system of seed Eq. 2.14
(:class:`geometry.pair.conventional_tca.ToothPair`: both sides' steps together by
Gauss–Newton, scipy's Levenberg–Marquardt where that fails), with a Newton–Broyden
iteration on 6D and 24E whose later evaluations start at ±pitch/4 from the contact of the
one before (no continuation: 2 roll solves instead of 8).
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

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


#: largest residual of seed Eq. 2.14 [mm] at a roll the TE is read from
_RESIDUAL = 1e-7


class _Followed(NamedTuple):
    """The contact at the target rolls of one TE evaluation (:func:`_te_at`): the next
    evaluation's start where the modified roll (or, in a series of syntheses, the pinion's
    tools) changes a little."""

    rolls: tuple[float, ...]  # [rad] the target rolls, in this order
    x: np.ndarray  # (R, 5) [mm, mm, mm, mm, rad] solutions (Z_p, P_p, Z_g, P_g, φ_g)
    params: np.ndarray  # (R, 8) envelope parameters of both flanks there
    start: np.ndarray  # (5,) the contact at M (roll 0) it was followed from
    rate: np.ndarray  # (5,) its rate per unit roll there


def _solve_rolls(pair: ToothPair, phi: np.ndarray, x0: np.ndarray,
                 guess: np.ndarray | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Seed Eq. 2.14 at K pinion rotations ``phi`` (K,) from starts ``x0`` (K, 5).

    The K positions together by :meth:`~geometry.pair.conventional_tca.ToothPair.
    newton_params` (``guess`` (K, 8): envelope parameters near the starts, NaN rows none);
    a position it leaves above :data:`_RESIDUAL` again alone by scipy's Levenberg–Marquardt
    (:meth:`~geometry.pair.conventional_tca.ToothPair.solve_one`, at most 50 evaluations).
    Returns the solutions (K, 5), their envelope parameters (K, 8) and residuals (K,)
    (max |F| of Eq. 2.14 [mm], inf where a flank is not generated).
    """
    x, _, par = pair.newton_params(phi, x0, guess=guess, damping=0.0)
    f, _, ok, _ = pair.residual(phi, x, par)
    res = np.where(ok, np.abs(np.where(ok[:, None], f, 0.0)).max(-1), np.inf)
    for i in np.flatnonzero(~(res <= _RESIDUAL)):
        g = None if guess is None else guess[i:i + 1]
        xi = pair.solve_one(float(phi[i]), x0[i], max_nfev=50, guess=g)
        xi, _, pi = pair.newton_params(phi[i:i + 1], xi[None], guess=g)
        fi, _, oki, _ = pair.residual(phi[i:i + 1], xi, pi)
        x[i], par[i] = xi[0], pi[0]
        res[i] = float(np.abs(fi[0]).max()) if oki[0] else np.inf
    return x, par, res


def _te_at(pair: ToothPair, start: np.ndarray, rate: np.ndarray, *, phi_p0: float,
           pinion_sense: int, gear_sense: int, ratio: float, rolls: tuple[float, ...],
           steps: int = 4, near: _Followed | None = None
           ) -> tuple[dict[float, float], _Followed]:
    """Transmission error (gear lag, :mod:`geometry.pair.conventional_tca` convention) at rolls.

    Continuation from M (``start`` = x at roll 0, ``rate`` = dx/droll there) in ``steps``
    steps per side, both sides' n-th steps solved together (:func:`_solve_rolls`); or,
    given ``near`` (the contact at the same rolls of a nearby modified roll), the target
    rolls directly from there, with the continuation where that fails. Returns the TE at
    each roll and the contact there; raises InputError if a step leaves a residual of seed
    Eq. 2.14 above :data:`_RESIDUAL` (1e-7 mm).
    """
    def te(r, x):
        return ratio * r - gear_sense * (x[4] - start[4])

    if near is not None and near.rolls == tuple(rolls):
        r = np.asarray(rolls, float)
        phi = phi_p0 + pinion_sense * r
        # its contact moved by the change of the first-order prediction from M (nothing
        # where start and rate are the same: within one tune)
        x0 = near.x + ((start[None, :] + rate[None, :] * r[:, None])
                       - (near.start[None, :] + near.rate[None, :] * r[:, None]))
        x, par, res = _solve_rolls(pair, phi, x0, near.params)
        if np.all(res <= _RESIDUAL):
            return ({r: te(r, x[i]) for i, r in enumerate(rolls)},
                    _Followed(tuple(rolls), x, par, start, rate))
    # the continuation: per side its grid of rolls (the targets among them), the rolls
    # solved so far, their solutions and the last one's envelope parameters
    sides = []
    for side in (1.0, -1.0):
        targets = sorted((r for r in rolls if r * side > 0), key=abs)
        if targets:
            far = abs(targets[-1])
            grid = sorted(set([far * k / steps for k in range(1, steps + 1)]
                              + [abs(r) for r in targets]))
            sides.append(([side * a for a in grid], [0.0], [start], [np.full(8, np.nan)]))
    solved: dict[float, tuple[np.ndarray, np.ndarray]] = {}
    for n in range(max((len(sd[0]) for sd in sides), default=0)):
        live = [sd for sd in sides if n < len(sd[0])]
        r = np.array([sd[0][n] for sd in live])
        x0 = np.empty((len(live), 5))
        for i, (_, pr, px, _) in enumerate(live):
            if len(pr) == 1:
                x0[i] = start + rate * r[i]
            else:
                t = (r[i] - pr[-1]) / (pr[-1] - pr[-2])
                x0[i] = px[-1] + t * (px[-1] - px[-2])
        guess = np.stack([sd[3][-1] for sd in live])
        x, par, res = _solve_rolls(pair, phi_p0 + pinion_sense * r, x0, guess)
        for i, (_, pr, px, pp) in enumerate(live):
            if not res[i] <= _RESIDUAL:
                raise InputError("synthesis: the contact near the mean point could not be "
                                 f"followed to roll {r[i]:.4g} rad (residual {res[i]:.3g})")
            pr.append(float(r[i]))
            px.append(x[i])
            pp.append(par[i])
            solved[float(r[i])] = (x[i], par[i])
    found = [next(v for k, v in solved.items() if abs(k - r) < 1e-15) for r in rolls]
    return ({r: te(r, found[i][0]) for i, r in enumerate(rolls)},
            _Followed(tuple(rolls), np.stack([v[0] for v in found]),
                      np.stack([v[1] for v in found]), start, rate))


#: the rolls, fractions of the pitch, at which the synthesis' step 6 puts the TE on its
#: parabola (:func:`tune_roll`'s ``fraction``), tried in turn: ±pitch/4 first; nearer M
#: where the contact cannot be followed that far (Litvin & Fuentes 2004 §9.4: the
#: parabolic TE is prescribed by a21 at M; the rolls it is imposed at are the synthesis'
#: choice). On a hypoid 8x41 with a narrow face (b2 22 mm, β_m1 52°, a 30 mm, ISO 23509
#: Method 1; ε_vα 0.94) the drive flank's contact at the synthesis' default prescriptions
#: climbs to the pinion's tip before +pitch/4 (pinion radius 26.2 → 31.2 mm at roll
#: 0.049 → 0.196 rad) and the roll solve stalls there (residual 0.09 mm at pitch/4,
#: 0.008 mm at 7/32 of the pitch), while ±pitch/6 is followed to 1e-12 mm
ROLL_FRACTIONS = (0.25, 1.0 / 6.0, 0.125)


#: the warm tune's tolerance (:class:`WarmRoll`), a fraction of the TE level at the target
#: rolls: a cold tune's Newton step from its finite-difference Jacobian lands within
#: 1e-6 to 5e-5 of the level (the TE is nearly linear in 6D and 24E) though it stops at
#: 0.5 %; the warm tune goes as near, so that its coefficients are near the cold tune's,
#: not anywhere within 0.5 %
WARM_ROLL_TOLERANCE = 1e-5


class WarmRoll:
    """The last modified roll of a series of nearby syntheses of one flank (issue 75: a
    development's trials), continued by the next one (:func:`tune_roll`'s ``warm``).

    With a last tune at the same fraction of the pitch, :func:`tune_roll` starts its
    Newton–Broyden iteration at the last 6D, 24E with the last Jacobian and solves the
    target rolls from the last contact there (moved by the change of the first-order
    prediction from M), instead of the continuation from M at 6D = 24E = 0 and a
    finite-difference Jacobian: 2 TE evaluations of 2 rolls each against 4 (and the 8 rolls
    of the continuation) on the passenger-car hypoid 10x43's trials. The coefficients meet
    a tighter tolerance (:data:`WARM_ROLL_TOLERANCE`) from another start, so they are not
    a cold tune's to the bit but within the cold tune's own tolerance (the TE at
    ±pitch/4 within 0.5 % of the prescribed level; the cold Newton step lands within
    1e-6 to 5e-5 of it on the 10x43: 6D, 24E within 2e-5, 1e-4 there,
    tests/test_synthesis_memo.py). Where the warm iteration fails, the cold one runs.

    Not used by :func:`~geometry.synthesis.case_synthesis.synthesize` (issue 75, helper
    dev75e): on the default case's development (kolivand2009_fm_11x41) the coast search's
    first trial, plastic at its design torque, changed its coarse peak flank pressure
    2577 → 2045 MPa with coefficients ~1e-5 relative off the cold tune's (and so did the
    tools' 1e-13: that metric is not continuous there), and the coast design torque the
    development prints moved 69.5 → 109.7 N·m (112.2 with the warm tools alone).

    Attributes
    ----------
    fraction : float or None
        The last tune's ``fraction`` (the target rolls ±fraction × pitch).
    coef : ndarray (2,) or None
        Its (6D, 24E).
    jac : ndarray (2, 2) or None
        Its Jacobian of the TE misses at ±pitch·fraction [rad] per unit of (6D, 24E).
    followed : _Followed or None
        Its contact at the target rolls.
    miss : float or None
        Its max |TE − level| at the target rolls [rad].
    used, cold : int
        Tunes continued from the last one / tuned cold.
    """

    def __init__(self) -> None:
        self.fraction: float | None = None
        self.coef: np.ndarray | None = None
        self.jac: np.ndarray | None = None
        self.followed: _Followed | None = None
        self.miss: float | None = None
        self.used = 0
        self.cold = 0


def tune_roll(tools: PinionTools, pair: ToothPair, start, rate, *, a21: float,
              pitch: float, fraction: float = 0.25, warm: WarmRoll | None = None,
              **kw) -> PinionTools:
    """Modified roll 6D, 24E that put the TE at ±pitch/4 (``fraction`` × pitch) on the
    prescribed parabola.

    Newton iteration with a finite-difference Jacobian (the TE is nearly linear in 6D and
    24E, which do not change the surface to second order at M, where q = 0); tolerance 0.5 %
    of the level a21 (pitch/4)²/2. At ±pitch/4 the contact stays well inside the flank (with
    a profile contact ratio near 1 it reaches the tooth tips near ±pitch/2). The first
    evaluation follows the contact from M (:func:`_te_at`); the Jacobian's and Newton's
    evaluations solve ±pitch/4 directly from the contact of the evaluation before (the
    same roots to the solver's tolerance: the TE within ~1e-13 rad of the continuation's,
    the coefficients within ~1e-6 relative; 0.36 against 1.40 s of CPU per trial
    synthesis of the passenger-car hypoid 10x43, docs/performance.md). ``warm``
    (:class:`WarmRoll`, a series of syntheses of one flank): the iteration starts from
    the last tune's coefficients, Jacobian and contact, and the tune is kept in it.
    """
    h = fraction * pitch
    level = 0.5 * a21 * h * h
    rolls = (h, -h)

    # step 5's 2C, where it made the mismatch with the ratio of roll (kept; 0 otherwise)
    c2 = tools.settings.modified_roll[0] if tools.settings.modified_roll else 0.0

    def g(coef, near=None):
        settings = replace(tools.settings, modified_roll=(c2, *coef))
        tuned = ToothPair(pair.pinion._replace(machine=settings), pair.gear, pair.transforms)
        te, followed = _te_at(tuned, start, rate, rolls=rolls, near=near, **kw)
        return np.array([te[h] - level, te[-h] - level]), followed

    def newton(x, g0, at, jac, tol=5e-3 * level):
        for _ in range(6):
            if np.abs(g0).max() < tol:
                return x, at, jac, float(np.abs(g0).max())
            dx = np.linalg.solve(jac, -g0)
            x_new = x + dx
            try:
                g_new, at = g(x_new, at)
            except InputError as err:
                raise InputError(f"{err}{_beyond_text(untuned, level, h, x_new)}") from err
            # Broyden update of the Jacobian
            jac = jac + np.outer(g_new - g0 - jac @ dx, dx) / (dx @ dx)
            x, g0 = x_new, g_new
        raise InputError("synthesis: the modified roll could not put the TE on the "
                         f"prescribed parabola (miss {np.abs(g0).max() * 1e6:.3g} urad)"
                         f"{_beyond_text(untuned, level, h, x)}")

    def kept(x, at, jac, miss):
        if warm is not None:
            warm.fraction, warm.coef, warm.jac, warm.followed = fraction, x, jac, at
            warm.miss = miss
        return tools._replace(settings=replace(tools.settings, modified_roll=(c2, *x)))

    untuned = None  # the TE at ±h without the modified roll (known on the cold start)
    if warm is not None and warm.fraction == fraction and warm.coef is not None:
        try:
            x0 = warm.coef.copy()
            g0, at = g(x0, warm.followed)
            out = newton(x0, g0, at, warm.jac.copy(), WARM_ROLL_TOLERANCE * level)
        except (InputError, np.linalg.LinAlgError):
            out = None
        if out is not None:
            warm.used += 1
            return kept(*out)
    x = np.zeros(2)
    g0, at = g(x)
    untuned = g0 + level  # the TE at ±h without the modified roll (its cause, if it fails)
    steps = np.array([0.05, 0.5])
    jac = np.column_stack([(g(x + steps[i] * np.eye(2)[i], at)[0] - g0) / steps[i]
                           for i in range(2)])
    out = newton(x, g0, at, jac)
    if warm is not None:
        warm.cold += 1
    return kept(*out)


def _beyond_text(untuned: np.ndarray | None, level: float, h: float,
                 coef: np.ndarray) -> str:
    """The cause a failed modified-roll step is reported with: the TE the flank has at ±h
    without the modified roll (``untuned`` [rad], None where not measured) against the
    parabola's ``level`` [rad] there, and the coefficients (6D, 24E) Newton's step asked
    for. Empty where the TE without the modified roll is within ten levels of the parabola
    (a miss the modified roll is made for).

    Why: the face-milled spiral bevel miter 12x12 (issue 71, docs/own_gear_set.md, "The
    12-tooth miter: a legitimate design, the pinion's higher-order TE") stopped on "the
    contact near the mean point could not be followed to roll −0.03272 rad": its drive
    pinion's TE at ±pitch/4 was +192 / −1050 urad against the parabola's 2.8 urad, and
    the first Newton step asked for 6D −350, 24E 1.72e4, where the pinion flank is no
    longer generated near M — a message that named the step, not the cause."""
    if untuned is None or np.abs(untuned).max() <= 10.0 * level:
        return ""
    return (f" (the modified roll's step to 6D {coef[0]:.3g}, 24E {coef[1]:.3g}: without "
            f"it the TE at +/-{h:.4g} rad is {untuned[0] * 1e6:+.4g} / "
            f"{untuned[1] * 1e6:+.4g} urad against the prescribed parabola's "
            f"{level * 1e6:.3g} urad, a higher-order departure of the mismatched pinion "
            "that 6D and 24E cannot correct; another path_angle, a longer ellipse_length "
            "or a larger cutter (rc0) asks the pinion for another mismatch)")


class ThirdOrderTE(NamedTuple):
    """Result of :func:`third_order_te`."""

    c3: float  # [1/rad²] the TE's coefficient of roll³ at M
    share: float  # [1] 2 |c3| (pitch/4) / a21: the cubic at ±pitch/4 over the parabola there


def third_order_te(tools: PinionTools, pair: ToothPair, start, rate, *, a21: float,
                   pitch: float, **kw) -> ThirdOrderTE:
    """The third-order term of the TE the local synthesis leaves at M (before step 6).

    Parameters
    ----------
    tools : PinionTools
        The pinion's tools of step 5 (their modified roll, if any, is used as given).
    pair : geometry.pair.conventional_tca.ToothPair
        The pair (its pinion's machine is replaced by ``tools.settings``).
    start, rate : array_like (5,)
        The contact at M and its rate per unit roll, as :func:`tune_roll`.
    a21 : float — [1/rad]
        The prescribed TE curvature at M (> 0).
    pitch : float — [rad]
        The pinion's angular pitch 2π/z1.
    **kw
        ``phi_p0``, ``pinion_sense``, ``gear_sense``, ``ratio`` as :func:`tune_roll`.

    Returns
    -------
    ThirdOrderTE
        c3 [1/rad²] from the TE's odd part, slope(h) = (TE(h) − TE(−h))/(2h) = c3 h² + O(h⁴)
        at h = pitch/64 and pitch/32, Richardson-extrapolated to h → 0; ``share`` = 2 |c3|
        (pitch/4) / a21, the cubic's size at ±pitch/4 against the prescribed parabola
        a21 (pitch/4)²/2 there.

    Raises
    ------
    InputError
        If a21 is not positive or the contact cannot be followed to ±pitch/32.

    Notes
    -----
    Source: the measurement of ``docs/synthesis.md``, "Near ratio 1: the third-order TE of
    the pinion generated on the Formate gear" (the 16x16 at Σ 60°: c3 −0.122 /rad², share
    41 on the Formate gear's copy; the face-milled pair on the generated gear's crown gear
    0.31), and ``tests/test_synthesis_ratio_one.py``, whose independent contact solve
    (seed Eq. 2.14) gives the same numbers.
    """
    if not a21 > 0.0:
        raise InputError(f"a21: must be > 0 1/rad for a third-order share, got {a21:.4g}")
    pinion = pair.pinion._replace(machine=tools.settings)
    followed = ToothPair(pinion, pair.gear, pair.transforms)
    h = pitch / 64.0
    te, _ = _te_at(followed, np.asarray(start, float), np.asarray(rate, float),
                   rolls=(h, -h, 2.0 * h, -2.0 * h), **kw)

    def over_h2(s: float) -> float:
        return (te[s] - te[-s]) / (2.0 * s) / s**2

    c3 = (4.0 * over_h2(h) - over_h2(2.0 * h)) / 3.0
    return ThirdOrderTE(float(c3), float(2.0 * abs(c3) * 0.25 * pitch / a21))
