"""Machine-setting optimisation for a loaded target (``ltca optimize``, docs/optimize.md).

Application layer: each design is analysed by :func:`contact.run_analysis` and summarised
by :func:`contact.study.summary.point_summary`; designs run on the study engine's Dask
workers (:mod:`contact.study.engine`).

Modules
-------
variables   the design variables (pinion settings, profile relief, synthesis inputs) and how
            they change a case
objective   the problem (torques, misalignments, limits, weights), objective and constraints
run         the optimiser (scipy differential evolution or Powell), log and provenance
methods     the optimisers by name
development the development bearing of a basic design (``ltca synthesize``'s default
            step): synthesis inputs developed to loaded-pattern, edge and LTE targets
"""

from geometry.core.lazy import lazy_exports

__all__ = ["FAILED_OBJECTIVE", "METHODS", "RELIEF_VARIABLES", "SYNTHESIS_VARIABLES",
           "TERM_NAMES", "DesignVariable", "DevelopmentResult", "DevelopmentTargets",
           "Evaluation", "OptimizeProblem", "OptimizeResult", "SharedDesign", "case_at",
           "check_variables", "constraint_names", "develop", "evaluate_design", "optimize",
           "optimized_case", "problem_from_table", "start_values", "variable_unit"]

#: the public names and their modules, imported when first used (PEP 562): the command
#: line's help needs only :mod:`contact.optimize.methods`, not the optimisation
_LAZY = {
    **dict.fromkeys(("FAILED_OBJECTIVE", "TERM_NAMES", "Evaluation", "OptimizeProblem",
                     "constraint_names", "evaluate_design", "problem_from_table"),
                    "contact.optimize.objective"),
    **dict.fromkeys(("OptimizeResult", "SharedDesign", "optimize", "optimized_case"),
                    "contact.optimize.run"),
    "METHODS": "contact.optimize.methods",
    **dict.fromkeys(("DevelopmentResult", "DevelopmentTargets", "develop"),
                    "contact.optimize.development"),
    **dict.fromkeys(("RELIEF_VARIABLES", "SYNTHESIS_VARIABLES", "DesignVariable", "case_at",
                     "check_variables", "start_values", "variable_unit"),
                    "contact.optimize.variables"),
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
