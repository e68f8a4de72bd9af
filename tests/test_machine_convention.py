"""Summaries typed in SpyGO's convention: the conversion table against SpyGO's own equations.

SpyGO (open-source spiral bevel / hypoid generator, Python) is not on PyPI, so its
equations are re-implemented here from its published model (not from its code text): the
9-joint cradle chain as a product of elementary rotations and translations about fixed axes,

    G(φ) = R_z(−ψ) T(0,0,−D) R_y(γ) T(B,0,0) T(0,E,0) R_x(−q) T(0,0,S) R_x(ζ) R_z(σ) R_y(−π/2),

each joint a Taylor series in the generating roll φ of the *typed* summary value times a
sign that depends on the member and the system hand (the pinion's), the roll terms of
order ≥ 2 scaled by the ratio of roll; and its blade, a circle through the point radius in
the tip plane with the blade angle there, centre on the work side for ρ_b > 0, blended to
the tip plane by the edge radius. Rotations are scipy's, independent of geometry.machine.cradle.

What is checked (tolerances justified where they are used):

* the table of geometry.machine.convention reproduces SpyGO's chain for the four
  (member, hand) cases (1e-12 relative: round-off of a product of 10 matrices);
* our blade edge lies on SpyGO's circles for both sides, convex and concave edges and a
  reference height off the tip (1e-9 mm);
* ours → SpyGO → ours is exact (H5, H6: one rounding of ×/÷ 1000);
* a case declared ``convention = "spygo"`` with the converted values generates the flanks of
  the case in ours to 1e-9 mm, for both hand assignments;
* flipping any single sign of the table moves a flank by at least 0.1 µm (or makes the
  case invalid); the amounts are logged;
* a bad convention name is an InputError naming the field and the accepted values, and
  ``Case.to_toml`` writes our convention.
"""

from __future__ import annotations

import copy
import logging
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from geometry.case import case_from_dict
from geometry.core.errors import InputError
from geometry.machine.convention import (
    CONVENTIONS,
    SPYGO_MACHINE,
    blade_from_spygo,
    blade_to_spygo,
    machine_from_spygo,
    machine_to_spygo,
)
from geometry.machine.cradle import MachineSettings, machine_transform
from geometry.machine.cutter import Blade, blade_profile, profile_sections
from geometry.machine.flank import flank_surface

log = logging.getLogger(__name__)

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "cases" / "kolivand2009_fm_11x41.toml"
DEG = math.pi / 180.0

# --------------------------------------------------------------- SpyGO's model, re-implemented
# Signs SpyGO puts on the typed summary before its chain, per (member, system hand), per
# joint: (sign of the constant term, signs of the derivatives 1, 2, …); for the roll:
# (sign of the ratio of roll, signs of 2C, 6D, 24E, 120F). Transcribed from
# SpyGO's published sign matrices (manage_machine_settings), written out per joint.
_P, _M = 1, -1
SPYGO_SIGNS = {
    ("pinion", "left"): {"S": (_P, [_P] * 6), "sigma": (_M, []), "zeta": (_M, []),
                         "E": (_P, [_P] * 6), "B": (_P, [_P] * 6), "q": (_M, []),
                         "roll": (_P, [_M, _M, _M, _M]), "D": (_P, []), "gamma": (_P, [])},
    ("pinion", "right"): {"S": (_P, [_P] * 6), "sigma": (_P, []), "zeta": (_P, []),
                          "E": (_M, [_M] * 6), "B": (_P, [_M, _P, _M, _P, _M, _P]),
                          "q": (_P, []), "roll": (_P, [_P, _M, _P, _M]), "D": (_P, []),
                          "gamma": (_P, [])},
    ("gear", "left"): {"S": (_P, [_P] * 6), "sigma": (_M, []), "zeta": (_P, []),
                       "E": (_M, [_P] * 6), "B": (_P, [_P] * 6), "q": (_P, []),
                       "roll": (_P, [_M, _M, _M, _M]), "D": (_P, []), "gamma": (_P, [])},
    ("gear", "right"): {"S": (_P, [_P, _P, _M, _P, _P, _P]), "sigma": (_P, []),
                        "zeta": (_P, []), "E": (_P, [_P, _M, _P, _M, _P, _P]),
                        "B": (_P, [_M, _P, _M, _P, _M, _P]), "q": (_M, []),
                        "roll": (_P, [_P, _M, _P, _M]), "D": (_P, []), "gamma": (_P, [])},
}


