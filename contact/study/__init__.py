"""Design studies at scale: misalignment maps, Monte Carlo tolerance analysis and the
V-H check, run on Dask (a LocalCluster by default, any cluster by address).

Public functions
----------------
sweep        a full grid of misalignments / deviation scales × torques × speeds
sample       Monte Carlo draws of the inputs from scipy.stats distributions (qmc)
sensitivity  which inputs drive an output's spread (rank correlation, SRC)
vh_check     the offset (V) and pinion mounting (H) that move the pattern to toe and heel
run_points   the engine under all of them: any list of points, on Dask
run_duty_cycle  a load spectrum with torque-dependent misalignment: efficiency, damage, life
read_duty_cycle, example_duty_cycle, DutyCycle, DeflectionTable  its inputs
StudyRun     how a study runs: LTCA options, flank, efficiency conditions, output, Dask
"""

from geometry.core.lazy import lazy_exports

__all__ = [
    "DEFAULT_TORQUE",
    "POINT_INPUTS",
    "STATUS_MEANINGS",
    "SUMMARY_VARIABLES",
    "SYNCHRONOUS",
    "DeflectionTable",
    "DutyCycle",
    "StudyInputs",
    "StudyRun",
    "analyse_point",
    "draw_points",
    "example_duty_cycle",
    "open_client",
    "parse_distribution",
    "point_summary",
    "read_duty_cycle",
    "run_duty_cycle",
    "run_points",
    "sample",
    "sensitivity",
    "study_inputs",
    "sweep",
    "vh_check",
]

#: the public names and their modules, imported when first used (PEP 562): a Dask worker
#: unpickling the engine's task imports :mod:`contact.study.engine` and what an analysis
#: needs, not the Monte Carlo draws (scipy.stats), the duty cycle or the V-H check
#: (~0.35 s of CPU per worker process)
_LAZY = {
    "run_duty_cycle": "contact.study.duty_cycle",
    **dict.fromkeys(("DeflectionTable", "DutyCycle", "example_duty_cycle",
                     "read_duty_cycle"), "contact.study.duty_cycle_inputs"),
    **dict.fromkeys(("SYNCHRONOUS", "analyse_point", "open_client", "run_points"),
                    "contact.study.engine"),
    **dict.fromkeys(("DEFAULT_TORQUE", "study_inputs", "sweep"), "contact.study.grid"),
    **dict.fromkeys(("draw_points", "parse_distribution", "sample", "sensitivity"),
                    "contact.study.monte_carlo"),
    **dict.fromkeys(("POINT_INPUTS", "StudyInputs"), "contact.study.points"),
    "StudyRun": "contact.study.run",
    **dict.fromkeys(("STATUS_MEANINGS", "SUMMARY_VARIABLES", "point_summary"),
                    "contact.study.summary"),
    "vh_check": "contact.study.vh_check",
}
__getattr__, __dir__ = lazy_exports(__name__, _LAZY, globals())
