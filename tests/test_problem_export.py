"""Real LTCA problems exported for solver studies (issue 21, items 3 and 8).

* problem files round-trip bit for bit, and bad manifests are refused by name;
* ``ltca export-problems`` writes one problem per (case, misalignment, torque, roll of one
  mesh cycle) with a manifest, and each problem is the one ``run_analysis``'s LTCA solved:
  its exact solution reproduces the LTE of that analysis;
* ``ltca compare-solvers --problems DIR -o F`` records solver versions, CPU and BLAS;
* the qpbenchmark command of ``benchmarks/ltca_contact.py`` runs and writes qpbenchmark's
  report (skipped without the ``bench`` extra);
* the fast reduced KKT solve equals the textbook one (SciPy's Cholesky).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

from contact.cli import main
from contact.errors import ProblemInputError
from contact.ltca import LTCAOptions
from contact.qp import ContactProblem, solve_contact
from contact.qp.benchmark_problems import ltca_like_problem
from contact.qp.problem import reduced_kkt, schur_floor
from contact.qp.problem_files import (
    MANIFEST,
    read_manifest,
    read_problem,
    read_problem_set,
    write_manifest,
    write_problem,
)
from contact.qp.solvers.active_set import initial_contact_set
from geometry.core.io import read_netcdf
from geometry.core.version import __version__

ROOT = Path(__file__).resolve().parents[1]
CASE = "kolivand2009_fm_11x41"
#: a short analysis: 4 rolls per cycle, 10 segments per curve, one torque
SMALL = LTCAOptions(rolls_per_cycle=4, segments=10)
TORQUE = 250.0


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    from contact.commands.export_problems import export_problems

    d = tmp_path_factory.mktemp("problems")
    export_problems([CASE], d, torques=[TORQUE], options=SMALL)
    return d


def test_problem_file_round_trips_bit_for_bit(tmp_path):
    p = ltca_like_problem(30, seed=4).problem
    path = write_problem(tmp_path / "p", p)
    assert path.suffix == ".npz"
    q = read_problem(path)
    for k in ("compliance", "separation", "moment_arm"):
        np.testing.assert_array_equal(getattr(q, k), getattr(p, k))
    assert q.torque == p.torque and q.name == "p"


def test_manifest_refuses_incomplete_or_repeated_entries(tmp_path):
    with pytest.raises(ProblemInputError, match="'n'"):
        write_manifest(tmp_path, [{"name": "a", "file": "a.npz"}])
    with pytest.raises(ProblemInputError, match="repeats"):
        write_manifest(tmp_path, [{"name": "a", "file": "a.npz", "n": 3}] * 2)
    with pytest.raises(ProblemInputError, match="no manifest"):
        read_manifest(tmp_path)
    (tmp_path / MANIFEST).write_text(json.dumps({"format": "other"}))
    with pytest.raises(ProblemInputError, match="format"):
        read_manifest(tmp_path)


def test_export_lists_every_roll_of_one_cycle_aligned_and_misaligned(exported):
    doc = read_manifest(exported)
    entries = doc["problems"]
    # 2 misalignments × 1 torque × 4 rolls of one mesh cycle (the second cycle repeats it)
    assert len(entries) == 2 * 1 * SMALL.rolls_per_cycle
    assert {e["misalignment"] for e in entries} == {"aligned", "misaligned"}
    assert sorted({e["roll"] for e in entries}) == list(range(SMALL.rolls_per_cycle))
    mis = next(e for e in entries if e["misalignment"] == "misaligned")
    assert (mis["delta_E_mm"], mis["delta_P_mm"]) == (-0.15, 0.12)  # seed Table 3.1
    for e in entries:
        assert (exported / e["file"]).is_file() and e["case"] == CASE
        assert e["torque_Nm"] == TORQUE
    problems = read_problem_set(exported)
    assert [tp.problem.size for tp in problems] == [e["n"] for e in entries]


def test_exported_problems_are_those_run_analysis_solved(exported):
    """The exact solution of each exported problem gives the loaded rotation Θ that
    run_analysis's LTCA recorded at that (torque, roll): the same problem, solved again.
    Tolerance 1e-9 relative: the solver's round-off (it is exact on a contact set)."""
    from contact.catalogue import SEED_TABLE_3_1
    from contact.pipeline import run_analysis
    from geometry.pair.assembly import Misalignment

    entries = read_manifest(exported)["problems"]
    for label, mis in (("aligned", Misalignment()),
                       ("misaligned", SEED_TABLE_3_1["misalignment"])):
        ltca = run_analysis(CASE, [TORQUE], misalignment=mis, options=SMALL,
                            geometry=False, root_stress=False)["ltca"].dataset
        for e in (e for e in entries if e["misalignment"] == label):
            sol = solve_contact(read_problem(exported / e["file"]))
            assert sol.found
            theta = ltca["loaded_rotation"].isel(torque=0, roll=e["roll"]).item()  # [µrad]
            assert sol.rotation * 1e6 == pytest.approx(theta, rel=1e-9)


