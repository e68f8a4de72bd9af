"""Shell compliance of GENERATED teeth (contact.compliance.tooth, contact.compliance.mesh).

References, none taken from the code under test:

* the generated flanks themselves (geometry.machine.meshing.solve_envelope): tooth thickness
  measured by intersecting a mid-surface normal line with both flanks (scipy root);
* ISO 23509:2016 Annex F blank data in the case files: the whole depth at the heel;
  sample 2's published mean cone distance and spiral angle with the closed-form
  face-hobbing tooth trace (geometry.iso23509.pitch_cone.face_hobbing_trace: ISO 23509 cl. 5–6,
  itself checked against a time-stepped epicycloid) for the lengthwise radius ρ_mβ;
* a 3-D finite-element model (scikit-fem, triquadratic hexahedra, no shell
  kinematics) of the GENERATED tooth — its solid bounded by the two generated flanks,
  the root cone, the face cone and the front and back cones — built here straight from
  solve_envelope points;
* ISO 6336-1:2019 §9: single mesh stiffness c′ ≈ 14 N/(mm·µm) of steel gear pairs;
* identities: round trips, unit normals, Maxwell–Betti symmetry, block structure.
"""

from __future__ import annotations

import functools
import math
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest
import skfem
from scipy.optimize import root
from skfem.helpers import dot
from skfem.models.elasticity import lame_parameters, linear_elasticity

from contact.compliance import (
    compliance_matrix,
    foundation_compliance,
    load_angle_from_normals,
    load_line_height,
    shell_deflection,
    weber_compliance,
)
from contact.compliance.mesh import (
    ContactSegments,
    mesh_compliance,
    pair_compliance_model,
)
from contact.compliance.tooth import (
    flank_points,
    member_compliance,
    shell_coordinates,
    shell_tooth_from_case,
    weber_depth,
)
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.iso23509.blank import spiral_angle_at
from geometry.iso23509.pitch_cone import face_hobbing_trace
from geometry.machine.cutter import profile_sections
from geometry.machine.flank import blank_outline, flank_surface
from geometry.machine.meshing import solve_envelope
from geometry.pair.assembly import case_transforms, transform_points, transform_vectors

ROOT = Path(__file__).resolve().parents[1]
DATA = Path(__file__).resolve().parent / "data"
CASES = ("hypoid_iso23509_s2", "spiral_bevel_iso23509_s1")
MIRROR = np.array([1.0, -1.0, 1.0])
DRIVE = {"pinion": "concave", "gear": "convex"}  # both example cases drive on the concave


def _case_path(name: str) -> Path:
    """The case file of ``name``: a path to a ``.toml`` file (relative to the repository
    root or absolute), else a file of tests/data, else a bundled case of cases/."""
    path = Path(name)
    if path.suffix == ".toml":
        return path if path.is_absolute() else ROOT / path
    return DATA / f"{name}.toml" if (DATA / f"{name}.toml").exists() else \
        ROOT / "cases" / f"{name}.toml"


@functools.cache
def _case(name: str):
    return load_case(_case_path(name))


@functools.cache
def _tooth(name: str, member: str, radius_source: str = "auto"):
    return shell_tooth_from_case(_case(name), member, radius_source=radius_source)


#: Face-hobbed cases of the FE check (test_face_hobbed_tooth_deflection_matches_fe): the
#: example surfaces of tests/data, then bundled synthesised FH cases. Add a name here when
#: its case exists; a name whose file does not exist (yet) is left out. Each case costs
#: ~11 s in the fast suite (two FE models) and ~35 s more in the slow study.
FH_CASES = [name for name in ("fh_iso23509_s2_crown", "kolivand2009_fh_12x41")
            if _case_path(name).exists()]
#: ... and in the slow study also the seed's Table 5.4 designs
FH_STUDY = FH_CASES + [name for name in ("kolivand2009_table54_A_fh",
                                         "kolivand2009_table54_B_fh")
                       if _case_path(name).exists()]
#: Bundled face-milled cases (cases/*.toml with pair.method = "FM")
FM_BUNDLED = sorted(p.stem for p in (ROOT / "cases").glob("*.toml")
                    if tomllib.loads(p.read_text(encoding="utf-8"))["pair"].get("method", "FM")
                    == "FM")


def _drive_side(case, member: str) -> int:
    """Shell side (+1 convex, −1 concave) of ``member``'s drive flank: the pinion's is the
    case's drive flank, the gear's the other flank type."""
    flank = case.pair.drive_flank
    if member == "gear":
        flank = "convex" if flank == "concave" else "concave"
    return 1 if flank == "convex" else -1


def _bilinear(corners, u, v):
    u = np.asarray(u, float)[..., None]
    v = np.asarray(v, float)[..., None]
    return ((1 - u) * (1 - v) * corners[0, 0] + u * (1 - v) * corners[1, 0]
            + (1 - u) * v * corners[0, 1] + u * v * corners[1, 1])


def _flank(case, member, flank, z, rho, shift=0):
    """Generated flank points/normals at projection-plane places, turned by `shift` pitches;
    also whether the blade's profile section generates them."""
    mem = case.member(member)
    tool = mem.flank(flank)
    bl = mem.blank
    z, rho = np.atleast_1d(np.asarray(z, float)), np.atleast_1d(np.asarray(rho, float))
    sol = solve_envelope(tool.blade, tool.machine, z, rho, length_scale=bl.outer_cone_distance,
                         depth=bl.outer_addendum + bl.outer_dedendum)
    pos, nrm = sol.position, sol.normal
    if mem.hand == "left":
        pos, nrm = pos * MIRROR, nrm * MIRROR
    a = shift * 2 * math.pi / bl.teeth
    rot = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])
    ok = (sol.reason == 0) & (sol.section == profile_sections(tool.blade).main)
    return pos @ rot.T, nrm @ rot.T, ok


