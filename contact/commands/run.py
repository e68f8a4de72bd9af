"""``ltca run`` and ``ltca plot``: the whole analysis of a case, and its plots from a file."""

from __future__ import annotations

import argparse
import logging
import math
import os
import sys
import textwrap
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from contact.commands.options import (
    ROOT_STRESS_COST,
    analysis_file_argument,
    case_and_misalignment,
    case_argument,
    checked_fe_level,
    checked_outputs,
    compliance_option,
    fe_level_option,
    flank_option,
    misalignment_from_args,
    misalignment_options,
    operating_options,
    output_option,
    plots_option,
    pressure_limit_options,
    progress_option,
    resolve_analysis_file,
    rolls_per_cycle_option,
    root_stress_option,
    segments_option,
    solver_option,
    torque_option,
)
from contact.commands.output_paths import check_output_dir
from geometry.core.text import plain_number

__all__ = ["TE_TABLE_HEADERS", "check_certified", "deviation_te_rows", "durability_lines",
           "misalignment_from_args", "plot", "print_verdict", "rating_lines", "register",
           "root_stress_rows", "run", "standard_scuffing", "write_figures"]

log = logging.getLogger(__name__)

#: Place in ``ltca --help``.
ORDER = 10


def register(sub) -> None:
    """Add the sub-commands to an ``argparse`` sub-parser collection."""
    p = sub.add_parser(
        "run",
        help="loaded TCA of a case (default: the bundled 11x41 pair at the seed's Table 3.1)",
        description="Geometry, ease-off UTCA and loaded TCA of a case at one or more torques; "
        "prints a summary, writes one netCDF (/geometry, /easeoff, /utca, /ltca, /friction) "
        "named after the case and plots. The torques, misalignment and efficiency conditions "
        "are the case's [operating] table unless given here; the default case's are the "
        "seed's Table 3.1 conditions (pinion torque 50/250/500 N m, dE = -0.15 mm, "
        "dP = +0.12 mm (the text extraction lost the seed's signs; this reading is argued "
        "in docs/cases.md); 1500 rpm, 75W90 at 90 degC, Rq 0.8 um).",
    )
    case_argument(p)
    torque_option(p)
    misalignment_options(p)
    operating_options(p)
    solver_option(p)
    flank_option(p)
    rolls_per_cycle_option(p)
    segments_option(p)
    pressure_limit_options(p)
    compliance_option(p)
    dev = p.add_mutually_exclusive_group()
    dev.add_argument(
        "--deviations",
        nargs=2,
        metavar=("PINION", "GEAR"),
        default=None,
        help="measured/wear normal deviations of the pinion and gear flanks in "
        "contact (CSV or netCDF, see contact.utca.deviations; '-' for none); overrides the "
        "case's [deviations] table; the theoretical results are kept under /theoretical",
    )
    dev.add_argument(
        "--no-deviations",
        action="store_true",
        help="ignore the case's [deviations] table (theoretical surfaces only)",
    )
    output_option(p, default="<case>.nc, e.g. kolivand2009_fm_11x41_reference.nc; "
                     "with --flank coast <case>_coast.nc")
    plots_option(p)
    p.add_argument("--report", default=None, metavar="HTML",
                   help="write the one-page HTML report (as `ltca report`) to HTML")
    root_stress_option(p, "the tooth-root stress of both members from FE influence "
                          "coefficients, in the summary, the file and the report")
    fe_level_option(p, "default the case's [root_stress] fe_level (the cases `ltca "
                       "synthesize` writes: coarse10), else default; --fe-level default "
                       "refines a new design's root stress to the default model")
    p.add_argument("--rating", action=argparse.BooleanOptionalAction, default=True,
                   help="the load-capacity rating of the case (ISO 10300 Method B1 unless "
                   "--rating-method or the case's [rating] method names another) at the "
                   "run's torques and speed, stored as /rating, printed beside the LTCA's "
                   "peak flank pressure and root stress and judged by the verdict (on by "
                   "default: analytic, < 0.5 s; docs/rating.md); --no-rating leaves it out")
    p.add_argument("--rating-method", default=None, metavar="NAME",
                   help="the load-capacity rating method of the registry (iso10300: ISO "
                   "10300-1/-2/-3:2014 Method B1; agma2003: ANSI/AGMA 2003-D19, the case's "
                   "[agma2003] table; a plug-in's; default the case's [rating] method, else "
                   "iso10300; an unknown name lists those available)")
    p.add_argument("--apply-remedy", dest="apply_remedy", action="store_true",
                   help="where the verdict finds a tooth root below its minimum safety: "
                   "analyse the case again with every blade's edge radius the largest the "
                   "point widths and the clearance allow (the remedy printed under the "
                   "verdict), print both, and write <output>_edge_radius.toml and .nc only "
                   "where the root improves and no criterion the case met is lost "
                   "(docs/verdicts.md)")
    progress_option(p)
    p.set_defaults(func=run, one_analysis=True)

    q = sub.add_parser("plot", help="redraw every plot of an analysis from its netCDF file")
    analysis_file_argument(q)
    plots_option(q, default="plots")
    progress_option(q)
    q.set_defaults(func=plot)


def root_stress_hint(case, flank, opts) -> str:
    """The line `ltca run --no-root-stress` prints: how to have the root stress and what
    it would cost for this design now (built, cached, or the FE compliance's own
    coefficients)."""
    from contact.ltca.root_stress import coefficients_cached

    if opts.compliance == "fe":
        cost = ("it takes the FE compliance's coefficients, already read: the "
                "superposition only, < 1 s")
    elif coefficients_cached(case, flank):
        cost = "this design's FE coefficients are in the cache: ~1 s more"
    else:
        cost = ROOT_STRESS_COST
    return (f"tooth-root stress not computed (--no-root-stress): leave the option out to "
            f"have it; {cost} (docs/fe.md)")


#: columns of the theoretical/deviated TE table (seed Tables 4.2, 4.4), all [µrad] but T_p
TE_TABLE_HEADERS = (
    "T_p [N m]",
    "surfaces",
    "LTE mean",
    "LTE p-p",
    "1st",
    "2nd",
    "3rd",
    "RMS*",
    "UTE p-p",
)


