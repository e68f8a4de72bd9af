"""The options the ``ltca`` commands share, written once: same name, same meaning everywhere.

Each function adds one option (or one group of options) to a sub-command's parser; the
commands call them instead of spelling the options themselves, so ``--torque``,
``--dE/--dP/--dG/--dSigma``, ``--rolls-per-cycle``, ``-o FILE``, ``--plots DIR``,
``--solver``, ``--flank`` and the operating conditions read the same in every
``ltca COMMAND --help``. Old spellings that scripts may use stay as hidden aliases
(:func:`deprecated_alias`) that warn once.

Units at this boundary: lengths [mm], ΔΣ [deg] (as in case files; ``Misalignment`` holds
rad), torques [N·m], speeds [rpm], temperatures [degC], roughness [µm].

Public functions
----------------
case_argument           the positional CASE: a case file or a bundled name (default case)
analysis_file_argument  the positional FILE of ``plot``/``report``: a netCDF file or a case name
torque_option           --torque
misalignment_options    --dE --dP --dG --dSigma (numbers, ranges or distributions)
misalignment_from_args  a Misalignment from those numbers over a base
operating_options       --speed --lubricant --temperature --roughness --surface-state
                        --friction-model
rolls_per_cycle_option  --rolls-per-cycle (alias --n-roll)
segments_option         --segments
flank_option            --flank
solver_option           --solver
output_option           -o/--output FILE
default_output          the output path named after the case unless -o was given
plots_option            --plots DIR
progress_option         --no-progress
verbosity_options       -v/--verbose, -q/--quiet (accepted before and after the command)
deprecated_alias        a hidden old spelling of an option that warns when used
count                   an argparse type: an integer in a closed range (counts, budgets)
root_stress_option      --root-stress/--no-root-stress (on by default)
film_model_options      --viscosity-model --isothermal (the mixed-EHL film)
ROOT_STRESS_COST        what the root stress costs, as the options and hints say it
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

__all__ = [
    "FE_LEVEL_NAMES",
    "FLANK_CHOICES",
    "analysis_file_argument",
    "case_argument",
    "case_stem",
    "checked_fe_level",
    "count",
    "default_output",
    "deprecated_alias",
    "fe_level_option",
    "film_model_options",
    "flank_option",
    "misalignment_from_args",
    "misalignment_options",
    "number_list",
    "operating_options",
    "output_option",
    "plots_option",
    "progress_option",
    "rolls_per_cycle_option",
    "root_stress_option",
    "segments_option",
    "solver_option",
    "torque_option",
    "verbosity_options",
]

#: ``--flank``: the pinion flank in contact, by role or by name (contact.utca.easeoff)
FLANK_CHOICES = ("drive", "coast", "concave", "convex")

#: ``--dE`` … → (Misalignment field, unit typed, factor to the field's unit, meaning)
MISALIGNMENT_OPTIONS = {
    "dE": ("delta_E", "mm", 1.0, "offset change dE (V), positive increases the offset"),
    "dP": ("delta_P", "mm", 1.0, "pinion axial displacement dP (H), positive away from the "
           "mesh"),
    "dG": ("delta_G", "mm", 1.0, "gear axial displacement dG, positive away from the mesh"),
    "dSigma": ("delta_Sigma", "deg", math.pi / 180.0,
               "shaft-angle change dSigma, positive increases the shaft angle"),
}


class _Deprecated(argparse.Action):
    """Store into ``dest`` like the new option, and say on stderr that the spelling is old."""

    def __init__(self, option_strings, dest, new: str = "", const_value=None, **kw):
        self.new = new
        self.const_value = const_value
        super().__init__(option_strings, dest, **kw)

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"ltca: warning: {option_string} is deprecated and will be removed; use "
              f"{self.new}", file=sys.stderr)
        setattr(namespace, self.dest, self.const_value if self.nargs == 0 else values)


def deprecated_alias(p: argparse.ArgumentParser, old: str, new: str, dest: str, *,
                     type=None, nargs=None) -> None:
    """A hidden option ``old`` that stores into ``dest`` as ``new`` does and warns.

    Parameters
    ----------
    p : argparse.ArgumentParser
    old, new : str
        The old spelling (hidden from ``--help``) and the one that replaces it.
    dest : str
        The destination of ``new``.
    """
    kw = {"type": type} if type is not None else {}
    if nargs is not None:
        kw["nargs"] = nargs
    p.add_argument(old, dest=dest, action=_Deprecated, new=new, help=argparse.SUPPRESS,
                   default=argparse.SUPPRESS, **kw)


def case_argument(p: argparse.ArgumentParser, *, many: bool = False,
                  what: str = "analyse") -> None:
    """The positional ``CASE``: a case file (TOML) or a bundled case name (``ltca cases``);
    default the bundled default case (``many``: every bundled case)."""
    default = "every bundled case" if many else "the bundled default case, " \
        "kolivand2009_fm_11x41_reference"
    p.add_argument("case", nargs="*" if many else "?", default=None, metavar="CASE",
                   help=f"case to {what}: a case file (TOML) or a bundled case name "
                        f"(`ltca cases`); default {default}")


def analysis_file_argument(p: argparse.ArgumentParser, *, written_by: str = "ltca run") -> None:
    """The positional ``FILE`` of a command that reads an analysis file: a netCDF path, or
    a case name whose ``<name>.nc`` (what ``ltca run NAME`` writes) is read; default the
    default case's file."""
    p.add_argument("file", nargs="?", default=None, metavar="FILE",
                   help=f"netCDF file written by `{written_by}`, or a case name for "
                        "<name>.nc in this directory (default "
                        "kolivand2009_fm_11x41_reference.nc, what a bare `ltca run` writes)")


