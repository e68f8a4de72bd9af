"""Small vector products over the last axis, faster than NumPy's for small batches.

Public functions
----------------
cross   the cross product of (..., 3) arrays
"""

from __future__ import annotations

import numpy as np

__all__ = ["cross"]


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product over the last axis of two broadcastable (..., 3) arrays.

    Parameters
    ----------
    a, b : array_like (..., 3)
        Vectors (any unit); broadcast against each other.

    Returns
    -------
    ndarray (broadcast shape)
        a × b. Each component is ``np.cross``'s expression (a_i b_j − a_j b_i: two
        rounded products and one rounded difference), so the same numbers; without its
        axis bookkeeping, which dominates for a few hundred vectors (~30 µs per call).
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out
