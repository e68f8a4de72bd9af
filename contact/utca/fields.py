"""The ease-off fields as smooth functions over the gear grid (seed §2.3.2.2, §4.4).

:class:`EaseOffFields` holds bicubic interpolants (which reproduce the exact node values) of
the fields of an :class:`contact.utca.easeoff.EaseOff` over the gear projection-plane grid
(u, v): the surface of roll angle Q, the angular ease-off ε, the gap curvature K, the
normal arm, the real gear flank (points and normals) and the mating pinion point's margin
in its blank. It answers the questions the contact curves, the edge contact and the LTCA
ask of the ease-off: which places can be touched (:meth:`EaseOffFields.inside`,
:meth:`EaseOffFields.measure`), where the iso-line Q = q crosses a lengthwise place
(:meth:`EaseOffFields.solve_v`), and the gap curvature held within its nodes' range
(:meth:`EaseOffFields.gap_at`).

ε, Q and K are built from the valid nodes and the computed nodes on the same smooth sheet
beyond them (both points on their blades' main sections), continued linearly past those
(:func:`contact.utca.easeoff.fill_missing`): a blade-section junction kinks the fields and
a cubic spline would carry the kink back. Their interpolant is the interpolating bicubic
spline (``RectBivariateSpline``, s = 0), except where a relief's corner crosses the sheet
(:func:`contact.utca.relief_corners.relief_corners`: from the blades' sections of the
nodes, not from the data): there it is :func:`contact.utca.corner_spline.corner_spline`,
its grid lines cut at the corner with shape-preserving slopes, where the global spline
rang (30 µrad below flat node data next to a tip relief's corner, issue 71), and the
other fields are the interpolating splines in the same form (same knots).

Q must be strictly monotone along the profile direction (checked; otherwise
``ModelUnavailableError``), so a contact curve is parameterised by the lengthwise fraction
u and its profile place v*(u) solved by Newton's method on the interpolant (on a set of
places shared by many curves, on the interpolant's cubic piece of each place's column:
:meth:`EaseOffFields.solve_columns`).

Public functions
----------------
EaseOffFields   splines of an ease-off's fields and the contact region's tests
fields_of       an ease-off's fields, built once per process and ease-off object
kernels_module  the iso-line searches' implementation (NumPy, or numba's compiled kernels)
"""

from __future__ import annotations

from types import ModuleType
from typing import NamedTuple

import numpy as np
from scipy.interpolate import BSpline, RectBivariateSpline

from contact.utca.corner_spline import corner_splines
from contact.utca.easeoff import EaseOff, fill_missing
from contact.utca.piecewise import PiecewiseSpline, from_splines, piece_basis
from contact.utca.relief_corners import relief_corners
from contact.utca.spline_group import SplineGroup
from geometry.core.caches import Carried, Same, memoised
from geometry.core.errors import InputError, ModelUnavailableError
from geometry.core.kernels import KERNELS
from geometry.core.kernels import kernels_module as select_kernels

__all__ = ["KERNELS", "EaseOffFields", "KernelSplines", "clear_fields_memo", "fields_of",
           "kernels_module"]

_KERNEL_MODULE = "contact.utca.isoline_numba"  # the iso-line searches' compiled kernels
#: the scalar fields of :meth:`EaseOffFields.values` (and ``pos``, ``nrm``: three each)
_FIELD_NAMES = ("q", "eps", "gap", "arm", "pos", "nrm", "margin", "pu", "pv")

_V_NEWTON = 6  # Newton steps of the profile place v*(u) on the spline of Q
_COLUMN_NEWTON = 12  # safeguarded Newton steps of v*(u) on a column's cubic piece


class KernelSplines(NamedTuple):
    """Splines as the compiled kernels take them: (bx, by, coefficients) each, the
    piecewise-polynomial form (:class:`contact.utca.piecewise.PiecewiseSpline`)."""

    q: tuple  # Q [rad]
    margin: tuple  # the pinion mate's inside measure [1]
    eps: tuple  # ε [rad]