def resolve_analysis_file(arg: str | None) -> Path:
    """The file of :func:`analysis_file_argument`: ``arg`` if it is a file, else
    ``<arg>.nc``; None gives the default case's ``<name>.nc``.

    Raises
    ------
    InputError
        Neither exists (the message says which command writes it).
    """
    from contact.catalogue import DEFAULT_CASE
    from geometry.core.errors import InputError

    name = arg if arg is not None else DEFAULT_CASE.removesuffix(".toml")
    path = Path(name)
    if path.is_dir():
        raise InputError(f"FILE: {str(path)!r} is a directory, not an analysis file (netCDF)")
    if path.is_file():
        if not _is_netcdf(path):
            what = ("a case file (TOML)" if path.suffix == ".toml" else "not a netCDF file")
            raise InputError(f"FILE: {str(path)!r} is {what}, not an analysis file: "
                             f"`ltca run {name}` writes {path.stem}.nc, which this command "
                             "reads")
        return path
    named = Path(f"{path.name.removesuffix('.toml')}.nc")
    if path.suffix in ("", ".toml") and named.is_file():
        return named
    tried = repr(str(path)) if named == path else f"{str(path)!r} nor {str(named)!r}"
    raise InputError(f"FILE: no such file {tried} (`ltca run CASE` writes CASE.nc)")


def _is_netcdf(path: Path) -> bool:
    """Whether a file starts as netCDF does (classic ``CDF``, or netCDF-4's HDF5
    signature)."""
    try:
        with open(path, "rb") as f:
            head = f.read(8)
    except OSError:
        return False
    return head[:3] == b"CDF" or head == b"\x89HDF\r\n\x1a\n"


def number_list(text: str) -> list[float]:
    """``"50"`` or ``"50,250"`` → [50.0] or [50.0, 250.0] (an argparse ``type``).

    Raises
    ------
    argparse.ArgumentTypeError
        A part that is not a finite number.
    """
    out = []
    for part in text.split(","):
        try:
            x = float(part)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"expected numbers separated by spaces or commas, got {text!r}") from None
        if not math.isfinite(x):
            raise argparse.ArgumentTypeError(f"must be finite, got {text!r}")
        out.append(x)
    return out


class _Flatten(argparse.Action):
    """Store the numbers of ``nargs="+"`` tokens, each a number or comma list, as one list."""

    def __call__(self, parser, namespace, values, option_string=None):
        setattr(namespace, self.dest, [x for v in values for x in v])


