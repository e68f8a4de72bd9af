"""Compiled fill of the shell tooth's grouped load-vector factors (numba; issue 75).

A study point's two shell solves take the mean load vectors of ≈ 1,600 segments a tooth,
4 Gauss points each (:meth:`contact.compliance.shell_tooth.ShellModel.load_vectors` with
``group_weights``): each segment's vector is the product of a (rows × 2G) matrix A — the
height functions' weighted works a_k (and c_k, a rotating family's ∂W/∂θ term) at the
segment's points — with a (2G × N) matrix B — the face functions g_m(η) (and g′_m) there
(:meth:`~contact.compliance.shell_tooth.ShellModel._grouped_load_vectors`). In NumPy the
two stacks are filled by ≈ 60 whole-array passes (Legendre recurrences, work scales,
transposed writes), ≈ 3–4 ms of a ≈ 5 ms call; :func:`load_vector_factors` fills them
point by point in one pass.

Every entry is formed by the NumPy path's own operations in the same order (Bonnet's
recurrence as ``_legendre_rows`` writes it, ξ^power by multiplication, the work scales of
``_work_scale``, ``f·scale − f′·a_x``, ``−(f·a_t)``, times the weight), and numba neither
contracts nor reassociates without ``fastmath``: A and B are the NumPy path's bit for bit,
so the stacked product that follows gives the same load vectors bit for bit
(``tests/test_compliance_fast_paths.py``).

This module imports numba. :mod:`contact.compliance.tooth_map_numba` (the compliance's
kernel module, :data:`geometry.core.kernels.KERNEL_MODULES`) re-exports the kernel, so
the kernels choice and numba's cache check (:func:`geometry.core.kernels.cache_ready`) of
that module cover it.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["load_vector_factors"]

_jit = numba.njit(cache=True, nogil=True)

#: helpers called from compiled code only: no CPython or C wrapper to compile
_helper = numba.njit(cache=True, nogil=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)

_W = 2  # the normal component (contact.compliance.shell_tooth._W)


@_helper
def _legendre(t, count, p, dp):
    """P_0 … P_{count−1}(t) and their derivatives into p, dp: Bonnet's recurrence in the
    order of :func:`contact.compliance.shell_tooth._legendre_rows` (the same bits)."""
    p[0] = 1.0
    dp[0] = 0.0
    if count > 1:
        p[1] = t
        dp[1] = 1.0
    for k in range(1, count - 1):
        row = t * (2 * k + 1)
        row = row * p[k]
        row = row - p[k - 1] * k
        p[k + 1] = row / (k + 1)
        dp[k + 1] = dp[k - 1] + p[k] * (2 * k + 1)


@_jit
def load_vector_factors(xi, eta, d, zs, wts, n_face, families, dxi, deta, radius,
                        a_mat, b_mat):
    """Fill the stacks A (groups, rows, terms) and B (groups, terms, n_face) of the grouped
    load vectors (module docstring; the NumPy path's ``a_mat`` and ``b_mat``).

    Parameters
    ----------
    xi, eta : float64 (P,) — [1] the points' height fraction x/a and face coordinate in
        [−1, 1]; P = groups × G, the groups' points consecutive
    d : float64 (P, 3) — [1] the unit forces' components (e_x, e_θ, e_z)
    zs : float64 (P,) — [mm] z of the application points
    wts : float64 (G,) — [1] the group weights
    n_face : int — [1] face functions N
    families : int64 (F, 6) — per family: rotates (0/1), component, z power, first row,
        height power, height count (``ShellModel._layout``, rows = offset / N)
    dxi, deta : float — [1/mm], [1/rad] dξ/dx and dη/dθ
    radius : float — [mm] the shell's mean radius R
    a_mat : float64 (groups, rows, terms) — written: terms = 2G where a family rotates
        (the c works in the second G), else G; rows of a family the forces do no work on
        are zero
    b_mat : float64 (groups, terms, n_face) — written: g_m at the points, then g′_m

    Source: seed Eq. 3.6b, 3.10 (the works of :meth:`ShellModel.load_vectors`).
    """
    n_grp = wts.size
    n_out = xi.size // n_grp
    n_terms = a_mat.shape[2]
    rotating = n_terms > n_grp
    n_fam = families.shape[0]
    most = 1
    for fi in range(n_fam):
        most = max(most, families[fi, 5])
    g = np.empty(n_face)
    dg = np.empty(n_face)
    p = np.empty(most)
    dp = np.empty(most)
    a_mat[:] = 0.0
    for o in range(n_out):
        for j in range(n_grp):
            q = o * n_grp + j
            _legendre(eta[q], n_face, g, dg)
            for m in range(n_face):
                b_mat[o, j, m] = g[m]
                if rotating:
                    b_mat[o, n_grp + j, m] = dg[m]
            x = xi[q]
            w = wts[j]
            for fi in range(n_fam):
                rotates = families[fi, 0] != 0
                comp = families[fi, 1]
                zpow = families[fi, 2]
                r0 = families[fi, 3]
                power = families[fi, 4]
                count = families[fi, 5]
                has_scale = True
                scale = 0.0
                if zpow == 0:
                    scale = d[q, comp]
                elif zpow == 1 and comp != _W:
                    scale = d[q, comp] * zs[q]
                else:
                    has_scale = False
                if not rotates and not has_scale:
                    continue
                _legendre(2.0 * x - 1.0, count, p, dp)
                xp = x**power
                xp1 = power * x ** (power - 1) if power >= 1 else 0.0
                a_x = zs[q] * d[q, 0] * dxi
                a_t = zs[q] * d[q, 1] * deta / radius
                for k in range(count):
                    f = xp * p[k]
                    if rotates:
                        df = xp1 * p[k] + 2.0 * xp * dp[k]
                        if has_scale:
                            a = f * scale - df * a_x
                        else:
                            a = -df * a_x
                        a_mat[o, r0 + k, n_grp + j] = -(f * a_t) * w
                    else:
                        a = f * scale
                    a_mat[o, r0 + k, j] = a * w