def system_hand(member: str, hand: str) -> str:
    """SpyGO's sign matrices are keyed by the system hand, which is the pinion's."""
    return hand if member == "pinion" else {"left": "right", "right": "left"}[hand]


def _series(c0: float, derivs, phi: float, extra_scale=None) -> float:
    """c0 + Σ d_k φ^k / k! (with SpyGO's extra 1/1000 on some orders)."""
    val = c0
    for k, d in enumerate(derivs, start=1):
        scale = (extra_scale or {}).get(k, 1.0)
        val += d * scale * phi**k / math.factorial(k)
    return val


def spygo_transform(typed: dict, member: str, hand: str, phi: float) -> np.ndarray:
    """SpyGO's cutter → member transform at roll φ [rad] from a typed summary.

    ``typed``: SpyGO's names and units (degrees for the angles, mm, 1): S, sigma (tilt),
    zeta (swivel), E, B (sliding base), q (cradle), m (ratio of roll), roll (2C, 6D, 24E,
    120F), D (machine centre to back), gamma (root angle), B_derivs (H1…H6), E_derivs
    (V1…V6).
    """
    sg = SPYGO_SIGNS[(member, system_hand(member, hand))]

    def joint(name, c0, derivs=(), extra=None):
        s0, sk = sg[name]
        return _series(s0 * c0, [s * d for s, d in zip(sk, derivs, strict=False)], phi, extra)

    s_r = joint("S", typed["S"])
    tilt = joint("sigma", typed["sigma"] * DEG)
    swivel = joint("zeta", typed["zeta"] * DEG)
    e_off = joint("E", typed["E"], typed.get("E_derivs", ()))
    # the 5th and 6th sliding-base derivatives are typed in thousandths
    b_sl = joint("B", typed["B"], typed.get("B_derivs", ()), extra={5: 1e-3, 6: 1e-3})
    cradle = _series(sg["q"][0] * typed["q"] * DEG, [1.0], phi)
    m = typed["m"]
    roll_signs = sg["roll"][1]
    psi = m * phi + sum(roll_signs[k] * m * c * phi**(k + 2) / math.factorial(k + 2)
                        for k, c in enumerate(typed.get("roll", ())))
    d_ctr = typed["D"]
    gamma = typed["gamma"] * DEG

    def rot(axis, angle):
        out = np.eye(4)
        out[:3, :3] = Rotation.from_rotvec(np.asarray(axis, float) * angle).as_matrix()
        return out

    def tr(x, y, z):
        out = np.eye(4)
        out[:3, 3] = (x, y, z)
        return out

    ex, ey, ez = (1, 0, 0), (0, 1, 0), (0, 0, 1)
    return (rot(ez, -psi) @ tr(0, 0, -d_ctr) @ rot(ey, gamma) @ tr(b_sl, 0, 0)
            @ tr(0, e_off, 0) @ rot(ex, -cradle) @ tr(0, 0, s_r) @ rot(ex, swivel)
            @ rot(ez, tilt) @ rot(ey, -math.pi / 2))


def to_spygo_names(fields: dict) -> dict:
    """Our field names (SpyGO-signed values, radians) → SpyGO's names in its units."""
    return {"S": fields["radial_setting"], "sigma": fields["tilt"] / DEG,
            "zeta": fields["swivel"] / DEG, "E": fields["blank_offset"],
            "B": fields["sliding_base"], "q": fields["cradle_angle"] / DEG,
            "m": fields["ratio_of_roll"], "roll": fields["modified_roll"],
            "D": fields["machine_center_to_back"],
            "gamma": fields["machine_root_angle"] / DEG,
            "B_derivs": fields["helical_motion"], "E_derivs": fields["vertical_motion"]}


