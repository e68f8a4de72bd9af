"""``ltca geometry`` and ``ltca plot-geometry``: tooth surfaces of a case, as netCDF and plots."""

from __future__ import annotations

import argparse
from pathlib import Path

from contact.commands.options import (
    case_argument,
    count,
    default_output,
    deprecated_alias,
    output_option,
    plots_option,
)
from contact.commands.output_paths import check_output_dir, check_output_file

#: Place in ``ltca --help``.
ORDER = 20


def register(sub) -> None:
    """Add the sub-commands to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "geometry",
        help="generate both flanks of both members of a case and write them as netCDF",
        description="Generate the tooth surfaces of a case from its machine settings "
        "(equation of meshing on the projection-plane grid) and write one netCDF file "
        "with a group per member and flank.",
    )
    case_argument(p, what="generate")
    output_option(p, default="<case>_geometry.nc")
    p.add_argument("--nu", type=count(3, 2001), default=41,
                   help="lengthwise grid points (default 41)")
    p.add_argument("--nv", type=count(3, 2001), default=21, help="profile grid points (default 21)")
    p.add_argument("--solid", metavar="FILE.stl", default=None,
                   help="also write each member's FE solid (the loaded tooth, its neighbours, "
                   "fillets, rim; contact.compliance.fe) as binary STL: FILE_pinion.stl and "
                   "FILE_gear.stl")
    p.set_defaults(func=run_geometry)

    q = sub.add_parser(
        "plot-geometry",
        help="plot both members' flanks in mesh and each flank's projection-plane grid",
    )
    case_argument(q, what="plot")
    plots_option(q, default=".")
    deprecated_alias(q, "--output-dir", "--plots", "plots")
    deprecated_alias(q, "-o", "--plots", "plots")
    q.add_argument("--nu", type=count(3, 2001), default=41,
                   help="lengthwise grid points (default 41)")
    q.add_argument("--nv", type=count(3, 2001), default=21, help="profile grid points (default 21)")
    q.set_defaults(func=run_plot_geometry)


def geometry_tree(case, nu: int = 41, nv: int = 21):
    """All four flanks of a case as an ``xarray.DataTree`` (``/pinion/concave`` …)."""
    import xarray as xr

    from geometry.machine.flank import geometry_datasets

    sets = geometry_datasets(case, nu=nu, nv=nv)
    tree = {"/": xr.Dataset(attrs={"case": case.name, "title": "tooth surfaces"})}
    tree.update({f"/{m}/{f}": ds for (m, f), ds in sets.items()})
    return xr.DataTree.from_dict(tree)


def run_geometry(args: argparse.Namespace) -> int:
    from contact.catalogue import resolve_case
    from geometry.core.io import write_netcdf

    output = default_output(args, "_geometry.nc")
    check_output_file(output)
    solids = _solid_paths(args.solid)
    case = resolve_case(args.case)
    tree = geometry_tree(case, args.nu, args.nv)
    path = write_netcdf(tree, Path(output), inputs=case.to_toml())
    for node in tree.subtree:
        if "mask" in node.dataset:
            ok = int(node.dataset["mask"].sum())
            print(f"{node.path:16s} {ok} of {node.dataset['mask'].size} grid points generated")
    print(f"wrote {path}")
    if solids:
        from contact.compliance.fe import build_tooth_solid
        from contact.compliance.fe.export import write_stl

        for member, target in solids.items():
            solid = build_tooth_solid(case, member)
            written = write_stl(solid.mesh, target, name=f"{case.name} {member} FE solid")
            print(f"wrote {written} ({solid.mesh.mesh.nelements} elements, "
                  f"{solid.options.teeth} teeth, rim {solid.rim_depth:.3g} mm)")
    return 0


def _solid_paths(solid: str | None) -> dict[str, Path]:
    """The STL files of ``--solid FILE.stl``: FILE_pinion.stl and FILE_gear.stl (checked
    before any work)."""
    if solid is None:
        return {}
    from geometry.core.errors import InputError

    base = Path(solid)
    if base.suffix.lower() != ".stl":
        raise InputError(f"--solid: must end in .stl, got {solid!r}")
    paths = {m: base.with_name(f"{base.stem}_{m}{base.suffix}") for m in ("pinion", "gear")}
    for target in paths.values():
        check_output_file(target, option="--solid")
    return paths


def run_plot_geometry(args: argparse.Namespace) -> int:
    from contact.catalogue import resolve_case
    from geometry.machine.flank import flank_surface
    from geometry.plot import plot_flanks_in_mesh, plot_projection_grid

    check_output_dir(args.plots, option="--plots")
    case = resolve_case(args.case)
    out = Path(args.plots)
    out.mkdir(parents=True, exist_ok=True)
    surfaces = {
        (m, f): flank_surface(case, m, f, nu=args.nu, nv=args.nv)
        for m in ("pinion", "gear")
        for f in ("concave", "convex")
    }
    # named for the case: the plots of several cases can share a directory
    written = [plot_flanks_in_mesh(case, surfaces.values(),
                                   out / f"{case.name}_flanks_in_mesh.png")]
    for (m, f), s in surfaces.items():
        written.append(plot_projection_grid(s, case.member(m).blank,
                                            out / f"{case.name}_grid_{m}_{f}.png"))
    for w in written:
        print(f"wrote {w}")
    return 0
