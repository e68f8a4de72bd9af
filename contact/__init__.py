"""Contact analysis of hypoid and spiral bevel gears: UTCA, compliance, the loaded-contact QP, LTCA.

Five layers, each a subpackage, each importing only those below it (tests/test_layers.py):

* :mod:`contact.qp` — the loaded-contact problem, its solver registry and studies (no gear);
* :mod:`contact.utca` — ease-off, contact curves, unloaded TE, deviations;
* :mod:`contact.compliance` — tooth bending and shear (shell), Weber contact, fillet
  foundation;
* :mod:`contact.ltca` — the loaded TCA over the mesh cycle (segments, screening, roll
  loop, dataset);
* the application on top: :mod:`contact.pipeline` (the whole analysis of a case),
  :mod:`geometry.core.io` (netCDF), :mod:`contact.plots`, :mod:`contact.cli` and
  :mod:`contact.commands` (the ``ltca`` command).

The loaded-contact problem and its solvers::

    from contact import ContactProblem, solve_contact, available_solvers

The whole analysis of a case (geometry → ease-off UTCA → LTCA) as one DataTree::

    from contact import run_analysis

Its steps (geometry, utca, ltca, root stress, mesh interface, efficiency, load capacity),
each chosen by name, replaced by a callable or skipped::

    from contact import AnalysisChain, available_steps

Every per-process cache (memo) of the toolkit is emptied by one call::

    from contact import clear_caches

The names in ``__all__`` are the package's public, stable surface (issue 54; with those of
``friction`` and ``geometry``, docs/api.md): the analysis, its options and files, the
studies, duty cycle, rating, optimisation and report, the QP and its solver registry, the
compliance-model registry. Everything else is internal and may move.
"""

from geometry import __version__
from geometry.core.lazy import lazy_exports

__all__ = [
    "DEFAULT_CASE",
    "DEFAULT_SOLVER",
    "DEFAULT_TOLERANCE",
    "AnalysisChain",
    "ChainState",
    "ContactError",
    "ContactProblem",
    "ContactSolution",
    "DevelopmentTargets",
    "DutyCycle",
    "FEOptions",
    "LTCAOptions",
    "NotPositiveDefiniteError",
    "OptimizeProblem",
    "ProblemInputError",
    "SolverNotFoundError",
    "StudyRun",
    "__version__",
    "available_compliance_models",
    "available_rating_methods",
    "available_solvers",
    "available_steps",
    "bundled_case_path",
    "bundled_cases",
    "clear_caches",
    "contact_pattern_figure",
    "contact_residuals",
    "develop",
    "ease_off",
    "example_duty_cycle",
    "export_rexs",
    "fe_compliance_matrix",
    "fillet_stress",
    "import_rexs",
    "influence_coefficients",
    "iso10300_capacity",
    "iso10300_rating",
    "load_share_figure",
    "loaded_tca",
    "map_figure",
    "plot_analysis",
    "rate_load_capacity",
    "read_deviations",
    "read_duty_cycle",
    "read_netcdf",
    "register_backend",
    "register_compliance_model",
    "register_rating_method",
    "resolve_case",
    "run_analysis",
    "run_duty_cycle",
    "sample",
    "save_png",
    "scuffing_micropitting",
    "sensitivity",
    "shell_assembler",
    "solve_contact",
    "sweep",
    "synthesize_case",
    "transmission_error_figure",
    "unloaded_tca",
    "unregister_backend",
    "unregister_compliance_model",
    "unregister_rating_method",
    "validate_rexs",
    "verdict",
    "vh_check",
    "write_netcdf",
    "write_report",
]

#: the public names and the module each comes from, imported when first used (PEP 562):
#: the QP layer pulls in SciPy and the pipeline the whole chain, which ``ltca --help`` and
#: ``ltca cases`` do not need (issue 32: start-up ≤ 0.5 s). This is the stable surface
#: (issue 54): the examples and the documentation import from here, never from a submodule.
_LAZY = {
    **dict.fromkeys(("DEFAULT_SOLVER", "DEFAULT_TOLERANCE", "ContactProblem", "ContactSolution",
                     "available_solvers", "contact_residuals", "solve_contact"), "contact.qp"),
    **dict.fromkeys(("register_backend", "unregister_backend"), "contact.qp.solvers"),
    **dict.fromkeys(("ContactError", "NotPositiveDefiniteError", "ProblemInputError",
                     "SolverNotFoundError"), "contact.errors"),
    **dict.fromkeys(("DEFAULT_CASE", "bundled_case_path", "bundled_cases", "resolve_case"),
                    "contact.catalogue"),
    **dict.fromkeys(("LTCAOptions", "loaded_tca", "available_compliance_models",
                     "register_compliance_model"), "contact.ltca"),
    **dict.fromkeys(("ease_off", "unloaded_tca"), "contact.utca"),
    "read_deviations": "contact.utca.deviation_files",
    **dict.fromkeys(("FEOptions", "fe_compliance_matrix", "fillet_stress",
                     "influence_coefficients"), "contact.compliance.fe"),
    **dict.fromkeys(("shell_assembler", "unregister_compliance_model"),
                    "contact.ltca.compliance_models"),
    **dict.fromkeys(("DutyCycle", "StudyRun", "example_duty_cycle", "read_duty_cycle",
                     "run_duty_cycle", "sample", "sensitivity", "sweep", "vh_check"),
                    "contact.study"),
    "verdict": "contact.study.verdicts",
    # (the optimiser itself is contact.optimize.optimize: a name ``optimize`` here would
    # hide the subpackage)
    **dict.fromkeys(("OptimizeProblem", "develop", "DevelopmentTargets"), "contact.optimize"),
    # the case `ltca synthesize` writes and its lines (issue 71, branch api88)
    "synthesize_case": "contact.optimize.synthesized_case",
    "iso10300_rating": "contact.load_capacity.iso10300",
    "iso10300_capacity": "contact.load_capacity.iso10300.capacity",
    **dict.fromkeys(("available_rating_methods", "rate_load_capacity", "register_rating_method",
                     "unregister_rating_method"), "contact.load_capacity.methods"),
    "scuffing_micropitting": "contact.load_capacity.scuffing_micropitting",
    "write_report": "contact.plots.report",
    # the figures a user draws most (every figure: contact.plots, an internal module)
    **dict.fromkeys(("contact_pattern_figure", "load_share_figure", "map_figure",
                     "plot_analysis", "save_png", "transmission_error_figure"), "contact.plots"),
    **dict.fromkeys(("read_netcdf", "write_netcdf"), "geometry.core.io"),
    "run_analysis": "contact.pipeline",
    **dict.fromkeys(("AnalysisChain", "ChainState", "available_steps"), "contact.chain"),
    "clear_caches": "geometry.core.caches",
    # REXS bevel stages in and out (docs/exchange.md)
    **dict.fromkeys(("export_rexs", "import_rexs", "validate_rexs"), "contact.exchange.rexs"),
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