# ------------------------------------------------------------------ the tooth and its fit
@pytest.mark.parametrize("name", CASES)
def test_tooth_pairs_the_right_flanks(name):
    """The geometry engineer's note: the gear's reference flanks bound a slot, the example
    pinion's bound a tooth — so the tooth's concave flank is the reference one turned by
    ±1 pitch for the gear, 0 for the pinion; and a tooth is thinner than a pitch."""
    for member, shifts in (("pinion", {0}), ("gear", {-1, 1})):
        data = _tooth(name, member)
        assert data.concave_shift in shifts
        t = data.tooth
        toe_root_pitch = 2 * math.pi * data.corners[0, 0, 1] / data.teeth  # arc at toe root
        assert 0 < t.thickness_tip < t.thickness_toe_root < toe_root_pitch


def _mid(case, member, shift, corners, u, v):
    """Mid-point between the flanks at the same projection-plane place (the tooth centre)."""
    z, rho = _bilinear(corners, u, v).T
    pv, _, ok_v = _flank(case, member, "convex", z, rho)
    pc, _, ok_c = _flank(case, member, "concave", z, rho, shift)
    ang = np.arctan2(pv[:, 1], pv[:, 0])
    ang = ang + 0.5 * np.remainder(np.arctan2(pc[:, 1], pc[:, 0]) - ang + np.pi, 2 * np.pi) \
        - 0.5 * np.pi
    return np.column_stack([rho * np.cos(ang), rho * np.sin(ang), z]), ok_v & ok_c