def spygo_blade_distance(spygo: dict, side: str, rho: np.ndarray, h: np.ndarray):
    """Distance [mm] of points (ρ, h) from SpyGO's blade: the profile circle through
    (R_p, tip plane) with the blade angle there, and the edge-radius circle tangent to the
    tip plane and to it (the nearer of the two circles, signed as |d − radius|)."""
    rp, alpha, rf, rb = (spygo["point_radius"], spygo["blade_angle"], spygo["edge_radius"],
                         spygo["profile_radius"])
    sgn = 1.0 if side == "outside" else -1.0
    # SpyGO's z points to the work: its Z is −h
    cx, cz = rp + sgn * rb * math.cos(alpha), rb * math.sin(alpha)
    d_prof = np.abs(np.hypot(rho - cx, -h - cz) - abs(rb))
    # edge circle: tangent to Z = 0 (centre at Z = −r_f) and to the profile circle, whose
    # centres are |ρ_b + r_f| apart (external for ρ_b > 0, internal for a convex edge)
    th0 = math.asin((cz + rf) / (rb + rf))
    xf = cx - sgn * (rb + rf) * math.cos(th0)
    d_edge = np.abs(np.hypot(rho - xf, -h + rf) - rf)
    return np.minimum(d_prof, d_edge), d_prof, d_edge


# --------------------------------------------------------------------------- fixtures
def generic_settings() -> MachineSettings:
    """Every setting non-zero, all motion orders the table covers."""
    return MachineSettings(
        process="Generate", radial_setting=98.7, cradle_angle=61.3 * DEG, swivel=-27.4 * DEG,
        tilt=19.2 * DEG, machine_root_angle=-3.1 * DEG, machine_center_to_back=-1.3,
        sliding_base=-6.2, blank_offset=18.4, ratio_of_roll=3.61,
        modified_roll=(0.012, -0.21, 0.73, -1.9),
        helical_motion=(0.8, -1.7, 2.9, -4.1, 6.3, -8.8),
        vertical_motion=(-0.6, 1.1, -2.3, 3.7, -5.2, 7.4))


def ours_fields(s: MachineSettings) -> dict:
    return {k: getattr(s, k) for k in (
        "radial_setting", "cradle_angle", "swivel", "tilt", "machine_root_angle",
        "machine_center_to_back", "sliding_base", "blank_offset", "ratio_of_roll",
        "modified_roll", "helical_motion", "vertical_motion")}


MIRROR = np.diag([1.0, -1.0, 1.0, 1.0])


# ------------------------------------------------------------------------------ tests
@pytest.mark.parametrize("member", ["pinion", "gear"])
@pytest.mark.parametrize("hand", ["right", "left"])
def test_table_reproduces_spygo_chain(member, hand):
    """ours → SpyGO-typed via the table, then SpyGO's chain = our chain for the member of
    that hand (left: the mirror D M_ref(−q) D of the right-hand reference, the cutter being
    its own mirror image). 1e-12 × the size of the numbers (≈ 100 mm): round-off only."""
    ref = generic_settings()
    typed = to_spygo_names(machine_to_spygo(ours_fields(ref), member, hand))
    for q in (-0.31, -0.05, 0.0, 0.17, 0.42):
        theirs = spygo_transform(typed, member, hand, q)
        if hand == "right":
            mine = machine_transform(ref, q)[0]
        else:
            mine = MIRROR @ machine_transform(ref, -q)[0] @ MIRROR
        np.testing.assert_allclose(theirs, mine, rtol=0, atol=1e-12 * 100)


def test_single_sign_error_breaks_the_chain():
    """The check above has teeth: each sign of the table flipped alone breaks it (the
    generic settings have every term non-zero)."""
    ref = generic_settings()
    base = ours_fields(ref)
    for (member, hand), rules in SPYGO_MACHINE.items():
        for name, factor in rules.items():
            entries = [None] if not isinstance(factor, tuple) else range(len(factor))
            for k in entries:
                typed = machine_to_spygo(base, member, hand)
                if k is None:
                    typed[name] = -typed[name]
                else:
                    seq = list(typed[name])
                    seq[k] = -seq[k]
                    typed[name] = tuple(seq)
                t = to_spygo_names(typed)
                q = 0.3
                theirs = spygo_transform(t, member, hand, q)
                mine = (machine_transform(ref, q)[0] if hand == "right"
                        else MIRROR @ machine_transform(ref, -q)[0] @ MIRROR)
                assert np.max(np.abs(theirs - mine)) > 1e-6, (member, hand, name, k)