def deviation_te_rows(tree) -> list[tuple[str, ...]]:
    """Rows of the TE table of an analysis with deviations (seed Tables 4.2, 4.4).

    Parameters
    ----------
    tree : xarray.DataTree
        Output of :func:`contact.pipeline.run_analysis` with deviations: ``/ltca``,
        ``/utca`` (deviated) and ``/theoretical/{ltca,utca}``.

    Returns
    -------
    list of tuple of str
        Per torque, a ``theoretical`` then a ``deviated`` row: T_p [N·m], LTE mean,
        peak-to-peak, amplitudes of the first three mesh harmonics, the seed's RMS
        (root-sum-square of those amplitudes, ``lte_harmonic_rss``) and the UTE
        peak-to-peak, all [µrad] with two decimals, as stored in the datasets (columns
        :data:`TE_TABLE_HEADERS`).
    """
    rows = []
    groups = {
        "theoretical": (tree["theoretical/ltca"].to_dataset(), tree["theoretical/utca"]),
        "deviated": (tree["ltca"].to_dataset(), tree["utca"]),
    }
    for i, T in enumerate(tree["ltca"]["torque"].values):
        for name, (lt, ut) in groups.items():
            h = lt["lte_harmonics"].values[i]
            rows.append(
                (
                    f"{T:g}",
                    name,
                    f"{lt['lte_mean'].values[i]:.2f}",
                    f"{lt['lte_peak_to_peak'].values[i]:.2f}",
                    f"{h[0]:.2f}",
                    f"{h[1]:.2f}",
                    f"{h[2]:.2f}",
                    f"{lt['lte_harmonic_rss'].values[i]:.2f}",
                    f"{float(ut['peak_to_peak_transmission_error']):.2f}",
                )
            )
    return rows


def ltca_options(args: argparse.Namespace, **defaults):
    """LTCAOptions of ``--rolls-per-cycle``, ``--segments``, ``--solver``,
    ``--edge-pressure-limit``, ``--flank-pressure-limit``, ``--compliance`` (those given;
    ``none`` turns a limit off)."""
    from contact.ltca import LTCAOptions

    kw = dict(defaults)
    for name in ("rolls_per_cycle", "segments", "solver", "compliance"):
        value = getattr(args, name, None)
        if value is not None:
            kw[name] = value
    for name in ("edge_pressure_limit", "flank_pressure_limit"):
        value = getattr(args, name, None)
        if value is not None:
            kw[name] = None if value == "none" else value
    return LTCAOptions(**kw)


def _chain_of(args: argparse.Namespace, operating, case):
    """The chain ``ltca run`` runs (:meth:`contact.AnalysisChain.analysis`): without the root
    stress for ``--no-root-stress``, without the efficiency step where there is no pinion
    speed (``operating`` None), and the load-capacity step's scuffing and micropitting
    without the rating for ``--no-rating``; otherwise /scuffing_micropitting, /rating by
    ``--rating-method``, else the case's ``[rating] method``, else ISO 10300, and the
    method's companions (/rating/flash_temperature; a bad [rating] table is refused before
    the work)."""
    from contact.chain import AnalysisChain
    from contact.load_capacity.methods import case_method

    chain = AnalysisChain.analysis().with_root_stress(bool(args.root_stress))
    if operating is None:
        chain = chain.without("efficiency")
    if not args.rating:
        return chain.with_load_capacity("scuffing_micropitting")
    named = rating_steps(args.rating_method)
    method = named["load_capacity"] if named else case_method(case)
    return chain if method is None else chain.with_load_capacity(method)


@contextmanager
def dask_hidden() -> Iterator[None]:
    """Keep dask (and distributed) out of the process while the block runs, unless
    already imported.

    xarray's netCDF writer asks dask for its scheduler and its duck arrays whenever dask
    is installed, importing dask and distributed for a file of NumPy arrays: ~0.5 s of
    CPU of a warm ``ltca run`` (docs/performance.md, issue 75 item 4), for nothing the
    command uses (it runs one analysis, no study). Marked unimportable
    (``sys.modules["dask"] = None``), xarray takes its path without dask and writes the
    same file. xarray's memos of dask (its duck-array and module-availability memos,
    private to xarray) are forgotten on entry, so it asks again, and on exit, after the
    mark is removed, so a process that goes on (a test calling ``main(["run", ...])``,
    then a study) finds dask as before.
    """
    if "dask" in sys.modules:
        yield
        return
    sys.modules["dask"] = None  # type: ignore[assignment]
    _forget_dask()  # what xarray found before (dask installed) is asked again
    try:
        yield
    finally:
        if "dask" in sys.modules and sys.modules["dask"] is None:
            del sys.modules["dask"]
        _forget_dask()


def _forget_dask() -> None:
    """Drop xarray's memos of whether dask is installed (its private names, looked up
    defensively: an xarray without them has nothing to forget)."""
    for module, name in (("xarray.namedarray.pycompat", "_cached_duck_array_modules"),
                         ("xarray.namedarray.utils", "module_available"),
                         ("xarray.namedarray.parallelcompat", "list_chunkmanagers")):
        memo = getattr(sys.modules.get(module), name, None)
        if isinstance(memo, dict):
            memo.pop("dask", None)
        elif hasattr(memo, "cache_clear"):
            memo.cache_clear()


