"""Splines on the same knots evaluated together, with one B-spline basis per place.

The ease-off's fields (:class:`contact.utca.fields.EaseOffFields`) and the forward map of
the conjugate mapping (:mod:`contact.utca.conjugate_map`) are interpolating bicubic
splines on one grid each, so all the splines of a group share their knots: at a place,
the B-spline basis (FITPACK's ``fpbspl``, the costly part of an evaluation) serves them
all. With the compiled kernels (:mod:`contact.utca.isoline_numba`) a group computes it
once per place; without them each spline's ``ev`` runs. Both give FITPACK's numbers to
the last bit.

Public functions
----------------
SplineGroup   splines on the same knots, evaluated together
"""

from __future__ import annotations

from types import ModuleType

import numpy as np

__all__ = ["SplineGroup"]


class SplineGroup:
    """Splines on the same knots evaluated together: their values, or one partial
    derivative of each, at the same places.

    Parameters
    ----------
    splines : list of scipy.interpolate.RectBivariateSpline
        K splines on the same knots and degrees (interpolating splines on one grid).
    kernels : module or None
        :mod:`contact.utca.isoline_numba` (each place's B-spline basis is then computed
        once for the K splines: :func:`~contact.utca.isoline_numba.ev_many`), or None
        (each spline's ``ev``). Both give FITPACK's numbers to the last bit.

    Calling it with ``(u, v, dx=0, dy=0)`` (u, v broadcastable [1]; dx, dy the orders of
    the derivative, each below the degree) returns an array of shape broadcast(u, v) +
    (K,).
    """

    def __init__(self, splines: list, kernels: ModuleType | None):
        self.splines = list(splines)
        self.kernels = kernels
        self._stacked: dict[tuple[int, int], tuple] = {}  # the derivatives' splines

    def __call__(self, u, v, dx: int = 0, dy: int = 0) -> np.ndarray:
        u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        if self.kernels is None:
            out = np.empty((*u.shape, len(self.splines)))
            for k, spline in enumerate(self.splines):
                out[..., k] = spline.ev(u, v, dx=dx, dy=dy)
            return out
        key = (int(dx), int(dy))
        stacked = self._stacked.get(key)
        if stacked is None:
            parts = [self.kernels.derivative_spline(s.tck, s.degrees, *key)
                     for s in self.splines]
            tx, ty, _, kx, ky = parts[0]
            stacked = self._stacked[key] = (tx, ty, np.stack([p[2] for p in parts]), kx, ky)
        tx, ty, c, kx, ky = stacked
        out = self.kernels.ev_many(tx, ty, c, kx, ky, np.ascontiguousarray(u.ravel()),
                                   np.ascontiguousarray(v.ravel()))
        return out.reshape(*u.shape, c.shape[0])