def kernels_module(kernels: str | None = None) -> ModuleType | None:
    """The compiled iso-line kernels to use, or None for the NumPy path.

    Parameters
    ----------
    kernels : {"numpy", "numba"} or None
        None: the environment variable ``LTCA_KERNELS`` (same values), else ``numba``
        where it is installed and ``numpy`` otherwise
        (:func:`geometry.core.kernels.kernels_module`).

    Returns
    -------
    module or None
        :mod:`contact.utca.isoline_numba`, or None (NumPy).

    Raises
    ------
    InputError
        An unknown name, or ``numba`` asked for where it is not installed.
    """
    return select_kernels(_KERNEL_MODULE, kernels)


class EaseOffFields:
    """Bicubic interpolants of the ease-off fields over the gear grid (u, v).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
    kernels : {"numpy", "numba"} or None
        The iso-line searches' implementation (:func:`kernels_module`; default None: numba
        where installed unless ``LTCA_KERNELS=numpy``). Both give the same numbers to
        the splines' round-off (:mod:`contact.utca.isoline_numba`).

    Attributes
    ----------
    eo : EaseOff
        The ease-off the splines are built on.
    u, v : ndarray — [1]
        The gear grid's lengthwise and profile fractions.
    q, eps, gap : RectBivariateSpline
        Q [rad], ε [rad] and the gap curvature K [1/rad] over (u, v): the interpolating
        splines, or where a relief's corner crosses the sheet (``cuts``) bicubic Hermite
        interpolants with double knots cut there
        (:func:`contact.utca.corner_spline.corner_spline`; the others then the
        interpolating splines in that form).
    cuts : (ndarray of bool (nu, nv), ndarray of bool (nu, nv)) or None
        The nodes at which the lines along u and along v are cut
        (:func:`contact.utca.relief_corners.relief_corners`); None: no relief corner.
    arm : RectBivariateSpline
        Normal arm ρ |n·e_θ| [mm].
    pos, nrm : list of 3 RectBivariateSpline
        Components of the real gear flank point [mm] and unit normal (gear frame).
    margin, pu, pv : RectBivariateSpline
        The mating pinion point's inside measure in its blank and its lengthwise and
        profile fractions.
    computed, cell_ok : ndarray of bool
        Nodes with computed fields (u, v); grid cells whose four corners are computed.
    q_sign : int
        Sign of ∂Q/∂v (Q is monotone along the profile).
    gap_range : (float, float) — [1/rad]
        Least and greatest K of the nodes (:meth:`gap_at` holds K within it).

    kernels : module or None
        The compiled kernels in use (:mod:`contact.utca.isoline_numba`), None for NumPy.
    kernel_splines : KernelSplines
        Q, the margin and ε as the kernels take them (only with ``kernels``).

    Raises
    ------
    InputError
        Fewer than 16 valid nodes, or an unknown ``kernels``.
    ModelUnavailableError
        Q is not monotone along the profile direction.
    """

    def __init__(self, eo: EaseOff, kernels: str | None = None):
        self.kernels = kernels_module(kernels)
        self.eo = eo
        self.u, self.v = eo.u, eo.v
        computed = np.isfinite(eo.raw_ease_off_angle) & np.isfinite(eo.raw_roll_angle)
        valid = eo.valid
        if valid.sum() < 16:
            raise InputError(f"eo: must have at least 16 valid nodes to contour, got "
                             f"{int(valid.sum())}")
        self.computed = computed
        gear_ok = np.all(np.isfinite(eo.gear_position), axis=-1)

        # the grid lines cut at a relief's corner, from the design (relief_corners): None
        # without a relief on the sheet, and then every field is the interpolating spline
        cuts = relief_corners(eo)
        self.cuts = cuts

        def spl(fields, ok, cut=False):
            return _field_splines(self.u, self.v, fields, ok,
                                  cuts if cut else None, cuts is None)

        # ε and Q from the valid nodes and, beyond them, from the computed nodes on the same
        # smooth sheet (both points on their blades' main sections), continued linearly
        # past those: a section junction (e.g. the gear's fillet) kinks the fields, and a
        # cubic spline would carry the kink back into the contact region. Where a relief's
        # corner crosses the sheet their grid lines are cut there (relief_corners: the
        # blades' sections of the nodes, not the data; corner_spline): the global spline
        # rang there, 30 µrad below flat node data next to a tip relief's corner (issue
        # 71). The gear flank's fields are smooth, and the pinion mate's margin is a least
        # of distances whose ridges are no corner of the contact region: their splines
        # uncut (then on the same knots as the cut ones, for the groups of values()).
        sheet = valid | eo.smooth
        self.q, self.eps, self.gap = spl(
            [eo.raw_roll_angle, eo.raw_ease_off_angle, eo.gap_curvature], sheet, True)
        k_nodes = eo.gap_curvature[sheet & np.isfinite(eo.gap_curvature)]
        self.gap_range = ((float(k_nodes.min()), float(k_nodes.max())) if k_nodes.size
                          else (-np.inf, np.inf))
        # (the gear flank's alone: the same nodes at every misalignment, so once per
        # study, _gear_splines)
        self.arm, *gear = _gear_splines(
            self.u, self.v, [eo.normal_arm, *np.moveaxis(eo.gear_position, -1, 0),
                             *np.moveaxis(eo.gear_normal, -1, 0)], gear_ok, cuts is None)
        self.pos, self.nrm = gear[:3], gear[3:]
        self.margin, self.pu, self.pv = spl([eo.margin, eo.pinion_u, eo.pinion_v], computed)
        dq = np.diff(np.where(valid, eo.raw_roll_angle, np.nan), axis=1)
        signs = np.sign(dq[np.isfinite(dq)])
        if signs.size == 0 or not (np.all(signs > 0) or np.all(signs < 0)):
            raise ModelUnavailableError(
                "contact curves: the roll-angle surface is not monotone along the profile "
                "direction of the gear grid, so a contact curve cannot be parameterised by "
                "the lengthwise position (met on a spiral bevel 12x12 miter of face "
                "contact ratio 0.56, docs/own_gear_set.md round 17)")
        self.q_sign = int(signs[0])
        # cell corners all computed (hard mask): cell (i, j) spans u[i]..u[i+1], v[j]..v[j+1]
        c = computed
        self.cell_ok = c[:-1, :-1] & c[1:, :-1] & c[:-1, 1:] & c[1:, 1:]
        # Q on the coarse places of the contact curves, by their number and range (the
        # curves and the probes of near misses use two sets)
        self._lattices: dict[tuple, np.ndarray] = {}
        self._columns: dict[tuple, tuple[np.ndarray, np.ndarray]] = {}
        self._groups: dict[tuple, SplineGroup] = {}  # values()'s groups, by names
        self._pieces: dict[str, PiecewiseSpline] = {}  # each field's, by name
        if self.kernels is not None:
            # the splines as the kernels take them: (bx, by, coefficients)
            self.kernel_splines = KernelSplines(
                *(tuple(self._field_pieces(name)) for name in ("q", "margin", "eps")))

    def gap_at(self, u, v):
        """The pinion's gap curvature K at gear places, held within the nodes' range.

        Parameters
        ----------
        u, v : array_like, broadcastable — [1]
            Gear fractions (finite).

        Returns
        -------
        ndarray — [1/rad]
            K (the angular gap at roll Q + t is ½ K t²), clipped to :attr:`gap_range`:
            near a fold or masked nodes the spline of the filled field can overshoot it
            (on ISO sample 2 to K < 0 at the gear tip, where the nodes hold K ≥ 0.055: an
            edge's separation ε + ½ K t² then fell by hundreds of µm).
        """
        return np.clip(self.values(("gap",), u, v)[..., 0], *self.gap_range)

    def good_cell(self, u, v):
        """True where (u, v) lies in a grid cell whose corners were all computed (places
        beyond the grid count as its edge cells)."""
        # (np.minimum/np.maximum: np.clip's arithmetic without its wrapper's overhead)
        iu = np.minimum(np.maximum(np.searchsorted(self.u, u, side="right") - 1, 0),
                        len(self.u) - 2)
        iv = np.minimum(np.maximum(np.searchsorted(self.v, v, side="right") - 1, 0),
                        len(self.v) - 2)
        return self.cell_ok[iu, iv]

    def inside(self, u, v):
        """Whether gear places can be touched.

        Parameters
        ----------
        u, v : ndarray, same shape — [1]
            Gear fractions (v may be NaN).

        Returns
        -------
        ndarray of bool
            In the grid, in a cell whose corners were all computed (:meth:`good_cell`) and
            with the pinion mate in its blank (margin ≥ 0).
        """
        u0, u1, v0, v1 = self.u[0], self.u[-1], self.v[0], self.v[-1]
        ok = (u >= u0) & (u <= u1) & (v >= v0) & (v <= v1) & np.isfinite(v)
        ok &= self.good_cell(np.where(ok, u, u0), np.where(ok, v, v0))
        # the margin only where the rest holds (the spline is evaluated point by point)
        ok[ok] = self.margin.ev(u[ok], v[ok]) >= 0.0
        return ok

    def _splines(self, name: str) -> list:
        """The splines of one field name (:meth:`values`)."""
        if name in ("pos", "nrm"):
            return list(getattr(self, name))
        if name not in _FIELD_NAMES:
            raise InputError(f"names: must be among {', '.join(_FIELD_NAMES)}, got {name!r}")
        return [getattr(self, name)]

    def values(self, names: tuple[str, ...], u, v, dx: int = 0, dy: int = 0) -> np.ndarray:
        """Several fields (or one partial derivative of each) at the same places.

        Parameters
        ----------
        names : tuple of str
            Fields among ``q`` [rad], ``eps`` [rad], ``gap`` [1/rad] (not held to
            :attr:`gap_range`), ``arm`` [mm], ``pos`` [mm] and ``nrm`` [1] (three
            components each: the real gear flank's point and normal, not normalised),
            ``margin`` [1], ``pu``, ``pv`` [1].
        u, v : array_like, broadcastable — [1]
            Gear fractions (finite).
        dx, dy : int
            Order of the partial derivative in u and in v (0–2 each).

        Returns
        -------
        ndarray, shape broadcast(u, v) + (K,)
            The fields in the order of ``names`` (K = 1 per scalar field, 3 for ``pos``
            and ``nrm``); each the spline's ``ev(u, v, dx, dy)``. With the compiled
            kernels the fields are evaluated in piecewise-polynomial form and share each
            place's cell (the fields' splines are all on the grid's knots): the same
            splines, to their round-off (~1e-15 of their scale).

        Raises
        ------
        InputError
            An unknown field name.
        """
        key = tuple(names)
        group = self._groups.get(key)
        if group is None:
            splines = [s for name in names for s in self._splines(name)]
            pieces = None
            if self.kernels is not None:  # each field's polynomials formed once
                parts = [self._field_pieces(name) for name in names]
                pieces = PiecewiseSpline(parts[0].bx, parts[0].by, np.ascontiguousarray(
                    np.concatenate([p.coefficients for p in parts], axis=2)))
            group = self._groups[key] = SplineGroup(splines, self.kernels, pieces)
        return group(u, v, dx, dy)

    def _field_pieces(self, name: str) -> PiecewiseSpline:
        """One field's splines in piecewise-polynomial form (formed once, for the kernels;
        the fields' splines share the grid's knots)."""
        pp = self._pieces.get(name)
        if pp is None:
            pp = self._pieces[name] = from_splines(self._splines(name), self.kernels)
        return pp

    def lattice(self, uc):
        """Q at the coarse places uc × the grid's profile nodes (cached)."""
        key = (len(uc), float(uc[0]), float(uc[-1]))
        lat = self._lattices.get(key)
        if lat is None:
            lat = self._lattices[key] = self.q(uc, self.v)
        return lat

    def columns(self, uc):
        """Q on lengthwise places as cubic pieces in v (cached per set of places).

        Parameters
        ----------
        uc : ndarray (nc,) — [1]
            Lengthwise fractions in the grid.

        Returns
        -------
        breaks : ndarray (n_int + 1,) — [1]
            The spline's knot intervals in v.
        coefficients : ndarray (nc, n_int, 4) — [rad]
            On [breaks[i], breaks[i + 1]], Q(uc[j], v) = Σ_p c[j, i, p] (v − breaks[i])^p:
            the bicubic interpolant of Q restricted to each column (a cubic B-spline in v
            whose coefficients are the u-basis at uc[j] applied to the spline's; cut at a
            relief corner, its piecewise-polynomial form's cell polynomial in u evaluated
            at uc[j]; de Boor, *A Practical Guide to Splines*, 1978), matching FITPACK's
            evaluation to round-off.
        """
        key = (len(uc), float(uc[0]), float(uc[-1]))
        cols = self._columns.get(key)
        if cols is None:
            if self.cuts is None:
                tx, ty, c = self.q.tck
                kx, ky = self.q.degrees
                d = BSpline.design_matrix(np.asarray(uc, dtype=float), tx, kx).toarray()
                coef = d @ c.reshape(len(tx) - kx - 1, len(ty) - ky - 1)  # per column
                basis = piece_basis(ty, ky)  # (n_int, 4, 4)
                n_int = basis.shape[0]
                idx = np.arange(n_int)[:, None] + np.arange(ky + 1)[None, :]
                cols = self._columns[key] = (ty[ky:ky + n_int + 1],
                                             np.einsum("jia,iap->jip", coef[:, idx], basis))
            else:  # double knots: the piecewise form's cell polynomials in u at uc
                pp = self._field_pieces("q")
                x = np.minimum(np.maximum(np.asarray(uc, dtype=float), pp.bx[0]), pp.bx[-1])
                i = np.minimum(np.searchsorted(pp.bx, x, side="right") - 1, len(pp.bx) - 2)
                powers = (x - pp.bx[i])[:, None] ** np.arange(pp.coefficients.shape[3])
                cols = self._columns[key] = (pp.by, np.einsum(
                    "jp,jipq->jiq", powers, pp.coefficients[i, :, 0]))
        return cols

    def solve_columns(self, uc, target):
        """Profile places of iso-lines on a set of lengthwise places (seed §2.3.2.2).

        :meth:`solve_v` of ``(uc[None, :], target[:, None])`` started from the lattice
        (:meth:`lattice`), but by Newton's method on each column's cubic piece
        (:meth:`columns`) in the bracketing grid cell (held in the cell) instead of on the
        bicubic spline: the same root (the piece is the spline there) without two spline
        evaluations per step (issue 32).

        Parameters
        ----------
        uc : array_like (nc,) — [1]
            Lengthwise fractions (the contact curves' coarse samples).
        target : array_like (nb,) — [rad]
            Values q of Q.

        Returns
        -------
        ndarray (nb, nc) — [1]
            v* in [v₀, v₁], NaN where Q misses the target in [v₀, v₁] or |Q − q| stays
            above 1e-9 rad; converged to |Q − q| < 1e-13 rad as :meth:`newton_v`.
        """
        uc = np.asarray(uc, dtype=float)
        target = np.asarray(target, dtype=float)
        nb, nc = target.size, uc.size
        vn, s = self.v, self.q_sign
        breaks, pieces = self.columns(uc)
        # the knot interval holding each cell (cells lie within one interval: the knots are
        # grid nodes)
        cell_piece = np.clip(np.searchsorted(breaks, 0.5 * (vn[:-1] + vn[1:]), side="right")
                             - 1, 0, len(breaks) - 2)
        if self.kernels is not None:  # the same arithmetic, compiled
            return self.kernels.solve_columns(self.lattice(uc), vn, float(s),
                                              target.ravel(), breaks, pieces, cell_piece,
                                              _COLUMN_NEWTON)
        qn = self.lattice(uc)[None, :, :]  # (1, nc, nv)
        tg = target[:, None]
        below = (s * (qn - tg[..., None])) <= 0
        k = np.clip(below.sum(-1) - 1, 0, len(vn) - 2)  # (nb, nc) bracketing cell
        qa = np.take_along_axis(np.broadcast_to(qn, (nb, nc, len(vn))), k[..., None], -1)[..., 0]
        qb = np.take_along_axis(np.broadcast_to(qn, (nb, nc, len(vn))), (k + 1)[..., None],
                                -1)[..., 0]
        t = np.clip((tg - qa) / np.where(qb != qa, qb - qa, 1.0), 0.0, 1.0)
        v = vn[k] + t * (vn[k + 1] - vn[k])
        miss = (s * (qn[..., 0] - tg) > 0) | (s * (qn[..., -1] - tg) < 0)
        piece = cell_piece[k]
        act = np.flatnonzero(~miss.ravel())
        vf = v.ravel().copy()
        out = np.full(nb * nc, np.nan)
        if act.size:
            col = np.broadcast_to(np.arange(nc), (nb, nc)).ravel()[act]
            ka = k.ravel()[act]
            c = pieces[col, piece.ravel()[act]]  # (M, 4)
            c0, c1, c2, c3 = c[:, 0], c[:, 1], c[:, 2], c[:, 3]
            x0 = breaks[piece.ravel()[act]]
            lo, hi = vn[ka] - x0, vn[ka + 1] - x0
            x = vf[act] - x0
            ta = np.broadcast_to(tg, (nb, nc)).ravel()[act]
            f = ((c3 * x + c2) * x + c1) * x + c0 - ta
            run = np.flatnonzero(~(np.abs(f) < 1e-13))
            for _ in range(_COLUMN_NEWTON):
                if run.size == 0:
                    break
                xr = x[run]
                d = (3.0 * c3[run] * xr + 2.0 * c2[run]) * xr + c1[run]
                xn = np.minimum(np.maximum(xr - f[run] / np.where(d != 0, d, 1e-30), lo[run]),
                                hi[run])
                fr = ((c3[run] * xn + c2[run]) * xn + c1[run]) * xn + c0[run] - ta[run]
                x[run], f[run] = xn, fr
                run = run[~(np.abs(fr) < 1e-13) & (xn != xr)]
            out[act] = np.where(np.abs(f) > 1e-9, np.nan, x + x0)
        return out.reshape(nb, nc)

    def measure_terms(self, u, v):
        """(5, ...) the terms whose least is the inside measure at (u, v) (v finite): the
        pinion mate's margin in its blank, v − v₀, v₁ − v, u − u₀, u₁ − u."""
        return np.stack([self.margin.ev(u, v), v - self.v[0], self.v[-1] - v,
                         u - self.u[0], self.u[-1] - u])

    def measure(self, u, v):
        """Continuous inside measure of the contact region.

        Parameters
        ----------
        u, v : array_like, broadcastable — [1]
            Gear fractions (v may be NaN).

        Returns
        -------
        ndarray — [1]
            The least of :meth:`measure_terms`: ≥ 0 inside the contact region, < 0
            outside, −1 where undefined (v NaN or a cell with an uncomputed corner).
        """
        if self.kernels is not None:
            u, v = (np.asarray(a, dtype=float) for a in (u, v))
            if u.shape != v.shape:
                u, v = np.broadcast_arrays(u, v)
            ks = self.kernel_splines
            # (writable arrays: a read-only one would compile and load a second
            # specialisation of the kernel in every process)
            uf, vf = (np.require(a.ravel(), requirements=["C", "W"]) for a in (u, v))
            return self.kernels.measure(ks.margin, self.u, self.v, self.cell_ok, uf,
                                        vf).reshape(u.shape)
        fin = np.isfinite(v)
        vs = np.where(fin, v, self.v[0])
        # the least of measure_terms, taken in their order (the reduction's own sequence of
        # minima, without stacking the five arrays)
        c = np.minimum(self.margin.ev(u, vs), vs - self.v[0])
        for term in (self.v[-1] - vs, u - self.u[0], self.u[-1] - u):
            np.minimum(c, term, out=c)
        return np.where(fin & self.good_cell(u, vs), c, -1.0)

    def solve_v(self, u, target, v_start=None, lattice=None):
        """Profile place v*(u) on the iso-line Q(u, v*) = target (seed §2.3.2.2).

        Parameters
        ----------
        u : array_like — [1]
            Lengthwise fractions (broadcast with ``target``).
        target : array_like — [rad]
            Values q of Q.
        v_start : array_like, optional — [1]
            A nearby solution (broadcast to the shape of u; NaN: the grid's middle).
        lattice : array_like (..., nv), optional — [rad]
            Q at u × the grid's profile nodes (:meth:`lattice`): the solution is started
            in the bracketing cell instead (and known misses are skipped).

        Returns
        -------
        ndarray — [1]
            v* (broadcast shape), NaN where Q misses the target in [v₀, v₁]; Newton's
            method on the spline to |ΔQ| < 1e-13 rad (:meth:`newton_v`).
        """
        u = np.asarray(u, dtype=float)
        target = np.asarray(target, dtype=float)
        if u.shape != target.shape:
            shape = np.broadcast_shapes(u.shape, target.shape)
            u = np.broadcast_to(u, shape)
            target = np.broadcast_to(target, shape)
        shape = u.shape
        if lattice is not None:
            vn = self.v
            qn = np.broadcast_to(lattice, (*shape, len(vn)))
            s = self.q_sign
            below = (s * (qn - target[..., None])) <= 0
            k = np.clip(below.sum(-1) - 1, 0, len(vn) - 2)
            qa = np.take_along_axis(qn, k[..., None], -1)[..., 0]
            qb = np.take_along_axis(qn, (k + 1)[..., None], -1)[..., 0]
            t = np.clip((target - qa) / np.where(qb != qa, qb - qa, 1.0), 0.0, 1.0)
            v = (vn[k] + t * (vn[k + 1] - vn[k])).ravel()
            miss = ((s * (qn[..., 0] - target) > 0) | (s * (qn[..., -1] - target) < 0)).ravel()
        else:
            v_start = np.asarray(v_start, dtype=float)
            v = (v_start.ravel() if v_start.shape == shape
                 else np.broadcast_to(v_start, shape).ravel()).copy()
            v[~np.isfinite(v)] = 0.5 * (self.v[0] + self.v[-1])
            miss = None
        return self.newton_v(u.ravel(), target.ravel(), v, miss).reshape(shape)

    def newton_v(self, uf, tf, v, miss=None):
        """:meth:`solve_v` on flat arrays, from a finite start (no broadcasting, no copy).

        Parameters
        ----------
        uf : ndarray (M,) — [1]
            Lengthwise fractions.
        tf : ndarray (M,) — [rad]
            Values q of Q.
        v : ndarray (M,) — [1]
            Finite start places; the NumPy path overwrites them with its iterates (pass a
            copy to keep them).
        miss : bool ndarray (M,), optional
            Points known to miss (left out, NaN).

        Returns
        -------
        ndarray (M,) — [1]
            v* within [v₀, v₁] (held there), NaN where Newton's method ended beyond the
            grid by more than 1e-9 of it or |Q − q| > 1e-9 rad.
        """
        v0, v1 = self.v[0], self.v[-1]
        if self.kernels is not None:
            ks = self.kernel_splines
            return self.kernels.newton_v(
                ks.q, v0, v1, np.asarray(uf, dtype=float),
                np.asarray(tf, dtype=float), np.asarray(v, dtype=float),
                np.zeros(len(uf), dtype=bool) if miss is None else np.asarray(miss, bool))
        f = self.q.ev(uf, v) - tf
        # Newton on the points not yet converged (and not known to miss) only
        act = np.flatnonzero(~(np.abs(f) < 1e-13) if miss is None
                             else ~(np.abs(f) < 1e-13) & ~miss)
        for _ in range(_V_NEWTON):
            if act.size == 0:
                break
            ua, va = uf[act], v[act]
            d = self.q.ev(ua, va, dy=1)
            # the spline is defined on [v0, v1] only (FITPACK clamps outside)
            vn = np.minimum(np.maximum(va - f[act] / np.where(d != 0, d, 1e-30), v0), v1)
            fa = self.q.ev(ua, vn) - tf[act]
            v[act], f[act] = vn, fa
            # a point whose step left it in place (held at v0 or v1 by the clamp) would
            # repeat the same step: it is finished (a miss unless |f| is already small)
            act = act[~(np.abs(fa) < 1e-13) & (vn != va)]
        tol = 1e-9 * (v1 - v0)
        bad = (v < v0 - tol) | (v > v1 + tol) | (np.abs(f) > 1e-9)
        if miss is not None:
            bad |= miss
        return np.where(bad, np.nan, np.minimum(np.maximum(v, v0), v1))


