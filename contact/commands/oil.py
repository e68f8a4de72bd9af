"""``ltca oil``: an oil file from the values of a gear oil's data sheet."""

from __future__ import annotations

import argparse

#: Place in ``ltca --help``.
ORDER = 63


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection (no numerical library
    imported: the base stock is checked by :class:`friction.oil_data_sheet.OilDataSheet`,
    which names the accepted ones)."""
    p = sub.add_parser(
        "oil",
        help="write an oil file from a data sheet's nu40, nu100, rho15 and base stock",
        description="Builds the oil file every command takes as --lubricant (or a case's "
        "[operating] lubricant) from the values of the oil's data sheet: the viscosity "
        "by ASTM D341 through nu40 and nu100, the density and the pressure-viscosity "
        "coefficient by ISO/TR 15144-1 (mineral, polyalphaolefin, polyglycol; another base "
        "stock needs --alpha38). docs/oils.md says what each value does. --list prints "
        "the bundled oils instead (the seed's 75W90 and the library's ISO VG grades), "
        "each usable by name as --lubricant or a case's [operating] lubricant.",
    )
    p.add_argument("--list", action="store_true",
                   help="list the bundled oils (name, base stock, nu40, nu100, VI, rho15, "
                   "eta and alpha at 40 and 100 degC) and exit")
    p.add_argument("--name", help="the oil's name (results record it)")
    p.add_argument("--nu40", type=float, metavar="MM2/S",
                   help="kinematic viscosity at 40 degC [mm2/s]")
    p.add_argument("--nu100", type=float, metavar="MM2/S",
                   help="kinematic viscosity at 100 degC [mm2/s]")
    p.add_argument("--rho15", type=float, metavar="KG/M3",
                   help="density at 15 degC [kg/m3] (a sheet's g/ml x 1000)")
    p.add_argument("--base-oil",
                   help="the base stock: mineral, polyalphaolefin, "
                   "polyglycol_non_water_soluble, polyglycol_water_soluble, phosphate_ester "
                   "or traction_fluid (the last two need --alpha38)")
    p.add_argument("--source", help="the data sheet (maker, product, edition)")
    p.add_argument("--alpha38", type=float, default=None, metavar="1/GPA",
                   help="measured pressure-viscosity coefficient at 38 degC [1/GPa] "
                   "(default: ISO/TR 15144-1's of the base stock)")
    p.add_argument("--fzg-stage", type=float, default=None,
                   help="FZG A/8.3/90 failure load stage (scuffing safety)")
    p.add_argument("--boundary-friction", default=None, metavar="MU_B",
                   help="boundary friction coefficient measured on the oil: one number, or "
                   "values measured at several oil temperatures as DEGC:MU_B pairs by "
                   "commas (e.g. 40:0.11,100:0.09; with --boundary-friction-source), "
                   "interpolated linearly in temperature (default the assumed 0.1)")
    p.add_argument("--boundary-friction-source", default=None, metavar="TEXT",
                   help="where the measured boundary friction table comes from (rig, load, "
                   "speed, slide-to-roll ratio, materials); required with DEGC:MU_B pairs")
    p.add_argument("--lambda-gfp", type=float, default=None,
                   help="permissible specific film thickness from the FVA 54 test "
                   "(micropitting safety)")
    p.add_argument("-o", "--output", metavar="FILE.toml", help="oil file to write")
    p.set_defaults(func=run)


#: what a data sheet's oil file needs (all but --list)
_REQUIRED = (("name", "--name"), ("nu40", "--nu40"), ("nu100", "--nu100"),
             ("rho15", "--rho15"), ("base_oil", "--base-oil"), ("source", "--source"),
             ("output", "-o"))


def list_oils() -> int:
    """Print the bundled oils: the oil files' and the library's (friction.oil_library)."""
    from tabulate import tabulate

    from friction.lubricant import (
        available_lubricants,
        kinematic_viscosity,
        load_lubricant,
        pressure_viscosity_coefficient,
        viscosity,
    )
    from friction.oil_library import library_oils

    library = library_oils()
    rows = []
    for name in available_lubricants():
        oil = load_lubricant(name)
        nu = kinematic_viscosity(oil, [40.0, 100.0])
        entry = library.get(name)
        rows.append((name, oil.base_oil, float(nu[0]), float(nu[1]),
                     "" if entry is None else f"{entry.viscosity_index:g}",
                     "" if entry is None else f"{entry.sheet.density_15:g}",
                     *(float(viscosity(oil, t)) * 1e3 for t in (40.0, 100.0)),
                     *(float(pressure_viscosity_coefficient(oil, t)) for t in (40.0, 100.0)),
                     "bundled file" if entry is None else "library (class values)"))
    print(tabulate(rows, headers=("name", "base oil", "nu40 [mm2/s]", "nu100 [mm2/s]", "VI",
                                  "rho15 [kg/m3]", "eta40 [mPa s]", "eta100 [mPa s]",
                                  "alpha40 [1/GPa]", "alpha100 [1/GPa]", "kind"),
                   floatfmt=("", "", ".1f", ".2f", "", "", ".1f", ".2f", ".2f", ".2f", "")))
    print("sources: docs/oils.md, 'The oil library'; each oil's source line "
          "(friction.lubricant.load_lubricant(name).source)")
    return 0


def boundary_friction_argument(text: str | None, source: str | None):
    """``--boundary-friction``'s value: None, one number, or a table mapping (temperature
    [degC], value [1], source) from ``DEGC:MU_B`` pairs by commas.

    Parameters
    ----------
    text : str or None
        The option's text: ``"0.09"`` or ``"40:0.11,100:0.09"`` (temperatures in degC,
        μ_b [1]); None when not given.
    source : str or None
        ``--boundary-friction-source``: where a table's values were measured.

    Returns
    -------
    None, float [1] or dict
        What :class:`friction.oil_data_sheet.OilDataSheet` takes as ``boundary_friction``
        (its ranges are checked there: :class:`friction.lubricant.BoundaryFrictionTable`).

    Raises
    ------
    InputError
        A value that is neither a number nor such pairs, a table without
        ``--boundary-friction-source``, a source without a table (naming the option).
    """
    from geometry.core.errors import InputError

    if text is None:
        if source is not None:
            raise InputError("--boundary-friction-source: given without a table of "
                             "--boundary-friction DEGC:MU_B pairs")
        return None
    if ":" not in text:
        if source is not None:
            raise InputError("--boundary-friction-source: goes with a table of DEGC:MU_B "
                             f"pairs, got the single value {text!r}")
        try:
            return float(text)
        except ValueError:
            raise InputError(f"--boundary-friction: must be a number or DEGC:MU_B pairs by "
                             f"commas (e.g. 40:0.11,100:0.09), got {text!r}") from None
    try:
        pairs = [tuple(float(x) for x in item.split(":")) for item in text.split(",")]
    except ValueError:
        pairs = [()]
    if any(len(p) != 2 for p in pairs):
        raise InputError(f"--boundary-friction: must be a number or DEGC:MU_B pairs by "
                         f"commas (e.g. 40:0.11,100:0.09), got {text!r}")
    if source is None:
        raise InputError("--boundary-friction-source: required with a table of "
                         "--boundary-friction DEGC:MU_B pairs (the rig, load, speed, "
                         "slide-to-roll ratio and materials of the measurement)")
    return {"temperature": [p[0] for p in pairs], "value": [p[1] for p in pairs],
            "source": source}


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.commands.output_paths import check_output_file
    from friction.lubricant import density, pressure_viscosity_coefficient, viscosity
    from friction.oil_data_sheet import (
        TABLE_TEMPERATURES,
        OilDataSheet,
        lubricant_from_data_sheet,
        oil_file_mapping,
    )
    from geometry.core.atomic_files import atomic_path
    from geometry.core.errors import InputError
    from geometry.core.toml_files import dump_toml

    if args.list:
        return list_oils()
    missing = [flag for key, flag in _REQUIRED if getattr(args, key) is None]
    if missing:
        raise InputError(f"ltca oil: {', '.join(missing)} required (or --list)")
    check_output_file(args.output)
    if not str(args.output).endswith(".toml"):
        raise InputError(f"-o: the oil file must end in .toml, got {args.output!r}")
    sheet = OilDataSheet(
        name=args.name, kinematic_viscosity_40=args.nu40, kinematic_viscosity_100=args.nu100,
        density_15=args.rho15, base_oil=args.base_oil, source=args.source,
        pressure_viscosity_38=args.alpha38, fzg_load_stage=args.fzg_stage,
        boundary_friction=boundary_friction_argument(args.boundary_friction,
                                                    args.boundary_friction_source),
        permissible_specific_film=args.lambda_gfp)
    oil = lubricant_from_data_sheet(sheet)  # validated as an oil file before it is written
    text = ("# Built by `ltca oil` from a data sheet (friction.oil_data_sheet); the source "
            "line says how.\n" + dump_toml(oil_file_mapping(sheet)))
    with atomic_path(args.output) as tmp:
        tmp.write_text(text, encoding="utf-8")
    rows = [(t, float(viscosity(oil, t)) * 1e3, float(pressure_viscosity_coefficient(oil, t)),
             float(density(oil, t))) for t in TABLE_TEMPERATURES]
    print(tabulate(rows, headers=("T [degC]", "eta [mPa s]", "alpha [1/GPa]", "rho [kg/m3]"),
                   floatfmt=("g", ".2f", ".2f", ".1f")))
    if sheet.boundary_friction is not None:
        from friction.lubricant import boundary_friction_source

        print(f"boundary friction: {boundary_friction_source(oil)}")
    print(f"wrote {args.output}")
    return 0