def _normal_line_thickness(case, member, shift, corners, u, v):
    """Thickness along the mid-surface normal at (u, v): the normal from finite differences
    of tooth-centre points, its intersections with both flanks by scipy root."""
    h = 1e-4
    m0, ok = _mid(case, member, shift, corners, [u, u + h, u, u - h, u], [v, v, v + h, v, v - h])
    assert ok.all()
    n = np.cross(m0[1] - m0[3], m0[2] - m0[4])
    n /= np.linalg.norm(n)
    e1 = np.cross(n, [0.0, 0.0, 1.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    hits = []
    for flank, k in (("convex", 0), ("concave", shift)):
        def f(zr, flank=flank, k=k):
            p, _, _ = _flank(case, member, flank, zr[0], zr[1], k)
            return [(p[0] - m0[0]) @ e1, (p[0] - m0[0]) @ e2]

        z0, r0 = m0[0, 2], math.hypot(*m0[0, :2])
        sol = root(f, [z0, r0], tol=1e-12)
        assert sol.success
        hits.append(_flank(case, member, flank, sol.x[0], sol.x[1], k)[0][0])
    return float(np.linalg.norm(hits[0] - hits[1])), m0[0]


@pytest.mark.parametrize("member", ["gear", "pinion"])
def test_thickness_measurement_and_fit_against_normal_line_intersections(member):
    """Hypoid example, mid face, three heights. (a) The module's measured thickness (chord
    between the flanks projected on the mid-surface normal) equals the thickness along the
    normal line through the tooth centre within 0.5 % (the chord projection is exact for
    locally plane, parallel-tapered flanks; the residue is flank curvature over ~t tan β).
    (b) The fitted linear function of seed Eq. 3.1 at the same shell point: within 2 % for
    the Formate gear, whose straight-bladed flanks make the thickness linear in height;
    within 8 % for the generated pinion, whose thickness is curved over the height
    (circular blades, generating roll) so that no function linear in x fits it closer
    (the FE test shows what it costs). Measured: (a) +0.02 … +0.35 %; (b) gear −0.4 …
    −1.1 %, pinion −2.9 … −6.1 %. Away from mid face Eq. 3.1 fits worse: its tip
    thickness is constant, the example gear's topland narrows from 2.3 mm at the toe to
    1.65 mm at the heel (data.thickness_fit_error 0.37 mm gear, 0.62 mm pinion)."""
    case = _case("hypoid_iso23509_s2")
    data = _tooth("hypoid_iso23509_s2", member)
    tol_fit = 0.02 if member == "gear" else 0.08
    j = int(np.argmin(np.abs(data.grid_u - 0.5)))
    for v in (0.3, 0.5, 0.8):
        t_line, centre = _normal_line_thickness(case, member, data.concave_shift,
                                                data.corners, 0.5, v)
        i = int(np.argmin(np.abs(data.grid_v - v)))
        assert data.grid_v[i] == pytest.approx(v)
        assert data.measured_thickness[j, i] == pytest.approx(t_line, rel=5e-3)
        sp = shell_coordinates(data, centre)
        assert abs(sp.offset[0]) < 1e-3  # the tooth centre is on the mid-surface
        assert data.tooth.thickness(sp.x, sp.theta)[0] == pytest.approx(t_line, rel=tol_fit)


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_heights_match_the_blank_depths(name, member):
    """Fitted heights h_heel, h_toe (length of the mid-surface profile from the root cone to
    the face cone, seed Eq. 3.1b) against the whole depth of the blank: at the heel ISO 23509
    Annex F's h_ae + h_fe (case file), at the toe the distance between the root and face
    cones along the front cone. Within 2 %, i.e. the tooth's mid-surface leans at most ~11°
    from the normal of the pitch cone (cos 11° = 0.98), along which the blank depth is
    measured. Measured +1.9 % (hypoid pinion, heel) at most."""
    case = _case(name)
    bl = case.member(member).blank
    data = _tooth(name, member)
    corners = blank_outline(bl).corners
    depth_toe = float(np.linalg.norm(corners[0, 1] - corners[0, 0]))
    assert data.tooth.height_heel == pytest.approx(bl.outer_addendum + bl.outer_dedendum,
                                                   rel=0.02)
    assert data.tooth.height_toe == pytest.approx(depth_toe, rel=0.02)
    assert data.height_fit_error < 0.1  # linear in the face fraction within 0.1 mm


# ------------------------------------------------------------------ the shell radius
@pytest.mark.parametrize("name", FM_BUNDLED)
def test_face_milled_members_keep_the_point_radius_that_formate_gears_measure(name):
    """Face milling keeps the seed's shell radius, the mean blade point radius (seed §3.2),
    bit for bit. What justifies it, for the Formate gear: its lengthwise curve is the
    cutter circle, and the measured lengthwise radius (mid-surface normal curvature along
    the mid-height lengthwise curve, averaged over the face) equals the point radius within
    2 %. Not 1 %: a tapered-depth tooth's mid-height curve climbs across the cutter circles
    at 4–6° (the mid-depth cone is not parallel to the root cone), and a cylinder's normal
    curvature along a line at γ to its circles is cos²γ / r (Euler), 0.5–1.1 % below; the
    principal radius is within −0.3 … +1.1 %. Measured +0.9 … +1.7 %. The generated
    pinions are not circles of their cutter radius: their measured radius is 4–14 % below
    the point radius (test_point_or_measured_radius_hardly_changes_the_shell says what
    that costs)."""
    for member in ("pinion", "gear"):
        data = _tooth(name, member)
        assert data.radius_source == "point"
        assert data.shell_radius == data.point_radius
        if _case(name).member(member).process == "Formate":
            assert data.measured_radius == pytest.approx(data.point_radius, rel=0.02)


@pytest.mark.parametrize("name", CASES)
def test_point_or_measured_radius_hardly_changes_the_shell(name):
    """The generated FM pinions keep the point radius although they measure 4–14 % less
    (hypoid example −8 %, spiral bevel −14 %): the shell's tip deflection under a load at
    mid face on the drive flank changes by < 1 % between the two radii (the tooth length
    R Θ₀ is the same; only the shell's curvature changes, and a shallow shell of these
    proportions is hardly stiffened by it). Measured: −0.24 % (hypoid pinion), −0.19 %
    (spiral bevel pinion), +0.02 % (gears). Against the FE of the generated tooth the
    hypoid pinion's peak ratio is 1.009 with the point radius, 1.007 with the measured."""
    case = _case(name)
    for member in ("pinion", "gear"):
        peaks = []
        for source in ("point", "measured"):
            data = _tooth(name, member, source)
            p, n = _profile_points(case, data, member, DRIVE[member], 0.5, [0.5])
            sp = shell_coordinates(data, p, n)
            th = np.linspace(0.0, data.tooth.subtended_angle, 41)
            tips = np.column_stack([data.tooth.height(th), th])
            w = shell_deflection(data.shell_model(), np.column_stack([sp.x, sp.theta]), tips,
                                 load_normals=sp.normal)
            peaks.append(float(np.max(np.abs(w))))
        assert peaks[1] == pytest.approx(peaks[0], rel=0.01)


def test_face_hobbed_gear_measures_the_iso_lengthwise_radius():
    """Face-hobbed example (tests/data/fh_iso23509_s2_crown.toml; design note §6): both
    members use the measured radius. The Formate FH gear's lengthwise curve is the extended
    epicycloid of its cutter (z0 = 5, r_c0 = 82.55 mm), whose radius of curvature ISO 23509
    gives in closed form: ρ_mβ at ISO's published mean point of sample 2 (R_m2 = 76.337 mm,
    β_m2 = 38.609°, crown gear z2/sin δ2, uniform depth) is 75.84 mm, 8 % below r_c0; the
    measured radius (a face-width mean) is within 1 % of it, and the LOCAL radius at the
    toe, mean point and heel within 1 % of ρ_mβ at those cone distances (β from ISO's
    face-hobbing spiral-angle law, geometry.iso23509.blank.spiral_angle_at). Tolerance 1 %: the
    mean over the face against the mid value (0.2 % here: the radius changes nearly
    linearly toe → heel), mid height against the crown gear's plane (0.3 % from root to
    tip), ISO's rounding (3 digits) and the flank-angle fit (0.1 %). Measured +0.12 %;
    local −0.1 … 0.0 %; spread −3.3 … +3.8 % about the mean radius. The generated FH
    pinion measures 82.4 mm, 8 % above its crown gear's ρ_mβ (76.4 mm): its radius grows
    from root (75.7 mm) to tip (87 mm) on its 21° cone."""
    name = "fh_iso23509_s2_crown"
    case = _case(name)
    for member in ("pinion", "gear"):
        data = _tooth(name, member)
        assert data.radius_source == "measured"
        assert data.shell_radius == data.measured_radius
        assert data.tooth.subtended_angle == pytest.approx(
            data.tooth.face_width / data.measured_radius, rel=1e-12)
    gear = case.gear
    bl = gear.blank
    z_p = bl.teeth / math.sin(bl.pitch_angle)
    r_m, beta_m = 76.337, math.radians(38.609)  # ISO 23509 Annex F sample 2: R_m2, β_m2
    rho_m = face_hobbing_trace(r_m, beta_m, gear.cutter_radius, gear.blade_groups,
                               z_p).rho_mbeta
    data = _tooth(name, "gear")
    assert rho_m < 0.93 * gear.cutter_radius  # the FH trace is not the cutter circle
    assert data.measured_radius == pytest.approx(rho_m, rel=0.01)
    for frac in (0.0, 0.5, 1.0):
        r = bl.outer_cone_distance - (1.0 - frac) * bl.face_width
        beta = spiral_angle_at(r, r_m, beta_m, gear.cutter_radius, gear.blade_groups, z_p)
        rho = face_hobbing_trace(r, beta, gear.cutter_radius, gear.blade_groups, z_p).rho_mbeta
        local = np.interp(frac, *data.lengthwise_radius)
        assert local == pytest.approx(rho, rel=0.01)
    lo, hi = data.radius_spread
    assert -0.06 < lo < -0.02 and 0.02 < hi < 0.06  # the epicycloid's radius grows to the heel


def test_radius_source_is_checked():
    with pytest.raises(InputError, match="radius_source"):
        shell_tooth_from_case(_case("hypoid_iso23509_s2"), "gear", radius_source="cutter")


# ------------------------------------------------------------------ coordinates, normals
@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_shell_coordinates_round_trip(name, member):
    """Generated flank point → shell (x, θ, side) → the flank point with that foot on the
    mid-surface (flank_points, solving the equation of meshing again) → the same point
    within 1e-6 mm (the projection and the inverse fixed point converge to 1e-12 in the
    fractions; RK4 along the orthogonal trajectories is ~1e-10). In the pair frame, on a
    tooth three pitches away at an arbitrary roll, the shell coordinates and local normals
    are the same as in the member frame on the reference tooth (1e-9)."""
    case = _case(name)
    data = _tooth(name, member)
    bl = case.member(member).blank
    uv = np.array([[0.3, 0.35], [0.5, 0.6], [0.7, 0.85]])
    z, rho = _bilinear(data.corners, uv[:, 0], uv[:, 1]).T
    for flank, shift in (("convex", 0), ("concave", data.concave_shift)):
        p, n, ok = _flank(case, member, flank, z, rho, shift)
        assert ok.all()
        sp = shell_coordinates(data, p, n)
        assert np.all(sp.side == (1 if flank == "convex" else -1))
        back, nb = flank_points(data, sp.x, sp.theta, sp.side)
        np.testing.assert_allclose(back, p, atol=1e-6)
        np.testing.assert_allclose(nb, n, atol=1e-8)
        k = 3
        rot = k * 2 * math.pi / bl.teeth
        c, s = math.cos(rot), math.sin(rot)
        turn = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        tp, tg = case_transforms(case, 0.37, -0.21)
        t = tp if member == "pinion" else tg
        sp2 = shell_coordinates(data, transform_points(t, p @ turn.T),
                                transform_vectors(t, n @ turn.T), transform=t)
        for a, b in ((sp.x, sp2.x), (sp.theta, sp2.theta), (sp.normal, sp2.normal)):
            np.testing.assert_allclose(b, a, atol=1e-9)


@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_local_normals_are_unit_and_point_out_of_the_tooth(name, member):
    """Over the generated flanks (profile sections): the normal in the shell frame is a unit
    vector (orthonormal frame, 1e-12); its e_z component has the sign of the flank (convex
    +, concave −) and a point moved along it leaves the tooth (|offset| grows); the flank
    tilts towards the tip (load angle α_m > 0, the tooth tapers); and it is close to the
    idealised shell's own flank normal (shell.flank_normals: the taper of the fitted
    thickness): for the straight-bladed Formate gears within 5° (median 2.5°: the real
    pressure angles differ per flank, the shell's taper is symmetric; measured 3.2°, 1.7°);
    for the generated pinions within 25° (median 7°; measured 21°, 6.3°), the largest near
    the root where the curved generated profile departs most from one linear taper — which
    is why the LTCA passes the real normals."""
    from contact.compliance import flank_normals

    case = _case(name)
    data = _tooth(name, member)
    for flank, sign in (("convex", 1), ("concave", -1)):
        fs = flank_surface(case, member, flank, nu=9, nv=7, u_limits=(0.05, 0.95),
                           v_limits=(0.1, 0.9))
        ok = fs.valid & (fs.section == profile_sections(case.member(member).flank(flank)
                                                        .blade).main)
        p, n = fs.position[ok], fs.normal[ok]
        if flank == "concave":
            a = data.concave_shift * data.pitch
            rot = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0],
                            [0, 0, 1]])
            p, n = p @ rot.T, n @ rot.T
        sp = shell_coordinates(data, p, n)
        np.testing.assert_allclose(np.linalg.norm(sp.normal, axis=1), 1.0, atol=1e-12)
        assert np.all(np.sign(sp.normal[:, 2]) == sign)
        out = shell_coordinates(data, p + 0.05 * n, n)
        assert np.all(np.abs(out.offset) > np.abs(sp.offset))
        assert np.all(load_angle_from_normals(sp.normal) > 0)
        ideal = flank_normals(data.tooth, np.column_stack([sp.x, sp.theta]), sp.side)
        angle = np.degrees(np.arccos(np.clip(np.sum(ideal * sp.normal, axis=1), -1, 1)))
        if member == "gear":  # straight blades, Formate: one taper per flank
            assert angle.max() < 5.0 and np.median(angle) < 2.5
        else:  # curved generated profile against one linear taper (worst at the root)
            assert angle.max() < 25.0 and np.median(angle) < 7.0


