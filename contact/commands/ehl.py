"""``ltca ehl``: solve one mixed-EHL line contact (friction.ehl) and write its dataset."""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from contact.commands.options import count, film_model_options
from contact.commands.output_paths import check_output_file
from geometry.core.bounds import PHYSICAL_BOUNDS

#: Place in ``ltca --help``.
ORDER = 60


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "ehl",
        help="solve one mixed-EHL line contact: pressure, film, asperity load, "
        "friction coefficient",
        description="One line contact of two surfaces under the Hertz pressure, radius, "
        "entraining velocity, slide-to-roll ratio and oil temperature given (friction.ehl, "
        "docs/ehl.md). Roughness 0 0 is the smooth film, solved steady on the grid its "
        "Moes load parameter asks. Rough surfaces are reproducible measured-like ground "
        "profiles (seeds 1 and 2) scaled to the Rq given; by default their asperity scale "
        "is described by its statistics (the stochastic model: average-flow Reynolds "
        "equation, elastic-plastic summits, the film's shear at the surfaces' flash "
        "temperature), which carries the contact from full film to dry. (The resolved "
        "transient model of the seed's Li & Kahraman form is no longer offered here: its "
        "asperities never carried the load in the mixed regime and its asperity share did "
        "not converge with the grid; docs/ehl.md.) Writes a netCDF of the profiles and the "
        "scalars (film_central, film_min, asperity_load_ratio, friction_coefficient) and "
        "prints one summary line.",
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
    film_model_options(p)
    p.add_argument("--nodes", type=count(16, 16384), default=None,
                   help="grid nodes (default: smooth, from Moes's M; rough, 512 over the "
                   "rough contact's spread)")
    p.add_argument("-o", "--output", default="ehl.nc", metavar="FILE",
                   help="netCDF file to write (default %(default)s)")
    p.set_defaults(func=run)


#: [um] the largest RMS roughness of one surface (a rough-turned flank; ground and lapped
#: flanks are 0.1-1 um): the table of physical bounds' (geometry.core.bounds)
MAX_ROUGHNESS = PHYSICAL_BOUNDS["roughness"].high


def check_inputs(args: argparse.Namespace) -> None:
    """Refuse, before any work, an input outside what the line-contact solvers are valid
    for, in one line naming the option, the value and the accepted range — the table of
    physical bounds (:data:`geometry.core.bounds.PHYSICAL_BOUNDS`): the Hertz pressure
    [0.01, 6] GPa (below 10 MPa no gear contact carries load, and the solvers ran tens of
    seconds to a Newton failure there), the radius [0.01, 5000] mm, the entraining
    velocity (0, 100] m/s, the slide-to-roll ratio [-2, 2] (both surfaces moving the oil
    in), the roughness [0, 5] um —, the oil (a bundled name or a valid oil file) and the
    temperature inside its data's range, and the grid's nodes."""
    from friction.ehl.line_contact import lubricant_of
    from friction.lubricant import temperature_range
    from geometry.core.bounds import check_bound
    from geometry.core.errors import InputError
    from geometry.core.validation import integer, real

    check_bound("hertz_pressure", args.pressure, field="--pressure", scale=1e3, unit="GPa")
    check_bound("radius", args.radius, field="--radius")
    check_bound("entraining_velocity", args.speed, field="--speed")
    check_bound("slide_to_roll", args.slide_to_roll, field="--slide-to-roll")
    try:
        oil = lubricant_of(args.lubricant)
    except InputError as exc:
        raise InputError(f"--lubricant: {str(exc).removeprefix('lubricant: ')}") from None
    lo, hi = temperature_range(oil)
    real("--temperature", args.temperature, unit="degC", low=lo, high=hi)
    for label, rq in zip(("RQ1", "RQ2"), args.roughness, strict=True):
        check_bound("roughness", rq, field=f"--roughness {label}")
    if args.nodes is not None:
        integer("--nodes", args.nodes, low=16, high=16384)