def run(args: argparse.Namespace) -> int:
    """``ltca run``: the analysis of a case, its summary and verdict, its file; dask
    kept out of the process (:func:`dask_hidden`)."""
    with dask_hidden():
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    from tabulate import tabulate

    from contact.pipeline import operating_conditions, run_analysis
    from geometry.core.io import write_netcdf

    output = checked_outputs(args, more={"--report": args.report})
    if args.rating_method is not None and not args.rating:
        from geometry.core.errors import InputError

        raise InputError("--rating-method: a method was named with --no-rating; give one "
                         "of the two")
    fe_level = checked_fe_level(getattr(args, "fe_level", None))
    if fe_level is not None and not args.root_stress:
        from geometry.core.errors import InputError

        raise InputError("--fe-level: names the FE model of the root stress, which "
                         "--no-root-stress leaves out; give one of the two")
    case, mis = case_and_misalignment(args)
    opts = ltca_options(args)
    devs = None  # the case's [deviations] table, if any
    if args.no_deviations:
        devs = False
    elif args.deviations:
        # file paths: run_analysis reads them (contact.utca.deviation_files.read_deviations)
        devs = tuple(None if f == "-" else f for f in args.deviations)
    operating = operating_conditions(
        case, pinion_speed=args.speed, lubricant=args.lubricant, temperature=args.temperature,
        roughness=args.roughness, friction_model=args.friction_model,
        surface_state=args.surface_state)

    def analyse(c):
        return run_analysis(
            c,
            args.torque,
            misalignment=mis,
            flank=args.flank,
            options=opts,
            deviations=devs,
            operating=operating,
            # a bar on a terminal, plain lines in a log (the LTCA and a first FE build)
            progress=args.progress,
            steps=_chain_of(args, operating, c),
            fe_level=fe_level,
        )

    tree = analyse(case)
    rating_why = ("ISO 10300 rating not computed (--no-rating)" if not args.rating
                  else str(tree.attrs.get("load_capacity_not_run", "")))
    fr = tree["friction"].to_dataset() if "friction" in tree.children else None
    standard = (tree["rating/flash_temperature"].to_dataset()
                if "rating" in tree.children and "flash_temperature" in tree["rating"].children
                else None)
    lt = tree["ltca"].to_dataset()
    print(
        f"case {case.name}: dE {mis.delta_E:g} mm, dP {mis.delta_P:g} mm, "
        f"dG {mis.delta_G:g} mm, dSigma {math.degrees(mis.delta_Sigma):g} deg; "
        f"solver {lt.attrs['solver']}"
        + (f"; tooth compliance {opts.compliance}" if opts.compliance != "shell" else "")
    )
    if args.torque is None:  # the coast side at its own design torque (flank_torques)
        from contact.pipeline import flank_torques

        why = flank_torques(case, args.flank)[1]
        if why:
            print(f"coast flank: {why}; --torque gives others")
    rows = []
    for i, T in enumerate(lt["torque"].values):
        h = lt["lte_harmonics"].values[i]
        none = not bool(lt["found"].isel(torque=i).any())  # no contact solution: no numbers
        rows.append(tuple("-" if none and k not in (0, 10) else cell for k, cell in enumerate(
            (
                f"{T:g}",
                f"{lt['lte_mean'].values[i]:.1f}",
                f"{lt['lte_peak_to_peak'].values[i]:.1f}",
                f"{h[0]:.1f}",
                f"{h[1]:.1f}",
                f"{h[2]:.1f}",
                f"{lt['lte_harmonic_rss'].values[i]:.1f}",
                f"{float(lt['pressure_max_flank'].values[i]):.0f}",
                f"{float(lt['pressure_max_edge'].values[i]):.0f}",
                plastic_summary(lt, i),
                f"{int(lt['found'].isel(torque=i).sum())}/{lt.sizes['roll']}",
                f"{100 * fr['efficiency_mean'].values[i]:.2f}" if fr is not None else "-",
            ))))
    print(
        tabulate(
            rows,
            headers=[
                "T_p [N m]",
                "LTE mean [urad]",
                "p-p",
                "1st",
                "2nd",
                "3rd",
                "RMS*",
                "p_max flank [MPa]",
                "p_max edge",
                "plastic",
                "certified",
                "efficiency [%]",
            ],
            tablefmt="github",
        )
    )
    if fr is not None:
        print(
            f"efficiency at {fr.attrs['pinion_speed_rpm']:g} rpm, {fr.attrs['lubricant']} at "
            f"{fr.attrs['inlet_temperature_degC']:g} degC, Rq {fr.attrs['roughness_rq_um']:g} um, "
            f"friction model {fr.attrs['friction_model']}"
        )
        print_extrapolation_warning(fr)
        print_mu_warning(fr)
        # scuffing and micropitting: the load-capacity step's group (issue 63)
        sm = (tree["scuffing_micropitting"].to_dataset()
              if "scuffing_micropitting" in tree.children else fr)
        for line in durability_lines(sm, standard):
            print(line)
    print("RMS*: root-sum-square of the first three harmonics, as the seed's Table 3.1.")
    between = lte_between_line(lt)
    if between is not None:  # the lte_range step's torques (contact.ltca.lte_range)
        print(between)
    print(plastic_note(lt))
    failed = str(tree.attrs.get("root_stress_not_run", ""))
    if "root_stress_max" not in lt and failed.startswith("root stress not computed"):
        print(failed)  # the FE model failed: why (contact.chain.root_stress_fe)
    elif "root_stress_max" not in lt:
        print(root_stress_hint(case, args.flank, opts))
    else:
        print("peak tooth-root stress over the mesh cycle (max principal, FE "
              "superposition) [MPa], at the face station u (toe 0, heel 1):")
        print(tabulate(root_stress_rows(lt), headers=["T_p [N m]", "pinion", "u", "gear",
                                                      "u"], tablefmt="github"))
        from contact.ltca.root_stress import (
            fe_level_note,
            root_stress_notes,
            slot_bottom_notes,
        )

        for line in root_stress_notes(lt):  # NaN torques and loads left out, and why
            print(line)
        for line in slot_bottom_notes(case, lt, args.flank or "drive"):  # step 2's arc
            print(line)
        level = fe_level_note(lt)  # a new design's coarse FE level: said, with its accuracy
        print(level if level is not None else
              "the FE model's peak fillet stress is mesh-converged within 5 % (docs/fe.md, "
              "Mesh convergence)")
    for line in rating_lines(tree, rating_why, args.case):
        print(line)
    if "theoretical" in tree.children:
        print(
            "transmission error of the theoretical and deviated surfaces "
            f"({tree['easeoff'].attrs.get('deviations', '')}; seed Tables 4.2, 4.4) [urad]:"
        )
        print(tabulate(deviation_te_rows(tree), headers=TE_TABLE_HEADERS, tablefmt="github"))
    times = {k[5:-2]: v for k, v in tree.attrs.items() if k.startswith("time_")}
    print("time [s]: " + ", ".join(f"{k} {v:.2f}" for k, v in times.items()))
    # the verdict before the file: what a reader needs first, and what the report lists
    print_plausibility_warnings(lt, case, mis)
    print_verdict(tree, rest=None if args.report else
                  f"`ltca report {Path(output).name}` or `ltca run --report FILE.html` "
                  "lists them all")
    apply = bool(getattr(args, "apply_remedy", False))
    for line in next_steps(tree, case, args.case, args.flank, remedy=not apply):  # under
        # the verdict's findings; the commands unwrapped, to paste
        print(line if line.startswith("    ltca ") else
              textwrap.fill(line, 100, subsequent_indent="      "))
    path = write_netcdf(tree, Path(output), inputs=tree.attrs["inputs"])
    print(f"wrote {path}")
    write_figures(path, args.plots, args.report, progress=not args.no_progress)
    if apply:
        _applied_remedy(case, tree, analyse, Path(output))
    check_certified(tree, path)
    return 0


