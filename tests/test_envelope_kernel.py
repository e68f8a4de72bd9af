"""The compiled envelope Newton (geometry.machine.envelope_numba) against the NumPy path.

The kernel repeats, point by point, the iteration of :func:`geometry.machine.meshing._newton`
(batched NumPy, the reference): the same equations (seed Eq. 2.7a, 2.8), the same analytic
Jacobian, steps, limits and stopping rules. The references here are that NumPy path and
the equations themselves:

- from the same starts (roots perturbed by up to 0.5 mm and 0.05 rad, and starts far
  enough off for Newton to stall or fail), both paths converge on the same points, to
  the same roots;
- the roots of a whole solve on the kernel satisfy the point equations evaluated by the
  NumPy family buffer, and give the NumPy solve's mask reasons.

Tolerances. The paths do not agree to the last bit: NumPy forms the chain's products with
BLAS and evaluates sin and cos with its own SIMD routines, numba with the C library's.
Both stop where |Δz|, |Δρ| < 1e-10 mm and |f| < 1e-12; Newton's last step takes the error
to the square of the previous one, so both roots are the exact root to round-off (~1e-16
× 100 mm divided by Jacobians of order 1–100 mm/rad: measured differences ≤ 1e-13 mm or
rad). The tests take 1e-10 (mm, rad): the convergence tolerance itself, which a logic
error in the kernel (a wrong derivative, a missed term) exceeds by orders of magnitude.
The equations at the kernel's roots are held to the convergence tolerances plus the
round-off of re-evaluating them (1e-11 mm on positions of ~100 mm, 1e-13 on f).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from contact.catalogue import resolve_case
from geometry.core.errors import InputError
from geometry.machine import meshing
from geometry.machine.family import generated_family, meshing_buffer, meshing_function
from geometry.machine.flank import flank_surface
from geometry.machine.meshing import solve_envelope

pytest.importorskip("geometry.machine.envelope_numba",
                    reason="numba (the 'fast' extra) is not installed")

ROOT_TOL = 1e-10  # [mm, rad] roots of the two paths (see the module docstring)

CASES = {
    "fm": "kolivand2009_fm_11x41_reference",  # Generate pinion (four blade sections), Formate gear
    "fh": "kolivand2009_fh_12x41_reference",  # placed blades, indexing, modified roll
    "iso": "iso23509_sample2_fm",  # modified roll
}
#: higher-order machine motions on top of a case's settings (helical and vertical motion:
#: no bundled case has them; the crown-gear test of test_meshing checks their equations)
MOTIONS = dict(helical_motion=(2.0, -3.0), vertical_motion=(1.0, 0.5))


def _setup(case_key, member, flank, motions=False):
    case = resolve_case(CASES[case_key])
    mem = case.member(member)
    tool = mem.flank(flank)
    fs = flank_surface(case, member, flank, nu=11, nv=7)
    settings = tool.machine
    if motions:
        settings = dataclasses.replace(settings, **MOTIONS)
    blank = mem.blank
    return fs, tool.blade, settings, blank


def _starts(fs, generate, rng):
    """Starts (n, m), sections, targets (z, ρ): the flank's roots perturbed, four times
    over with growing offsets (the last far enough for stalls and failures)."""
    ok = fs.reason == 0
    x = np.stack([fs.s[ok], fs.theta[ok], fs.q[ok]], -1)[:, : 3 if generate else 2]
    section = fs.section[ok]
    z, rho = fs.grid.axial[ok], fs.grid.radius[ok]
    scale = np.array([0.5, 0.05, 0.05])[: x.shape[1]]
    starts = [x + f * scale * rng.uniform(-1.0, 1.0, x.shape) for f in (0.1, 1.0, 8.0, 40.0)]
    return (np.concatenate(starts), np.tile(section, 4), np.tile(z, 4), np.tile(rho, 4))


@pytest.mark.parametrize("case_key, member, flank, motions", [
    ("fm", "pinion", "concave", False), ("fm", "pinion", "convex", True),
    ("fm", "gear", "convex", False), ("fh", "pinion", "concave", False),
    ("fh", "pinion", "convex", True), ("fh", "gear", "concave", False),
    ("iso", "pinion", "convex", False)])
def test_newton_from_the_same_starts(case_key, member, flank, motions):
    """Both paths converge on the same points, to the same roots (1e-10 mm, rad), and
    fail on the same ones (stalled, singular, or not converged in 30 steps)."""
    fs, blade, settings, blank = _setup(case_key, member, flank, motions)
    generate = settings.process == "Generate"
    x0, section, z, p = _starts(fs, generate, np.random.default_rng(7))
    kept = x0.copy()
    out = {}
    for kernels in ("numpy", "numba"):
        ctx = meshing._context(blade, settings, blank.outer_cone_distance, kernels)
        assert (ctx.kernel is None) == (kernels == "numpy")
        out[kernels] = meshing._newton(ctx, x0, section, z, p)
    (xa, oka), (xb, okb) = out["numpy"], out["numba"]
    assert oka.dtype == okb.dtype == bool and xb.shape == xa.shape
    np.testing.assert_array_equal(okb, oka)
    assert 0.3 * oka.size < oka.sum() < oka.size  # some fail: the failure paths ran too
    np.testing.assert_allclose(xb[oka], xa[oka], rtol=0, atol=ROOT_TOL)
    np.testing.assert_array_equal(x0, kept)  # the starts are not overwritten


@pytest.mark.parametrize("case_key, member, flank", [
    ("fm", "pinion", "concave"), ("fm", "gear", "concave"), ("fh", "pinion", "convex"),
    ("fh", "gear", "convex")])
def test_solve_on_the_kernel_satisfies_the_equations(case_key, member, flank):
    """A whole solve on the kernel: the NumPy family buffer at its roots meets the point
    equations (position error and meshing residual, seed Eq. 2.8), with the NumPy
    solve's reasons and roots."""
    fs, blade, settings, blank = _setup(case_key, member, flank)
    z, rho = fs.grid.axial, fs.grid.radius
    kw = dict(length_scale=blank.outer_cone_distance,
              depth=blank.outer_addendum + blank.outer_dedendum)
    a = solve_envelope(blade, settings, z, rho, kernels="numpy", **kw)
    b = solve_envelope(blade, settings, z, rho, kernels="numba", **kw)
    np.testing.assert_array_equal(b.reason, a.reason)
    valid = b.reason == 0
    assert valid.sum() >= 0.9 * valid.size
    # the point equations in NumPy's family buffer at the kernel's roots
    fam = generated_family(blade, settings, b.s[valid], b.theta[valid], b.q[valid],
                           section=b.section[valid])
    position_error = np.maximum(np.abs(fam.r[:, 2] - z[valid]),
                                np.abs(np.hypot(fam.r[:, 0], fam.r[:, 1]) - rho[valid]))
    assert position_error.max() < 1e-10 + 1e-11
    if settings.process == "Generate":
        residual, _ = meshing_function(fam, blank.outer_cone_distance)
        assert np.abs(residual).max() < 1e-12 + 1e-13
    for name in ("s", "theta", "q", "position"):
        np.testing.assert_allclose(getattr(b, name)[valid], getattr(a, name)[valid], rtol=0,
                                   atol=ROOT_TOL, err_msg=name)


