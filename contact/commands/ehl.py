"""``ltca ehl``: solve one mixed-EHL line contact (friction.ehl) and write its dataset."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from contact.commands.output_paths import check_output_file

#: Place in ``ltca --help``.
ORDER = 60


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "ehl",
        help="solve one mixed-EHL line contact: pressure, film, asperity load, "
        "friction coefficient",
        description="One line contact of two surfaces under the Hertz pressure, radius, "
        "entraining velocity, slide-to-roll ratio and oil temperature given, solved by the "
        "unified Reynolds equation with elastic deflection (friction.ehl, docs/ehl.md). "
        "Roughness 0 0 is the smooth case, solved steady. Rough surfaces get reproducible "
        "measured-like ground profiles (seeds 1 and 2) scaled to the Rq given and move "
        "through the contact with their own speeds: the transient solution (the seed's "
        "model), whose scalars are time means (--steady freezes the roughness instead). "
        "Writes a netCDF of the profiles and the scalars (film_central, film_min, "
        "asperity_load_ratio, friction_coefficient) and prints one summary line.",
    )
    p.add_argument("--pressure", type=float, required=True, metavar="GPA",
                   help="Hertz maximum pressure p_h [GPa]")
    p.add_argument("--radius", type=float, required=True, metavar="MM",
                   help="equivalent radius of curvature R [mm]")
    p.add_argument("--speed", type=float, required=True, metavar="M/S",
                   help="entraining velocity (u1 + u2)/2 [m/s]")
    p.add_argument("--slide-to-roll", type=float, default=0.3, metavar="SR",
                   help="slide-to-roll ratio (u1 - u2)/u_e (default %(default)s)")
    p.add_argument("--temperature", type=float, default=90.0, metavar="DEGC",
                   help="oil inlet temperature [degC] (default %(default)s)")
    p.add_argument("--roughness", type=float, nargs=2, default=(0.0, 0.0),
                   metavar=("RQ1", "RQ2"), help="Rq of the two surfaces [um] (default 0 0)")
    p.add_argument("--lubricant", default="75W90", metavar="NAME",
                   help="bundled oil name or oil TOML file (default %(default)s)")
    p.add_argument("--nodes", type=int, default=None,
                   help="grid nodes (default 1024 over -4 ... 1.5 Hertz half-widths for a "
                   "steady run; 256 from the smooth film's pressure onset to 1.5 for a "
                   "transient one)")
    p.add_argument("--steady", action="store_true",
                   help="rough surfaces: solve with the roughness frozen (steady) instead of "
                   "moving (often no solution below lambda ~1.4, docs/ehl.md)")
    p.add_argument("--courant", type=float, default=1.0, metavar="C",
                   help="transient: node spacings the faster surface moves per time step "
                   "(default %(default)s)")
    p.add_argument("-o", "--output", default="ehl.nc", metavar="FILE",
                   help="netCDF file to write (default %(default)s)")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from friction.ehl.line_contact import (
        STEEL_E_PRIME,
        Grid,
        LineContactCondition,
        hertz_line_contact,
        solve_line_contact,
    )
    from friction.ehl.roughness import GroundSurface, ground_profile
    from friction.ehl.transient import (
        TimeGrid,
        default_transient_grid,
        solve_transient_line_contact,
    )
    from geometry.core.errors import InputError
    from geometry.core.io import write_netcdf

    check_output_file(args.output)
    if not args.pressure > 0.0 or not math.isfinite(args.pressure):
        raise InputError(f"--pressure: must be > 0 GPa, got {args.pressure}")
    if not args.radius > 0.0 or not math.isfinite(args.radius):
        raise InputError(f"--radius: must be > 0 mm, got {args.radius}")
    ph = args.pressure * 1e3                                  # [MPa]
    load = 2.0 * math.pi * args.radius * ph**2 / STEEL_E_PRIME  # w′ = π b p_h/2 [N/mm]
    rq1, rq2 = args.roughness
    for name, rq in (("--roughness RQ1", rq1), ("--roughness RQ2", rq2)):
        if not 0.0 <= rq <= 50.0:
            raise InputError(f"--roughness: {name.split()[-1]} must be in [0, 50] um, got {rq}")
    if args.nodes is not None and not 16 <= args.nodes <= 16384:
        raise InputError(f"--nodes: must be in [16, 16384], got {args.nodes}")
    rough = rq1 > 0.0 or rq2 > 0.0
    fields = dict(load_per_length=load, radius=args.radius, entraining_velocity=args.speed,
                  slide_to_roll=args.slide_to_roll, temperature=args.temperature,
                  lubricant=args.lubricant)
    if rough and not args.steady:
        cond = LineContactCondition(**fields)
        grid = default_transient_grid(cond, args.nodes or 256)
        ds = solve_transient_line_contact(
            cond, (GroundSurface(rq1, seed=1), GroundSurface(rq2, seed=2)), grid,
            TimeGrid(courant=args.courant))
    else:
        grid = Grid(nodes=args.nodes or 1024, step_limit=3.0 if rough else 0.3)
        grid.check()
        b, _ = hertz_line_contact(load, args.radius, STEEL_E_PRIME)
        x = grid.coordinates() * b
        cond = LineContactCondition(
            **fields,
            roughness_1=ground_profile(x, rq1, seed=1) if rq1 > 0 else None,
            roughness_2=ground_profile(x, rq2, seed=2) if rq2 > 0 else None,
        )
        ds = solve_line_contact(cond, grid)
    inputs = " ".join(f"{k}={v}" for k, v in sorted(vars(args).items()) if k != "func")
    path = write_netcdf(ds, Path(args.output), inputs=inputs)
    kind = "time means, " if "time" in ds.dims else ""
    print(f"p_h {args.pressure:g} GPa, w' {load:.1f} N/mm: {kind}h_c "
          f"{float(ds.film_central):.4f} um, h_min {float(ds.film_min):.4f} um, asperity load "
          f"{float(ds.asperity_load_ratio):.3f}, mu {float(ds.friction_coefficient):.4f} "
          f"-> {path}")
    return 0