class _One(argparse.Action):
    """Store one number (a comma list of several is refused)."""

    def __call__(self, parser, namespace, values, option_string=None):
        if len(values) != 1:
            parser.error(f"argument {option_string}: one value, got {len(values)}")
        setattr(namespace, self.dest, values[0])


def torque_option(p: argparse.ArgumentParser, *, many: bool = True,
                  default: str = "the case's [operating] torques, 50 250 500 for the "
                                 "default case") -> None:
    """``--torque N_M [N_M ...]``: pinion torques [N·m], separated by spaces or commas (as
    every command takes them)."""
    p.add_argument("--torque", type=number_list, nargs="+" if many else None,
                   action=_Flatten if many else _One, default=None, metavar="N_M",
                   help=f"pinion torque{'s' if many else ''} [N m]"
                        f"{', by spaces or commas' if many else ''} (default {default})")


def misalignment_options(p: argparse.ArgumentParser, *, kind: str = "value",
                         default: str = "the case's [operating] values",
                         extra: dict[str, str] | None = None) -> None:
    """``--dE --dP --dG [mm] --dSigma [deg]``: misalignments over the case's.

    Parameters
    ----------
    kind : {"value", "range", "distribution"}
        A number each (``ltca run``), a ``START:STOP:N`` range (``ltca sweep``) or a
        distribution (``ltca tolerance``).
    default : str
        What an option not given means (for the help).
    extra : dict, optional
        Option → help text replacing the generic one (e.g. ``vh-check``'s V, H grids).
    """
    g = p.add_argument_group("misalignment (dE, dP, dG in mm; dSigma in deg, as in case files)")
    metavar = {"value": None, "range": "RANGE", "distribution": "DIST"}[kind]
    for opt, (_field, unit, _factor, meaning) in MISALIGNMENT_OPTIONS.items():
        if extra is not None and opt not in extra:
            continue
        text = (extra or {}).get(opt) or f"{meaning} [{unit}] (default {default})"
        kw = ({"type": float, "metavar": unit.upper()} if kind == "value"
              else {"metavar": metavar})
        g.add_argument(f"--{opt}", default=None, help=text, **kw)


def misalignment_from_args(args: argparse.Namespace, base):
    """A Misalignment from ``--dE --dP --dG [mm] --dSigma [deg]`` over ``base``.

    Parameters
    ----------
    args : argparse.Namespace
        With ``dE``, ``dP``, ``dG``, ``dSigma`` (None: not given).
    base : geometry.pair.assembly.Misalignment or None
        The values of the options not given (None: aligned).

    Returns
    -------
    geometry.pair.assembly.Misalignment or None
        ``base`` when no option is given.
    """
    from geometry.pair.assembly import Misalignment

    given = {opt: getattr(args, opt, None) for opt in MISALIGNMENT_OPTIONS}
    if all(v is None for v in given.values()):
        return base
    kw = {} if base is None else {f: getattr(base, f) for f, *_ in
                                  MISALIGNMENT_OPTIONS.values()}
    for opt, value in given.items():
        field, _unit, factor, _ = MISALIGNMENT_OPTIONS[opt]
        if value is not None:
            kw[field] = value * factor
    return Misalignment(**kw)


