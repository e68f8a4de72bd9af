"""Friction models mapped beside the measured correlations, over roughness, temperature,
speed, torque and oil (issue 74, item 3).

For Table 5.4's face-hobbed A and B (100 / 500 / 1000 N·m, 20 rolls per cycle) and the
default case (``kolivand2009_fm_11x41_reference``) and a spiral bevel pair (ISO 23509's
sample 1, ``spiral_bevel_iso23509_s1``; both 50 / 250 / 500 N·m), prints the
**flank** load-weighted μ (edge contacts apart) and the mean mesh efficiency of

* ``mixed_ehl`` — the default model;
* ISO/TR 14179-2 — Schlenk's correlation of FZG gear measurements,
  μ = 0.048 (F_bt/b/(v_Σ ρ))^0.2 η^−0.05 Ra^0.25 X_L, evaluated per loaded flank segment
  (:func:`friction.coefficient.iso_tr_14179_2`) with X_L of the oil's base stock
  (:data:`friction.lubricant.BASE_OIL_FACTORS`);
* ``xu2007`` — Xu, Kahraman et al. (2007)'s regression (published coefficients);
* ``thermal_eyring`` — the opt-in thermal Eyring film shear (:mod:`friction.thermal_eyring`;
  ``film_heating`` 1, Johnson & Greenwood's) on the asperities from the flanks' roughness
  (:mod:`friction.flank_summits`), the same with the surfaces' flash temperature alone
  (``film_heating`` 0, column ``thermal_eyring_s``) and, with ``--fixed-summits``, its
  first version with ``mixed_ehl``'s fixed ηβσ 0.05 and σ/β 0.01 (column
  ``thermal_eyring_fixed``) and Johnson, Greenwood & Poon's load sharing with the ground
  summits instead of Zhou & Hoeprich's share (column ``thermal_eyring_jgp``),

over Rq 0.1–1.3 µm × oil inlet 50–100 °C (1500 rpm), pinion speed 100–6000 rpm, torque and
three oils: the bundled 75W90 (the seed's Table 5.2), an ISO VG 220 mineral gear oil and a
PAO VG 220, both built from typical data-sheet values with
:mod:`friction.oil_data_sheet` (mineral: ν40 220, ν100 19.4 mm²/s, ρ15 890 kg/m³; PAO:
ν40 220, ν100 25 mm²/s, ρ15 850 kg/m³ — typical values of the class, not one product's).
Run-in flanks (the default surface state: the friction is evaluated at 0.68 × the given
Rq, the correlations too). Then issue 74's "Done when" relations, each met or not, with
the number.

Usage::

    python benchmarks/friction_correlation_map.py [--ltca-cache DIR] [--cases A,B,default]
        [--no-thermal] [--fixed-summits]   (cases: A, B, default, spiral)

The LTCAs are those of ``benchmarks/friction_anchors.py`` / ``friction_map.py`` (computed
once and cached in ``--ltca-cache``, default ``~/.cache/hypoid-ltca/benchmarks``).
"""

from __future__ import annotations

import argparse
import functools
import sys
import tempfile
import warnings
from pathlib import Path

from tabulate import tabulate

sys.path.insert(0, str(Path(__file__).resolve().parent))
# the tree this script belongs to, before an installed copy of the package
sys.path.insert(1, str(Path(__file__).resolve().parents[1]))

from friction_anchors import _flank_weighted, _ltca

from friction.coefficient import FrictionModelRangeWarning, iso_tr_14179_2
from friction.efficiency import efficiency_analysis
from friction.lubricant import BASE_OIL_FACTORS, load_lubricant
from friction.oil_data_sheet import OilDataSheet, oil_file_mapping
from friction.operating import OperatingConditions
from friction.thermal_eyring import thermal_eyring
from geometry.core.toml_files import dump_toml

#: label → (case, torques [N·m], rolls per cycle or None, index of the 500 N·m torque)
CASES = {
    "A": ("kolivand2009_table54_A_fh", (100.0, 500.0, 1000.0), 20, 1),
    "B": ("kolivand2009_table54_B_fh", (100.0, 500.0, 1000.0), 20, 1),
    "default": ("kolivand2009_fm_11x41_reference", (50.0, 250.0, 500.0), None, 2),
    "spiral": ("spiral_bevel_iso23509_s1", (50.0, 250.0, 500.0), None, 2),
}
ROUGHNESS = (0.1, 0.4, 0.8, 1.3)
TEMPERATURES = (50.0, 70.0, 90.0, 100.0)
SPEEDS = (100.0, 500.0, 1500.0, 3000.0, 6000.0)
#: the seed's point (Table 5.4's efficiencies): 1500 rpm, 500 N·m, 90 °C, Rq 0.8 µm
SEED = (1500.0, 90.0, 0.8)

