"""The tapered shell tooth of seed §3.2 and its Rayleigh–Ritz model's data.

:class:`ShellTooth` is the tooth of seed Eq. 3.1 — a segment of a circular cylindrical
shell of mean radius R, height h(θ) and thickness t(x, θ) linear in both variables;
:data:`THEORIES` the kinematic theories of the shell (a registry: Mindlin with shear,
Kirchhoff); :class:`ShellModel` the assembled Rayleigh–Ritz model (polynomial shape
functions clamped at the root, free at the tip, toe and heel; Gauss quadrature) that
:func:`contact.compliance.shell.build_shell_model` returns.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import linalg

from geometry.core.errors import InputError
from geometry.core.kernels import kernels_module
from geometry.core.validation import positive, real

__all__ = [
    "THEORIES",
    "ShellModel",
    "ShellTooth",
]

#: Mindlin shear correction factor used unless told otherwise (Mindlin 1951).
SHEAR_CORRECTION = 5.0 / 6.0

#: the compliance's compiled kernel module (it re-exports the grouped load vectors' fill,
#: :mod:`contact.compliance.shell_loads_numba`; the string of
#: :data:`contact.compliance.tooth_map.KERNEL_MODULE`, not imported: tooth_map imports this)
_KERNEL_MODULE = "contact.compliance.tooth_map_numba"

#: displacement components of the shape-function families (u along x, v along θ, w normal)
_U, _V, _W = 0, 1, 2


# ---------------------------------------------------------------------------------------
# the tooth
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ShellTooth:
    """Tapered cylindrical-shell idealisation of one tooth (seed Eq. 3.1, Fig. 3.1).

    Parameters
    ----------
    thickness_toe_root : float — [mm] tooth thickness at the root, toe end (t_toe)
    thickness_heel_root : float — [mm] tooth thickness at the root, heel end (t_heel)
    thickness_tip : float — [mm] tooth thickness at the tip (t_tip)
    height_toe : float — [mm] tooth height (root to tip) at the toe (h_toe)
    height_heel : float — [mm] tooth height at the heel (h_heel)
    radius : float — [mm] mean radius R of the shell mid-surface (for face milling
        the cutter radius r_c); must exceed half the largest thickness
    subtended_angle : float — [rad] angle Θ₀ the face width subtends about the
        shell axis, ≈ face width / R; in (0, π]
    youngs_modulus : float — [MPa] E
    poisson_ratio : float — [1] ν, in [0, 0.5)

    Raises
    ------
    InputError
        A field is not finite, not positive, or out of its range (the message names
        the field and the range).

    Notes
    -----
    Seed Eq. 3.1 is garbled in the extraction; we reconstruct it as the linear
    two-variable fit through the three thicknesses the text names (toe-root,
    heel-root, tip), with η_f = θ/Θ₀ = r_c θ / f the face fraction and
    ξ_h = x / h(θ) the profile fraction::

        h(θ)    = h_toe + (h_heel − h_toe) · θ/Θ₀                        (3.1b)
        t(x, θ) = [t_toe + (t_heel − t_toe) · θ/Θ₀] · (1 − x/h(θ)) + t_tip · x/h(θ)   (3.1a)

    i.e. the root thickness varies linearly from toe to heel and the tip
    thickness is constant.
    """

    thickness_toe_root: float
    thickness_heel_root: float
    thickness_tip: float
    height_toe: float
    height_heel: float
    radius: float
    subtended_angle: float
    youngs_modulus: float
    poisson_ratio: float

    def __post_init__(self) -> None:
        for name, unit in (
            ("thickness_toe_root", "mm"),
            ("thickness_heel_root", "mm"),
            ("thickness_tip", "mm"),
            ("height_toe", "mm"),
            ("height_heel", "mm"),
            ("radius", "mm"),
            ("youngs_modulus", "MPa"),
        ):
            object.__setattr__(self, name, positive(name, getattr(self, name), unit))
        object.__setattr__(
            self,
            "subtended_angle",
            positive("subtended_angle", self.subtended_angle, "rad", high=math.pi),
        )
        object.__setattr__(self, "poisson_ratio",
                           real("poisson_ratio", self.poisson_ratio, unit="1", low=0.0,
                                high=0.5, high_open=True))
        t_max = max(self.thickness_toe_root, self.thickness_heel_root, self.thickness_tip)
        if self.radius <= 0.5 * t_max:
            raise InputError(
                f"radius: must exceed half the largest thickness ({0.5 * t_max} mm) [mm], "
                f"got {self.radius}"
            )

    @classmethod
    def from_face_width(
        cls,
        *,
        thickness_toe_root: float,
        thickness_heel_root: float,
        thickness_tip: float,
        height_toe: float,
        height_heel: float,
        face_width: float,
        radius: float,
        youngs_modulus: float,
        poisson_ratio: float,
    ) -> ShellTooth:
        """Build a tooth from its face width [mm] (Θ₀ = face_width / radius).

        All lengths in [mm], ``youngs_modulus`` in [MPa], ``poisson_ratio`` [1].
        Raises :class:`InputError` as the constructor does, naming ``face_width``
        when it is not positive or subtends more than π.
        """
        fw = positive("face_width", face_width, "mm")
        r = positive("radius", radius, "mm")
        if fw / r > math.pi:
            raise InputError(
                f"face_width / radius: must be at most pi [rad], got {fw}/{r} = {fw / r}"
            )
        return cls(
            thickness_toe_root=thickness_toe_root,
            thickness_heel_root=thickness_heel_root,
            thickness_tip=thickness_tip,
            height_toe=height_toe,
            height_heel=height_heel,
            radius=r,
            subtended_angle=fw / r,
            youngs_modulus=youngs_modulus,
            poisson_ratio=poisson_ratio,
        )

    @property
    def face_width(self) -> float:
        """Face width R·Θ₀ along the mid-surface [mm]."""
        return self.radius * self.subtended_angle

    @property
    def shear_modulus(self) -> float:
        """G = E / (2 (1 + ν)) [MPa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))

    def height(self, theta: np.ndarray | float) -> np.ndarray:
        """Tooth height h(θ) [mm] at face angle ``theta`` [rad] (seed Eq. 3.1b)."""
        s = np.asarray(theta, dtype=float) / self.subtended_angle
        return self.height_toe + (self.height_heel - self.height_toe) * s

    def thickness(self, x: np.ndarray | float, theta: np.ndarray | float) -> np.ndarray:
        """Tooth thickness t(x, θ) [mm] at height ``x`` [mm], face angle ``theta`` [rad].

        Seed Eq. 3.1a as reconstructed in the class docstring.
        """
        theta = np.asarray(theta, dtype=float)
        s = theta / self.subtended_angle
        t_root = self.thickness_toe_root + (self.thickness_heel_root - self.thickness_toe_root) * s
        r = np.asarray(x, dtype=float) / self.height(theta)
        return t_root * (1.0 - r) + self.thickness_tip * r

    def thickness_gradient(
        self, x: np.ndarray | float, theta: np.ndarray | float
    ) -> tuple[np.ndarray, np.ndarray]:
        """(∂t/∂x [1], ∂t/∂θ [mm/rad]) of the thickness of seed Eq. 3.1a."""
        x = np.asarray(x, dtype=float)
        theta = np.asarray(theta, dtype=float)
        th0 = self.subtended_angle
        h = self.height(theta)
        t_root = self.thickness_toe_root + (
            self.thickness_heel_root - self.thickness_toe_root
        ) * (theta / th0)
        dt_root = (self.thickness_heel_root - self.thickness_toe_root) / th0
        dh = (self.height_heel - self.height_toe) / th0
        r = x / h
        t_x = (self.thickness_tip - t_root) / h
        t_t = dt_root * (1.0 - r) + (t_root - self.thickness_tip) * r * dh / h
        return t_x, t_t