def operating_options(p: argparse.ArgumentParser, *, many: bool = False,
                      speed_help: str = "") -> None:
    """``--speed --lubricant --temperature --roughness --surface-state --friction-model``:
    the efficiency stage's conditions, each defaulting to the case's ``[operating]`` table
    (``--surface-state`` to :class:`friction.operating.OperatingConditions`' run-in)."""
    from friction.defaults import DEFAULT_FRICTION_MODEL
    from geometry.core.operating_defaults import OPERATING_DEFAULTS as D

    g = p.add_argument_group("operating conditions of the efficiency stage (default: the "
                             "case's [operating] table; the values in brackets are the "
                             "default case's)")
    nargs = "+" if many else None
    g.add_argument("--speed", type=float, nargs=nargs, default=None, metavar="RPM",
                   help=speed_help or f"pinion speed [rpm] (0: no efficiency stage) "
                                      f"({D['pinion_speed']:g} rpm)")
    g.add_argument("--lubricant", default=None,
                   help=f"bundled oil name or oil TOML file ({D['lubricant']})")
    g.add_argument("--temperature", type=float, nargs=nargs, default=None, metavar="DEGC",
                   help=f"oil inlet temperature [degC] ({D['temperature']:g} degC)")
    g.add_argument("--roughness", type=float, nargs=nargs, default=None, metavar="UM",
                   help=f"RMS roughness Rq of each flank [um] ({D['roughness']:g} um)")
    g.add_argument("--surface-state", choices=("run_in", "new"), default=None,
                   help="the flanks' state: run_in (a gear in service: the film and friction "
                        "on Rq x 0.68, AGMA's run-in improvement of carburised gears) or new "
                        "(Rq as given) (run_in; docs/friction.md)")
    g.add_argument("--friction-model", default=None,
                   help=f"friction coefficient model: a bundled one, or one of an "
                        f"installed plug-in (docs/extending.md) ({DEFAULT_FRICTION_MODEL})")


def count(low: int, high: int):
    """An argparse ``type``: an integer in [low, high], refused by the parser (before any
    work, exit 2) with ``must be an integer in [low, high], got VALUE`` otherwise — for the
    options that bound work (evaluation budgets, repeats, points, workers, steps), whose
    zero or negative value would otherwise fall back to a default or run without end.

    Parameters
    ----------
    low, high : int
        The accepted range, both ends included.

    Returns
    -------
    callable
        ``str -> int`` for ``add_argument(type=...)``.
    """
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"must be an integer in [{low}, {high}], got {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(
                f"must be an integer in [{low}, {high}], got {value}")
        return value

    parse.__name__ = "integer"  # argparse names the type in its messages
    return parse


#: what the root stress costs, as the options' help and `ltca run`'s hint say it (docs/fe.md,
#: "Cost": the default FE model of the default case with the default solver, CHOLMOD, on
#: one core, issue 53)
ROOT_STRESS_COST = ("the first run of a design builds its FE influence coefficients, ~15-20 s "
                    "per member (~35 s for both on the default case, up to 1.5 GB), later "
                    "runs read them from the cache (~1 s)")


def film_model_options(p: argparse.ArgumentParser) -> None:
    """``--viscosity-model`` and ``--isothermal``: the mixed-EHL film's viscosity-pressure
    law and whether its shear sees the surfaces' flash temperature (``ltca ehl`` and the
    friction study: one condition or many, the same model)."""
    p.add_argument("--viscosity-model", choices=("barus", "roelands"), default="barus",
                   help="viscosity-pressure law of the film and its shear (default "
                   "%(default)s, the friction study's and the mu model's)")
    p.add_argument("--isothermal", action="store_true",
                   help="the film's shear at the inlet temperature, without the surfaces' "
                   "flash temperature (smooth and rough films alike)")


def root_stress_option(p: argparse.ArgumentParser, what: str) -> None:
    """``--root-stress/--no-root-stress``: the tooth-root stress of both members from FE
    influence coefficients, on by default (issue 53); ``what`` says what it adds in this
    command."""
    p.add_argument("--root-stress", action=argparse.BooleanOptionalAction, default=True,
                   help=f"{what} (on by default; docs/fe.md): {ROOT_STRESS_COST}; "
                        "--no-root-stress leaves it out")


#: the FE levels ``--fe-level`` accepts, as the help text names them (the keys of
#: :data:`contact.compliance.fe.options.LEVELS`, which the command checks against: not
#: imported to build the parser)
FE_LEVEL_NAMES = ("default", "coarse", "coarse10")


def fe_level_option(p: argparse.ArgumentParser, what: str) -> None:
    """``--fe-level LEVEL``: the FE model of the root stress by its level
    (:data:`contact.compliance.fe.options.LEVELS`); ``what`` says its default in this
    command."""
    p.add_argument("--fe-level", default=None, metavar="LEVEL",
                   help=f"the FE model of the root stress: {', '.join(FE_LEVEL_NAMES)} "
                        f"(docs/fe.md: coarse10's peak root stress -1.0 ... +7.1 %% of the "
                        f"default model's, at ~0.5 of its build CPU); {what}")


