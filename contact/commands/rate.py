"""``ltca rate``: the load capacity rating of a case by a method of the registry
(:mod:`contact.load_capacity`; default ISO 10300 Method B1)."""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

from contact.commands.options import case_argument, output_option, torque_option

#: Place in ``ltca --help``.
ORDER = 45


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "rate",
        help="ISO 10300 Method B1 rating: contact and root stresses, permissible stresses "
        "and safety factors",
        description="Rate the case's pair by ISO 10300-1/-2/-3 Method B1 "
        "(contact.load_capacity.iso10300, docs/rating.md): the virtual cylindrical gears "
        "of its ISO 23509 blank (the case's [design] table), the load factors, the contact "
        "stress against pitting and the tooth root stress of both members, with the permissible stresses and "
        "safety factors, printed in the layout of ISO/TR 10300-30's result tables. The "
        "rating inputs (application factor, pitch deviation, mounting, oil, roughness, material "
        "quality, life, minimum safety factors) are the case's [rating] table; the "
        "bundled iso10300_30_sample1..3 are the TR's samples.",
    )
    case_argument(p, what="rate")
    torque_option(p, default="the case's [operating] torques")
    p.add_argument("--speed", type=float, default=None, metavar="RPM",
                   help="pinion speed [rpm] (default the case's [operating] pinion_speed)")
    output_option(p, default="none: the tables only",
                  what="netCDF file of the /rating dataset")
    p.set_defaults(func=run)


#: (variable, label, digits) of the rows of each table; a variable without the member
#: dimension is shown once, in the column of the pair
_GEOMETRY = (("d_v", "d_v [mm]", 3), ("z_v", "z_v", 3), ("z_vn", "z_vn", 3),
             ("d_van", "d_van [mm]", 3), ("g_va", "g_va [mm]", 3), ("eps_va", "eps_va", 3),
             ("eps_vb", "eps_vb", 3), ("eps_vg", "eps_vg", 3), ("b_veff", "b_v,eff [mm]", 3),
             ("l_bm", "l_bm [mm]", 3), ("rho_rel", "rho_rel [mm]", 3))
_PITTING = (("Z_MB", "Z_M-B", 3), ("Z_LS", "Z_LS", 3), ("Z_E", "Z_E [N^0.5/mm]", 3),
            ("Z_Hyp", "Z_Hyp", 3), ("Z_L", "Z_L", 3), ("Z_speed", "Z_v", 3), ("Z_R", "Z_R", 3),
            ("Z_NT", "Z_NT", 3), ("sigma_H0", "sigma_H0 [N/mm2]", 1),
            ("sigma_H", "sigma_H [N/mm2]", 1), ("sigma_HP", "sigma_HP [N/mm2]", 1),
            ("S_H", "S_H", 3))
_BENDING = (("Y_Fa", "Y_Fa", 3), ("Y_Sa", "Y_Sa", 3), ("Y_eps", "Y_eps", 3),
            ("Y_BS", "Y_BS", 3), ("Y_LS", "Y_LS", 3), ("Y_deltarelT", "Y_delta,relT", 3),
            ("Y_RrelT", "Y_R,relT", 3), ("Y_NT", "Y_NT", 3),
            ("sigma_F0", "sigma_F0 [N/mm2]", 1), ("sigma_F", "sigma_F [N/mm2]", 1),
            ("sigma_FP", "sigma_FP [N/mm2]", 1), ("S_F", "S_F", 3))


def _rows(ds, spec) -> list[tuple[str, str, str, str]]:
    """(label, pair, pinion, gear): a value of the pair once, a member's in its column."""
    rows = []
    for name, label, digits in spec:
        x = ds[name]
        if "member" in x.dims:
            rows.append((label, "", *(f"{float(v):.{digits}f}" for v in x.values)))
        else:
            rows.append((label, f"{float(x):.{digits}f}", "", ""))
    return rows


def tables(ds) -> str:
    """The rating as text: the virtual gears, then per torque the load factors and the
    pitting and bending tables (the layout of ISO/TR 10300-30's result tables)."""
    from tabulate import tabulate

    head = ("", "pair", "pinion", "gear")
    deg = 180.0 / math.pi
    out = [f"ISO 10300 Method B1: {ds.attrs.get('case', '')} ({ds.attrs['side']} side), "
           f"n1 {float(ds['pinion_speed']):g} rpm, K_A {float(ds['K_A']):.3f}, "
           f"beta_v {float(ds['beta_v']) * deg:.3f} deg, alpha_vet "
           f"{float(ds['alpha_vet']) * deg:.3f} deg",
           "",
           "virtual cylindrical gears (ISO 10300-1 Annex A)",
           tabulate(_rows(ds, _GEOMETRY), headers=head, tablefmt="simple",
                    disable_numparse=True)]
    for t in ds["torque"].values:
        one = ds.sel(torque=t)
        out += ["", f"T1 = {t:g} N m: F_mt1 {float(one['F_mt1']):.1f} N, F_vmt "
                    f"{float(one['F_vmt']):.1f} N, F_n {float(one['F_n']):.1f} N",
                "load factors: " + "  ".join(
                    f"{label} {float(one[name]):.3f}" for name, label in (
                        ("K_v", "K_v"), ("K_Hbeta", "K_Hbeta"), ("K_Fbeta", "K_Fbeta"),
                        ("K_Halpha", "K_Halpha"), ("K_Falpha", "K_Falpha"))),
                "", "pitting (ISO 10300-2)",
                tabulate(_rows(one, _PITTING), headers=head, tablefmt="simple",
                         disable_numparse=True),
                "", "tooth root (ISO 10300-3)",
                tabulate(_rows(one, _BENDING), headers=head, tablefmt="simple",
                         disable_numparse=True)]
        for s, smin, what in (("S_H", "S_Hmin", "pitting"), ("S_F", "S_Fmin", "bending")):
            low = [m for m, v in zip(ds["member"].values, one[s].values, strict=True)
                   if v < float(ds[smin])]
            if low:
                out.append(f"{what}: {s} below {s},min {float(ds[smin]):g} for the "
                           f"{' and the '.join(low)}")
    return "\n".join(out)


def run(args: argparse.Namespace) -> int:
    import xarray as xr

    from contact.catalogue import resolve_case
    from contact.commands.output_paths import check_output_file
    from contact.load_capacity.iso10300 import iso10300_rating
    from geometry.core.io import write_netcdf

    if args.output:
        check_output_file(args.output)
    case = resolve_case(args.case)
    ds = iso10300_rating(case, args.torque, args.speed)
    print(tables(ds))
    rz = json.loads(ds.attrs["rating_inputs"])["flank_roughness"]
    if "flank_roughness" not in (case.extra.get("rating") or {}):
        print(f"flank roughness Rz {rz[0]:g} / {rz[1]:g} um: the case's [operating] roughness "
              f"Rq {case.operating.roughness:g} um (the flanks the analysis runs) as Rz = 6 "
              "Ra = 6 sqrt(2/pi) Rq (docs/rating.md)")
    if args.output:
        tree = xr.DataTree.from_dict({
            "/": xr.Dataset(attrs={"case": case.name,
                                   "title": "ISO 10300 Method B1 load capacity rating"}),
            "/rating": ds})
        path = write_netcdf(tree, Path(args.output), inputs=case.to_toml())
        print(f"wrote {path}")
    return 0