# ---------------------------------------------------------------------------------------
# kinematic theories (registry)
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Family:
    """One family of Ritz unknowns: ``z^z_power · f_k(ξ) · P_n(η)`` in one component.

    component : 0 = U (along x), 1 = V (along θ), 2 = W (along z)
    z_power : power of z through the thickness
    x_power : root order of the height functions (1: value vanishes at the root,
        2: value and slope vanish)
    x_extra : height functions beyond the number of height modes M
    rotates : a W function also rotates the normal, U = −z ∂W/∂x, V = −(z/R) ∂W/∂θ
        (the seed's unknowns are the shear strains ψ, with β = ψ − ∇W)
    """

    component: int
    z_power: int
    x_power: int
    x_extra: int = 0
    rotates: bool = False


@dataclass(frozen=True)
class Theory:
    families: tuple[Family, ...]
    shear_corrected: bool  # transverse shear energy × κ (constant shear strain)
    doc: str


#: Kinematic theories of the Ritz model, by name.
#:
#: ``"seed"`` — seed Eq. 3.5–3.9 as read: Mindlin shell (U = z(ψ_x − ∂W/∂x),
#: V = z(ψ_θ − ∂W/∂θ / R), W(x, θ)), plane stress, shear correction κ, unknowns W, ψ_x,
#: ψ_θ with W = ∂W/∂x = ψ_x = ψ_θ = 0 at the root ((x/a)^(m+1) and (x/a)^m families).
#: ``"mindlin"`` — the same kinematics with Mindlin's own unknowns (W, β_x, β_θ) and
#: clamp W = β = 0 (the root shear strain is free).
#: ``"higher-order"`` (our extension) — U, V with z⁰, z¹, z³ terms (membrane, rotation,
#: cubic warping), W(x, θ), plane stress, no shear correction: the transverse shear
#: strain varies through the thickness instead of being constant; see
#: :func:`build_shell_model`.
THEORIES: dict[str, Theory] = {
    "seed": Theory(
        (Family(_W, 0, 2, 0, True), Family(_U, 1, 1), Family(_V, 1, 1)),
        True,
        "Mindlin shell, seed Eq. 3.9 root conditions W = dW/dx = psi = 0",
    ),
    "mindlin": Theory(
        (Family(_W, 0, 1, 1), Family(_U, 1, 1), Family(_V, 1, 1)),
        True,
        "Mindlin shell, clamp W = beta = 0",
    ),
    "higher-order": Theory(
        (Family(_W, 0, 1, 1), *(Family(c, k, 1) for c in (_U, _V) for k in (0, 1, 3))),
        False,
        "U, V with z^0, z^1, z^3 terms, W(x, theta), plane stress, no shear correction",
    ),
}


