"""Efficiency, friction, root stress and flank pressure of analysis files beside their anchors.

Reads analysis files written by ``ltca run CASE --torque T1 T2 T3 [--flank coast] -o FILE``
(a design at 15 / 50 / 100 % of its design torque, say) and prints per file and torque the
quantities users read, each beside a measurement-based or closed-form anchor
(docs/validation.md, "The outputs users trust over the range of designs"):

* η, ``/friction/efficiency_mean``, and η_ISO, the same LTCA's efficiency with ISO/TR
  14179-2's μ (Schlenk's FZG correlation, ``friction_model="iso_tr_14179_2"``);
* μ, the flank (curve-segment) load-weighted friction coefficient, its ratio to ISO/TR
  14179-2's μ on the same segments, and the flank load-weighted λ;
* the H_V ratio: the LTCA's kinematic loss factor Σ F·|V_s| / (T₁ ω₁) (flank segments, mean
  over the rolls) over Ohlendorf's H_V = π(u+1)/(z₁ u cos β_b)·(1 − ε_α + ε₁² + ε₂²) of the
  ISO 10300 virtual cylindrical gears of ``/rating`` (ISO/TR 14179-2; no lengthwise sliding,
  so 1 for a spiral bevel, above 1 for a hypoid);
* the share of the force on edge segments;
* p/σ_H, ``pressure_max_flank`` over ISO 10300-2's σ_H; FE/σ_F, ``root_stress_max`` over
  ISO 10300-3's σ_F, pinion / gear;
* L/2a_H, the median over the rolls of the loaded contact-line length of the most loaded pair
  over the major axis of the Hertz ellipse of its flank force (Hamrock & Brewe, ASME J. Lubr.
  Technol. 105 (1983) 171): R_x its force-weighted equivalent radius, R_y the relative radius
  along the contact curve fitted (vertex at the touching point, the longer side within 10 µm)
  to the unloaded separation of ``/utca``, E/(1 − ν²) from the LTCA's own line contacts.

Usage::

    python benchmarks/design_range_survey.py RUN.nc [RUN.nc ...]

Each file takes a few seconds (the efficiency stage once more with ISO's μ).
"""

from __future__ import annotations

import argparse
import warnings

import numpy as np
import xarray as xr
from tabulate import tabulate

from friction.coefficient import FrictionModelRangeWarning
from friction.efficiency import efficiency_analysis
from friction.operating import OperatingConditions

SWEEP = ("roll", "pair", "segment")


def flank_weighted(lt: xr.Dataset, q: xr.DataArray) -> np.ndarray:
    """Load-weighted mean of ``q`` over the loaded flank (curve) segments, per torque."""
    f = lt["force"].fillna(0.0).where(lt["segment_kind"] == "curve", 0.0)
    return ((q.fillna(0.0) * f).sum(SWEEP) / f.sum(SWEEP)).values


def hertz_ellipse(force, rx, ry, e_prime):
    """Semi-axes a_x (across), a_y (along) [mm] and p₀ [MPa] of a Hertz point contact.

    Hamrock & Brewe (1983): k = α^(2/π), ℰ = 1 + (π/2 − 1)/α, α = R_y/R_x; E' = E/(1 − ν²)
    of equal materials."""
    alpha = ry / rx
    k = alpha ** (2 / np.pi)
    ell = 1 + (np.pi / 2 - 1) / alpha
    r = 1 / (1 / rx + 1 / ry)
    ay = (6 * k**2 * ell * force * r / (np.pi * e_prime)) ** (1 / 3)
    ax = (6 * ell * force * r / (np.pi * k * e_prime)) ** (1 / 3)
    return ax, ay, 3 * force / (2 * np.pi * ax * ay)


def along_radius(ut: xr.Dataset) -> float:
    """Median relative radius [mm] along the unloaded contact curves of the active pairs."""
    sep = ut["separation"].values * 1e-3
    pos = ut["curve_position"].values
    radii = []
    for r, p in zip(*np.nonzero(ut["active"].values == 1), strict=True):
        s, x = sep[r, p], pos[r, p]
        ok = np.isfinite(s) & np.all(np.isfinite(x), axis=-1)
        if ok.sum() < 7:
            continue
        s, x = s[ok], x[ok]
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(x, axis=0), axis=1))])
        i0 = int(np.argmin(s))
        d, xi = s - s[i0], arc - arc[i0]
        sides = [side & (d < 0.010) for side in (xi < 0, xi > 0)]
        best = max(sides, key=np.count_nonzero)
        if np.count_nonzero(best) < 4:
            continue
        c = np.sum(xi[best] ** 2 * d[best]) / np.sum(xi[best] ** 4)
        if c > 0:
            radii.append(1 / (2 * c))
    return float(np.median(radii)) if radii else float("nan")


