"""Why ``thermal_eyring`` misses two rows of issue 74's "Done when": its flank μ split into
the asperities' part and the film's, and the boundary friction μ_b those rows would need.

On the seed's Table 5.4 designs A and B (100 / 500 / 1000 N·m; the 500 N·m torque read),
1500 rpm, run-in flanks, for the bundled 75W90 and the data-sheet ISO VG 220 mineral oil
(ν40 220, ν100 19.4 mm²/s, ρ15 890 kg/m³: class values, as
``tests/test_thermal_eyring_criteria.py``), prints per inlet temperature and Rq:

* the flank λ and the load-weighted **asperity share** of the load (of the model's
  default load sharing: Zhou & Hoeprich's exp(−B λ^C) since issue 74's last step; before
  it γ₂⁻¹ of Johnson, Greenwood & Poon's with the summits of ``friction.flank_summits``);
* the flank μ split into the asperities' part μ_b·share and the film's part (the rest),
  beside ISO/TR 14179-2's μ on the same segments (Schlenk's correlation of FZG gear
  measurements, ``iso_tr_14179_2``);

then, with the 75W90's μ_b made a table of 0.10 at 50 °C and a value x at 90 °C (held
outside, the oil file's ``[boundary_friction]`` mechanism of docs/friction.md), the rows of
the issue that depend on it: the roughness cost (Rq 0.1 → 1.3 µm) over ISO's at 50 and
90 °C, the level at the seed's point, the VG 220's μ over the 75W90's (its μ_b the same
table), hot against cold at Rq 1.3 and A − B. **A sensitivity, not a model**: x is what a
measured μ_b(T) of the oil would have to show; nothing here is adopted (docs/friction.md,
"Why the roughness cost grows with temperature").

``--share-curve`` prints instead the asperity share of that load sharing against the
smooth-surface central λ at one flank point like A's at 500 N·m (p_h 1.0 GPa, R 15 mm,
E′ 230 GPa, 75W90 at 90 °C, SR 0.5, no inlet thermal reduction; the entraining speed
varied), run-in Rq 0.544 and 0.884 µm (given 0.8 and 1.3): where the model's mixed regime
begins and ends, against Zhu & Wang's deterministic range (docs/friction.md, "What
measurements say about μ_b(T) and the asperity share"), beside Zhou & Hoeprich's
exp(−B λ^C) with the two published constant sets (``load_sharing="zhou_hoeprich"``).

``--share-curve --stochastic`` adds, at the same points, the asperity load ratio of the
toolkit's stochastic mixed-EHL line-contact solver (``friction.ehl.stochastic``: Patir &
Cheng's average-flow Reynolds equation with statistical elastic–plastic summits of the
ground profile, solved over the contact — the construction whose regression fits are
Masjedi & Khonsari's asperity-load formulas, J. Tribol. 134 (2012) 011503; isothermal
shear, ``thermal=False``, which does not enter the load ratio) and its own λ (Pan–Hamrock
h_min over the composite Rq): what a relation fitted to that class of model would give
(docs/friction.md, "Masjedi & Khonsari's asperity-load formulas").

Usage::

    python benchmarks/friction_share_map.py [--rolls 6] [--segments 12]
    python benchmarks/friction_share_map.py --share-curve [--stochastic]

The default resolution is the criteria test's (one mesh cycle, 6 rolls, 12 segments): its
ratios to ISO equal the full-resolution map's (``friction_correlation_map.py``, 20 rolls,
24 segments) to the digits docs/friction.md shows (2.43 / 2.63, +13.2 %, −18.2 %).
"""

from __future__ import annotations

import argparse
import inspect
import sys
import tempfile
import tomllib
import warnings
from pathlib import Path

from tabulate import tabulate

# the tree this script belongs to, before an installed copy of the package
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from friction.coefficient import FrictionModelRangeWarning
from friction.efficiency import efficiency_analysis
from friction.oil_data_sheet import OilDataSheet, oil_file_mapping
from friction.operating import OperatingConditions
from friction.thermal_eyring import _load_sharing, _model_sharing, thermal_eyring
from geometry.core.toml_files import dump_toml

