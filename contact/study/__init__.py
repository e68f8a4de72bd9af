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

from contact.study.duty_cycle import run_duty_cycle
from contact.study.duty_cycle_inputs import (
    DeflectionTable,
    DutyCycle,
    example_duty_cycle,
    read_duty_cycle,
)
from contact.study.engine import SYNCHRONOUS, analyse_point, open_client, run_points
from contact.study.grid import DEFAULT_TORQUE, study_inputs, sweep
from contact.study.monte_carlo import draw_points, parse_distribution, sample, sensitivity
from contact.study.points import POINT_INPUTS, StudyInputs
from contact.study.run import StudyRun
from contact.study.summary import STATUS_MEANINGS, SUMMARY_VARIABLES, point_summary
from contact.study.vh_check import vh_check

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