def _applied_remedy(case, tree, analyse, output: Path) -> None:
    """``--apply-remedy``: the edge radius applied and judged
    (:func:`contact.commands.run_remedy.apply_remedy`), printed; the remedied case and its
    analysis written beside ``output`` (``<stem>_edge_radius.toml``, ``.nc``) only where
    the remedy is kept: a case whose result was seen to fail is never offered."""
    from contact.commands.run_remedy import apply_remedy
    from geometry.core.io import write_netcdf

    done = apply_remedy(case, tree, analyse)
    for line in map(console_text, done.lines):
        print(textwrap.fill(line, 100, subsequent_indent=" " * (len(line) - len(line.lstrip())
                                                                 + 4)))
    if done.kept and done.case is not None and done.tree is not None:
        stem = output.with_suffix("")
        toml = stem.with_name(stem.name + "_edge_radius.toml")
        toml.write_text(done.case.to_toml(), encoding="utf-8")
        nc = write_netcdf(done.tree, stem.with_name(stem.name + "_edge_radius.nc"),
                          inputs=done.tree.attrs["inputs"])
        print(f"wrote {toml} (the case with the edge radius) and {nc}")


#: the verdict's checks a bearing change answers (the pattern, its edges, its pressure)
BEARING_CHECKS = ("implausible", "plastic_edges", "edge_pressure", "edge_contact",
                  "flank_pressure")
#: the checks only a larger or stronger gear set answers
CAPACITY_CHECKS = ("rating", "static")
#: the failing checks the bearing's optimisation (``ltca optimize``) cannot change: its
#: objective and constraints hold no scuffing or micropitting safety, which the operation
#: (oil, inlet temperature, speed, finish) moves (issue 71, Round 37: the truck hypoid
#: 8x45's S_B 0.93 FAIL, the optimisation printed for a 0.07 % edge attention beside it
#: kept its start, "ltca run's verdict is FAIL: scuffing safety S_B 0.927")
OPERATION_CHECKS = ("scuffing", "micropitting")
#: the case-level variables the bearing hint offers, with their half-range about the
#: flank's own value (file units): lengthwise crowning by the point radius, profile
#: position by the blade angle, the bias by the ratio of roll, and the profile relief;
#: measured on the reference design's coast flank (docs/optimize.md, "A flank that fails")
BEARING_VARIABLES = {"point_radius": 4.0, "blade_angle": 1.25, "ratio_of_roll": 0.03}


def _bearing_answers(findings) -> bool:
    """Whether the bearing's next steps (V-H check, ``ltca optimize``) answer a FAIL
    verdict's ``findings``: a bearing finding that fails itself, or a bearing attention
    beside a failing finding the bearing can change. A bearing attention beside FAILs of
    :data:`OPERATION_CHECKS` alone is not printed an optimisation: it would keep the FAIL."""
    fails = [f for f in findings if f.severity == "fail"]
    return any(f.check in BEARING_CHECKS for f in fails) or any(
        f.check not in OPERATION_CHECKS for f in fails)