def test_machine_round_trip_is_exact():
    fields = ours_fields(generic_settings())
    for member, hand in SPYGO_MACHINE:
        back = machine_from_spygo(machine_to_spygo(fields, member, hand), member, hand)
        for name, val in fields.items():
            if name == "helical_motion":
                # H5, H6 pass through ×1000 and ÷1000: at most one rounding each
                assert back[name][:4] == val[:4]
                np.testing.assert_allclose(back[name][4:], val[4:], rtol=4.5e-16, atol=0)
            else:
                assert back[name] == val, (member, hand, name)


BLADES = [
    # (side, point radius, blade angle deg, edge radius, R_pr, h_ref)
    ("outside", 95.2, 21.9, 0.8, -843.0, 6.3),
    ("inside", 105.7, 28.1, 0.8, -1518.0, 6.7),
    ("outside", 95.2, 21.9, 0.8, 400.0, 3.0),
    ("inside", 105.7, 28.1, 0.5, 250.0, 4.0),
    ("outside", 95.2, 21.9, 0.8, 600.0, 0.0),
    ("inside", 99.0, 20.0, 0.0, -300.0, 2.0),
]


@pytest.mark.parametrize("blade", BLADES)
def test_blade_lies_on_spygo_circles(blade):
    """Our edge, sampled along its arc length, lies on SpyGO's profile or edge circle with
    the converted values (1e-9 mm: the closed-form sections are exact to round-off), the
    profile section on the profile circle, the edge section on the edge circle."""
    side, rp, a, re, rpr, href = blade
    ours = {"point_radius": rp, "blade_angle": a * DEG, "edge_radius": re,
            "profile": "circular", "profile_radius": rpr, "profile_reference_height": href}
    b = Blade(side=side, **ours)
    sec = profile_sections(b)
    s = np.linspace(0.0, 12.0, 241)
    p = blade_profile(sec, s)
    spy = blade_to_spygo(ours, side)
    assert spy["profile_radius"] == -rpr
    dist, d_prof, d_edge = spygo_blade_distance(spy, side, p.rho, p.h)
    assert np.max(dist) < 1e-9
    main = (s > sec.s_lo[sec.main] + 1e-9)
    assert np.max(d_prof[main]) < 1e-9
    if re > 0:
        edge = s < sec.s_hi[0] - 1e-9
        assert np.max(d_edge[edge]) < 1e-9
    # a wrong sign of ρ_b or the nominal (reference-height) values typed as the tip values
    # miss SpyGO's blade by far more than the tolerance
    wrong = dict(spy, profile_radius=rpr)
    assert np.max(spygo_blade_distance(wrong, side, p.rho, p.h)[0][main]) > 1e-4
    if href > 0:
        naive = dict(spy, point_radius=rp, blade_angle=a * DEG)
        assert np.max(spygo_blade_distance(naive, side, p.rho, p.h)[0][main]) > 1e-4


@pytest.mark.parametrize("blade", BLADES)
def test_blade_round_trip(blade):
    """ours → SpyGO → ours: radii to 1e-9 mm, angles to 1e-13 rad (asin of a sum, tan of
    a half sum: a few roundings on numbers ≤ 10² mm)."""
    side, rp, a, re, rpr, href = blade
    ours = {"point_radius": rp, "blade_angle": a * DEG, "edge_radius": re,
            "profile": "circular", "profile_radius": rpr, "profile_reference_height": href}
    back = blade_from_spygo(blade_to_spygo(ours, side), side, reference_height=href)
    assert back["profile"] == "circular" and back["profile_radius"] == rpr
    assert back["edge_radius"] == re and back["profile_reference_height"] == href
    assert abs(back["point_radius"] - rp) < 1e-9
    assert abs(back["blade_angle"] - a * DEG) < 1e-13
    straight = {"point_radius": rp, "blade_angle": a * DEG, "edge_radius": re}
    assert blade_from_spygo(blade_to_spygo(straight, side), side) == {
        **straight, "profile": "straight", "profile_radius": 0.0,
        "profile_reference_height": 0.0}


def test_blade_outside_the_table_is_refused():
    with pytest.raises(InputError, match=r"^toprem_angle: not in the SpyGO conversion table"):
        blade_to_spygo({"point_radius": 90.0, "blade_angle": 0.3, "toprem_angle": 0.05},
                       "outside")
    with pytest.raises(InputError, match=r"^toprem_angle: not a SpyGO blade field"):
        blade_from_spygo({"point_radius": 90.0, "blade_angle": 0.3, "toprem_angle": 0.05},
                         "outside")
    with pytest.raises(InputError, match=r"^profile_radius: the circular profile"):
        blade_to_spygo({"point_radius": 90.0, "blade_angle": 0.3, "profile": "circular",
                        "profile_radius": 5.0, "profile_reference_height": 4.0}, "outside")


