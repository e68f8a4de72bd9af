"""Derive basic machine settings for the example cases and write them as TOML.

Run from the repository root::

    python cases/derive_basic_settings.py

It writes ``cases/spiral_bevel_iso23509_s1.toml``, ``cases/hypoid_iso23509_s2.toml`` and,
for the tests, the same pairs without crowning (exactly conjugate) in ``tests/data/``.

Blanks: ISO 23509:2016 Annex F, sample 1 (spiral bevel, 14/39, face milling) and sample 2
(hypoid, 13/42, offset 15 mm, face milling); input and published results copied below.
Apex positions are recomputed from the published outer cone distance, addendum, dedendum,
cone angles and crown-to-crossing-point distances (see ``blank``).

Settings (basic relations, not a Gleason summary):

* Gear, Formate (the gear is the imprint of a spread-blade cutter). Machine root angle
  γ_m = δ_f (the cutter-tip plane contains the root generatrix), root apex at the machine
  centre (X_p = t_zR, X_b = E_m = 0, no tilt). With R_mf the root cone distance of the mean
  point, r_c0 the nominal cutter radius and β_m the mean spiral angle:
  S_r² = R_mf² + r_c0² − 2 R_mf r_c0 sin β_m, q_c = atan2(r_c0 cos β_m, R_mf − r_c0 sin β_m).
  Blade angles = normal pressure angles of the flanks; point width at the mean root
  W = π m_mn − s_mn2 − h_fm2 (tan α_IB + tan α_OB); point radii r_c0 ∓ W/2.
* Pinion, Generate, by the gear's own imprint as generating gear: cradle axis = gear axis,
  ratio of roll R_a = z2/z1 (= sin δ2/sin δ1 without offset). Each pinion flank is cut by a
  blade lying on the cone of the gear blade that cuts the mating gear flank (pinion concave
  ↔ gear convex), facing the other way, its tip plane at the pinion's mean root; the machine
  settings follow from these poses by :func:`geometry.machine.cradle.settings_from_poses`.
  Without crowning the pair is conjugate (line contact). The case files add lengthwise
  crowning (pinion cutter radius ±2 % of r_c0, the cutter centre moved so the cone still
  passes through the mean point with the same normal) and profile crowning (convex circular
  pinion blades tangent to the nominal line at the mean point).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from geometry.case import case_from_dict  # noqa: E402
from geometry.machine.cradle import MachineSettings, cutter_pose, settings_from_poses  # noqa: E402
from geometry.machine.flank import line_intersection  # noqa: E402
from geometry.pair.assembly import member_transform  # noqa: E402

D = math.radians
MIRROR = np.array([1.0, -1.0, 1.0])

# ISO 23509:2016 Annex F (copied from the standard's tables F.1-F.6; degrees and mm)
ISO = {
    "s1": dict(
        z1=14, z2=39, Sigma=90.0, a=0.0, b1=25.4, b2=25.4, beta_m1=35.0, beta_m2=35.0,
        rc0=114.3, alpha_D=20.0, alpha_C=20.0, Re1=93.973, Re2=93.973,
        delta1=19.747, delta2=70.253, delta_a1=26.240, delta_f1=17.613, delta_a2=72.387,
        delta_f2=63.760, hae1=6.281, hfe1=2.867, hae2=2.064, hfe2=7.085, m_mn=3.213,
        smn2=3.511, txo1=86.324, txo2=29.808),
    "s2": dict(
        z1=13, z2=42, Sigma=90.0, a=15.0, b1=31.910, b2=30.0, beta_m1=49.998,
        beta_m2=38.609, rc0=63.5, alpha_D=17.747, alpha_C=22.253, Re1=89.608, Re2=91.468,
        # pitch angles from the published face angle minus addendum angle (tables F.5)
        delta1=25.232 - 3.943, delta2=64.324 + 4.0, delta_a1=25.232, delta_f1=20.303,
        delta_a2=69.323, delta_f2=64.324, hae1=4.541, hfe1=2.784, hae2=2.112, hfe2=5.150,
        m_mn=2.640, smn2=3.241, txo1=83.070, txo2=30.247),
}


def blank(z, b, re, delta, delta_a, delta_f, hae, hfe, txo):
    """Blank fields (degrees, mm); apexes from the crown-to-crossing-point distance txo."""
    d = D(delta)
    z_tip = re * math.cos(d) - hae * math.sin(d)  # relative to the pitch apex
    zp = txo - z_tip  # pitch apex position on the member axis (from the crossing point)
    g = np.array([math.cos(d), math.sin(d)])
    perp = np.array([-math.sin(d), math.cos(d)])
    tip = np.array([zp, 0.0]) + re * g + hae * perp
    root = np.array([zp, 0.0]) + re * g - hfe * perp
    z_face = tip[0] - tip[1] / math.tan(D(delta_a))
    z_root = root[0] - root[1] / math.tan(D(delta_f))
    return {
        "teeth": z, "face_width": b, "outer_cone_distance": re, "pitch_angle": delta,
        "face_angle": delta_a, "root_angle": delta_f, "pitch_apex": round(-zp, 6),
        "face_apex": round(-z_face, 6), "root_apex": round(-z_root, 6),
        "outer_addendum": hae, "outer_dedendum": hfe,
    }


def mean_points(bl):
    """Mean pitch point, mean root point (z, ρ) and mean dedendum of a blank dict."""
    d, df = D(bl["pitch_angle"]), D(bl["root_angle"])
    rm = bl["outer_cone_distance"] - 0.5 * bl["face_width"]
    apex = np.array([-bl["pitch_apex"], 0.0])
    pm = apex + rm * np.array([math.cos(d), math.sin(d)])
    pr = line_intersection([-bl["root_apex"], 0.0], [math.cos(df), math.sin(df)], pm,
                    [-math.sin(d), math.cos(d)])
    return pm, pr, float(np.linalg.norm(pm - pr))


def rotz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def derive(key, *, crowning: bool):
    p = ISO[key]
    gear_bl = blank(p["z2"], p["b2"], p["Re2"], p["delta2"], p["delta_a2"], p["delta_f2"],
                    p["hae2"], p["hfe2"], p["txo2"])
    pin_bl = blank(p["z1"], p["b1"], p["Re1"], p["delta1"], p["delta_a1"], p["delta_f1"],
                   p["hae1"], p["hfe1"], p["txo1"])
    rc0, beta2 = p["rc0"], D(p["beta_m2"])
    # --- gear, Formate ---------------------------------------------------------------
    pm2, pr2, hfm2 = mean_points(gear_bl)
    rmf = float(np.hypot(pr2[0] + gear_bl["root_apex"], pr2[1]))
    sr = math.sqrt(rmf**2 + rc0**2 - 2 * rmf * rc0 * math.sin(beta2))
    qc = math.atan2(rc0 * math.cos(beta2), rmf - rc0 * math.sin(beta2))
    a_ib, a_ob = p["alpha_D"], p["alpha_C"]  # gear convex = drive side (pinion concave drives)
    w = math.pi * p["m_mn"] - p["smn2"] - hfm2 * (math.tan(D(a_ib)) + math.tan(D(a_ob)))
    edge2 = round(min(0.25 * p["m_mn"], 0.4 * w), 3)
    gear_machine = {
        "radial_setting": sr, "cradle_angle": math.degrees(qc), "swivel": 0.0, "tilt": 0.0,
        "machine_root_angle": gear_bl["root_angle"],
        "machine_center_to_back": gear_bl["root_apex"], "sliding_base": 0.0,
        "blank_offset": 0.0,
    }
    gear_cutter = {
        "convex": {"point_radius": rc0 - w / 2, "blade_angle": a_ib, "edge_radius": edge2},
        "concave": {"point_radius": rc0 + w / 2, "blade_angle": a_ob, "edge_radius": edge2},
    }
    gms = MachineSettings(process="Formate", radial_setting=sr, cradle_angle=qc,
                          machine_root_angle=D(gear_bl["root_angle"]),
                          machine_center_to_back=gear_bl["root_apex"])
    c2, u2 = cutter_pose(gms, 0.0)
    # --- pair placement ----------------------------------------------------------------
    sigma = D(p["Sigma"])
    kw = dict(shaft_angle=sigma, offset=p["a"], gear_hand="right")
    pm1, pr1, _ = mean_points(pin_bl)
    rho2, z2 = pm2[1], pm2[0]
    t_p0 = member_transform("pinion", **kw)
    axis_p, orig_p = t_p0[:3, 2], t_p0[:3, 3]
    best = None
    for sgn in (1.0, -1.0):
        # mean point on the gear pitch circle at the pinion's mean pitch radius
        y_e = orig_p[1]
        disc = pm1[1] ** 2 - z2**2
        sin_z = (y_e + sgn * math.sqrt(max(disc, 0.0))) / rho2
        zeta = math.asin(sin_z)
        pt = np.array([rho2 * math.cos(zeta), rho2 * math.sin(zeta), z2])
        axial = float(np.dot(pt - orig_p, axis_p))
        mismatch = abs(axial - pm1[0])
        if best is None or mismatch < best[0]:
            best = (mismatch, zeta, pt)
    mismatch, zeta, p_mean = best
    t_g = member_transform("gear", rotation=zeta, **kw)
    c2g = t_g[:3, :3] @ c2 + t_g[:3, 3]
    u2g = t_g[:3, :3] @ u2
    rp = t_p0[:3, :3].T  # global → pinion (actual, left-hand) frame

    def to_ref(x, point=True):
        v = rp @ (x - orig_p) if point else rp @ x
        return v * MIRROR  # left-hand pinion → right-hand reference frame

    # pinion mean root point, at the azimuth of the mean point in the pinion frame
    pp = rp @ (p_mean - orig_p)
    az = math.atan2(pp[1], pp[0])
    root3 = orig_p + t_p0[:3, :3] @ np.array([pr1[1] * math.cos(az), pr1[1] * math.sin(az),
                                               pr1[0]])
    # the pinion tip plane is parallel to the gear root plane, which is inclined by
    # delta_a2 - delta_f2 to the gear face cone: set it deeper than the mean root by the rise
    # of the gear face over half the face width, so the gear tip clears the pinion root at
    # the heel (the toe is cut deeper than the blank's root cone instead)
    extra_depth = 0.5 * p["b2"] * math.tan(D(p["delta_a2"] - p["delta_f2"]))
    h_root1 = float(np.dot(c2g - root3, u2g)) + extra_depth
    cradle_axis = to_ref(-t_g[:3, 2], point=False)
    cradle_point = to_ref(t_g[:3, 3])
    ratio = p["z2"] / p["z1"]
    pin_machine, pin_cutter, phases = {}, {}, {}
    for flank, gear_flank, side in (("concave", "convex", 1), ("convex", "concave", -1)):
        gb = gear_cutter[gear_flank]
        sig2 = -side  # gear blade side: inside (-1) for the gear convex flank
        r1 = gb["point_radius"] + sig2 * h_root1 * math.tan(D(gb["blade_angle"]))
        c1 = c2g - h_root1 * u2g
        u1 = -u2g
        blade = {"point_radius": r1, "blade_angle": gb["blade_angle"],
                 "edge_radius": round(0.25 * p["m_mn"], 3)}
        if crowning:
            dr = 0.02 * rc0
            x = p_mean - c1
            erho = x - np.dot(x, u1) * u1
            erho /= np.linalg.norm(erho)
            c1 = c1 - side * dr * erho
            blade["point_radius"] = r1 + side * dr
            blade["profile"] = "circular"
            blade["profile_radius"] = 500.0 if key == "s1" else 400.0
            blade["profile_reference_height"] = round(float(np.dot(c1 - p_mean, u1)), 4)
        ps = settings_from_poses(cradle_point=cradle_point, cradle_axis=cradle_axis,
                                 cutter_centre=to_ref(c1), cutter_axis=to_ref(u1, False),
                                 process="Generate", ratio_of_roll=ratio)
        s = ps.settings
        pin_machine[flank] = {k: round(v, 10) for k, v in {
            "radial_setting": s.radial_setting, "cradle_angle": math.degrees(s.cradle_angle),
            "swivel": math.degrees(s.swivel), "tilt": math.degrees(s.tilt),
            "machine_root_angle": math.degrees(s.machine_root_angle),
            "machine_center_to_back": s.machine_center_to_back,
            "sliding_base": s.sliding_base, "blank_offset": s.blank_offset}.items()}
        pin_machine[flank]["ratio_of_roll"] = ratio
        pin_cutter[flank] = blade
        phases[flank] = math.degrees(ps.blank_phase)
    names = {"s1": ("spiral_bevel_iso23509_s1", "spiral bevel 14/39, ISO 23509 Annex F "
                    "sample 1"),
             "s2": ("hypoid_iso23509_s2", "hypoid 13/42, offset 15 mm, ISO 23509 Annex F "
                    "sample 2")}
    name, title = names[key]
    if not crowning:
        name += "_conjugate"
    source = (
        f"{title}. Blank: ISO 23509:2016 Annex F (tables F.1-F.6); apexes recomputed from "
        "the published R_e, h_ae, h_fe, cone angles and crown-to-crossing-point distances. "
        "Machine settings: basic relations written by cases/derive_basic_settings.py, not "
        "a Gleason summary. Gear Formate: gamma_m = root angle, root apex at the machine "
        "centre, S_r^2 = R_mf^2 + r_c0^2 - 2 R_mf r_c0 sin(beta_m), "
        "q_c = atan2(r_c0 cos beta_m, R_mf - r_c0 sin beta_m) with R_mf the mean root cone "
        f"distance ({rmf:.4f} mm), r_c0 = {rc0} mm, beta_m2 = {p['beta_m2']} deg; blade "
        "angles = flank pressure angles; point width at the mean root "
        f"W = pi m_mn - s_mn2 - h_fm2 (tan a_IB + tan a_OB) = {w:.4f} mm. Pinion Generate "
        "with the gear's imprint as generating gear: cradle axis = gear axis, ratio of "
        f"roll z2/z1 = {ratio:.6f}; each pinion blade on the cone of the mating gear blade, "
        f"tip plane {h_root1:.4f} mm above the gear cutter tips (the pinion mean root plus "
        f"(b2/2) tan(delta_a2 - delta_f2) = {extra_depth:.4f} mm so the gear tip clears the "
        "pinion root at the heel; the toe is cut deeper than the root cone); "
        "settings from the poses by geometry.machine.cradle.settings_from_poses. "
        + ("Crowning: pinion cutter radius +/- 2 % of r_c0 about the mean point, convex "
           "circular pinion blades tangent at the mean point."
           if crowning else "No crowning: the pair is conjugate (line contact).")
    )
    synth = [f"{m}.machine.{f}" for m in ("pinion", "gear") for f in ("concave", "convex")]
    synth += [f"{m}.cutter.{f}" for m in ("pinion", "gear") for f in ("concave", "convex")]
    synth += [f"{m}.blank.{k}" for m in ("pinion", "gear")
              for k in ("pitch_apex", "face_apex", "root_apex")]
    if key == "s2":
        synth += ["pinion.blank.pitch_angle", "gear.blank.pitch_angle"]
    doc = {
        "name": name, "source": source, "synthesised": synth,
        "pair": {"shaft_angle": p["Sigma"], "offset": p["a"], "method": "FM",
                 "pinion_hand": "left", "gear_hand": "right", "drive_flank": "concave"},
        "pinion": {"process": "Generate", "blank": pin_bl, "cutter": pin_cutter,
                   "machine": pin_machine},
        "gear": {"process": "Formate", "blank": gear_bl, "cutter": gear_cutter,
                 "machine": {"concave": gear_machine, "convex": gear_machine}},
        "derivation": {
            "note": "informational: how the pinion was generated from the gear imprint. In "
                    "the pair frame the pinion turns by phi1 = -(phase + R_a q) (left-hand) "
                    "while the gear turns by phi2 = gear_rotation + q, q the cradle roll.",
            "gear_rotation_deg": math.degrees(zeta),
            "pinion_phase_deg": phases,
            "mean_point_axial_mismatch_mm": mismatch,
            "pinion_tip_plane_height_mm": h_root1,
            "pinion_tip_plane_extra_depth_mm": extra_depth,
        },
    }
    return case_from_dict(doc)


def main() -> None:
    out = []
    for key in ("s1", "s2"):
        crowned = derive(key, crowning=True)
        conj = derive(key, crowning=False)
        out.append((ROOT / "cases" / f"{crowned.name}.toml", crowned))
        out.append((ROOT / "tests" / "data" / f"{conj.name}.toml", conj))
    for path, case in out:
        header = ("# Generated by cases/derive_basic_settings.py (blank: ISO 23509:2016 Annex F; "
                  "settings: basic relations, see `source`).\n")
        path.write_text(header + case.to_toml(), encoding="utf-8")
        print(f"wrote {path.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