def next_steps(tree, case, case_arg: str | None, flank: str | None,
               remedy: bool = True) -> list[str]:
    """The lines `ltca run` prints under a FAIL verdict's findings (indented as they are):
    the commands that answer them. A bearing finding (plastic or edge contact, flank
    pressure; :data:`BEARING_CHECKS`) gets the V-H check and an `ltca optimize` command
    for this flank with the case's own setting variables (:data:`BEARING_VARIABLES`, those
    the pinion's process has) and the profile relief, edge share limited to 2 % (and the
    flank peak to the static strength it exceeded) — never the optimisation whose result
    the case already is (:func:`contact.commands.next_steps.bearing_lines`); a capacity
    finding (:data:`CAPACITY_CHECKS`) the rating's factors — first where the gear set is
    too small for its load (a failed rating, or a flank pressure above its static
    strength: no bearing change answers that); a scuffing finding the oil, inlet temperature
    and roughness it depends on (ISO/TS 6336-20: the flash temperature and the oil's
    scuffing temperature), as the same run with those options; an ``lte`` FAIL (an LTE
    beyond :data:`contact.study.verdicts.LTE_FAIL_FACTOR` times its limit) the basic-file
    remedy of an attention's. For a verdict that is not
    FAIL only an ``lte`` finding's basic-file remedy where the design's contact ratios are
    below their limits (:func:`contact.commands.next_steps.overlap_lines`), else nothing.

    Parameters
    ----------
    tree : xarray.DataTree
        The analysis (:func:`contact.study.verdicts.verdict` reads it).
    case : geometry.case.Case
    case_arg : str or None
        The CASE argument as given (None: the default case).
    flank : str or None
        ``"drive"``, ``"coast"``, or the pinion flank by name (``"concave"``,
        ``"convex"``); None: drive.
    remedy : bool, optional
        Whether a root below its minimum gets the edge-radius remedy and its
        ``--apply-remedy`` command (:func:`contact.commands.run_remedy.remedy_lines`;
        default True; False where ``--apply-remedy`` is applying it).

    Returns
    -------
    list of str
    """
    from contact.commands.next_steps import bearing_lines, static_flank_strength
    from contact.study.verdicts import verdict
    from contact.utca.easeoff import FLANK_ROLES

    v = verdict(tree)
    side = flank or "drive"
    if side not in FLANK_ROLES:  # a pinion flank by name: its role, as `ltca optimize` takes
        side = "drive" if side == case.pair.drive_flank else "coast"
    lte = _light_design_lte(tree)
    shown = case_arg if case_arg is not None else case.name
    torques = " ".join(f"{t:g}" for t in tree["ltca"]["torque"].values)
    root: list[str] = []
    if remedy and any(f.check == "root_stress" for f in v.findings):
        # the fillet first where the root is below its minimum (issue 71, remedy84)
        from contact.commands.run_remedy import remedy_lines

        root = remedy_lines(case, v, shown, side, torques)
    if v.severity != "fail":
        # an LTE above the verdict's limit whose cause is the design's low contact ratios:
        # the basic-file change that raises them (issue 71), or what `ltca synthesize`
        # said sets it instead (the written flank's unloaded TE)
        if any(f.check == "lte" for f in v.findings):
            from contact.commands.next_steps import overlap_lines

            return root + overlap_lines(case, "the LTE", lte, side)
        return root
    failed = {f.check for f in v.findings}
    method = (str(tree["rating"].attrs.get("rating_method", "")) if "rating" in tree.children
              else "")
    method = "" if method in ("", "iso10300") else method
    coast = ("rating" in tree.children
             and tree["rating"].attrs.get("side") == "coast")  # the side it rated
    speed = (float(tree["rating"]["pinion_speed"].values) if "rating" in tree.children
             and "pinion_speed" in tree["rating"].variables
             and tree["rating"]["pinion_speed"].ndim == 0 else 0.0)
    out: list[str] = []
    capacity: list[str] = []
    if failed & set(CAPACITY_CHECKS):
        capacity = ["  next, the load capacity: every factor of the rating; a wider face, a "
                    "larger module or a stronger material (the basic file's [design] and "
                    "[rating]) carry more (docs/rating.md):",
                    f"    ltca rate {shown} --torque {torques}"
                    + (f" --method {method}" if method else "")
                    + (f" --speed {speed:g}" if speed else "")
                    + (" --flank coast" if coast else "")]
    # a gear set too small for its load (a failed rating, a flank above its static
    # strength) is answered first: no bearing change carries the load it cannot
    overloaded = any(f.severity == "fail" and (f.check in CAPACITY_CHECKS or (
        f.check == "flank_pressure" and "static strength" in f.reason)) for f in v.findings)
    if overloaded:
        out += capacity
    out += root
    if failed & set(BEARING_CHECKS) and _bearing_answers(v.findings):
        # a flank peak above the static strength: the optimisation is given it as a limit;
        # an optimised case's own optimisation is not printed again (its [optimize] table)
        static = any(f.check == "flank_pressure" and f.severity == "fail" for f in v.findings)
        out += bearing_lines(case, shown, side, torques, BEARING_VARIABLES,
                             static_flank_strength(tree["ltca"].to_dataset()) if static
                             else None, rate=not failed & set(CAPACITY_CHECKS))
    if not overloaded:
        out += capacity
    from contact.commands.next_steps import overlap_lines, spread_failed

    if "implausible" in failed and spread_failed(v.findings):
        # an LTE spread that is the design's low face contact ratio
        out = overlap_lines(case, lte=lte, side=side) + out
    elif "lte" in failed:  # an LTE beyond twice its limit: the same remedy, said once
        out = overlap_lines(case, "the LTE", lte, side) + out
    if "scuffing" in failed:
        # the example remedy ltca synthesize's scuffing note computes S_B at
        from contact.optimize.written_scuffing import REMEDY_COOLER, REMEDY_SMOOTHER

        op = case.operating
        out += ["  next, scuffing: the flash temperature falls with a cooler oil inlet, smoother "
                "flanks and a lower speed, and an oil of a higher FZG load stage has a higher "
                "scuffing temperature (--lubricant OIL.toml, an oil file: docs/friction.md; "
                "docs/scuffing_micropitting.md); `ltca optimize` (the bearing) does not model "
                f"it; the same run {REMEDY_COOLER:g} K cooler with flanks half as rough, for "
                "example:",
                f"    ltca run {shown} --flank {side} --torque {torques} --temperature "
                f"{op.temperature - REMEDY_COOLER:g} --roughness "
                f"{op.roughness / REMEDY_SMOOTHER:g}"]
    return out


def lte_between_line(ltca) -> str | None:
    """The line ``ltca run`` prints under its LTE table: the LTE p-p [µrad] the
    ``lte_range`` step analysed between the run's torques (the contact alone,
    :mod:`contact.ltca.lte_range`), which the verdict's ``lte`` check judges beside the
    table's; None where the result has none (issue 71)."""
    import numpy as np

    if "lte_range_source" not in ltca or "lte_range_peak_to_peak" not in ltca:
        return None
    alone = np.asarray(ltca["lte_range_source"].values) == 1
    if not alone.any():
        return None
    t = np.asarray(ltca["lte_torque"].values, float)[alone]
    y = np.asarray(ltca["lte_range_peak_to_peak"].values, float)[alone]
    return ("LTE p-p between the torques, the contact alone (/ltca/lte_range_peak_to_peak; "
            "the verdict judges them up to the design torque): "
            + " / ".join(f"{v:.1f}" for v in y) + " urad at "
            + " / ".join(f"{plain_number(x)}" for x in t) + " N m")


def _light_design_lte(tree) -> list[float] | None:
    """The analysis' LTE p-p [µrad] at its lightest and its heaviest torque (as
    ``ltca synthesize``'s development states it: light/design), None where the tree has
    none."""
    import numpy as np

    if "ltca" not in tree.children or "lte_peak_to_peak" not in tree["ltca"].variables:
        return None
    ds = tree["ltca"]
    lte = np.asarray(ds["lte_peak_to_peak"].values, float)
    torque = np.asarray(ds["torque"].values, float) if "torque" in ds.variables else None
    if lte.ndim != 1 or lte.size == 0:
        return None
    if torque is not None and torque.shape == lte.shape:
        lte = lte[np.argsort(torque)]
    return [float(lte[0]), float(lte[-1])]