# ------------------------------------------------------------------ case files
def raw_case(hands=("left", "right"), generated_gear=False) -> dict:
    """The Kolivand 11x41 case, optionally with hands swapped, and optionally with the
    gear replaced by a generated member (the pinion's tools and blank plus helical and
    vertical motion) so that every entry of the gear's table is exercised."""
    raw = tomllib.loads(CASE.read_text(encoding="utf-8"))
    raw["pair"]["pinion_hand"], raw["pair"]["gear_hand"] = hands
    for flank in ("concave", "convex"):
        m = raw["pinion"]["machine"][flank]
        m["helical_motion"] = [0.4, -0.9]
        m["vertical_motion"] = [0.3, 0.6]
    if generated_gear:
        raw["gear"] = copy.deepcopy(raw["pinion"])
    return raw


def to_spygo_file(raw: dict) -> dict:
    """The same case with both members' summaries typed in SpyGO's convention."""
    out = copy.deepcopy(raw)
    for member in ("pinion", "gear"):
        hand = raw["pair"][f"{member}_hand"]
        tab = out[member]
        tab["machine"]["convention"] = "spygo"
        tab["cutter"]["convention"] = "spygo"
        for flank, side in (("concave", "outside"), ("convex", "inside")):
            m = machine_to_spygo(
                {k: tuple(v) if isinstance(v, list) else v
                 for k, v in raw[member]["machine"][flank].items()}, member, hand)
            tab["machine"][flank] = {k: list(v) if isinstance(v, tuple) else v
                                     for k, v in m.items()}
            b = dict(raw[member]["cutter"][flank])
            b["blade_angle"] *= DEG
            spy = blade_to_spygo(b, side)
            spy["blade_angle"] /= DEG
            tab["cutter"][flank] = spy
    return out


def flank_points(case, member, flank):
    surf = flank_surface(case, member, flank, nu=7, nv=5)
    ok = surf.reason == 0
    return surf.position, ok


@pytest.mark.parametrize("hands", [("left", "right"), ("right", "left")])
@pytest.mark.parametrize("generated_gear", [False, True])
def test_spygo_case_generates_our_flanks(hands, generated_gear):
    """A case typed in SpyGO's convention loads to the same flanks (1e-9 mm: the machine
    settings convert exactly, the blades to the same circle re-referenced to the tip)."""
    raw = raw_case(hands, generated_gear)
    ours = case_from_dict(raw)
    theirs = case_from_dict(to_spygo_file(raw))
    for member in ("pinion", "gear"):
        for flank in ("concave", "convex"):
            assert ours.member(member).flank(flank).machine == \
                theirs.member(member).flank(flank).machine
            p0, ok0 = flank_points(ours, member, flank)
            p1, ok1 = flank_points(theirs, member, flank)
            assert np.array_equal(ok0, ok1) and ok0.sum() > 20
            assert np.max(np.abs(p0 - p1)[ok0]) < 1e-9
    # written back in our convention, with no convention key
    text = theirs.to_toml()
    assert "convention" not in text
    assert case_from_dict(tomllib.loads(text)) == theirs


def _flip(typed: dict, name: str, k):
    out = copy.deepcopy(typed)
    if k is None:
        out[name] = -out[name]
    else:
        out[name][k] = -out[name][k]
    return out


def _entries(member: str, hand: str):
    out = []
    for name, factor in SPYGO_MACHINE[(member, hand)].items():
        if isinstance(factor, tuple):
            out += [("machine", name, k) for k in range(len(factor))]
        else:
            out.append(("machine", name, None))
    return [*out, ("cutter", "profile_radius", None)]