# ------------------------------------------------------------------ FE of the generated tooth
def _grid(n, marks):
    uni = np.linspace(0.0, 1.0, n + 1)
    m = np.asarray(marks, float)
    near = np.min(np.abs(uni[:, None] - m[None, :]), axis=1) < 0.3 / n
    near[[0, -1]] = False
    return np.union1d(uni[~near], m)


def _angles_filled(case, member, flank, shift, corners, uu, vv):
    """Flank angles about the member axis on a (v, u) node grid; below the profile section
    (fillets, not generated) extrapolated by a quadratic in v per u column."""
    z, rho = _bilinear(corners, uu, vv).reshape(-1, 2).T
    p, _, ok = _flank(case, member, flank, z, rho, shift)
    phi = np.arctan2(p[:, 1], p[:, 0]).reshape(uu.shape)
    ok = ok.reshape(uu.shape)
    for i in range(uu.shape[1]):
        good = ok[:, i]
        ref = phi[good, i][0]
        col = ref + np.remainder(phi[:, i] - ref + np.pi, 2 * np.pi) - np.pi
        cf = np.polyfit(vv[good, i], col[good], 2)
        phi[:, i] = np.where(good, col, np.polyval(cf, vv[:, i]))
    return phi


def fe_generated_tooth(case, member, shift, load, side, *, patch=(0.08, 0.1), cells=(6, 16, 2),
                       youngs_modulus=206000.0, poisson_ratio=0.3):
    """3-D FE of the generated tooth: the solid between the two generated flanks (nodes on
    the arc between them at the same projection-plane place), from the root cone (clamped)
    to the face cone, toe to heel (front/back cones); unit force as a uniform pressure on a
    patch of one flank around the projection-plane fractions ``load``; returns the tip-line
    nodes (mid-thickness, member frame) and their displacement along the tooth's mid-surface
    normal computed from the mesh [mm/N]."""
    bl = case.member(member).blank
    corners = blank_outline(bl).corners
    (u0, v0), (du, dv) = load, patch
    um, vm = (u0 - du / 2, u0 + du / 2), (v0 - dv / 2, v0 + dv / 2)
    vn, un, zn = _grid(cells[0], vm), _grid(cells[1], um), np.linspace(0, 1, cells[2] + 1)
    vv, uu = np.meshgrid(vn, un, indexing="ij")
    phv = _angles_filled(case, member, "convex", 0, corners, uu, vv)
    phc = _angles_filled(case, member, "concave", shift, corners, uu, vv)
    phc = phv + np.remainder(phc - phv + np.pi, 2 * np.pi) - np.pi
    unit = skfem.MeshHex.init_tensor(vn, un, zn)
    pu = unit.p
    iv, iu = np.searchsorted(vn, pu[0]), np.searchsorted(un, pu[1])
    phi = phc[iv, iu] + pu[2] * (phv[iv, iu] - phc[iv, iu])  # convex flank at ζ = 1
    zr = _bilinear(corners, uu, vv)[iv, iu]
    x = np.vstack([zr[:, 1] * np.cos(phi), zr[:, 1] * np.sin(phi), zr[:, 0]])
    mesh = skfem.MeshHex(x, unit.t)
    elem = skfem.ElementVector(skfem.ElementHex2())
    basis = skfem.Basis(mesh, elem, intorder=4)
    lam, mu = lame_parameters(youngs_modulus, poisson_ratio)
    stiffness = skfem.asm(linear_elasticity(lam, mu), basis)
    fmid = pu[:, unit.facets].mean(axis=1)
    eps = 1e-9
    face = 1.0 if side > 0 else 0.0
    on = ((np.abs(fmid[2] - face) < eps) & (fmid[0] > vm[0] - eps) & (fmid[0] < vm[1] + eps)
          & (fmid[1] > um[0] - eps) & (fmid[1] < um[1] + eps))
    facets = np.nonzero(on)[0]
    area = skfem.Functional(lambda w: 1.0 + 0.0 * w.x[0]).assemble(
        skfem.FacetBasis(mesh, skfem.ElementHex1(), facets=facets, intorder=4))

    @skfem.LinearForm
    def pressure(v, w):
        return -dot(w.n, v) / area  # unit force along −n (into the tooth)

    rhs = skfem.asm(pressure, skfem.FacetBasis(mesh, elem, facets=facets, intorder=4))
    root_dofs = basis.get_dofs(facets=np.nonzero(np.abs(fmid[0]) < eps)[0]).all()
    disp = skfem.solve(*skfem.condense(stiffness, rhs, D=root_dofs))

    def nodes(v, zeta):
        sel = np.nonzero((np.abs(pu[0] - v) < eps) & (np.abs(pu[2] - zeta) < eps))[0]
        return sel[np.argsort(pu[1, sel])]

    tip, below, conv = nodes(1.0, 0.5), nodes(vn[-2], 0.5), nodes(1.0, 1.0)
    t_u = np.gradient(x[:, tip], pu[1, tip], axis=1).T
    normal = np.cross(t_u, (x[:, tip] - x[:, below]).T)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    normal *= np.sign(np.sum(normal * (x[:, conv] - x[:, tip]).T, axis=1))[:, None]
    d = np.stack([disp[basis.nodal_dofs[k, tip]] for k in range(3)], axis=1)
    return x[:, tip].T, np.sum(d * normal, axis=1)