def test_compare_solvers_records_versions_cpu_and_blas(exported, tmp_path, capsys):
    pytest.importorskip("daqp", reason="an optional backend: pip install 'hypoid-ltca[solvers]'")
    path = tmp_path / "cmp.nc"
    assert main(["compare-solvers", "--problems", str(exported), "--solvers", "active_set",
                 "daqp", "--no-progress", "-o", str(path)]) == 0
    assert "BLAS" in capsys.readouterr().out
    ds = read_netcdf(path)
    assert ds.sizes["problem"] == 2 * SMALL.rolls_per_cycle
    versions = dict(zip(ds["solver"].values, ds["solver_version"].values, strict=True))
    assert metadata.version("daqp") in versions["daqp"]
    assert versions["active_set"] == f"hypoid-ltca {__version__}"
    for key in ("cpu", "cpu_count", "blas", "blas_threads", "platform", "numpy_version"):
        assert key in ds.attrs and str(ds.attrs[key])
    assert int(ds["found"].sum()) == ds.sizes["solver"] * ds.sizes["problem"]


def test_qpbenchmark_command_writes_its_report(exported, tmp_path):
    pytest.importorskip("qpbenchmark")  # the [bench] extra
    pytest.importorskip("daqp", reason="an optional backend: pip install 'hypoid-ltca[solvers]'")
    # the test set of benchmarks/ltca_contact.py on the small export, without the
    # standard set (its N = 2000 problems take minutes)
    test_set = tmp_path / "small_set.py"
    test_set.write_text(
        "from contact.qp.qpbenchmark_export import LtcaContact\n\n\n"
        "class SmallSet(LtcaContact):\n"
        f"    problems_dir = {str(exported)!r}\n"
        "    standard = False\n"
    )
    results = tmp_path / "results" / "small_set.csv"
    results.parent.mkdir()
    cmd = [sys.executable, "-m", "qpbenchmark.benchmark", str(test_set), "--results-path",
           str(results), "run", "--solver", "daqp", "--author", "ci"]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.returncode == 0, done.stderr[-2000:]
    report = (results.parent / "small_set.md").read_text()
    assert "| daqp" in report and metadata.version("daqp") in report
    assert "CPU info" in report
    import pandas

    df = pandas.read_csv(results)
    assert len(df) == 2 * SMALL.rolls_per_cycle and df["found"].all()


def test_reduced_kkt_equals_scipy_cholesky_solution():
    """On a contact set of an LTCA-like problem, the LAPACK-direct solve equals the
    textbook one with scipy.linalg.cho_factor/cho_solve (same LAPACK routines: 1e-12)."""
    p = ltca_like_problem(120, seed=11).problem
    idx = np.flatnonzero(initial_contact_set(p))
    F_A, theta = reduced_kkt(p.compliance, p.separation, p.moment_arm, p.torque, idx,
                             schur_floor(p))
    cf = scipy.linalg.cho_factor(p.compliance[np.ix_(idx, idx)], lower=True)
    x_s = scipy.linalg.cho_solve(cf, p.separation[idx])
    x_r = scipy.linalg.cho_solve(cf, p.moment_arm[idx])
    theta_ref = (p.torque + p.moment_arm[idx] @ x_s) / (p.moment_arm[idx] @ x_r)
    assert theta == pytest.approx(theta_ref, rel=1e-12)
    np.testing.assert_allclose(F_A, theta_ref * x_r - x_s, rtol=0,
                               atol=1e-12 * np.max(np.abs(F_A)))
    # equilibrium on the set: R_Aᵀ F_A = T
    assert p.moment_arm[idx] @ F_A == pytest.approx(p.torque, rel=1e-12)


def test_reduced_kkt_refuses_an_indefinite_set():
    C = np.array([[1.0, 2.0], [2.0, 1.0]])  # eigenvalues 3, −1
    p = ContactProblem(np.eye(2), np.zeros(2), np.ones(2), 1.0)
    assert reduced_kkt(C, np.zeros(2), np.ones(2), 1.0, np.arange(2), schur_floor(p)) is None