def _flip_moves(raw: dict, member: str) -> dict:
    """Flank move [mm] of each single sign flip of ``member``'s SpyGO-typed summary (max
    over the 7 x 5 grid of the first flank where the entry is non-zero; inf: the flipped
    case is refused on load or has no envelope in the blank). Entries that are 0 in the
    case are left out."""
    spy = to_spygo_file(raw)
    ref = case_from_dict(spy)
    hand = raw["pair"][f"{member}_hand"]
    base = {flank: flank_points(ref, member, flank) for flank in ("concave", "convex")}
    moves = {}
    for table, name, k in _entries(member, hand):
        move, touched = 0.0, False
        for flank in ("concave", "convex"):
            typed = spy[member][table][flank]
            val = typed.get(name)
            if val is None or (k is None and val == 0) or (
                    k is not None and (k >= len(val) or val[k] == 0)):
                continue
            touched = True
            bad = copy.deepcopy(spy)
            bad[member][table][flank] = _flip(typed, name, k)
            try:
                p, ok = flank_points(case_from_dict(bad), member, flank)
            except InputError:
                move = math.inf
                break
            p0, ok0 = base[flank]
            both = ok & ok0
            move = max(move, float(np.max(np.linalg.norm(p - p0, axis=-1)[both])))
            break  # one flank per entry keeps the test short
        if touched:
            moves[(name, k)] = move
    return moves


@pytest.mark.parametrize("hands", [("left", "right"), ("right", "left")])
def test_each_wrong_sign_moves_the_flank(hands):
    """Every entry of the table (machine fields, each motion coefficient, the blade's
    profile radius) typed with the wrong sign moves the flank by >= 0.1 µm or makes the
    case invalid. Entries whose value is 0 in a case cannot move anything and are skipped;
    the generated pinion (with helical and vertical motion added), a generated gear (the
    pinion's tools on the gear's hand) and the Formate gear (root angle, machine centre to
    back) together cover every entry of both members' tables for both hands."""
    covered = {}
    for member, generated_gear in (("pinion", False), ("gear", True), ("gear", False)):
        moves = _flip_moves(raw_case(hands, generated_gear), member)
        log.info("hands %s, %s%s: flank move of each single wrong sign [mm]: %s", hands,
                 member, " (generated)" if generated_gear else "", moves)
        for key, move in moves.items():
            assert move >= 1e-4, (hands, member, generated_gear, key, move)
            covered.setdefault(member, set()).add(key)
    for member in ("pinion", "gear"):
        hand = hands[0] if member == "pinion" else hands[1]
        wanted = {(name, k) for _, name, k in _entries(member, hand)
                  if not (name in ("helical_motion", "vertical_motion") and k >= 2)
                  and not (name == "modified_roll" and k == 3)}
        if member == "pinion":
            wanted -= {("machine_root_angle", None)}  # 0 for the case's pinion
        assert wanted <= covered[member], wanted - covered[member]


def test_convention_name_is_checked():
    raw = raw_case()
    raw["pinion"]["machine"]["convention"] = "gleason"
    with pytest.raises(InputError, match=r"^pinion\.machine\.convention: must be one of "
                                         r"\['ours', 'spygo'\], got 'gleason'$"):
        case_from_dict(raw)
    raw = raw_case()
    raw["gear"]["cutter"]["convention"] = 1
    with pytest.raises(InputError, match=r"^gear\.cutter\.convention: must be one of "):
        case_from_dict(raw)
    assert CONVENTIONS == ("ours", "spygo")
    # explicit "ours" is the default
    raw = raw_case()
    raw["pinion"]["machine"]["convention"] = "ours"
    raw["pinion"]["cutter"]["convention"] = "ours"
    assert case_from_dict(raw) == case_from_dict(raw_case())


def test_spygo_blade_table_names_its_fields():
    raw = to_spygo_file(raw_case())
    raw["pinion"]["cutter"]["concave"]["profile_reference_height"] = 2.0
    with pytest.raises(InputError, match=r"^pinion\.cutter\.concave\.profile_reference_height: "
                                         r"unknown field; accepted: point_radius"):
        case_from_dict(raw)
    raw = to_spygo_file(raw_case())
    raw["pinion"]["machine"]["concave"]["modified_roll"] = [0.0] * 5
    with pytest.raises(InputError, match=r"^pinion\.machine\.concave\.modified_roll"):
        case_from_dict(raw)


def test_spygo_summaries_are_face_milling_only():
    raw = tomllib.loads((ROOT / "cases" / "kolivand2009_fh_12x41.toml").read_text("utf-8"))
    raw["pinion"]["machine"]["convention"] = "spygo"
    with pytest.raises(InputError, match=r"^pinion\.machine\.convention: 'spygo' summaries "
                                         r"are face milling"):
        case_from_dict(raw)