def shell_tip_deflection(case, member, data, tip_points, load, side, patch=(0.08, 0.1),
                         model=None):
    """The shell model's tip deflection W (along e_z) under the same patch load: unit point
    loads at a 4 × 4 Gauss grid over the patch on the REAL flank, along the real flank
    normals expressed in the shell frame, averaged (superposition). ``model``: a shell
    model of ``data.tooth`` (default: data.shell_model(), the default modes)."""
    g, w = np.polynomial.legendre.leggauss(4)
    (u0, v0), (du, dv) = load, patch
    ug, vg = np.meshgrid(u0 + 0.5 * du * g, v0 + 0.5 * dv * g, indexing="ij")
    z, rho = _bilinear(data.corners, ug.ravel(), vg.ravel()).T
    flank = "convex" if side > 0 else "concave"
    p, n, _ = _flank(case, member, flank, z, rho, 0 if side > 0 else data.concave_shift)
    sp = shell_coordinates(data, p, n)
    tips = shell_coordinates(data, tip_points)
    w_tip = shell_deflection(model or data.shell_model(), np.column_stack([sp.x, sp.theta]),
                             np.column_stack([tips.x, tips.theta]), load_normals=sp.normal)
    return w_tip @ (np.outer(w, w).ravel() / 4.0)