def run(args: argparse.Namespace) -> int:
    from threadpoolctl import threadpool_limits

    from friction.ehl.line_contact import (
        STEEL_E_PRIME,
        Grid,
        LineContactCondition,
        solve_line_contact,
    )
    from friction.ehl.roughness import GroundSurface
    from friction.ehl.stochastic import (
        StochasticOptions,
        roughness_statistics,
        solve_stochastic_line_contact,
        stochastic_grid,
    )
    from geometry.core.io import write_netcdf

    check_output_file(args.output)
    check_inputs(args)
    ph = args.pressure * 1e3                                  # [MPa]
    load = 2.0 * math.pi * args.radius * ph**2 / STEEL_E_PRIME  # w′ = π b p_h/2 [N/mm]
    rq1, rq2 = args.roughness
    rough = rq1 > 0.0 or rq2 > 0.0
    fields = dict(load_per_length=load, radius=args.radius, entraining_velocity=args.speed,
                  slide_to_roll=args.slide_to_roll, temperature=args.temperature,
                  lubricant=args.lubricant, viscosity_model=args.viscosity_model)
    surfaces = (GroundSurface(rq1, seed=1), GroundSurface(rq2, seed=2))
    # one BLAS thread: the dense Newton systems of ≤ 1 k unknowns gain nothing from more,
    # and on a busy 2-core machine the default threads cost ~8x the CPU (issue 51)
    with threadpool_limits(limits=1):
        if not rough:
            cond = LineContactCondition(**fields)
            grid = None if args.nodes is None else Grid(nodes=args.nodes)
            ds = solve_line_contact(cond, grid, thermal=not args.isothermal)
        else:
            cond = LineContactCondition(**fields)
            grid = None if args.nodes is None else stochastic_grid(
                cond, roughness_statistics(surfaces), args.nodes)
            ds = solve_stochastic_line_contact(
                cond, surfaces, grid, StochasticOptions(thermal=not args.isothermal))
    inputs = " ".join(f"{k}={v}" for k, v in sorted(vars(args).items()) if k != "func")
    path = write_netcdf(ds, Path(args.output), inputs=inputs)
    lam = float(ds.lambda_ratio)
    lam_text = f"lambda {lam:.3g}, " if lam > 0.0 else ""
    print(f"p_h {args.pressure:g} GPa, w' {load:.1f} N/mm: {lam_text}{film_text(ds)}, "
          f"asperity load "
          f"{float(ds.asperity_load_ratio):.3f}, mu {float(ds.friction_coefficient):.4f} "
          f"(film {float(ds.fluid_friction):.4f}, boundary "
          f"{float(ds.boundary_friction_part):.4f}) -> {path}")
    return 0


def film_text(ds) -> str:
    """The film part of ``ltca ehl``'s summary line: ``h_c … um, h_min … um`` where the
    surfaces are separated, and where the mean planes of rough surfaces interpenetrate
    (the asperities interlock: no film separates them, the stochastic model's
    ``film_central``/``film_min`` are negative) the *separation* of the mean planes, named
    as such, with the mean gap the oil fills (``mean_gap_central``, ≥ 0): a film thickness
    is never printed negative (issue 64).

    Parameters
    ----------
    ds : xarray.Dataset
        The line contact's dataset (``film_central``, ``film_min`` [µm]; rough:
        ``mean_gap_central`` [µm]).

    Returns
    -------
    str
    """
    hc, hmin = float(ds.film_central), float(ds.film_min)
    if hmin >= 0.0:
        return f"h_c {hc:.4f} um, h_min {hmin:.4f} um"
    gap = (f", mean gap (oil) {float(ds.mean_gap_central):.4f} um at x = 0"
           if "mean_gap_central" in ds else "")
    return (f"no film: the mean planes interpenetrate (asperities in contact), separation "
            f"of the mean planes {hc:.4f} um at x = 0, least {hmin:.4f} um{gap}")