def loss_factor(rt: xr.Dataset) -> float:
    """Ohlendorf's H_V of the virtual cylindrical gears (ISO/TR 14179-2)."""
    zv, u = rt["z_v"].values, float(rt["u_v"])
    at, pet = float(rt["alpha_vet"]), float(rt["p_vet"])
    tip = [(np.sqrt((rt["d_va"].values[i] / 2) ** 2 - (rt["d_vb"].values[i] / 2) ** 2)
            - rt["d_v"].values[i] / 2 * np.sin(at)) / pet for i in range(2)]
    return float(np.pi * (u + 1) / (zv[0] * u * np.cos(float(rt["beta_vb"])))
                 * (1 - float(rt["eps_va"]) + tip[0] ** 2 + tip[1] ** 2))


def file_rows(path: str) -> list[list]:
    """One row per torque of an analysis file."""
    lt = xr.open_dataset(path, group="ltca").load()
    fr = xr.open_dataset(path, group="friction").load()
    rt = xr.open_dataset(path, group="rating").load()
    ut = xr.open_dataset(path, group="utca").load()
    a = fr.attrs
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FrictionModelRangeWarning)
        iso = efficiency_analysis(lt, OperatingConditions(
            pinion_speed=float(a["pinion_speed_rpm"]), lubricant=a["lubricant"],
            temperature=float(a["inlet_temperature_degC"]),
            roughness=float(a["roughness_rq_um"]), friction_model="iso_tr_14179_2",
            surface_state=a["surface_state"]))
    mu = flank_weighted(lt, fr["friction_coefficient"])
    mu_iso = flank_weighted(lt, iso["friction_coefficient"])
    lam = flank_weighted(lt, fr["lambda_ratio"])
    curve = lt["segment_kind"] == "curve"
    force = lt["force"].fillna(0.0)
    omega = float(a["pinion_speed_rpm"]) * np.pi / 30
    kin = ((force * abs(fr["sliding_velocity"]).fillna(0.0)).where(curve, 0.0)
           .sum(("pair", "segment")).mean("roll") / (lt["torque"] * omega)).values
    edge = (force.where(~curve, 0.0).sum(SWEEP) / force.sum(SWEEP)).values
    hv = loss_factor(rt)
    loaded = (lt["force"] > 0) & (lt["load_per_length"] > 0)
    e_prime = float(np.nanmedian((2 * np.pi * lt["equivalent_radius"] * lt["pressure_max"] ** 2
                                  / lt["load_per_length"]).where(loaded).values))
    ry = along_radius(ut)
    rows = []
    t_max = float(lt["torque"].max())
    for i, t in enumerate(lt["torque"].values):
        fc = force.isel(torque=i).where(curve, 0.0)
        pair_force = fc.sum("segment")
        top = pair_force.argmax("pair")
        rx = ((lt["equivalent_radius"] * fc).sum("segment")
              / pair_force.where(pair_force > 0)).isel(pair=top)
        length = lt["segment_length"].where((fc > 0) & curve, 0.0).sum("segment").isel(pair=top)
        _, ay, _ = hertz_ellipse(pair_force.max("pair").values, rx.values, ry, e_prime)
        fe, sf = lt["root_stress_max"].values[i], rt["sigma_F"].values[i]
        rows.append([path, f"{t:g} ({100 * t / t_max:.0f} %)",
                     fr["efficiency_mean"].values[i] * 100, iso["efficiency_mean"].values[i] * 100,
                     mu[i], mu[i] / mu_iso[i], lam[i], kin[i] / hv, edge[i],
                     lt["pressure_max_flank"].values[i] / rt["sigma_H"].values[i],
                     f"{fe[0] / sf[0]:.2f} / {fe[1] / sf[1]:.2f}",
                     float(np.nanmedian(length.values / (2 * ay)))])
    return rows


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("files", nargs="+", help="analysis files of `ltca run`")
    args = p.parse_args(argv)
    rows = [row for path in args.files for row in file_rows(path)]
    print(tabulate(rows, headers=["file", "T1 [N m] (% of largest)", "eta [%]", "eta_ISO [%]",
                                  "mu", "mu/mu_ISO", "lambda", "H_V ratio", "edge",
                                  "p/sigma_H", "FE/sigma_F", "L/2a_H"],
                   floatfmt=("", "", ".2f", ".2f", ".3f", ".2f", ".2f", ".2f", ".2f", ".2f", "",
                             ".2f")))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