def _fe_comparison(name, member, side, load):
    case = _case(name)
    data = _tooth(name, member)
    tips, w_fe = fe_generated_tooth(case, member, data.concave_shift, load, side)
    w_sh = shell_tip_deflection(case, member, data, tips, load, side)
    peak = float(np.max(np.abs(w_fe)))
    return float(np.max(np.abs(w_sh))) / peak, float(np.max(np.abs(w_sh - w_fe))) / peak, peak


@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_generated_tooth_deflection_matches_fe_of_the_generated_tooth(member):
    """Hypoid example, unit patch load at mid face / mid profile on the drive flank: the
    tip-line deflection of the shell model (fitted dimensions, shell coordinates, real flank
    normals, default 6 × 21 modes) against 3-D FE of the generated tooth. Tolerance 15 % on
    the peak and on the largest difference along the tip: the shell and FE of the SAME
    idealised tooth differ by up to 7 % (seed theory, benchmarks/compliance.py) and the
    linear thickness of seed Eq. 3.1 misfits the generated flanks by up to 0.6 mm (pinion).
    Measured: peak ratio 0.98 (pinion), 1.08 (gear); shape error 4 %, 10 %. The FE mesh
    (6 × 16 × 2 triquadratic) is within 0.5 % of 8 × 32 × 4. The peak is ~1e-6 mm/N."""
    side = 1 if DRIVE[member] == "convex" else -1
    ratio, err, peak = _fe_comparison("hypoid_iso23509_s2", member, side, (0.5, 0.5))
    assert 0.85 < ratio < 1.15
    assert err < 0.15
    assert 5e-7 < peak < 5e-6


@pytest.mark.slow
@pytest.mark.parametrize("name", CASES)
@pytest.mark.parametrize("member", ["pinion", "gear"])
@pytest.mark.parametrize("side", [1, -1])
@pytest.mark.parametrize("load", [(0.5, 0.5), (0.25, 0.75)])
def test_fe_study_of_generated_teeth(name, member, side, load):
    """The whole study of benchmarks/compliance_tooth.py (both cases, members, flanks, two
    load places): same tolerances as the fast test (measured 0.91–1.12, shape ≤ 13 %)."""
    ratio, err, _ = _fe_comparison(name, member, side, load)
    assert 0.85 < ratio < 1.15
    assert err < 0.15


@pytest.mark.parametrize("name", FH_CASES)
@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_face_hobbed_tooth_deflection_matches_fe(name, member):
    """Face-hobbed teeth (FH_CASES), unit patch load at mid face / mid profile on the drive
    flank: the shell with the MEASURED lengthwise radius against 3-D FE of the generated
    tooth, the same 15 % bounds as for face milling (the seed applies the circular shell to
    FH unchanged; design note §6). Measured (fh_iso23509_s2_crown): peak ratio 1.017
    (pinion), 1.058 (gear), shape error 4 %, 6 %; with the cutter radius instead of the
    measured one the ratios change by < 0.2 %. The seed's Table 4.3 pair (measured radius
    67.6/65.8 mm against the cutter's 81.9/80.9, lengthwise radius ±19 % along the face):
    0.997 (pinion), 1.084 (gear), shape 3 %, 8 %; Table 5.4 A and B (slow study): 0.93–1.09,
    shape ≤ 9 %."""
    case = _case(name)
    ratio, err, peak = _fe_comparison(name, member, _drive_side(case, member), (0.5, 0.5))
    assert 0.85 < ratio < 1.15
    assert err < 0.15
    assert 5e-7 < peak < 5e-6


@pytest.mark.slow
@pytest.mark.parametrize("name", FH_STUDY)
@pytest.mark.parametrize("member", ["pinion", "gear"])
@pytest.mark.parametrize("side", [1, -1])
@pytest.mark.parametrize("load", [(0.5, 0.5), (0.25, 0.75)])
def test_fe_study_of_face_hobbed_teeth(name, member, side, load):
    """Both flanks and two load places of the FH cases, same bounds (measured for
    fh_iso23509_s2_crown: 0.99–1.07, shape ≤ 8 %)."""
    ratio, err, _ = _fe_comparison(name, member, side, load)
    assert 0.85 < ratio < 1.15
    assert err < 0.15


# ------------------------------------------------------------------ compliance matrices
def _profile_points(case, data, member, flank, u, vs):
    z, rho = _bilinear(data.corners, np.full(len(vs), u), vs).T
    p, n, ok = _flank(case, member, flank, z, rho,
                      0 if flank == "convex" else data.concave_shift)
    assert ok.all()
    return p, n