#: typical data-sheet values of the two VG 220 oils (not one product's)
OIL_SHEETS = (
    OilDataSheet(name="VG220_mineral", kinematic_viscosity_40=220.0,
                 kinematic_viscosity_100=19.4, density_15=890.0, base_oil="mineral",
                 source="typical ISO VG 220 mineral EP gear oil (class values)"),
    OilDataSheet(name="VG220_PAO", kinematic_viscosity_40=220.0,
                 kinematic_viscosity_100=25.0, density_15=850.0, base_oil="polyalphaolefin",
                 source="typical ISO VG 220 PAO gear oil (class values)"),
)


def iso_model(x_l: float):
    """ISO/TR 14179-2 with the base-oil factor X_L fixed (a model function)."""
    return functools.partial(iso_tr_14179_2, base_oil_factor=x_l)


def models(x_l: float, thermal: bool, fixed_summits: bool = False) -> dict:
    out = {"mixed_ehl": "mixed_ehl", "ISO": iso_model(x_l), "xu2007": "xu2007"}
    if thermal:
        out["thermal_eyring"] = "thermal_eyring"
        out["thermal_eyring_s"] = functools.partial(thermal_eyring, film_heating=0.0)
        if fixed_summits:
            out["thermal_eyring_fixed"] = functools.partial(thermal_eyring, summits="fixed")
            # Johnson, Greenwood & Poon's sharing with the ground summits (the model's
            # default before Zhou & Hoeprich's share, issue 74)
            out["thermal_eyring_jgp"] = functools.partial(
                thermal_eyring, load_sharing="johnson_greenwood_poon")
    return out


class Evaluator:
    """μ (flank, load-weighted), efficiency [%] and λ per torque, cached per condition."""

    def __init__(self, cache: Path, oils: dict[str, str], thermal: bool,
                 fixed_summits: bool = False):
        self.cache, self.oils, self.thermal = cache, oils, thermal
        self.fixed_summits = fixed_summits
        self.lt = {}
        self.memo = {}

    def ltca(self, label):
        if label not in self.lt:
            case, torques, rolls, _ = CASES[label]
            self.lt[label] = _ltca(case, torques, rolls, self.cache)
        return self.lt[label]

    def __call__(self, label, speed, temp, rq, oil="75W90") -> dict:
        key = (label, speed, temp, rq, oil)
        if key in self.memo:
            return self.memo[key]
        lt = self.ltca(label)
        x_l = BASE_OIL_FACTORS[load_lubricant(self.oils[oil]).base_oil]
        res = {}
        for name, model in models(x_l, self.thermal, self.fixed_summits).items():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", FrictionModelRangeWarning)
                fr = efficiency_analysis(lt, OperatingConditions(
                    pinion_speed=speed, temperature=temp, roughness=rq,
                    friction_model=model, lubricant=self.oils[oil]))
            res[name] = (_flank_weighted(lt, fr, "friction_coefficient"),
                         100.0 * fr["efficiency_mean"].values)
            if name == "mixed_ehl":
                res["lam"] = _flank_weighted(lt, fr, "lambda_ratio")
        self.memo[key] = res
        return res


def _names(ev: Evaluator) -> list[str]:
    return list(models(1.0, ev.thermal, ev.fixed_summits))


def roughness_temperature(ev: Evaluator, label: str) -> list[list]:
    ti = CASES[label][3]
    rows = []
    for t in TEMPERATURES:
        for rq in ROUGHNESS:
            r = ev(label, 1500.0, t, rq)
            rows.append([label, t, rq, r["lam"][ti], *(r[m][0][ti] for m in _names(ev)),
                         *(r[m][1][ti] for m in _names(ev))])
    return rows


def cost_rows(ev: Evaluator, label: str) -> list[list]:
    """Rq 0.1 → 1.3 efficiency cost [points] per model and temperature, and the ratio of
    each model's cost to ISO's."""
    ti = CASES[label][3]
    rows = []
    for t in TEMPERATURES:
        smooth, rough = ev(label, 1500.0, t, 0.1), ev(label, 1500.0, t, 1.3)
        cost = {m: smooth[m][1][ti] - rough[m][1][ti] for m in _names(ev)}
        rows.append([label, t, *(cost[m] for m in _names(ev)),
                     *(cost[m] / cost["ISO"] for m in _names(ev) if m != "ISO")])
    return rows