def fields_of(eo: EaseOff, kernels: str | None = None) -> EaseOffFields:
    """The :class:`EaseOffFields` of an ease-off, built once per process and ease-off
    object.

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
        The ease-off (compared by identity: the object the ease-off memo,
        :func:`contact.utca.easeoff.ease_off`, hands to every step of an analysis).
    kernels : {"numpy", "numba"} or None
        As :class:`EaseOffFields` (resolved first: the memo keeps one entry per
        implementation).

    Returns
    -------
    EaseOffFields
        The same object to every caller with the same ease-off object (its splines are
        fixed; what it computes lazily, the Q lattices and spline pieces, is the same
        arithmetic whoever asks first): the unloaded cycle and the LTCA's segment geometry
        of one analysis share one instead of building one each (~3–4 ms a build on the
        default case), and the analyses of a torque series share the memoised ease-off's.

    Raises
    ------
    InputError, ModelUnavailableError
        As :class:`EaseOffFields`.

    Notes
    -----
    Source: the splines of seed §2.3.2.2 (module docstring); the memo changes no number.
    """
    name = "numpy" if kernels_module(kernels) is None else "numba"
    return _memo_fields(Same(eo), name)


def clear_fields_memo() -> None:
    """Forget the :class:`EaseOffFields` memoised per process by :func:`fields_of` (frees
    memory; the next call builds afresh), and the gear flank's splines they share
    (:func:`_gear_splines`)."""
    _memo_fields.cache_clear()
    _memo_gear_splines.cache_clear()