CASES = {"A": "kolivand2009_table54_A_fh", "B": "kolivand2009_table54_B_fh"}
TORQUES = (100.0, 500.0, 1000.0)
AT = 1  # 500 N·m
VG220 = OilDataSheet(name="VG220_mineral", kinematic_viscosity_40=220.0,
                     kinematic_viscosity_100=19.4, density_15=890.0, base_oil="mineral",
                     source="typical ISO VG 220 mineral EP gear oil (class values)")
_SHARING = ("load_per_length", "hertz_pressure", "radius", "e_prime", "entraining_velocity",
            "sliding_velocity", "viscosity", "pressure_viscosity", "roughness_1",
            "roughness_2", "thermal_factor", "eyring_stress", "limiting_shear_coefficient",
            "boundary_friction")


def asperity_part(**inputs):
    """μ_b × the asperity share of ``thermal_eyring``'s load sharing (its defaults: Zhou &
    Hoeprich's share since issue 74's last step), as a model function: the efficiency
    stage then stores it per segment."""
    sol = _model_sharing(load_sharing=_DEFAULT["load_sharing"],
                         asperity_load_constants=_DEFAULT["asperity_load_constants"],
                         summits=_DEFAULT["summits"], asperity_density_radius_sigma=0.05,
                         sigma_over_beta=0.01,
                         **{k: v for k, v in inputs.items() if k in _SHARING})
    return sol.boundary_friction


#: thermal_eyring's default load-sharing keywords
_DEFAULT = {k: p.default for k, p in inspect.signature(thermal_eyring).parameters.items()
            if k in ("load_sharing", "asperity_load_constants", "summits")}


asperity_part.__signature__ = inspect.signature(thermal_eyring)


def _flank(lt, fr, name):
    force = lt["force"].fillna(0.0).where(lt["segment_kind"] == "curve", 0.0)
    dims = ("roll", "pair", "segment")
    return float(((fr[name].fillna(0.0) * force).sum(dims) / force.sum(dims)).values[AT])


def _run(lt, model, oil, temperature, roughness):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        return efficiency_analysis(lt, OperatingConditions(
            friction_model=model, lubricant=oil, temperature=temperature,
            roughness=roughness))


def split_rows(lts, oils):
    rows = []
    for label, lt in lts.items():
        for oil_label, oil in oils.items():
            for t, rq in ((50.0, 0.8), (50.0, 1.3), (90.0, 0.8), (90.0, 1.3)):
                fr = _run(lt, "thermal_eyring", oil, t, rq)
                mu = _flank(lt, fr, "friction_coefficient")
                mu_b = float(fr.attrs["boundary_friction"])
                asp = _flank(lt, _run(lt, asperity_part, oil, t, rq), "friction_coefficient")
                iso = _flank(lt, _run(lt, "iso_tr_14179_2", oil, t, rq),
                             "friction_coefficient")
                rows.append([label, oil_label, t, rq, _flank(lt, fr, "lambda_ratio"),
                             asp / mu_b, mu, asp, mu - asp, iso, mu / iso])
    return rows


def _with_mu_b(doc, x, folder, tag):
    d = dict(doc)
    d["boundary_friction"] = {"temperature": [50.0, 90.0], "value": [0.1, x],
                              "source": "sensitivity of benchmarks/friction_share_map.py"}
    path = Path(folder) / f"{tag}_{x:g}.toml"
    path.write_text(dump_toml(d), encoding="utf-8")
    return str(path)


def sensitivity_rows(lts, folder, values=(0.10, 0.09, 0.085, 0.08, 0.075, 0.07)):
    from friction.lubricant import _bundled

    w90 = tomllib.loads(_bundled()["75W90"].read_text(encoding="utf-8"))
    vg = oil_file_mapping(VG220)
    rows = []
    for x in values:
        oil, vgo = _with_mu_b(w90, x, folder, "75W90"), _with_mu_b(vg, x, folder, "vg220")
        eff = {}
        row = [x]
        for label, lt in lts.items():
            def e(model, t, rq, o=oil, lt=lt):
                return 100.0 * float(_run(lt, model, o, t, rq)["efficiency_mean"].values[AT])

            def m(model, t, rq, o=oil, lt=lt):
                return _flank(lt, _run(lt, model, o, t, rq), "friction_coefficient")

            cost = {t: (e("thermal_eyring", t, 0.1) - e("thermal_eyring", t, 1.3))
                    / (e("iso_tr_14179_2", t, 0.1) - e("iso_tr_14179_2", t, 1.3))
                    for t in (50.0, 90.0)}
            level = m("thermal_eyring", 90.0, 0.8) / m("iso_tr_14179_2", 90.0, 0.8)
            rank = {t: 100.0 * (m("thermal_eyring", t, 0.8, vgo) / m("thermal_eyring", t, 0.8)
                                - 1.0) for t in (50.0, 90.0)}
            hot = e("thermal_eyring", 100.0, 1.3) - e("thermal_eyring", 50.0, 1.3)
            eff[label] = e("thermal_eyring", 90.0, 0.8)
            row += [f"{cost[50.0]:.2f} / {cost[90.0]:.2f}", f"{level:.2f}",
                    f"{rank[50.0]:+.1f} / {rank[90.0]:+.1f}", f"{hot:+.2f}"]
        row.append(f"{eff['A'] - eff['B']:.2f}")
        rows.append(row)
    return rows