def hot_rows(ev: Evaluator, label: str) -> list[list]:
    """Efficiency at 100 °C minus at 50 °C [points] per roughness (negative: hotter worse)."""
    ti = CASES[label][3]
    return [[label, rq, *(ev(label, 1500.0, 100.0, rq)[m][1][ti]
                          - ev(label, 1500.0, 50.0, rq)[m][1][ti] for m in _names(ev))]
            for rq in ROUGHNESS]


def speed_rows(ev: Evaluator, label: str) -> list[list]:
    ti = CASES[label][3]
    rows = []
    for t, rq in ((50.0, 0.1), (90.0, 0.8)):
        for n in SPEEDS:
            r = ev(label, n, t, rq)
            rows.append([label, t, rq, n, r["lam"][ti], *(r[m][0][ti] for m in _names(ev))])
    return rows


def speed_trend(ev: Evaluator, label: str, t=50.0, rq=0.1) -> dict:
    """μ(6000)/μ(1500) − 1 and μ(6000)/μ(100) − 1 per model [%]."""
    ti = CASES[label][3]
    mu = {n: ev(label, n, t, rq) for n in (100.0, 1500.0, 6000.0)}
    return {m: (100 * (mu[6000.0][m][0][ti] / mu[1500.0][m][0][ti] - 1),
                100 * (mu[6000.0][m][0][ti] / mu[100.0][m][0][ti] - 1)) for m in _names(ev)}


def torque_rows(ev: Evaluator, label: str) -> list[list]:
    r = ev(label, *SEED)
    return [[label, t, r["lam"][i], *(r[m][0][i] for m in _names(ev)),
             *(r[m][1][i] for m in _names(ev))] for i, t in enumerate(CASES[label][1])]


def oil_rows(ev: Evaluator, label: str) -> list[list]:
    ti = CASES[label][3]
    rows = []
    for t in (50.0, 90.0):
        for rq in (0.1, 0.8):
            ref = ev(label, 1500.0, t, rq, "75W90")
            for oil in ev.oils:
                r = ev(label, 1500.0, t, rq, oil)
                rows.append([label, t, rq, oil, r["lam"][ti],
                             *(r[m][0][ti] for m in _names(ev)),
                             *(r[m][0][ti] / ref[m][0][ti] for m in _names(ev))])
    return rows