def checked_fe_level(level: str | None) -> str | None:
    """``--fe-level``'s value checked against the levels (None where not given).

    Raises
    ------
    InputError — a level not in :data:`contact.compliance.fe.options.LEVELS` (named as
        ``--fe-level``, with the levels).
    """
    if level is None:
        return None
    from contact.compliance.fe.options import LEVELS
    from geometry.core.errors import InputError

    if level not in LEVELS:
        raise InputError(f"--fe-level: must be one of {', '.join(LEVELS)} (the FE model "
                         f"of the root stress, docs/fe.md), got {level!r}")
    return level


def rolls_per_cycle_option(p: argparse.ArgumentParser, default: int | None = None,
                           alias: str | None = None) -> None:
    """``--rolls-per-cycle N``: roll positions per mesh cycle (``alias``: an old spelling)."""
    text = "the LTCA's, 20" if default is None else str(default)
    p.add_argument("--rolls-per-cycle", type=count(4, 400), default=default, metavar="N",
                   help=f"roll positions per mesh cycle (default {text})")
    if alias:
        deprecated_alias(p, alias, "--rolls-per-cycle", "rolls_per_cycle", type=int)


def segments_option(p: argparse.ArgumentParser) -> None:
    """``--segments N``: segments per contact curve (default the LTCA's, 24)."""
    p.add_argument("--segments", type=count(2, 1000), default=None, metavar="N",
                   help="segments per contact curve (default the LTCA's, 24)")


def flank_option(p: argparse.ArgumentParser, default: str | None = None) -> None:
    """``--flank``: the pinion flank in contact, ``drive``/``coast`` or by name."""
    p.add_argument("--flank", choices=FLANK_CHOICES, default=default,
                   help="pinion flank in contact: drive, coast, or by name concave/convex "
                        "(default drive)")


def solver_option(p: argparse.ArgumentParser) -> None:
    """``--solver NAME``: the contact solver (default the exact ``active_set``)."""
    p.add_argument("--solver", default=None, metavar="NAME",
                   help="contact solver (default active_set; `ltca compare-solvers` lists "
                        "them, those of installed plug-ins among them: docs/extending.md)")


def pressure_limit_options(p: argparse.ArgumentParser) -> None:
    """``--edge-pressure-limit``, ``--flank-pressure-limit``: the elastic–perfectly-plastic
    limits of the edge and flank segments (``LTCAOptions``)."""
    from geometry.core.materials import CONTACT_PRESSURE_LIMITS

    names = [*CONTACT_PRESSURE_LIMITS, "none"]
    p.add_argument("--edge-pressure-limit", choices=names, default=None,
                   help="contact-pressure limit of the edge segments, from the members' "
                        "material (default shakedown; none: elastic to any pressure)")
    p.add_argument("--flank-pressure-limit", choices=names, default=None,
                   help="the same limit on the flank (contact-curve) segments (default "
                        "none)")


def compliance_name(name: str) -> str:
    """An argparse ``type``: a name of the compliance models' registry
    (:mod:`contact.ltca.compliance_models`, read when the option is given, so that
    ``ltca --help`` imports no NumPy); an unknown name is refused at parsing, listing the
    available ones."""
    from contact.ltca.compliance_models import get_compliance_model
    from geometry.core.errors import ModelUnavailableError

    try:
        return get_compliance_model(name).name
    except ModelUnavailableError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def compliance_option(p: argparse.ArgumentParser) -> None:
    """``--compliance NAME``: the teeth's compliance model (``LTCAOptions.compliance``)."""
    p.add_argument("--compliance", type=compliance_name, default=None, metavar="NAME",
                   help="tooth compliance of the loaded TCA: shell (default; the seed's "
                        "tapered shells on a fillet foundation), fe (3-D FE models of the "
                        "generated teeth, fillets and rim, docs/fe.md: the first run of a "
                        "design builds their influence coefficients, ~0.5-1.5 min per member "
                        "with PARDISO, then reads them from the cache) or a model of an "
                        "installed plug-in (docs/extending.md); Weber's contact term in all")