def check_certified(tree, path) -> None:
    """Raise :class:`contact.errors.AnalysisFailedError` (``ltca`` exits with 1) for an
    analysis written to ``path`` whose ``analysis_status`` is not ``"ok"``: a torque or roll
    position without a certified contact solution is no result a script may take for one
    (:func:`contact.ltca.summary.certification`)."""
    from contact.errors import AnalysisFailedError

    status = str(tree.attrs.get("analysis_status", "ok"))
    if status != "ok":
        raise AnalysisFailedError(
            f"analysis {status}: {tree.attrs.get('analysis_status_reason', '')}; {path} "
            "holds what was found"
            + (" (root attribute analysis_status)" if str(path).endswith(".nc") else ""))


def rating_steps(method: str | None) -> dict | None:
    """The chain's steps for ``--rating-method``: None (the default chain, the case's
    ``[rating] method`` or ISO 10300) or ``{"load_capacity": method}`` for a registered
    method (an unknown name refused listing the available ones)."""
    if method is None:
        return None
    from contact.load_capacity.methods import METHODS
    from geometry.core.errors import ModelUnavailableError, UnknownNameError

    try:
        return {"load_capacity": METHODS.entry(method).name}
    except ModelUnavailableError as exc:
        raise UnknownNameError(f"--rating-method: {exc}") from None


def rating_lines(tree, why: str = "", case_arg: str | None = None) -> list[str]:
    """The lines ``ltca run`` prints on the rating, from the load-capacity methods' result
    contract (:func:`contact.commands.rating_text.rating_lines`)."""
    from contact.commands.rating_text import rating_lines as lines

    return lines(tree, why, case_arg)


def plastic_summary(ltca, i: int) -> str:
    """'<n> (<share> %)' of torque ``i``: the segments at their force limit counted over
    the roll positions, and the largest share of the torque they carry at one roll
    ('-' for files without the variables)."""
    import numpy as np

    if "plastic_segments" not in ltca:
        return "-"
    n = int(ltca["plastic_segments"].values[i])
    share = np.nan_to_num(ltca["plastic_load_share"].isel(torque=i).values, nan=0.0)
    return f"{n} ({100 * float(np.max(share, initial=0.0)):.1f} %)"


def plastic_note(ltca) -> str:
    """The line under the summary table that says what the plastic column counts."""
    limit = float(ltca.attrs.get("edge_pressure_limit_MPa", float("nan")))
    flank = float(ltca.attrs.get("flank_pressure_limit_MPa", float("nan")))
    if not (math.isfinite(limit) or math.isfinite(flank)):
        return "plastic: no contact-pressure limit (edges elastic to any pressure)."
    where = ", ".join(f"{name} {p:.0f} MPa" for name, p in (("edges", limit), ("flanks", flank))
                      if math.isfinite(p))
    return ("plastic: segments at the material's contact-pressure limit (" + where
            + "), counted over the roll positions (largest share of the torque they carry "
            "at one roll); /ltca/segment_state.")


def print_plausibility_warnings(ltca, case=None, misalignment=None) -> None:
    """A WARNING line for each cause that makes the analysis implausible
    (:func:`contact.ltca.plausibility.plausibility_warnings`), and for a misalignment
    beyond the plausible range of the case's blanks
    (:func:`contact.ltca.plausibility.misalignment_warnings`; ``ltca run`` warns, the
    studies refuse it without ``--force``)."""
    from contact.ltca.plausibility import misalignment_warnings, plausibility_warnings

    texts = plausibility_warnings(ltca, edge_free_spread=False)  # the verdict's lte judges
    if case is not None and misalignment is not None:
        texts += misalignment_warnings(case, misalignment)
    for text in texts:
        print(f"WARNING: {console_text(text)}")


#: findings a command prints under its verdict (the report lists them all)
VERDICT_LINES = 8


def print_verdict(result, rest: str | None = None) -> None:
    """Print the verdict of a result (:func:`contact.study.verdicts.verdict`: an analysis
    tree, a duty cycle or a V-H check), short: its severity and at most
    :data:`VERDICT_LINES` findings, each wrapped at 100 columns; ``rest`` says where the
    findings not printed can be read (default: the report)."""
    import textwrap

    from contact.study.verdicts import verdict

    for line in verdict(result).lines(VERDICT_LINES, rest=rest):
        line = console_text(line)
        indent = " " * (len(line) - len(line.lstrip()))
        print(textwrap.fill(line, 100, initial_indent="", subsequent_indent=indent + "    ",
                            break_on_hyphens=False))


def root_stress_rows(ltca) -> list[tuple[str, ...]]:
    """Rows of the root-stress table `ltca run` prints: per torque, each member's peak
    tooth-root stress [MPa] and the lengthwise face station u where it is (the
    ``fillet_u`` of the peak over rolls and teeth: toe 0, heel 1).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` with ``root_stress`` (torque, roll, member, tooth, fillet_point) and
        ``root_stress_max`` (torque, member).

    Returns
    -------
    list of tuple of str
        (torque, pinion peak, its u, gear peak, its u).
    """
    rs = ltca["root_stress"]
    rows = []
    for i, t in enumerate(ltca["torque"].values):
        cells = [plain_number(t)]
        for member in ("pinion", "gear"):
            face = rs.isel(torque=i).sel(member=member).max(("roll", "tooth"))
            if not bool(face.notnull().any()):  # not computed: the notes say why
                cells += ["nan", "-"]
                continue
            k = int(face.argmax("fillet_point", skipna=True))
            cells += [f"{float(ltca['root_stress_max'].isel(torque=i).sel(member=member)):.0f}",
                      f"{float(face['fillet_u'].values[k]):.2f}"]
        rows.append(tuple(cells))
    return rows