def _field_splines(u: np.ndarray, v: np.ndarray, fields: list, ok: np.ndarray, cuts,
                   plain: bool) -> list:
    """The splines of :class:`EaseOffFields` of ``fields`` (K arrays (nu, nv)) on the grid
    (u, v), each filled beyond the nodes ``ok`` (:func:`fill_missing`; the fields sharing a
    mask filled together, the same arithmetic per field): ``RectBivariateSpline`` where
    the ease-off has no relief corner on its sheet (``plain``), else
    :func:`contact.utca.corner_spline.corner_splines` with the grid lines cut at ``cuts``
    (cut_x, cut_y) or uncut (None: on the same knots as the cut ones)."""
    filled = fill_missing(np.stack(fields, -1), ok)
    if plain:
        return [RectBivariateSpline(u, v, filled[..., k]) for k in range(len(fields))]
    cx, cy = cuts if cuts is not None else (None, None)
    return corner_splines(u, v, np.moveaxis(filled, -1, 0), cx, cy)


def _gear_splines(u: np.ndarray, v: np.ndarray, fields: list, ok: np.ndarray,
                  plain: bool) -> list:
    """:func:`_field_splines` of the gear flank's fields (uncut), kept per process by
    their values (:func:`_memo_gear_splines`).

    The gear's normal arm, points and normals on the ease-off's grid do not depend on the
    misalignment (the gear nodes are memoised per flank,
    :func:`contact.utca.conjugate_map.gear_nodes`), so a study's every point built the
    same seven splines again (≈ 1.5 ms a point, issue 75). The key is every input's
    bytes, shape and dtype (the grid, the fields, the mask, ``plain``): a hit is the same
    computation on the same numbers, so the same splines bit for bit; any change of a
    value (deviations of the gear, another design) is a miss.
    """
    arrays = [np.ascontiguousarray(a) for a in (u, v, ok, *fields)]
    key = (bool(plain), *((a.dtype.str, a.shape, a.tobytes()) for a in arrays))
    return list(_memo_gear_splines(key, Carried((u, v, fields, ok, plain))))


@memoised(maxsize=4)
def _memo_gear_splines(key: tuple, inputs: Carried) -> tuple:
    """:func:`_gear_splines`' memo: ``key`` the inputs' bytes, ``inputs`` the arrays
    themselves (not part of the key)."""
    u, v, fields, ok, plain = inputs.value
    return tuple(_field_splines(u, v, fields, ok, None, plain))


@memoised(maxsize=8)
def _memo_fields(eo: Same, kernels: str) -> EaseOffFields:
    """:class:`EaseOffFields` of ``eo.obj``, memoised per process by the ease-off object
    and the kernels' name (:func:`fields_of`)."""
    return EaseOffFields(eo.obj, kernels)
