"""One or two examples per ``ltca`` command, shown at the end of its ``--help``.

Every example runs as written from any directory (bundled case names, files named after
the case); ``tests/test_cli_messages.py`` checks that each command has its examples and
that they parse.
"""

from __future__ import annotations

__all__ = ["EXAMPLES", "TOP_EXAMPLES"]

#: ``ltca --help``
TOP_EXAMPLES = (
    "ltca run                        # the default case at its [operating] conditions",
    "ltca run kolivand2009_fh_12x41 --torque 100 300 --plots figs",
    "ltca cases                      # the bundled case names every command takes",
)

#: command → its examples
EXAMPLES: dict[str, tuple[str, ...]] = {
    "cases": ("ltca cases",),
    "run": ("ltca run                                  # 50/250/500 N m, 1500 rpm",
            "ltca run kolivand2009_fh_12x41 --torque 200 --dE 0.05 --plots figs "
            "--report report.html"),
    "plot": ("ltca plot kolivand2009_fm_11x41_reference.nc --plots figs",),
    "report": ("ltca report kolivand2009_fm_11x41_reference.nc -o report.html",),
    "mesh-interface": ("ltca mesh-interface                       # "
                       "<case>_mesh_interface.csv",
                       "ltca mesh-interface kolivand2009_fh_12x41 --torque 100 200 300 "
                       "-o mesh.csv --plots figs"),
    "efficiency-map": ("ltca efficiency-map --speed 500 1500 4000 --torque 100 500",
                       "ltca efficiency-map --speed 1500 --torque 500 --temperature 50 90 "
                       "--roughness 0.4 0.8"),
    "wear": ("ltca wear --torque 200 --wear-coefficient 1e-17 --cycles 2.5e6 --steps 10 "
             "-o wear.nc",),
    "rate": ("ltca rate iso10300_30_sample1 --torque 300 --speed 1200",
             "ltca rate iso10300_30_sample3 -o rating.nc",
             "ltca rate agma2003_d19_annex_e --method agma2003 --torque 162.70 --speed 1750"),
    "ehl": ("ltca ehl --pressure 1.0 --radius 20 --speed 5 --slide-to-roll 0.3 "
            "--temperature 75 --roughness 0 0 -o ehl.nc",),
    "friction-study": ("ltca friction-study -n 16 --nodes 128 -o friction_study.nc",
                       "ltca friction-study --design factorial --scheduler tcp://host:8786 "
                       "-o table_5_1.nc"),
    "friction-fit": ("ltca friction-fit friction_study.nc -o kolivand2009_fit.toml",),
    "compile": ("ltca compile",),
    "oil": ("ltca oil --name VG220_mineral --nu40 220 --nu100 19.4 --rho15 890 "
            "--base-oil mineral --fzg-stage 12 --source vendor-data-sheet "
            "-o vg220_mineral.toml",),
    "duty-cycle": ("ltca duty-cycle -o duty.nc --plots duty_plots   # illustrative spectrum",
                   "ltca duty-cycle kolivand2009_fm_11x41_reference --duty spectrum.toml "
                   "--no-root-stress -o duty.nc"),
    "geometry": ("ltca geometry -o flanks.nc",),
    "plot-geometry": ("ltca plot-geometry -o figs",),
    "synthesize": ("ltca synthesize kolivand2009_fh_12x41 -o my_case.toml",),
    "export-rexs": ("ltca export-rexs kolivand2009_fh_12x41 -o stage.rexs --version 1.7",
                    "ltca export-rexs kolivand2009_fm_11x41_reference "
                    "kolivand2009_fm_11x41_reference.nc -o stage.rexsj"),
    "import-rexs": ("ltca import-rexs stage.rexs -o my_case.toml",),
    "correct": ("ltca correct iso23509_sample2_fm_measured -o corrected.toml",),
    "optimize": ("ltca optimize kolivand2009_fm_11x41 -o optimized.toml --variable "
                 "tip_relief 0 40 --torque 50 250 500",),
    "utca": ("ltca utca --plots figs",),
    "sweep": ("ltca sweep --dE -0.2:0.2:11 --dP -0.2:0.2:11 --torque 250 -o map.nc "
              "--plots figs",),
    "tolerance": ("ltca tolerance --dE normal:-0.15:0.05 --dP normal:0.12:0.05 -n 64 "
                  "--torque 250 --plots figs",),
    "vh-check": ("ltca vh-check --plots figs",),
    "compare-solvers": ("ltca compare-solvers kolivand2009_fm_11x41",),
    "export-problems": ("ltca export-problems kolivand2009_fm_11x41 -o problems",),
    "export-step": ("ltca export-step kolivand2009_fm_11x41_reference -o pair.step",
                    "ltca export-step my_case.toml --dE 0.1 -o misaligned_pair.step"),
}