def standard_scuffing(tree, friction):
    """The standard's flash-temperature method on the virtual cylindrical gears of the
    tree's ``/rating`` group and its hypoid lengthwise-sliding variant, with the spread of
    S_B, at the efficiency stage's oil, temperature and roughness
    (:func:`contact.chain.scuffing_flash_temperature`, which the chain's load-capacity step
    stores as ``/rating/flash_temperature``), or None where the tree has no ``/rating`` or
    the method cannot be applied (the reason logged)."""
    if friction is None or "rating" not in tree.children:
        return None
    from contact.chain import scuffing_flash_temperature

    return scuffing_flash_temperature(tree["rating"].to_dataset(), friction)


def durability_lines(friction, standard=None) -> list[str]:
    """The lines `ltca run` prints on scuffing and micropitting: one per torque with the
    peak contact temperature of the flanks (its flash part), the scuffing safety S_B and
    the least specific film thickness λ_GF (and S_λ where the oil gives λ_GFP), each
    followed by the standard's peak contact temperature and S_B on the virtual cylindrical
    gears where ``standard`` gives that torque, then the oil's scuffing temperature and
    why a safety is missing where it is (none for a file that predates the variables).

    Parameters
    ----------
    friction : xarray.Dataset
        The ``/scuffing_micropitting`` dataset
        (:func:`contact.load_capacity.scuffing_micropitting.scuffing_micropitting`; the
        ``/friction`` dataset of a file written before issue 63).
    standard : xarray.Dataset, optional
        The standard's method (:func:`standard_scuffing`) for comparison.

    Returns
    -------
    list of str
    """
    if "contact_temperature_max" not in friction:
        return []
    lines = []
    theta_s = float(friction["scuffing_temperature"])
    inlet = friction.get("specific_film_thickness_min_inlet")
    for i, t in enumerate(friction["torque"].values):
        s_b = float(friction["scuffing_safety"].values[i])
        s_l = float(friction["micropitting_safety"].values[i])
        lines.append(
            f"T_p {plain_number(t)} N m: peak contact temperature "
            f"{float(friction['contact_temperature_max'].values[i]):.0f} degC (flash "
            f"{float(friction['flash_temperature_max'].values[i]):.0f} K), scuffing safety "
            f"S_B {_number(s_b)}, least lambda_GF (film at the bulk temperature theta_M, "
            f"ISO/TS 6336-22) {_film_at_bulk(friction, i)}"
            + (f" (at the oil inlet {float(inlet.values[i]):.3f})" if inlet is not None
               else "")
            + (f", S_lambda {s_l:.2f}" if math.isfinite(s_l) else ""))
        if standard is not None and t in standard["torque"].values:
            lines += _standard_lines(standard.sel(torque=t))
    if math.isfinite(theta_s):
        lines.append(f"scuffing temperature of the oil {theta_s:.0f} degC (FZG load stage "
                     f"{friction.attrs.get('fzg_load_stage', float('nan')):g}); temperatures "
                     "and lambda_GF of the flanks, the edge contacts apart "
                     "(docs/scuffing_micropitting.md); the verdict judges the LTCA's S_B, "
                     "each torque's first"
                     + (", and says where the standard's is below 1 (docs/verdicts.md)"
                        if standard is not None else " (docs/verdicts.md)"))
    for name in ("scuffing_safety", "micropitting_safety"):
        comment = str(friction[name].attrs.get("comment", ""))
        if comment.startswith("NaN"):
            lines.append(f"{name.replace('_', ' ')}: {comment}")
    return lines


#: how the console names the variants of the standard's flash temperature method
STANDARD_VARIANT_LABELS = {
    "standard": "ISO/TS 6336-20 on the ISO 10300 virtual cylindrical gears (the standard)",
    "lengthwise_sliding": "the same with the hypoid's lengthwise sliding (not a standard)",
}


def _standard_lines(iso) -> list[str]:
    """One line per variant of the standard's flash temperature method at one torque: peak
    contact and flash temperature, μ_m, S_B and its spread (a file written before the
    variants has one line)."""
    if "variant" not in iso.dims:
        return [f"  the standard's flash temperature method on the virtual cylindrical gears: "
                f"{float(iso['contact_temperature_max']):.0f} degC, S_B "
                f"{_number(float(iso['scuffing_safety']))}"]
    out, said = [], []
    for v in iso["variant"].values:
        one = iso.sel(variant=v)
        spread = ""
        if "scuffing_safety_low" in one:
            spread = (f" ({_number(float(one['scuffing_safety_low']))}-"
                      f"{_number(float(one['scuffing_safety_high']))} over the uncertain "
                      "constants)")
        numbers = (f"{float(one['contact_temperature_max']):.0f} degC (flash "
                   f"{float(one['flash_temperature_max']):.0f} K, mu_m "
                   f"{float(one['mean_friction_coefficient']):.3f}), S_B "
                   f"{_number(float(one['scuffing_safety']))}{spread}")
        # a pair without offset (a spiral bevel): the variant's numbers are the line
        # above's; said once (round 14: the same numbers printed twice)
        out.append(f"  {STANDARD_VARIANT_LABELS.get(str(v), str(v))}: "
                   + ("the same numbers as the line above" if numbers in said else numbers))
        said.append(numbers)
    return out


def _film_at_bulk(friction, i: int) -> str:
    """The least λ_GF at θ_M of torque ``i`` (3 decimals), or "-" with the reason where
    the bulk temperature lies beyond the oil's data (no film computed there; the
    segments' ``specific_film_thickness`` comment says so) instead of a bare "nan"."""
    lam = float(friction["specific_film_thickness_min"].values[i])
    if math.isfinite(lam):
        return f"{lam:.3f}"
    bulk = friction.get("bulk_temperature")
    comment = str(friction["specific_film_thickness"].attrs.get("comment", "")
                  if "specific_film_thickness" in friction else "")
    if bulk is not None and math.isfinite(float(bulk.values[i])) and "beyond" in comment:
        return (f"- (theta_M {float(bulk.values[i]):.0f} degC lies beyond the oil's "
                "viscosity data: no film computed there)")
    return "-"


def _number(value: float, decimals: int = 2) -> str:
    return f"{value:.{decimals}f}" if math.isfinite(value) else "-"