@pytest.mark.parametrize("member", ["pinion", "gear"])
def test_member_compliance_symmetric_positive_definite_and_tip_most_compliant(member):
    """Loads on one generated tooth (3 profile lines × 5 heights on the drive flank): the
    Ritz compliance Φᵀ K⁻¹ Φ is symmetric before symmetrisation (Maxwell–Betti, rounding
    only: < 1e-10) and positive definite; along each profile line a load nearer the tip is
    more compliant (cantilever: δ grows monotonically with the load's distance from the
    clamp)."""
    case = _case("hypoid_iso23509_s2")
    data = _tooth("hypoid_iso23509_s2", member)
    vs = np.array([0.3, 0.45, 0.6, 0.75, 0.9])
    pts, nrms = [], []
    for u in (0.3, 0.5, 0.7):
        p, n = _profile_points(case, data, member, DRIVE[member], u, vs)
        pts.append(p)
        nrms.append(n)
    p, n = np.concatenate(pts), np.concatenate(nrms)
    c = member_compliance(data, p, n)
    assert np.all(np.linalg.eigvalsh(c) > 0)
    sp = shell_coordinates(data, p, n)
    raw = compliance_matrix(data.shell_model(), np.column_stack([sp.x, sp.theta]), sp.normal)
    assert raw.asymmetry < 1e-10
    diag = np.diag(c).reshape(3, len(vs))
    assert np.all(np.diff(diag, axis=1) > 0)


def test_line_load_mesh_stiffness_matches_iso_6336():
    """ISO 6336-1:2019 §9 gives c′ ≈ 14 N/(mm·µm) for the single mesh stiffness of steel
    pairs (solid gears, standard basic rack). Our tooth pair at mid height, hypoid example,
    per unit length of a line load over each tooth's length: pinion and gear bending/shear
    (shell, one segment along the whole face) + both Sainsot foundations + Weber at
    w′ = 300 N/mm, R_eq = 15 mm; c′ = 1 / Σ q. Within 30 %: ISO's value is a typical one
    for spur and helical gears (its own spread over geometries is ±25 %); the bevel virtual
    gears are not standard racks. Measured 10.8 N/(mm·µm)."""
    case = _case("hypoid_iso23509_s2")
    q, depth = 0.0, []
    for member in ("pinion", "gear"):
        data = _tooth("hypoid_iso23509_s2", member)
        p, n = _profile_points(case, data, member, DRIVE[member], 0.5, [0.5])
        sp = shell_coordinates(data, p, n)
        th0 = data.tooth.subtended_angle
        ends = np.array([[[0.5 * data.tooth.height(0.0), 0.0],
                          [0.5 * data.tooth.height(th0), th0]]])
        c_line = compliance_matrix(data.shell_model(), ends, sp.normal).matrix[0, 0]
        q += c_line * data.tooth.face_width  # [mm²/N] per unit length
        alpha = load_angle_from_normals(sp.normal)
        u_f = load_line_height(sp.x, data.tooth.thickness(sp.x, sp.theta), alpha)
        q += foundation_compliance(data.foundation, u_f, alpha)[0] * data.foundation.face_width
        depth.append(weber_depth(data, sp)[0])
    q += float(weber_compliance(300.0, 1.0, depth[0], depth[1], e1=206000.0, nu1=0.3,
                                e2=206000.0, nu2=0.3, r_eq=15.0))
    c_prime = 1.0 / q / 1000.0  # N/mm² → N/(mm·µm)
    assert c_prime == pytest.approx(14.0, rel=0.30)


# ------------------------------------------------------------------ the mesh
@functools.cache
def _conjugate_segments():
    """Contact segments of the conjugate hypoid pair (tests/data, no crowning: the pinion
    point generated at roll q touches the gear with the pinion at −R_a q and the gear at
    ψ₂ + q, case [derivation]): two tooth pairs at one roll position, points along each
    contact line on the pinion's drive (concave) flank, interpolated on a fine grid."""
    name = "hypoid_iso23509_s2_conjugate"
    case = _case(name)
    with open(DATA / f"{name}.toml", "rb") as fh:
        der = tomllib.load(fh)["derivation"]
    ra = case.gear.blank.teeth / case.pinion.blank.teeth
    pitch1 = 2 * math.pi / case.pinion.blank.teeth
    pitch2 = 2 * math.pi / case.gear.blank.teeth
    fs = flank_surface(case, "pinion", "concave", nu=41, nv=9)
    ok = fs.valid & (fs.section == profile_sections(case.pinion.concave.blade).main)
    q0 = float(np.nanmedian(fs.q[ok]))
    rot1, rot2 = -ra * q0, math.radians(der["gear_rotation_deg"]) + q0
    tp, tg = case_transforms(case, rot1, rot2)
    gear = shell_tooth_from_case(case, "gear")
    mids, nrms, pairs = [], [], []
    for k in (0, 1):  # pair k: the reference pinion tooth at roll q0 − k·2π/z2, turned by k
        a = k * pitch1
        turn = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0],
                         [0, 0, 1]])
        for j in range(1, fs.q.shape[1] - 1):
            good = ok[:, j]
            qq, order = fs.q[good, j], np.argsort(fs.q[good, j])
            target = q0 - k * pitch2
            if not qq.min() < target < qq.max():
                continue
            u = np.interp(target, qq[order], fs.grid.u[good][order])
            z, rho = np.interp(u, fs.grid.u, fs.grid.axial[:, j]), \
                np.interp(u, fs.grid.u, fs.grid.radius[:, j])
            p, n, _ = _flank(case, "pinion", "concave", z, rho)
            pp, nn = transform_points(tp, p[0] @ turn.T), transform_vectors(tp, n[0] @ turn.T)
            try:  # keep the points inside the gear blank (the rest is not a contact)
                shell_coordinates(gear, pp, -nn, transform=tg)
            except InputError:
                continue
            mids.append(pp)
            nrms.append(nn)
            pairs.append(k)
    mids, pairs = np.array(mids), np.array(pairs)
    ends = np.zeros((len(mids), 2, 3))
    for k in (0, 1):
        idx = np.flatnonzero(pairs == k)
        d = np.gradient(mids[idx], axis=0)
        ends[idx, 0], ends[idx, 1] = mids[idx] - 0.5 * d, mids[idx] + 0.5 * d
    seg = ContactSegments(mids, ends, np.array(nrms), np.linalg.norm(ends[:, 1] - ends[:, 0],
                                                                      axis=1),
                          10.0, pairs, 100.0, pinion_rotation=rot1, gear_rotation=rot2)
    return case, seg, tp