@pytest.mark.parametrize("case_key, member, flank, motions", [
    ("fm", "pinion", "concave", True), ("fm", "gear", "convex", False),
    ("fh", "pinion", "convex", False), ("fh", "gear", "concave", False)])
def test_family_buffer_on_the_kernel(case_key, member, flank, motions):
    """The kernel's family buffer (r_g and its eleven derivative vectors, the normal) and
    the point equations' residuals and Jacobian, at roots and off them, against
    geometry.machine.family.family_buffer and meshing._evaluate: the same expressions, to
    round-off (1e-12 of each vector's, residual's or Jacobian entry's scale: products of a
    chain of rotations of ~100 mm vectors, with sin and cos that may differ by an ulp)."""
    fs, blade, settings, blank = _setup(case_key, member, flank, motions)
    generate = settings.process == "Generate"
    x0, section, z, p = _starts(fs, generate, np.random.default_rng(3))
    q = x0[:, 2] if generate else np.zeros(len(x0))
    out = {}
    for kernels in ("numpy", "numba"):
        ctx = meshing._context(blade, settings, blank.outer_cone_distance, kernels)
        out[kernels] = meshing._family(ctx, x0[:, 0], x0[:, 1], q, section)
    a, b = out["numpy"], out["numba"]
    assert a.shape == b.shape == (3, 11, len(x0))
    scale = np.max(np.abs(a), axis=(0, 2), keepdims=True)  # per vector of the buffer
    assert np.all(np.isfinite(a)) and np.all(np.isfinite(b))
    assert (np.abs(b - a) / scale).max() < 1e-12
    # the residuals and their Jacobian (meshing._evaluate), scaled per row and column
    res = {}
    for kernels in ("numpy", "numba"):
        ctx = meshing._context(blade, settings, blank.outer_cone_distance, kernels)
        res[kernels] = meshing._evaluate(ctx, x0, section, z, p)[:2]
    (fa, ja), (fb, jb) = res["numpy"], res["numba"]
    assert fb.shape == fa.shape and jb.shape == ja.shape
    f_scale = np.max(np.abs(fa), axis=0)
    j_scale = np.max(np.abs(ja), axis=0)
    assert (np.abs(fb - fa) / f_scale).max() < 1e-12
    assert (np.abs(jb - ja) / j_scale).max() < 1e-12
    if generate:
        # the meshing function of the buffer, computed with it in the kernel: IEEE
        # products, sums, square roots and divisions in the NumPy path's order, so the
        # same numbers on any machine; the buffer the same as the kernel's without it
        ctx = meshing._context(blade, settings, blank.outer_cone_distance, "numba")
        buf, *got = meshing._family_meshing(ctx, x0[:, 0], x0[:, 1], q, section)
        np.testing.assert_array_equal(buf, b)
        want = meshing_buffer(b, blank.outer_cone_distance)
        np.testing.assert_array_equal(got[0], want[0])
        np.testing.assert_array_equal(got[1], want[1])


def test_kernels_name_is_checked():
    """An unknown implementation is an InputError naming the field."""
    fs, blade, settings, blank = _setup("fm", "gear", "concave")
    with pytest.raises(InputError, match="kernels: must be one of numpy, numba"):
        solve_envelope(blade, settings, fs.grid.axial, fs.grid.radius,
                       length_scale=blank.outer_cone_distance, depth=10.0,
                       kernels="fortran")
