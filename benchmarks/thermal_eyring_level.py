"""Where ``thermal_eyring``'s flank μ on the default case stands against ISO/TR 14179-2.

Issue 74's step "map the 100 °C / 50 N·m level miss": on the default case
(``kolivand2009_fm_11x41_reference``, 50 / 250 / 500 N·m, 1500 rpm, 75W90, Rq 0.8 µm
run-in) prints, per oil temperature and torque, the flank load-weighted (edge contacts
apart) smooth-surface central λ, Zhou & Hoeprich's asperity share, μ's asperity part
μ_b N_a/N and film part, ISO/TR 14179-2's μ on the same segments and the ratio; then, at
``--temperature`` and the lightest torque, the same split by λ band (which segments carry
the excess), and what each candidate cause would move: the film's shear removed (its
flash temperature and thermal Eyring law act only there), the inlet's thermal reduction
removed (φ_T = 1, the film and λ as isothermal), Zhou & Hoeprich's other published set
(the raceway's), and the μ_b that would put the level at 1.4 × ISO's.

Usage::

    python benchmarks/thermal_eyring_level.py [--ltca-cache DIR] [--temperature 100]
"""

from __future__ import annotations

import argparse
import itertools
import sys
import warnings
from pathlib import Path

import numpy as np
from tabulate import tabulate

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(1, str(Path(__file__).resolve().parents[1]))

from friction_anchors import _ltca

import friction.efficiency as eff_mod
from friction.coefficient import FrictionModelRangeWarning, friction_coefficient
from friction.efficiency import efficiency_analysis, loaded_segments
from friction.operating import OperatingConditions
from friction.thermal_eyring import _model_sharing, thermal_eyring

CASE, TORQUES = "kolivand2009_fm_11x41_reference", (50.0, 250.0, 500.0)
TEMPERATURES = (50.0, 75.0, 90.0, 100.0)
_SHARING = ("load_per_length", "hertz_pressure", "radius", "e_prime", "entraining_velocity",
            "sliding_velocity", "viscosity", "pressure_viscosity", "roughness_1",
            "roughness_2", "thermal_factor")


def efficiency_inputs(lt, op: OperatingConditions) -> tuple[dict, object]:
    """The inputs the efficiency stage gives ``op``'s friction model (1-D over the loaded
    segments, caught at its call of ``friction_coefficient``) and the stage's /friction
    Dataset; the model's range warnings silenced."""
    seen: dict = {}
    original = eff_mod.friction_coefficient

    def spy(name, **inputs):
        seen.update(inputs)
        return original(name, **inputs)

    eff_mod.friction_coefficient = spy
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FrictionModelRangeWarning)
            fr = efficiency_analysis(lt, op)
    finally:
        eff_mod.friction_coefficient = original
    return seen, fr


def _inputs(lt, temperature: float, model: str = "thermal_eyring") -> dict:
    """The inputs the efficiency stage gives ``model`` (1-D over the loaded segments)."""
    return efficiency_inputs(lt, OperatingConditions(temperature=temperature,
                                                     friction_model=model))[0]


def split(lt, temperature: float) -> dict:
    """Per loaded segment: λ_s, share, asperity and film parts of μ, ISO's μ, weights."""
    seg = loaded_segments(lt)
    inp = _inputs(lt, temperature)
    kw = {k: inp[k] for k in _SHARING}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        sol = _model_sharing(load_sharing="zhou_hoeprich", asperity_load_constants="rib",
                             summits="ground", eyring_stress=inp.get("eyring_stress", 5.0),
                             limiting_shear_coefficient=inp.get(
                                 "limiting_shear_coefficient", 0.08),
                             boundary_friction=inp["boundary_friction"],
                             asperity_density_radius_sigma=0.05, sigma_over_beta=0.01, **kw)
        extra = {k: inp[k] for k in ("temperature_viscosity", "oil_thermal_conductivity",
                                     "pressure_viscosity_temperature", "eyring_stress",
                                     "limiting_shear_coefficient", "boundary_friction")
                 if k in inp}
        mu = np.asarray(thermal_eyring(**kw, **extra), float)
        iso = np.asarray(friction_coefficient(
            "iso_tr_14179_2", load_per_length=inp["load_per_length"],
            entraining_velocity=inp["entraining_velocity"], radius=inp["radius"],
            viscosity=inp["viscosity"], roughness_1=inp["roughness_1"],
            roughness_2=inp["roughness_2"]), float)
    sigma = np.hypot(inp["roughness_1"], inp["roughness_2"])
    torque = np.nonzero(seg.loaded)[0]
    weight = np.where(seg.edge, 0.0, seg.force)
    return {"lam": sol.smooth_film_thickness / sigma, "share": sol.asperity_load_share,
            "mu_b": sol.boundary_friction, "film": mu - sol.boundary_friction, "mu": mu,
            "iso": iso, "w": weight, "torque": torque, "inputs": inp}