#: the one flank point of ``--share-curve``: radius of relative curvature [mm], E' [MPa],
#: Hertz pressure [MPa], the 75W90 at 90 degC
_POINT = {"radius": 15.0, "e_prime": 230e3, "p_h": 1000.0, "temperature": 90.0}


def _point_load() -> float:
    """Load per length [N/mm] of the line contact at :data:`_POINT`'s Hertz pressure."""
    import numpy as np

    b = 4.0 * _POINT["radius"] * _POINT["p_h"] / _POINT["e_prime"]  # Hertz half-width, mm
    return float(np.pi * b * _POINT["p_h"] / 2.0)


def _point_share(rq: float, u):
    """(central λ, asperity load share) of thermal_eyring's load sharing at
    :data:`_POINT`, run-in ground summits of Rq ``rq`` [µm] on both flanks, entraining
    speeds ``u`` [m/s] (array), slide-to-roll 0.5."""
    import numpy as np

    from friction.lubricant import load_lubricant, pressure_viscosity_coefficient, viscosity

    oil, t = load_lubricant("75W90"), _POINT["temperature"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        sol = _load_sharing(
            summits="ground", load_per_length=_point_load(), hertz_pressure=_POINT["p_h"],
            radius=_POINT["radius"], e_prime=_POINT["e_prime"], entraining_velocity=u,
            sliding_velocity=0.5 * u, viscosity=float(viscosity(oil, t)),
            pressure_viscosity=float(pressure_viscosity_coefficient(oil, t)),
            roughness_1=rq, roughness_2=rq, thermal_factor=1.0, eyring_stress=5.0,
            limiting_shear_coefficient=0.08, boundary_friction=0.1,
            asperity_density_radius_sigma=0.05, sigma_over_beta=0.01)
    return sol.smooth_film_thickness / (np.sqrt(2.0) * rq), sol.asperity_load_share


def share_curve_rows(lambdas=(0.05, 0.09, 0.15, 0.2, 0.28, 0.52, 0.75, 1.2)):
    """Asperity share at the smooth-surface central λ nearest each of ``lambdas`` (module
    docstring, ``--share-curve``); rows (λ, share at Rq 0.544, share at Rq 0.884, Zhou &
    Hoeprich's share with the rib's and the raceway's constants at λ itself)."""
    import numpy as np

    from friction.thermal_eyring import zhou_hoeprich_share

    u = np.geomspace(0.02, 60.0, 600)
    cols = [_point_share(rq, u) for rq in (0.544, 0.884)]
    rows = []
    for target in lambdas:
        row = [target]
        for lam, share in cols:
            i = int(np.argmin(abs(lam - target)))
            row.append(float(share[i]) if abs(lam[i] / target - 1.0) < 0.05 else float("nan"))
        rows.append(row + [float(zhou_hoeprich_share(target, c)) for c in ("rib", "raceway")])
    return rows


def stochastic_share_rows(speeds=((0.15, 0.3, 0.6, 1.0, 1.5, 2.5, 5.0, 8.0, 12.0, 20.0),
                                  (0.3, 0.6, 1.0, 1.5, 2.5, 4.0, 8.0, 12.0, 20.0, 50.0))):
    """At ``--share-curve``'s flank point, per run-in Rq (0.544, 0.884 µm) and entraining
    speed [m/s]: rows (Rq, u_e, central λ, JGP share, stochastic solver's asperity load
    ratio, its Pan–Hamrock λ); NaN where the solver did not converge."""

    import numpy as np

    from friction.ehl.complementarity import ConvergenceError
    from friction.ehl.line_contact import LineContactCondition
    from friction.ehl.roughness import GroundSurface
    from friction.ehl.stochastic import StochasticOptions, stochastic_summary

    radius, e_prime, w = _POINT["radius"], _POINT["e_prime"], _point_load()
    rows = []
    for rq, us in zip((0.544, 0.884), speeds, strict=True):
        lam, share = _point_share(rq, np.asarray(us, dtype=float))
        for i, ue in enumerate(us):
            cond = LineContactCondition(load_per_length=w, radius=radius,
                                        entraining_velocity=ue, slide_to_roll=0.5,
                                        temperature=_POINT["temperature"],
                                        e_prime=e_prime)
            try:
                s = stochastic_summary(cond, (GroundSurface(rq, seed=1),
                                              GroundSurface(rq, seed=2)),
                                       options=StochasticOptions(thermal=False))
                st = (s.asperity_load_ratio, s.lambda_ratio)
            except ConvergenceError:
                st = (float("nan"), float("nan"))
            rows.append([rq, ue, float(lam[i]), float(share[i]), *st])
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rolls", type=int, default=6)
    ap.add_argument("--segments", type=int, default=12)
    ap.add_argument("--share-curve", action="store_true",
                    help="the asperity share against lambda at one flank point and exit")
    ap.add_argument("--stochastic", action="store_true",
                    help="with --share-curve: the stochastic solver's load ratio beside it")
    args = ap.parse_args(argv)
    if args.share_curve:
        print("asperity share of thermal_eyring's load sharing at one flank point (p_h 1.0 "
              "GPa, R 15 mm, 75W90 at 90 degC, SR 0.5) against the smooth-surface central "
              "lambda")
        print(tabulate(share_curve_rows(), headers=("lambda", "JGP share, Rq 0.544 um",
                                                    "JGP share, Rq 0.884 um",
                                                    "Zhou-Hoeprich, rib", "ZH, raceway"),
                       floatfmt=("g", ".3f", ".3f", ".3f", ".3f")))
        if args.stochastic:
            print("\nthe same point: Johnson-Greenwood-Poon share against the stochastic "
                  "mixed-EHL solver's asperity load ratio (friction.ehl.stochastic)")
            print(tabulate(stochastic_share_rows(),
                           headers=("Rq [um]", "u_e [m/s]", "lambda (central, smooth)",
                                    "JGP share", "stochastic load ratio",
                                    "its lambda (Pan-Hamrock h_min)"),
                           floatfmt=("g", "g", ".3f", ".3f", ".3f", ".3f")))
        return 0
    opts = LTCAOptions(cycles=1, rolls_per_cycle=args.rolls, segments=args.segments)
    lts = {k: loaded_tca(resolve_case(v), list(TORQUES), options=opts)
           for k, v in CASES.items()}
    with tempfile.TemporaryDirectory() as folder:
        vg = Path(folder) / "vg220.toml"
        vg.write_text(dump_toml(oil_file_mapping(VG220)), encoding="utf-8")
        print("thermal_eyring's flank mu split (500 N m, 1500 rpm, run-in flanks)")
        print(tabulate(split_rows(lts, {"75W90": "75W90", "VG220": str(vg)}),
                       headers=("case", "oil", "degC", "Rq [um]", "lambda", "asperity share",
                                "mu", "asperity part", "film part", "ISO mu", "mu/ISO"),
                       floatfmt=("", "", "g", "g", ".3f", ".3f", ".4f", ".4f", ".4f", ".4f",
                                 ".2f")))
        print("\nmu_b of the 75W90 and the VG 220: 0.10 at 50 degC, x at 90 degC (a "
              "sensitivity, not adopted)")
        print(tabulate(sensitivity_rows(lts, folder),
                       headers=("x", "A cost/ISO 50/90", "A level", "A VG220 % 50/90",
                                "A hot-cold Rq1.3", "B cost/ISO 50/90", "B level",
                                "B VG220 % 50/90", "B hot-cold Rq1.3", "A - B")))
    print("issue 74's bounds: cost 0.5-2 x ISO at 50 and 90 degC; level 0.7-1.4; VG 220 "
          "within +-15 %; hot-cold <= 0; A - B 1.0-2.0 points")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