def criteria(ev: Evaluator, model: str = "mixed_ehl") -> list[list]:
    """Issue 74's relations for ``model``: (relation, measured, met)."""
    out = []
    have = [c for c in ("A", "B") if c in ev.lt]
    for label in have:
        ti = CASES[label][3]
        for t in (50.0, 90.0):
            s, r = ev(label, 1500.0, t, 0.1), ev(label, 1500.0, t, 1.3)
            c = s[model][1][ti] - r[model][1][ti]
            ci = s["ISO"][1][ti] - r["ISO"][1][ti]
            out.append([f"{label} {t:g} °C: Rq 0.1→1.3 cost 0.5–2 × ISO's",
                        f"{c:.2f} vs {ci:.2f} pt ({c / ci:.2f} ×)", 0.5 <= c / ci <= 2.0])
        hot = ev(label, 1500.0, 100.0, 1.3)[model][1][ti]
        cold = ev(label, 1500.0, 50.0, 1.3)[model][1][ti]
        out.append([f"{label} Rq 1.3: 100 °C not better than 50 °C",
                    f"{hot:.2f} vs {cold:.2f} %", hot <= cold])
        m6 = ev(label, 6000.0, 50.0, 0.1)[model][0][ti]
        m15 = ev(label, 1500.0, 50.0, 0.1)[model][0][ti]
        out.append([f"{label} 50 °C Rq 0.1: μ(6000 rpm) < μ(1500 rpm)",
                    f"{m6:.4f} vs {m15:.4f}", m6 < m15])
        r = ev(label, *SEED)
        ratio = r[model][0][ti] / r["ISO"][0][ti]
        out.append([f"{label} seed's point: μ / ISO in 0.7–1.4", f"{ratio:.2f}",
                    0.7 <= ratio <= 1.4])
    if len(have) == 2:
        a, b = ev("A", *SEED), ev("B", *SEED)
        d = a[model][1][1] - b[model][1][1]
        di = a["ISO"][1][1] - b["ISO"][1][1]
        out.append(["A − B in 1.0–2.0 points (seed's point)", f"{d:.2f} (ISO {di:.2f})",
                    1.0 <= d <= 2.0])
    for label in have:
        ti = CASES[label][3]
        for t in (50.0, 90.0):
            ref = ev(label, 1500.0, t, 0.8, "75W90")[model][0][ti]
            vg = ev(label, 1500.0, t, 0.8, "VG220_mineral")[model][0][ti]
            out.append([f"{label} {t:g} °C Rq 0.8: VG 220 mineral μ within ±15 % of 75W90's",
                        f"{100 * (vg / ref - 1):+.1f} %", abs(vg / ref - 1) <= 0.15])
            pao = ev(label, 1500.0, t, 0.8, "VG220_PAO")[model][0][ti]
            out.append([f"{label} {t:g} °C Rq 0.8: PAO below mineral VG 220 (X_L 0.8)",
                        f"{100 * (pao / vg - 1):+.1f} %", pao < vg])
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ltca-cache", type=Path,
                    default=Path.home() / ".cache" / "hypoid-ltca" / "benchmarks")
    ap.add_argument("--cases", default="A,B,default,spiral")
    ap.add_argument("--no-thermal", action="store_true",
                    help="leave the opt-in thermal_eyring model out (faster)")
    ap.add_argument("--fixed-summits", action="store_true",
                    help="add thermal_eyring's first version (fixed ηβσ, σ/β)")
    args = ap.parse_args(argv)
    labels = args.cases.split(",")
    with tempfile.TemporaryDirectory() as tmp:
        oils = {"75W90": "75W90"}
        for sheet in OIL_SHEETS:
            path = Path(tmp) / f"{sheet.name}.toml"
            path.write_text(dump_toml(oil_file_mapping(sheet)), encoding="utf-8")
            oils[sheet.name] = str(path)
        ev = Evaluator(args.ltca_cache, oils, not args.no_thermal, args.fixed_summits)
        for label in labels:
            ev.ltca(label)
        names = _names(ev)
        print("Oils:", ", ".join(
            f"{k} (base {load_lubricant(v).base_oil}, X_L "
            f"{BASE_OIL_FACTORS[load_lubricant(v).base_oil]:g})" for k, v in oils.items()))
        print("\n1. Roughness × temperature, 1500 rpm, 500 N·m, 75W90, run-in flanks: flank "
              "μ and efficiency [%]")
        rows = [r for lb in labels for r in roughness_temperature(ev, lb)]
        print(tabulate(rows, headers=["case", "°C", "Rq", "λ", *(f"μ {m}" for m in names),
                                      *(f"η {m}" for m in names)], floatfmt=".4g"))
        print("\n2. Rq 0.1 → 1.3 µm efficiency cost [points] and ratio to ISO's cost")
        rows = [r for lb in labels for r in cost_rows(ev, lb)]
        print(tabulate(rows, headers=["case", "°C", *names,
                                      *(f"{m}/ISO" for m in names if m != "ISO")],
                       floatfmt=".3g"))
        print("\n3. η(100 °C) − η(50 °C) [points] (negative: hotter worse), 1500 rpm, 500 N·m")
        rows = [r for lb in labels for r in hot_rows(ev, lb)]
        print(tabulate(rows, headers=["case", "Rq", *names], floatfmt="+.2f"))
        print("\n4. Speed, 500 N·m, 75W90: flank μ")
        rows = [r for lb in labels for r in speed_rows(ev, lb)]
        print(tabulate(rows, headers=["case", "°C", "Rq", "rpm", "λ", *names],
                       floatfmt=".4g"))
        for lb in labels:
            tr = speed_trend(ev, lb)
            print(f"  {lb} 50 °C Rq 0.1, μ change 1500→6000 / 100→6000 rpm: " + "; ".join(
                f"{m} {a:+.0f} / {b:+.0f} %" for m, (a, b) in tr.items()))
        print("\n5. Torque, 1500 rpm, 90 °C, Rq 0.8, 75W90: flank μ and efficiency [%]")
        rows = [r for lb in labels for r in torque_rows(ev, lb)]
        print(tabulate(rows, headers=["case", "T [N·m]", "λ", *(f"μ {m}" for m in names),
                                      *(f"η {m}" for m in names)], floatfmt=".4g"))
        print("\n6. Oils, 1500 rpm, 500 N·m: flank μ and its ratio to the 75W90's")
        rows = [r for lb in labels for r in oil_rows(ev, lb)]
        print(tabulate(rows, headers=["case", "°C", "Rq", "oil", "λ", *(f"μ {m}" for m in names),
                                      *(f"/75W90 {m}" for m in names)], floatfmt=".4g"))
        for model in [m for m in names if m not in ("ISO", "xu2007")] + ["xu2007"]:
            print(f"\nIssue 74's relations, {model}:")
            print(tabulate(criteria(ev, model), headers=["relation", "measured", "met"]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