def _mean(d: dict, key: str, mask: np.ndarray) -> float:
    return float(np.sum(d[key][mask] * d["w"][mask]) / np.sum(d["w"][mask]))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ltca-cache", type=Path,
                    default=Path.home() / ".cache" / "hypoid-ltca" / "benchmarks")
    ap.add_argument("--temperature", type=float, default=100.0)
    args = ap.parse_args(argv)
    lt = _ltca(CASE, TORQUES, None, args.ltca_cache)
    rows, keep = [], {}
    for t in TEMPERATURES:
        d = split(lt, t)
        keep[t] = d
        for i, tq in enumerate(TORQUES):
            m = d["torque"] == i
            mu, iso = _mean(d, "mu", m), _mean(d, "iso", m)
            rows.append([t, tq, f"{_mean(d, 'lam', m):.3f}", f"{_mean(d, 'share', m):.3f}",
                         f"{_mean(d, 'mu_b', m):.4f}", f"{_mean(d, 'film', m):.4f}",
                         f"{mu:.4f}", f"{iso:.4f}", f"{mu / iso:.2f}",
                         f"{1e3 * float(d['inputs']['viscosity']):.2f}",
                         f"{float(d['inputs']['boundary_friction']):.3f}"])
    print("thermal_eyring (Zhou & Hoeprich, rib) on the default case, 1500 rpm, Rq 0.8 run-in;"
          " flank load-weighted")
    print(tabulate(rows, headers=["°C", "N·m", "λ_s", "share", "μ_b part", "film part", "μ",
                                  "ISO μ", "μ/ISO", "η₀ mPa s", "μ_b"]))
    d = keep[args.temperature]
    m0 = d["torque"] == 0
    edges = np.array([0.0, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0, np.inf])
    rows = []
    total = np.sum(d["w"][m0])
    for lo, hi in itertools.pairwise(edges):
        m = m0 & (d["lam"] >= lo) & (d["lam"] < hi) & (d["w"] > 0)
        if not np.any(m):
            continue
        frac = np.sum(d["w"][m]) / total
        ex = np.sum(((d["mu"] - 1.4 * d["iso"]) * d["w"])[m]) / total
        rows.append([f"{lo:g}–{hi:g}", f"{frac:.3f}", f"{_mean(d, 'share', m):.3f}",
                     f"{_mean(d, 'mu_b', m):.4f}", f"{_mean(d, 'film', m):.4f}",
                     f"{_mean(d, 'mu', m) / _mean(d, 'iso', m):.2f}", f"{ex:+.4f}",
                     f"{np.mean(d['inputs']['hertz_pressure'][m]):.0f}"])
    print(f"\n{args.temperature:g} °C, {TORQUES[0]:g} N·m by smooth λ band (load fraction; μ "
          "above 1.4 × ISO's, load-weighted, adds to the flank mean)")
    print(tabulate(rows, headers=["λ_s", "load", "share", "μ_b part", "film part", "μ/ISO",
                                  "excess over 1.4×", "p_h MPa"]))
    inp = d["inputs"]
    iso = _mean(d, "iso", m0)
    lam_iso = d["lam"] / np.asarray(inp["thermal_factor"])
    alt = {
        "as computed": d["mu"],
        "film part removed (μ_b N_a/N alone)": d["mu_b"],
        "φ_T = 1 (share at the isothermal λ; film part kept)":
            inp["boundary_friction"] * np.exp(-1.90 * lam_iso**0.99) + d["film"],
        "raceway constants B 2.32, C 0.97 (film part kept)":
            inp["boundary_friction"] * np.exp(-2.32 * d["lam"]**0.97) + d["film"],
    }
    rows = [[k, f"{np.sum(v[m0] * d['w'][m0]) / np.sum(d['w'][m0]) / iso:.2f}"]
            for k, v in alt.items()]
    need = (1.4 * iso - _mean(d, "film", m0)) / _mean(d, "share", m0)
    rows.append(["μ_b for 1.4 × ISO (share as computed)", f"μ_b = {need:.3f}"])
    print(f"\n{args.temperature:g} °C, {TORQUES[0]:g} N·m: μ / ISO under each candidate")
    print(tabulate(rows, headers=["", "μ / ISO"]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