# ---------------------------------------------------------------------------------------
# the model
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class ShellModel:
    """A built Rayleigh–Ritz model of one tooth: stiffness assembled and factorised.

    Build it with :func:`build_shell_model`; the fields are read-only.

    Attributes
    ----------
    tooth : ShellTooth
    n_height, n_face : int — [1] modes per direction (seed ICF and IFF counts)
    theory : str — key of :data:`THEORIES`
    shear_factor : float — [1] κ (used by the Mindlin theories only)
    n_dof : int — [1] number of Ritz unknowns
    build_time : float — [s] wall time to assemble and factorise
    reference_height : float — [mm] a, the height that normalises x (max height)
    """

    tooth: ShellTooth
    n_height: int
    n_face: int
    theory: str
    shear_factor: float
    n_dof: int
    build_time: float
    reference_height: float
    _layout: tuple = field(repr=False)  # ((family, offset, x_power, x_count), ...)
    _factor: tuple = field(repr=False)
    _scale: np.ndarray = field(repr=False)
    _half_operator: np.ndarray = field(repr=False)  # U⁻ᵀ S, lower triangular, Fortran order

    def w_functions(self, x: np.ndarray, theta: np.ndarray) -> np.ndarray:
        """Mid-surface deflection read-out: W(x, θ, z = 0) = ``w_functions(x, θ).T @ a``.

        Parameters
        ----------
        x : array_like, shape (P,) — [mm] height from the root
        theta : array_like, shape (P,) — [rad] face angle from the toe

        Returns
        -------
        ndarray, shape (n_dof, P) — [1] read-out vectors over all Ritz unknowns
        """
        p = np.atleast_1d(np.asarray(x, dtype=float)).size
        zero = np.zeros(p)
        return self.load_vectors(x, theta, np.column_stack([zero, zero, zero + 1.0]), zero)

    def load_vectors(
        self,
        x: np.ndarray,
        theta: np.ndarray,
        direction: np.ndarray,
        offset: np.ndarray,
        group_weights: np.ndarray | None = None,
    ) -> np.ndarray:
        """Generalised load vectors of unit forces (seed Eq. 3.6b, 3.10).

        A unit force with components ``direction`` = (f_x, f_θ, f_z) in the local
        frame (e_x, e_θ, e_z), applied at (x, θ) at distance ``offset`` = z_s from
        the mid-surface (on a flank: ±t/2), does the work
        ``f_z W(0) + f_x [U(0) + z_s ∂U/∂z(0)] + f_θ [V(0) + z_s ∂V/∂z(0)]``:
        the force is carried to the mid-surface by a rigid normal segment (exact
        for the Mindlin theories, where U = z β; for ``"higher-order"`` it takes
        the mid-surface rotation). The same vector reads the displacement
        along ``direction`` at that point, so the compliance is reciprocal.

        Parameters
        ----------
        x, theta : array_like, shape (P,) — [mm], [rad] load points
        direction : array_like, shape (P, 3) — [1] force components (unit vectors)
        offset : array_like, shape (P,) — [mm] z of the application point
        group_weights : array_like, shape (G,), optional — [1]
            The points come in P/G consecutive groups of G (e.g. the Gauss points of a
            segment): return each group's weighted sum Σ_g w_g φ_g instead (the
            segment's mean load vector), without forming the per-point vectors.

        Returns
        -------
        ndarray, shape (n_dof, P), or (n_dof, P/G) with ``group_weights`` — [1]

        Raises
        ------
        InputError
            If ``group_weights`` is empty or its size does not divide P.
        """
        xi = np.atleast_1d(np.asarray(x, dtype=float)).ravel() / self.reference_height
        eta = 2.0 * np.atleast_1d(np.asarray(theta, dtype=float)).ravel()
        eta = eta / self.tooth.subtended_angle - 1.0
        n_pts = xi.size
        d = np.asarray(direction, dtype=float).reshape(n_pts, 3)
        zs = np.broadcast_to(np.asarray(offset, dtype=float), (n_pts,))
        dxi = 1.0 / self.reference_height
        deta = 2.0 / self.tooth.subtended_angle
        if group_weights is None:
            wts = np.ones(1)
        else:
            wts = np.asarray(group_weights, dtype=float).ravel()
            if wts.size == 0 or n_pts % wts.size:
                raise InputError(f"group_weights: {wts.size} weights do not divide the "
                                 f"{n_pts} points into groups")
        n_out = n_pts // wts.size
        if wts.size > 1:
            return self._grouped_load_vectors(xi, eta, d, zs, wts)
        g, dg = _legendre_rows(eta, self.n_face)
        heights: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
        # filled as (loads, unknowns) and returned transposed: a Fortran-ordered
        # (unknowns, loads) array, the layout half_solve's BLAS product takes as it is
        out_t = np.empty((n_out, self.n_dof))

        def outer(a: np.ndarray, b: np.ndarray) -> np.ndarray:
            # a[k, n] b[m, n] as rows n, columns (k, m) (one point a load: groups of G > 1
            # are _grouped_load_vectors')
            return (a.T[:, :, None] * b.T[:, None, :]).reshape(n_pts, -1)

        plain: list[tuple[int, np.ndarray]] = []  # (column, rows a) of works outer(a, g)
        for fam, off, power, count in self._layout:
            if (power, count) not in heights:
                heights[(power, count)] = _height_rows(xi, power, count)
            f, df = heights[(power, count)]
            scale = _work_scale(fam, d, zs)
            cols = slice(off, off + f.shape[0] * g.shape[0])
            if fam.rotates:  # U_z = −∂W/∂x, V_z = −∂W/∂θ / R at z = 0
                a_x = zs * d[:, 0] * dxi
                a_t = zs * d[:, 1] * deta / self.tooth.radius
                hx = -df * a_x if scale is None else f * scale - df * a_x
                out_t[:, cols] = outer(hx, g) - outer(f * a_t, dg)
            elif scale is None:
                out_t[:, cols] = 0.0
            else:
                plain.append((off, f * scale))
        # families outer(a, g) whose columns follow each other: one product for the run
        # (its rows stacked; each entry the same sum of G products)
        i = 0
        while i < len(plain):
            start, rows = plain[i][0], [plain[i][1]]
            end = start + rows[0].shape[0] * g.shape[0]
            while i + 1 < len(plain) and plain[i + 1][0] == end:
                i += 1
                rows.append(plain[i][1])
                end += plain[i][1].shape[0] * g.shape[0]
            out_t[:, start:end] = outer(rows[0] if len(rows) == 1 else np.concatenate(rows), g)
            i += 1
        return out_t.T

    def _grouped_load_vectors(self, xi: np.ndarray, eta: np.ndarray, d: np.ndarray,
                              zs: np.ndarray, wts: np.ndarray, *,
                              kernels: str | None = None) -> np.ndarray:
        """:meth:`load_vectors` with ``group_weights`` (G > 1 points a group): the works
        of all families in one stacked product, written straight into the output.

        Every family's unknowns are its height functions f_k(ξ) times the face functions
        g_m(η) (k-major, :func:`contact.compliance.shell._dof_layout`), and a load's work
        on the unknown (k, m) is a_k g_m + c_k g′_m (c ≠ 0 only for a rotating family's
        ∂W/∂θ term). Each group's weighted sum is then the product of its (rows × 2G)
        matrix [w a | w c] with the (2G × N) matrix [g; g′], and the output (groups,
        unknowns) is the stack of those (rows × N) products: one stacked product for all
        families, no temporaries of the (groups, unknowns) size. The same vectors as one
        product per family and term (to round-off: the 2G terms are summed in one dot
        product instead of two sums subtracted; 4e-16 of the largest entry on the default
        case's segments).

        Where the compliance's compiled kernels run (``kernels``, as
        :func:`geometry.core.kernels.kernels_module`; None: the process's choice), A and
        B are filled point by point in one pass
        (:func:`contact.compliance.shell_loads_numba.load_vector_factors`: the same
        entries bit for bit, issue 75); the product is the same.
        """
        n_grp = wts.size
        n_out = xi.size // n_grp
        n_face = self.n_face
        rows = self.n_dof // n_face
        dxi = 1.0 / self.reference_height
        deta = 2.0 / self.tooth.subtended_angle
        rotating = any(fam.rotates for fam, *_ in self._layout)
        n_terms = 2 * n_grp if rotating else n_grp
        # filled as (loads, unknowns) and returned transposed: a Fortran-ordered
        # (unknowns, loads) array, the layout half_solve's BLAS product takes as it is
        out_t = np.empty((n_out, self.n_dof))
        compiled = kernels_module(_KERNEL_MODULE, kernels)
        if compiled is not None:
            a_mat = np.empty((n_out, rows, n_terms))
            b_mat = np.empty((n_out, n_terms, n_face))
            families = np.array([(fam.rotates, fam.component, fam.z_power, off // n_face,
                                  power, count) for fam, off, power, count in self._layout],
                                dtype=np.int64)
            compiled.load_vector_factors(
                np.ascontiguousarray(xi), np.ascontiguousarray(eta),
                np.ascontiguousarray(d), np.ascontiguousarray(zs),
                np.ascontiguousarray(wts), n_face, families, dxi, deta,
                float(self.tooth.radius), a_mat, b_mat)
            np.matmul(a_mat, b_mat, out=out_t.reshape(n_out, rows, n_face))
            return out_t.T
        g, dg = _legendre_rows(eta, n_face)
        # A (groups, rows, terms): each height row's weighted works a (and c) at the
        # group's points (zero for a family the force does no work on)
        a_mat = np.zeros((n_out, rows, n_terms))
        heights: dict[tuple[int, int], tuple[np.ndarray, np.ndarray]] = {}
        for fam, off, power, count in self._layout:
            if (power, count) not in heights:
                heights[(power, count)] = _height_rows(xi, power, count)
            f, df = heights[(power, count)]
            scale = _work_scale(fam, d, zs)
            r0 = off // n_face
            if fam.rotates:  # U_z = −∂W/∂x, V_z = −∂W/∂θ / R at z = 0
                a_x = zs * d[:, 0] * dxi
                a_t = zs * d[:, 1] * deta / self.tooth.radius
                a = -df * a_x if scale is None else f * scale - df * a_x
                c = -(f * a_t)
                a_mat[:, r0:r0 + count, n_grp:] = (c.reshape(count, n_out, n_grp) * wts
                                                   ).transpose(1, 0, 2)
            elif scale is None:
                continue
            else:
                a = f * scale
            a_mat[:, r0:r0 + count, :n_grp] = (a.reshape(count, n_out, n_grp) * wts
                                               ).transpose(1, 0, 2)
        # B (groups, terms, N): the face functions (and their derivatives) at the points
        b_mat = np.empty((n_out, n_terms, n_face))
        b_mat[:, :n_grp, :] = g.reshape(n_face, n_out, n_grp).transpose(1, 2, 0)
        if rotating:
            b_mat[:, n_grp:, :] = dg.reshape(n_face, n_out, n_grp).transpose(1, 2, 0)
        np.matmul(a_mat, b_mat, out=out_t.reshape(n_out, rows, n_face))
        return out_t.T

    def solve(self, loads: np.ndarray) -> np.ndarray:
        """Ritz unknowns ``K⁻¹ F`` for load vectors ``loads`` (n_dof, P) [per N]."""
        sc = self._scale[:, None]
        return sc * linalg.cho_solve(self._factor, sc * loads, check_finite=False)

    def half_solve(self, loads: np.ndarray, *, overwrite_loads: bool = False) -> np.ndarray:
        """``Y = U⁻ᵀ S F`` for load vectors ``loads`` (n_dof, P), with S K S = UᵀU the
        Jacobi-scaled Cholesky factorisation: ``Fᵀ K⁻¹ F = Yᵀ Y`` [(N·mm)^(−1/2) per N]
        with one triangular product instead of the two solves of :meth:`solve`.
        ``overwrite_loads``: a Fortran-ordered float ``loads`` is multiplied in place and
        returned (no copy of the (n_dof, P) array: the same Y bit for bit).

        U⁻ᵀ S is formed once with the model (:func:`contact.compliance.shell.
        _scaled_cholesky`): a triangular product (BLAS trmm) costs half the triangular
        solve it replaces (trsm; 4.7 vs 9.2 ms for 1,465 loads of 378 unknowns) and gives
        the same compliance YᵀY to ~5e-15 relative (cond U ≤ 2e6 on the default case's
        teeth). The scale S folded into the operator's columns (issue 75, speed89) spares
        a pass over the loads (≈ 1 ms of a study point's 1,576 loads a tooth); Y then
        differs from U⁻ᵀ (S F) by round-off (each term L_ij s_j F_jk rounded in another
        order: within 1e-14 of max |Y| on the default case's teeth,
        ``tests/test_compliance_fast_paths.py``).

        Parameters
        ----------
        loads : ndarray, shape (n_dof, P) — [1] load vectors (:meth:`load_vectors`)
        overwrite_loads : bool — multiply a Fortran-ordered float ``loads`` in place

        Returns
        -------
        ndarray, shape (n_dof, P), Fortran order — [(N·mm)^(−1/2) per N]
        """
        # (BLAS's layout, Fortran order: multiplied in place, nothing copied either way)
        if not (overwrite_loads and isinstance(loads, np.ndarray) and loads.ndim == 2
                and loads.dtype == float
                and loads.flags.f_contiguous and loads.flags.writeable):
            loads = np.array(loads, dtype=float, order="F")
        return linalg.blas.dtrmm(1.0, self._half_operator, loads, lower=1, overwrite_b=1)


