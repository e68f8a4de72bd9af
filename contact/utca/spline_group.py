"""Splines on the same knots evaluated together, with one cell look-up per place.

The ease-off's fields (:class:`contact.utca.fields.EaseOffFields`) and the forward map of
the conjugate mapping (:mod:`contact.utca.conjugate_map`) are interpolating bicubic
splines on one grid each, so all the splines of a group share their knots. With the
compiled kernels (:mod:`contact.utca.isoline_numba`) a group holds them in
piecewise-polynomial form (:mod:`contact.utca.piecewise`) and finds each place's cell
once for all of them; without them each spline's ``ev`` (FITPACK) runs. The two agree to
the splines' round-off (~1e-15 of their scale).

Public functions
----------------
SplineGroup   splines on the same knots, evaluated together
"""

from __future__ import annotations

from types import ModuleType

import numpy as np

from contact.utca.piecewise import PiecewiseSpline, derivative, from_splines

__all__ = ["SplineGroup"]


class SplineGroup:
    """Splines on the same knots evaluated together: their values, or one partial
    derivative of each, at the same places.

    Parameters
    ----------
    splines : list of scipy.interpolate.RectBivariateSpline
        K splines on the same knots and degrees (interpolating splines on one grid).
    kernels : module or None
        :mod:`contact.utca.isoline_numba` (the K splines in piecewise-polynomial form,
        each place's cell found once: :func:`~contact.utca.isoline_numba.ev`), or None
        (each spline's ``ev``).
    pieces : PiecewiseSpline, optional
        The K splines' piecewise-polynomial form, where the caller holds it already
        (:func:`contact.utca.piecewise.from_splines` of ``splines``); formed on first use
        otherwise.

    Calling it with ``(u, v, dx=0, dy=0)`` (u, v broadcastable [1]; dx, dy the orders of
    the derivative, each below the degree) returns an array of shape broadcast(u, v) +
    (K,).
    """

    def __init__(self, splines: list, kernels: ModuleType | None,
                 pieces: PiecewiseSpline | None = None):
        self.splines = list(splines)
        self.kernels = kernels
        self._pieces: dict[tuple[int, int], PiecewiseSpline] = {}  # by derivative order
        if pieces is not None:
            if pieces.coefficients.shape[2] != len(self.splines):
                raise ValueError(f"pieces: must hold the {len(self.splines)} splines, got "
                                 f"{pieces.coefficients.shape[2]}")
            self._pieces[(0, 0)] = pieces

    def __call__(self, u, v, dx: int = 0, dy: int = 0) -> np.ndarray:
        u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        if self.kernels is None:
            out = np.empty((*u.shape, len(self.splines)))
            for k, spline in enumerate(self.splines):
                out[..., k] = spline.ev(u, v, dx=dx, dy=dy)
            return out
        key = (int(dx), int(dy))
        pp = self._pieces.get(key)
        if pp is None:
            base = self._pieces.get((0, 0))
            if base is None:
                base = self._pieces[(0, 0)] = from_splines(self.splines, self.kernels)
            pp = self._pieces[key] = derivative(base, *key)
        out = self.kernels.ev(pp.bx, pp.by, pp.coefficients, np.ascontiguousarray(u.ravel()),
                              np.ascontiguousarray(v.ravel()))
        return out.reshape(*u.shape, len(self.splines))