def output_option(p: argparse.ArgumentParser, *, default: str, what: str = "netCDF file",
                  metavar: str = "FILE") -> None:
    """``-o/--output FILE``; ``default`` describes the name used without it."""
    p.add_argument("-o", "--output", default=None, metavar=metavar,
                   help=f"{what} to write (default {default})")


def case_stem(case: str | None) -> str:
    """The name a CASE argument's outputs are named after, known before the case is
    loaded (so output paths are checked before any work): the bundled name, or the case
    file's name without ``.toml``; None the default case's."""
    from contact.catalogue import DEFAULT_CASE

    return Path(DEFAULT_CASE if case is None else case).name.removesuffix(".toml")


def default_output(args: argparse.Namespace, suffix: str = ".nc") -> str:
    """``-o`` if given, else the file named after the case: ``<case><suffix>``
    (:func:`case_stem` of ``args.case``); of a command run on another flank than the
    drive (``--flank coast``, or a pinion flank by name), ``<case>_<flank><suffix>``, so
    that ``ltca run CASE --flank coast`` does not replace the drive's ``<case>.nc`` of
    ``ltca run CASE`` (issue 71, round 13: it did, with the same "wrote" line)."""
    if args.output:
        return args.output
    flank = getattr(args, "flank", None)
    named = f"_{flank}" if flank not in (None, "drive") else ""
    return f"{case_stem(args.case)}{named}{suffix}"


def checked_outputs(args: argparse.Namespace, suffix: str = ".nc",
                    more: dict[str, str | None] | None = None) -> str:
    """The command's output file (:func:`default_output`), checked before any work with
    ``--plots`` (if the command has it and it is given) and the further output files
    ``more`` (``{option: path}``, None = not asked for).

    Raises
    ------
    contact.commands.output_paths checks' InputError
        an output that cannot be written, naming its option.
    """
    from contact.commands.output_paths import check_output_dir, check_output_file

    output = default_output(args, suffix)
    check_output_file(output)
    if getattr(args, "plots", None):
        check_output_dir(args.plots)
    for option, path in (more or {}).items():
        if path:
            check_output_file(path, option=option)
    return output


def case_and_misalignment(args: argparse.Namespace):
    """The command's case (:func:`contact.catalogue.resolve_case` of ``args.case``) and
    its misalignment: the case's own, with the ``--dE/--dP/--dG/--dSigma`` given
    (:func:`misalignment_from_args`).

    Returns
    -------
    (Case, Misalignment)
    """
    from contact.catalogue import resolve_case

    case = resolve_case(args.case)
    return case, misalignment_from_args(args, case.misalignment)


def plots_option(p: argparse.ArgumentParser, default: str | None = None) -> None:
    """``--plots DIR``: directory of the PNG figures (created if missing)."""
    p.add_argument("--plots", default=default, metavar="DIR",
                   help="write the PNG figures into DIR" +
                        (f" (default {default})" if default else ""))


def progress_option(p: argparse.ArgumentParser) -> None:
    """``--no-progress`` (progress bars show only on a terminal and without ``-q``)."""
    p.add_argument("--no-progress", action="store_true",
                   help="no progress bars (they show only on a terminal, and not with -q)")


def verbosity_options(p: argparse.ArgumentParser, *, top: bool = False) -> None:
    """``-v/--verbose`` (repeatable) and ``-q/--quiet``; on the top parser and on every
    sub-command, so they are accepted before and after the command (counted together)."""
    suffix = "" if top else "_sub"
    p.add_argument("-v", "--verbose", action="count", default=0, dest=f"verbose{suffix}",
                   help="more log output (-v info, -vv debug)")
    p.add_argument("-q", "--quiet", action="store_true", dest=f"quiet{suffix}",
                   help="warnings and errors only, no progress bars")