def test_mesh_compliance_structure_and_parts():
    """Total compliance of two tooth pairs of the conjugate hypoid pair: symmetric and
    positive definite; no coupling across tooth pairs (exact zeros); the sum of its parts
    (1e-15 relative); the pinion's shell part equals member_compliance of the same segments
    given in the pinion's member frame (the pair-frame transform is applied right, 1e-12);
    every pinion load is on its concave (drive) flank and every gear load on its convex
    flank — the drive sides, found from the contact normals."""
    case, seg, tp = _conjugate_segments()
    assert seg.size >= 10 and set(seg.pair_index) == {0, 1}
    c, info = mesh_compliance(case, seg)
    np.testing.assert_array_equal(c, c.T)
    assert np.all(np.linalg.eigvalsh(c) > 0)
    a, b = seg.pair_index == 0, seg.pair_index == 1
    assert np.all(c[np.ix_(a, b)] == 0.0)
    parts = sum(info[k] for k in ("pinion_shell", "gear_shell", "pinion_foundation",
                                  "gear_foundation", "weber"))
    np.testing.assert_allclose(c, parts, rtol=1e-15, atol=1e-15 * np.abs(c).max())
    assert np.all(info["pinion_points"].side == -1)
    assert np.all(info["gear_points"].side == 1)
    model = info["model"]
    inv = np.linalg.inv(tp)
    for mask in (a, b):
        ref = member_compliance(model.pinion, transform_points(inv, seg.midpoints[mask]),
                                transform_vectors(inv, seg.normals[mask]),
                                transform_points(inv, seg.ends[mask]))
        np.testing.assert_allclose(info["pinion_shell"][np.ix_(mask, mask)], ref, rtol=1e-12,
                                   atol=1e-12 * np.abs(ref).max())
    assert info["asymmetry"] < 1e-10


def test_mesh_models_are_built_once_per_case():
    """The second roll position reuses both members' tooth models and factorised shells:
    the same objects come back, no new shell model is built, and the call is faster than
    the first, which measured the teeth and factorised the stiffness matrices."""
    case, seg, _ = _conjugate_segments()
    opts = dict(n_height=5, n_face=11)  # settings no other test uses: a fresh memo entry
    t0 = time.perf_counter()
    _, info1 = mesh_compliance(case, seg, **opts)
    t1 = time.perf_counter()
    _, info2 = mesh_compliance(case, seg, **opts)
    t2 = time.perf_counter()
    assert info2["model"] is info1["model"] is pair_compliance_model(case, **opts)
    assert len(info1["model"].pinion._models) == len(info1["model"].gear._models) == 1
    assert t2 - t1 < t1 - t0


# ------------------------------------------------------------------ validation
def test_bad_input_names_the_field():
    case = _case("hypoid_iso23509_s2")
    data = _tooth("hypoid_iso23509_s2", "gear")
    with pytest.raises(InputError, match="member"):
        shell_tooth_from_case(case, "rack")
    with pytest.raises(InputError, match="poisson_ratio"):
        shell_tooth_from_case(case, "gear", poisson_ratio=0.6)
    with pytest.raises(InputError, match="face fraction"):
        shell_coordinates(data, [[0.0, 0.0, 500.0]])
    p, n = _profile_points(case, data, "gear", "convex", 0.5, [0.5])
    with pytest.raises(InputError, match="out of the gear's material"):
        shell_coordinates(data, p, -n)
    with pytest.raises(InputError, match="unit"):
        shell_coordinates(data, p, 2 * n)
    with pytest.raises(InputError, match="side"):
        flank_points(data, [1.0], [0.1], 0)
    _, seg, _ = _conjugate_segments()
    kw = dict(midpoints=seg.midpoints, ends=seg.ends, normals=seg.normals, length=1.0,
              r_eq=10.0, pair_index=seg.pair_index, load=10.0)
    with pytest.raises(InputError, match="load"):
        ContactSegments(**{**kw, "load": -1.0})
    with pytest.raises(InputError, match="ends"):
        ContactSegments(**{**kw, "ends": seg.ends[:, 0]})
    with pytest.raises(InputError, match="r_eq"):
        ContactSegments(**{**kw, "r_eq": 0.0})
    with pytest.raises(InputError, match="model"):
        mesh_compliance(case, seg, model=pair_compliance_model(_case(
            "hypoid_iso23509_s2_conjugate")), theory="seed")
