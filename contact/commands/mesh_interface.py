"""``ltca mesh-interface``: the mesh of a case for dynamic models, as a documented CSV."""

from __future__ import annotations

import argparse
import shlex
from pathlib import Path

from contact.commands.options import (
    case_and_misalignment,
    case_argument,
    checked_outputs,
    flank_option,
    misalignment_options,
    output_option,
    plots_option,
    progress_option,
    rolls_per_cycle_option,
    segments_option,
    solver_option,
    torque_option,
)

#: Place in ``ltca --help``.
ORDER = 14


def register(sub) -> None:
    """Add the sub-command to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "mesh-interface",
        help="mesh point, line of action, mesh stiffness and TE excitation for dynamic "
             "models (CSV)",
        description="Loaded TCA of a case, reduced at every torque and roll position to what "
        "a lumped-parameter or multibody model of the drive takes: the effective mesh point, "
        "the line of action, the mesh stiffness along it [N/um], the directional rotation "
        "radii and the transmission-error excitation with its mesh harmonics (Cheng & Lim "
        "2001). Writes a CSV whose comment lines document every column "
        "(docs/mesh_interface.md); `ltca run` stores the same as /mesh_interface.",
    )
    case_argument(p)
    torque_option(p)
    misalignment_options(p)
    solver_option(p)
    flank_option(p)
    rolls_per_cycle_option(p)
    segments_option(p)
    output_option(p, default="<case>_mesh_interface.csv; --flank coast: "
                             "<case>_coast_mesh_interface.csv", what="CSV file")
    plots_option(p)
    progress_option(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.chain import AnalysisChain
    from contact.commands.run import check_certified, ltca_options
    from contact.ltca.mesh_interface import write_mesh_interface_csv
    from contact.pipeline import run_analysis
    from contact.plots.style import misalignment_text
    from geometry.core.text import plain_number

    output = checked_outputs(args, "_mesh_interface.csv")
    case, mis = case_and_misalignment(args)
    tree = run_analysis(case, args.torque, misalignment=mis, flank=args.flank,
                        options=ltca_options(args), deviations=None,
                        progress=not args.no_progress,
                        steps=AnalysisChain.contact_only().with_mesh_interface())
    mesh = tree["mesh_interface"].to_dataset()
    print(f"mesh interface of {case.name} ({misalignment_text(tree.attrs)}), means over the "
          "mesh cycles and the peak amplitudes of the first mesh harmonics:")
    rows = []
    for i, t in enumerate(mesh["torque"].values):
        k1 = mesh["mesh_stiffness_amplitude"].values[i]
        e1 = mesh["te_excitation_amplitude"].values[i]
        rows.append((plain_number(t), f"{float(mesh['mesh_force'].isel(torque=i).mean()):.0f}",
                     f"{float(mesh['mesh_stiffness_mean'].values[i]):.1f}",
                     " / ".join(f"{v:.1f}" for v in k1[:3]),
                     f"{float(mesh['te_excitation_mean'].values[i]):.2f}",
                     " / ".join(f"{v:.3f}" for v in e1[:3]),
                     f"{float(mesh['gear_rotation_radius'].isel(torque=i).mean()):.2f}",
                     f"{float(abs(mesh['pinion_rotation_radius'].isel(torque=i)).mean()):.2f}"))
    print(tabulate(rows, headers=("T_p [N m]", "W [N]", "k_m [N/um]", "k_m 1st/2nd/3rd",
                                  "e mean [um]", "e 1st/2nd/3rd [um]", "lambda_g [mm]",
                                  "|lambda_p| [mm]"), tablefmt="github"))
    command = "ltca " + " ".join(shlex.quote(a) for a in getattr(args, "argv", None)
                                 or ["mesh-interface"])
    path = write_mesh_interface_csv(mesh, Path(output), header=f"written by {command}")
    print(f"wrote {path} ({mesh.sizes['torque'] * mesh.sizes['roll']} rows; columns "
          "documented in its # lines)")
    if args.plots:
        from contact.plots.analysis import torque_tag
        from contact.plots.dynamics import mesh_interface_figure
        from contact.plots.style import save_png

        # named for the command and its torques: apart from the analysis's own
        # mesh_interface figure (<case>_T<torques>_mesh_interface.png, ltca run / plot)
        target = (Path(args.plots)
                  / f"{case.name}_mesh_interface_{torque_tag(mesh['torque'].values)}.png")
        print(f"wrote {save_png(mesh_interface_figure(mesh, tree['ltca'].to_dataset()), target)}")
    check_certified(tree, path)  # no certified contact: exit 1, as ltca run (issue 64)
    return 0