def _legendre_rows(t: np.ndarray, count: int) -> tuple[np.ndarray, np.ndarray]:
    """P_0 … P_{count−1} and their derivatives at 1-D ``t``: two (count, T) arrays.

    Bonnet's recurrence (k + 1) P_{k+1} = (2k + 1) t P_k − k P_{k−1} and
    P′_{k+1} = P′_{k−1} + (2k + 1) P_k: the same functions as
    :func:`contact.compliance._basis.face_basis` (values and first derivatives),
    without its general polynomial evaluation (to round-off).

    Each row is formed in place, the operations in the order of the expressions above
    (((2k + 1) t) P_k − k P_{k−1}) / (k + 1) and P′_{k−1} + (2k + 1) P_k: the same rows bit
    for bit as with their temporaries, ≈ 25 % less time (a study point's 6,304 load points:
    1.12 → 0.83 ms a call of 21 rows, issue 75).
    """
    p = np.empty((count, t.size))
    dp = np.empty((count, t.size))
    p[0] = 1.0
    dp[0] = 0.0
    if count > 1:
        p[1] = t
        dp[1] = 1.0
    tmp = np.empty(t.size)
    for k in range(1, count - 1):
        row = p[k + 1]
        np.multiply(t, 2 * k + 1, out=row)
        np.multiply(row, p[k], out=row)
        np.multiply(p[k - 1], k, out=tmp)
        np.subtract(row, tmp, out=row)
        np.divide(row, k + 1, out=row)
        np.multiply(p[k], 2 * k + 1, out=tmp)
        np.add(dp[k - 1], tmp, out=dp[k + 1])
    return p, dp


def _work_scale(fam, d: np.ndarray, zs: np.ndarray) -> np.ndarray | None:
    """The multiplier of a shell family's height rows f_k in the work of unit forces
    ``d`` (P, 3) [1] applied at z = ``zs`` (P,) [mm] (:meth:`ShellTooth.load_vectors`'
    docstring): the force component itself for a field that does not vary through the
    thickness, the component times z for a linear in-plane field, None where the force
    does no work on the family but through its rotation (a rotating family's ∂W terms)."""
    comp = d[:, fam.component]
    if fam.z_power == 0:
        return comp
    if fam.z_power == 1 and fam.component != _W:
        return comp * zs
    return None


def _height_rows(xi: np.ndarray, power: int, count: int) -> tuple[np.ndarray, np.ndarray]:
    """f_k(ξ) = ξ^power P_k(2ξ − 1) and df_k/dξ at 1-D ``xi``: two (count, Q) arrays.

    The functions of :func:`contact.compliance._basis.height_basis` (to round-off).
    """
    p, dp = _legendre_rows(2.0 * xi - 1.0, count)
    xp = xi**power
    xp1 = power * xi ** (power - 1) if power >= 1 else np.zeros_like(xi)
    return xp * p, xp1 * p + 2.0 * xp * dp