def print_extrapolation_warning(friction) -> None:
    """One WARNING line when the friction model ran outside its fitted range: how many
    flank segments and their share of the load (from the
    ``model_range_by_contact`` attribute; per segment ``/friction/friction_model_extrapolated``),
    with the edge contacts' count and load share after it. Edge contacts alone (a rounded
    tooth edge, outside every line-contact study's box and checked against the solver
    separately, docs/friction.md) give the line only when they carry ≥ 1 % of the load;
    nothing flagged, nothing printed."""
    import json

    from friction.efficiency import extrapolated_segments

    flagged, _loaded = extrapolated_segments(friction)
    if not flagged:
        return
    try:
        parts = json.loads(friction.attrs.get("model_range_by_contact", "{}"))
    except (TypeError, ValueError):
        parts = {}
    flank, edge = parts.get("flank") or {}, parts.get("edge") or {}
    n_flank, n_edge = int(flank.get("extrapolated", 0)), int(edge.get("extrapolated", 0))
    edge_share = float(edge.get("load_share", 0.0))
    if not n_flank and edge_share < 0.01 and parts:
        return
    model = friction.attrs.get("friction_model", "")
    if not parts:
        print(f"WARNING: {model} extrapolated at {flagged} segments (docs/friction.md)")
        return
    text = (f"WARNING: {model} extrapolated: {n_flank} flank segments "
            f"({float(flank.get('load_share', 0.0)):.2%} of load)")
    if n_edge:
        text += f", {n_edge} edge contacts ({edge_share:.1%})"
    print(text)


def print_mu_warning(friction) -> None:
    """One WARNING line on stderr where the friction model's μ exceeded
    :data:`friction.coefficient.MU_CAP` (0.3; refused above ``MU_MAX`` = 1): the model's
    own warning text from the ``model_range_warnings`` attribute
    (:func:`friction.coefficient.is_mu_above_cap`), the first of them, the others counted;
    nothing where there is none (issue 71: the verdict's attention named it, the console
    did not say the μ). Stderr, as the toolkit's other warnings (logging, Python's
    warnings), so a pipe of the table stays the table."""
    import json

    from friction.coefficient import is_mu_above_cap

    try:
        notes = json.loads(friction.attrs.get("model_range_warnings", "[]"))
    except (TypeError, ValueError):
        return
    said = [str(n) for n in notes if is_mu_above_cap(str(n))]
    if not said:
        return
    more = (f" (and {len(said) - 1} more such in /friction model_range_warnings)"
            if len(said) > 1 else "")
    print(f"WARNING: {console_text(' '.join(said[0].split()))}{more}", file=sys.stderr)


#: the width [characters] the command line wraps its long messages to
LINE_WIDTH = 100

#: the page's unit spellings → the console's (docs/nomenclature.md, Units: one spelling
#: per medium; the console writes the files' UDUNITS spelling, in ASCII)
CONSOLE_UNITS = {"N·m": "N m", "µm": "um", "µrad": "urad", "°C": "degC"}

#: the page's symbols → the console's, in this order (docs/nomenclature.md, Units): the
#: misalignments as the CLI flags name them, the Greek letters as the files' variables do
#: (``sigma_Hlim``, ``lambda_GF``), the page's punctuation in ASCII
CONSOLE_SYMBOLS = {"ΔΣ": "dSigma", "Δ": "d", "Σ": "Sigma", "σ": "sigma", "λ": "lambda",
                   "μ": "mu", "θ": "theta", "ε": "eps", "β": "beta", "α": "alpha", "δ": "delta",
                   "ρ": "rho", "ν": "nu", "η": "eta", "π": "pi", "–": "-", "−": "-",
                   "—": "-", "…": "...", "≥": ">=", "≤": "<=", "×": "x", "±": "+/-",
                   "≈": "~", "→": "->", "²": "2", "³": "3", "’": "'"}


def console_text(text: str) -> str:
    """``text`` (a finding, a warning shared with the HTML report) with its units and
    symbols spelt as the console spells them (:data:`CONSOLE_UNITS`,
    :data:`CONSOLE_SYMBOLS`): ASCII."""
    for page, console in (*CONSOLE_UNITS.items(), *CONSOLE_SYMBOLS.items()):
        text = text.replace(page, console)
    return text


def print_wrapped(text: str, width: int = LINE_WIDTH) -> None:
    """Print ``text`` wrapped to ``width`` columns at spaces (never inside a word, a path
    or a number), its continuation lines indented by two."""
    import textwrap

    print(textwrap.fill(text, width, subsequent_indent="  ", break_long_words=False,
                        break_on_hyphens=False), flush=True)


def write_figures(path: Path, plots: str | None, report: str | None,
                  progress: bool = False) -> None:
    """The PNGs (``--plots``) and the HTML report (``--report``) of the file just written,
    drawn from the file alone (what ``ltca plot`` and ``ltca report`` would draw), each
    figure once."""
    if not plots and not report:
        return
    from contact.plots import render_analysis
    from contact.plots.analysis import figure_prefix
    from contact.plots.report import write_report
    from geometry.core.atomic_files import atomic_path
    from geometry.core.io import read_netcdf

    tree = read_netcdf(path, tree=True)
    prefix = figure_prefix(tree)
    figures = []
    # two processes draw the figures (independent of each other): on two free cores the
    # drawing takes half the wall time (benchmarks/plots.py)
    for rf in render_analysis(tree, n_workers=min(2, os.cpu_count() or 1), progress=progress):
        if plots:
            target = Path(plots) / f"{prefix}{rf.name}.png"
            with atomic_path(target) as tmp:
                tmp.write_bytes(rf.png)
            print(f"wrote {target}")
        if report:
            figures.append(rf)
    if report:
        print(f"wrote {write_report(tree, report, figures)}")


def plot(args: argparse.Namespace) -> int:
    from contact.plots import plot_analysis
    from geometry.core.io import read_netcdf

    path = resolve_analysis_file(args.file)
    check_output_dir(args.plots)
    tree = read_netcdf(path, tree=True)
    for p in plot_analysis(tree, args.plots, n_workers=min(2, os.cpu_count() or 1),
                           progress=not args.no_progress):
        print(f"wrote {p}")
    return 0
