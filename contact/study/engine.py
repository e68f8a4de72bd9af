"""Running the points of a study on Dask: a local cluster by default, any cluster by address.

Every study (:func:`contact.study.sweep`, :func:`contact.study.sample`, the V-H check)
comes down to a list of points, each a dict of :data:`contact.study.points.POINT_INPUTS`,
and the inputs all points share (:class:`contact.study.points.StudyInputs`).
:func:`run_points` analyses them with :func:`contact.run_analysis` on ``dask.distributed``
workers and returns one dataset over a ``point`` dimension.

* **Where**: ``scheduler=None`` starts a ``LocalCluster`` of one single-threaded process
  per core (``n_workers`` to choose); ``scheduler="tcp://host:8786"`` uses a running
  cluster (its workers need the toolkit installed); a ``distributed.Client`` is used as
  it is; ``scheduler="synchronous"`` runs the points one after the other in this process
  (debugging, small studies, no cluster to start).
* **Once per worker**: the shared inputs are scattered to every worker once
  (``Client.scatter(broadcast=True)``), and the tooth models — the shells' Ritz systems,
  factorised, which do not depend on the misalignment or the deviations — are memoised
  per worker process (:func:`contact.compliance.pair_compliance_model`), so they are
  built once per worker, not once per point; so are the pinion points of the ease-off's
  forward map and the gear flank on its grid (:mod:`contact.utca.conjugate_map`), under
  the same key.
* **Workers' environment**: a LocalCluster's workers start without distributed's
  ``MALLOC_TRIM_THRESHOLD_`` and with this process's compiled-kernels choice
  (``LTCA_KERNELS``) (:func:`worker_environment`; ``docs/study.md`` for a cluster of
  one's own).
* **One failing point never stops a study**: its ``status`` is ``failed`` and
  ``reason`` says why (e.g. the flanks separate); its summaries are NaN.
* **Streaming and resume**: with an output file the finished points go to disk in
  chunks as they come (:class:`contact.study.store.ResultStore`); at most a few points
  per worker are in flight, so memory stays flat in the number of points; a study
  killed and started again with the same output computes only the missing points.

Public functions
----------------
analyse_point   one point's summaries (runs on a worker)
one_cycle       a point's LTCA options: the study's over one mesh cycle
run_points      all points of a study, on Dask
check_plausible_points  refuse points whose misalignment is beyond the blanks' range
open_client     a Dask client for a scheduler argument (context manager)
worker_environment  a LocalCluster's workers started without distributed's malloc trim
run_tasks       any function over items on Dask, results as they finish
stream_tasks    run_tasks with each result streamed, as a dataset, to a store (progress, flush)
write_study     write a study's result file and remove its parts
"""

from __future__ import annotations

import contextlib
import dataclasses
import logging
import os
import signal
import threading
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from contact.ltca.options import LTCAOptions
from contact.qp.solvers import solver_name
from contact.study.points import POINT_INPUTS, StudyInputs, check_point, misalignment_of
from contact.study.store import ChunkSpec, ResultStore
from contact.study.summary import (
    STATUS_MEANINGS,
    SUMMARY_VARIABLES,
    failed_summary,
    plausibility_bits,
    point_summary,
    summary_variable,
)
from geometry import __version__
from geometry.core.caches import rows_not_kept
from geometry.core.conventions import data_var
from geometry.core.errors import InputError, raise_if_interrupted

__all__ = ["CLOSE_TIMEOUT", "SYNCHRONOUS", "WORKER_ENVIRON_UNSET", "analyse_point",
           "check_plausible_points", "close_local_cluster", "one_cycle", "open_client",
           "run_points", "run_tasks", "stream_tasks", "worker_environment", "write_study"]

log = logging.getLogger(__name__)

#: The ``scheduler`` value that runs a study in this process, point after point.
SYNCHRONOUS = "synchronous"


@dataclasses.dataclass(frozen=True)
class PointResult:
    """What a worker sends back for one point: small, whatever the analysis's size."""

    index: int
    status: int
    reason: str
    summary: dict[str, np.ndarray]


def analyse_point(shared: StudyInputs, index: int, point: Mapping[str, float]) -> PointResult:
    """Analyse one study point and summarise it (the function Dask runs on a worker).

    Parameters
    ----------
    shared : StudyInputs
        The inputs every point shares.
    index : int
        The point's place in the study.
    point : mapping of str to float
        Its inputs (:data:`contact.study.points.POINT_INPUTS`, their units).

    Returns
    -------
    PointResult
        ``status`` 0 ok, 1 some roll position uncertified, 2 failed (``reason`` the
        error's message, every summary NaN; or an analysis with a torque none of whose
        roll positions has a certified contact solution, ``reason`` saying so,
        :func:`contact.ltca.summary.certification`). Never raises for a failing analysis.

    Notes
    -----
    The analysis is exactly :func:`contact.run_analysis` of the case with the point's
    misalignment and scaled deviations (no ``/geometry``, no theoretical groups, no
    ``/mesh_interface``: the summary does not read it, and its roll problems cost 2–3 % of
    a point; the LTCA over one mesh cycle, :func:`one_cycle`; ``/utca`` of the UTE alone,
    the chain's ``utca="ute"`` step, :func:`contact.chain.utca_ute`: the contact curves'
    flank points, separations and paths no summary reads are not evaluated) and
    :func:`friction.efficiency.efficiency_analysis` of its ``/ltca`` at each speed, so a
    study's numbers equal those of single analyses at the same inputs (but for the order
    of floating-point sums: ≈ 1e-15 relative, the LTE harmonics ≤ 1e-14 of the largest
    over one cycle instead of two). The analysis runs inside
    :func:`geometry.core.caches.rows_not_kept`: its contact segments are new, so the
    compliance's mapped points and columns are computed as in a process that kept none
    (a point no longer depends, at round-off, on the rows earlier points left in the
    stores), without the stores' bookkeeping.
    """
    from contact.chain import AnalysisChain
    from contact.pipeline import run_analysis
    from friction.efficiency import efficiency_analysis

    case = shared.case
    if shared.coefficients:   # the client's FE coefficients into this worker's cache
        from contact.compliance.fe import prime_cache

        prime_cache(shared.coefficients)
    try:
        # a point's contact segments are new (its own misalignment, deviations): the
        # compliance's stores of mapped points and columns would keep nothing it reads
        with rows_not_kept():
            tree = run_analysis(
                case.replaced(misalignment=misalignment_of(case.misalignment, point)),
                list(shared.torque), flank=shared.flank, options=one_cycle(shared.options),
                deviations=shared.deviations_at(point.get("deviation_scale")),
                theoretical=False,
                steps=AnalysisChain.contact_only().with_steps(utca="ute")
                .with_root_stress(shared.root_stress))
        friction = []
        if shared.speed:
            ltca = tree["/ltca"].to_dataset()
            friction = [efficiency_analysis(ltca, shared.operating, pinion_speed=float(n))
                        for n in shared.speed]
        summary = point_summary(tree, case, friction)
        cert = tree.attrs.get("analysis_status", "ok")
        if cert == "failed":  # a torque without any certified roll: no result there
            return PointResult(index, 2, str(tree.attrs["analysis_status_reason"]), summary)
        status = 0 if bool(np.all(summary["certified"] > 0)) else 1
        return PointResult(index, status, "", summary)
    except Exception as exc:
        raise_if_interrupted(exc)
        log.info("study point %d %s failed: %s", index, dict(point), exc)
        reason = f"{type(exc).__name__}: {exc}".splitlines()[0]
        summary = failed_summary(len(shared.torque), max(len(shared.speed), 1))
        # the input is judged even where the analysis failed (a slip such as ΔE = 5 mm)
        summary["plausibility"] = plausibility_bits(
            None, case, misalignment_of(case.misalignment, point), len(shared.torque))
        return PointResult(index, 2, reason, summary)


def one_cycle(options: LTCAOptions) -> LTCAOptions:
    """The LTCA options of a study point: ``options`` over one mesh cycle.

    Parameters
    ----------
    options : contact.ltca.LTCAOptions
        The study's options (any ``cycles``, 1–20).

    Returns
    -------
    contact.ltca.LTCAOptions
        The same options with ``cycles=1`` (``options`` itself where it has one cycle).

    Notes
    -----
    Every summary of a point is taken over whole mesh cycles (the LTE's mean, peak-to-peak
    and mesh harmonics, the peak pressures, the edge load share Σ F·arm / Σ F·arm, the
    pattern's envelope, the efficiency's mean, the root stress's peak), and the rolls of
    the later cycles repeat the first cycle's rolls exactly: their targets agree to 1e-12
    pitch, so :func:`contact.ltca.segments.segment_geometry` copies their segments and
    :mod:`contact.ltca.roll_loop` their results (seed §3.3–3.4: the LTCA is periodic in
    the mesh cycle). A point's summaries over one cycle are therefore those over
    ``options.cycles`` but for the order of floating-point sums over 20 instead of 40
    rolls (measured on the default case, the FH 12×41 and the spiral bevel sample, four
    points each at 250 and 500 N·m with the efficiency at 1,000 rpm: ≤ 4e-16 relative,
    the LTE harmonics ≤ 1e-14 of the largest, 1e-13 of their own smallest),
    without building, copying and keeping the second cycle's rolls: ≈ 10 ms of a ≈ 135 ms
    point (issue 75).
    """
    return options if options.cycles == 1 else dataclasses.replace(options, cycles=1)


def _point_dataset(shared: StudyInputs, names: Sequence[str], index: int,
                   point: Mapping[str, float], result: PointResult) -> xr.Dataset:
    """One finished point as a dataset over a ``point`` dim of length 1."""
    data: dict[str, Any] = {
        name: summary_variable(name, ("point",), result.summary[name][None])
        for name in SUMMARY_VARIABLES}
    data["status"] = data_var(("point",), np.array([result.status], np.int8), "1",
                              "outcome of the point's analysis",
                              flag_values=np.arange(len(STATUS_MEANINGS), dtype=np.int8),
                              flag_meanings=" ".join(STATUS_MEANINGS))
    data["reason"] = data_var(("point",), np.array([result.reason], dtype=object), None,
                              "why the point failed (empty when it did not)")
    coords = {"point": ("point", np.array([index]), {"units": "1",
                                                       "long_name": "study point index"})}
    for name in names:
        units, long_name = POINT_INPUTS[name]
        coords[name] = ("point", np.array([float(point[name])]),
                        {"units": units, "long_name": long_name})
    return xr.Dataset(data, coords=coords)


#: the environment variables of distributed's ``distributed.nanny.pre-spawn-environ`` that a
#: study's workers are started without (None unsets a variable of that configuration):
#: ``MALLOC_TRIM_THRESHOLD_`` (distributed's default 65536 bytes) makes glibc return freed
#: memory to the system at every chance and fixes its mmap threshold, so every large array
#: of an analysis is mapped afresh: measured 92–151 thousand page faults and 0.18–0.28 s of
#: system time per study point; unset, a worker's CPU time per point fell by 0.25 s with
#: memory still flat in the number of points (``benchmarks/sweep.py``, issue 32)
WORKER_ENVIRON_UNSET = ("MALLOC_TRIM_THRESHOLD_",)


@contextlib.contextmanager
def worker_environment() -> Iterator[None]:
    """Start a LocalCluster's workers without :data:`WORKER_ENVIRON_UNSET` and with this
    process's compiled-kernels choice (``LTCA_KERNELS``,
    :func:`geometry.core.kernels.process_choice`) (context manager).

    Sets distributed's ``distributed.nanny.pre-spawn-environ`` entries of those variables to
    None (unset) while the cluster starts; the variables the user set in this process's
    environment are kept (distributed's precedence). A cluster of one's own gets the same
    with ``dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_":
    None})`` before it starts, or with ``dask worker`` started from a shell without the
    variable and a ``distributed.yaml`` setting it to null (``docs/study.md``).

    Yields
    ------
    None
    """
    import dask

    from geometry.core.kernels import announce_compiling, compiled_modules, process_choice

    # numba compiles in the workers where its cache holds no kernels yet: said now, as the
    # workers start (the command line's compile note, issue 71)
    for name in compiled_modules():
        announce_compiling(name)
    # the workers run the kernels this process runs (numba's cache may fill meanwhile):
    # a study's points equal this process's analyses to round-off and below
    with dask.config.set({f"distributed.nanny.pre-spawn-environ.{name}": None
                          for name in WORKER_ENVIRON_UNSET}
                         | {"distributed.nanny.pre-spawn-environ.LTCA_KERNELS":
                            process_choice()}):
        yield


class _QuietDistributed(contextlib.AbstractContextManager):
    """Once :meth:`on`, distributed's loggers say nothing below CRITICAL until the context
    exits (their levels are restored then)."""

    def __init__(self) -> None:
        self.saved: dict[str, int] = {}

    def on(self) -> None:
        names = ["distributed", *(n for n in logging.root.manager.loggerDict
                                  if n.startswith("distributed."))]
        for name in names:
            lg = logging.getLogger(name)
            self.saved.setdefault(name, lg.level)
            lg.setLevel(logging.CRITICAL)

    def __exit__(self, *exc: object) -> None:
        for name, level in self.saved.items():
            logging.getLogger(name).setLevel(level)


#: distributed's worker log line of a heartbeat that did not reach the scheduler: an
#: ``OSError`` the worker recovers from by itself (``distributed.worker.Worker.heartbeat``
#: logs it with its traceback and carries on; the next heartbeat, every ~0.5-5 s, tries
#: again, and a scheduler really gone closes the worker, which the study then reports).
#: On a loaded machine a study printed it mid-run, a 30-line traceback before a correct
#: result (issue 71, round 32: ``ltca duty-cycle`` at load 10 on 2 cores).
HEARTBEAT_HICCUP = "Failed to communicate with scheduler during heartbeat"


class RecoverableCommFilter(logging.Filter):
    """Drops distributed's worker log record of a recoverable heartbeat failure
    (:data:`HEARTBEAT_HICCUP`); every other record passes, among them the heartbeat's
    "Unexpected exception during heartbeat. Closing worker." that ends a worker."""

    def filter(self, record: logging.LogRecord) -> bool:
        return not (record.name == "distributed.worker"
                    and str(record.msg).startswith(HEARTBEAT_HICCUP))


def _quiet_worker_logs() -> Any:
    """A ``distributed`` worker plugin that adds :class:`RecoverableCommFilter` to the
    worker process's ``distributed.worker`` logger (once), for a local cluster's workers."""
    from distributed.diagnostics.plugin import WorkerPlugin

    class QuietHeartbeat(WorkerPlugin):
        name = "hypoid-ltca-quiet-heartbeat"

        def setup(self, worker: Any) -> None:
            logger = logging.getLogger("distributed.worker")
            if not any(isinstance(f, RecoverableCommFilter) for f in logger.filters):
                logger.addFilter(RecoverableCommFilter())

    return QuietHeartbeat()


@contextlib.contextmanager
def _workers_ignore_sigint() -> Iterator[None]:
    """SIGINT ignored while a local cluster starts its worker processes, which keep that
    disposition (a spawned Python leaves an ignored SIGINT ignored, and asyncio then
    installs no handler): Ctrl-C reaches the whole process group, and only this process
    should answer it — with one line (contact.cli) — while the workers are closed by the
    cluster, not interrupted mid-task with a traceback each. Off the main thread (where
    signals cannot be set) nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


#: Why a local cluster's workers did not start, and the two ways to run the study.
NOT_STARTED = ("scheduler: the local cluster's worker processes failed to start ({exc}); a "
               "script that runs a study (run_duty_cycle, sweep, sample, …) must call it "
               "under `if __name__ == \"__main__\":` (Python's rule for the worker "
               "processes it spawns, which import the script again), or pass "
               "StudyRun(scheduler=\"synchronous\") to run it in this process")


@contextlib.contextmanager
def open_client(scheduler: Any = None, n_workers: int | None = None) -> Iterator[Any]:
    """A ``distributed.Client`` for a study's ``scheduler`` argument.

    Parameters
    ----------
    scheduler : None, str or distributed.Client
        None: a new ``LocalCluster`` (closed on exit) of ``n_workers`` single-threaded
        worker processes, started without distributed's malloc trim
        (:func:`worker_environment`); an address (``"tcp://host:8786"``): a client of
        that running cluster; a Client: used as it is (not closed); ``"synchronous"``: no
        client (yields None).
    n_workers : int, optional
        Workers of the local cluster; default one per core (``os.cpu_count()``).

    Yields
    ------
    distributed.Client or None

    Raises
    ------
    InputError
        Bad ``n_workers``, a scheduler address that cannot be reached (the message
        names it), or a local cluster whose workers did not start (:data:`NOT_STARTED`:
        a script calling a study outside ``if __name__ == "__main__":``).
    """
    if scheduler == SYNCHRONOUS:
        yield None
        return
    from distributed import Client, LocalCluster

    if isinstance(scheduler, Client):
        yield scheduler
        return
    if scheduler is None:
        n = (os.cpu_count() or 1) if n_workers is None else n_workers
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise InputError(f"n_workers: must be an integer >= 1, got {n_workers!r}")
        with _workers_ignore_sigint(), worker_environment():
            # no dashboard, and the scheduler's HTTP server (health, metrics) on a free
            # port: not 8787, which another cluster on the machine may hold (a warning)
            try:
                cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=logging.ERROR,
                                       scheduler_kwargs={"dashboard_address": ":0"})
            except RuntimeError as exc:
                # most often a script calling a study at its top level: each spawned
                # worker imports the script again and starts a cluster of its own, which
                # Python refuses ("Nanny failed to start."; round 21 of issue 71)
                raise InputError(NOT_STARTED.format(exc=exc)) from exc
        quiet = _QuietDistributed()
        with quiet:
            client = Client(cluster)
            # the workers' recoverable heartbeat hiccups are not printed as tracebacks
            client.register_plugin(_quiet_worker_logs())
            finished = False
            try:
                yield client
                finished = True
            except KeyboardInterrupt:
                # Ctrl-C: the workers ignore it (they would each print a traceback); the
                # cluster closes them, killing those still busy: not worth a warning each
                quiet.on()
                raise
            finally:
                # a finished study's idle workers get time to stop by themselves; after
                # an error or an interrupt the busy ones are killed at once, as before
                close_local_cluster(client, cluster,
                                    CLOSE_TIMEOUT if finished else _ABORT_TIMEOUT)
        return
    if not isinstance(scheduler, str) or "://" not in scheduler:
        raise InputError(f"scheduler: must be None (a local cluster), 'synchronous', a "
                         f"scheduler address such as 'tcp://host:8786' or a "
                         f"distributed.Client; got {scheduler!r}")
    try:
        client = Client(scheduler, timeout="20s")
    except OSError as exc:
        raise InputError(f"scheduler: cannot reach {scheduler!r}: {exc}") from None
    with client:
        yield client


def _stamp(ds: xr.Dataset, shared: StudyInputs, kind: str, resumed: int) -> xr.Dataset:
    ds = ds.copy()
    ds.attrs = {
        "title": f"hypoid-ltca {kind} of {shared.case.name}",
        "case": shared.case.name,
        "case_source": shared.case.source,
        "toolkit_version": __version__,
        "study": kind,
        "solver": solver_name(shared.options.solver),
        "flank": shared.flank or "drive",
        "points_resumed": int(resumed),
    }
    return ds


def run_points(
    shared: StudyInputs,
    points: Sequence[Mapping[str, float]],
    *,
    names: Sequence[str] | None = None,
    output: str | os.PathLike[str] | None = None,
    scheduler: Any = None,
    n_workers: int | None = None,
    progress: bool = False,
    kind: str = "study",
    chunk_size: int = 32,
    force: bool = False,
) -> xr.Dataset:
    """Analyse every point of a study on Dask; one dataset over a ``point`` dim.

    Parameters
    ----------
    shared : StudyInputs
        What every point shares (case, torques [N·m], speeds [rpm], options …).
    points : sequence of mappings
        Each point's inputs (:data:`contact.study.points.POINT_INPUTS`; mm, rad, 1).
    names : sequence of str, optional
        The inputs stored as ``point`` coordinates (default: those of the first point).
    output : path-like, optional
        Final netCDF file. Finished points stream to ``OUTPUT.parts/`` and a study
        started again with the same output resumes (:class:`~contact.study.store.
        ResultStore`); the directory must exist. None: results kept in memory. A chunk
        of the parts that is not this study's (unreadable, other variables, inputs or
        dims, NaN LTE at an ``ok`` point) is named in a warning, moved to
        ``OUTPUT.parts/set-aside/`` and its points computed again.
    scheduler, n_workers
        Where to run (:func:`open_client`): default a LocalCluster, one process per core.
    progress : bool or {"lines"}
        A tqdm bar (True) or plain periodic lines (``"lines"``) on the client
        (:func:`stream_tasks`).
    kind : str
        What the study is (recorded in the title): ``"sweep"``, ``"sample"`` …
    chunk_size : int
        Points per chunk file of the parts directory.
    force : bool
        Run points whose misalignment is beyond the plausible range of the pair's blanks
        (:func:`contact.ltca.plausibility.misalignment_limits`); they are flagged in
        ``plausibility``. False (default): such points are refused before any work.

    Returns
    -------
    xarray.Dataset
        dims ``point`` (+ ``torque``, ``harmonic``, ``speed``): the summaries of
        :data:`contact.study.summary.SUMMARY_VARIABLES`, ``status`` (CF flag: ok,
        uncertified, failed) and ``reason``; coordinates ``point`` and the inputs
        ``names``, ``torque`` [N·m], ``speed`` [rpm]. ``plausibility`` (point, torque):
        the CF flag of the causes ``ltca run`` warns of (bits of
        :data:`contact.ltca.plausibility.CAUSES`, 0 plausible). Attribute
        ``points_resumed``: how many points were read from an interrupted run's parts.

    Raises
    ------
    InputError
        Points whose misalignment is beyond the plausible range of the blanks (without
        ``force``; the message gives the limits and the values), an unknown or non-finite
        input, no points, parts of another study at
        ``OUTPUT.parts``, a bad scheduler or worker count, points missing from the parts
        after the run (a chunk set aside meanwhile: the study started again computes them).
    """
    if not points:
        raise InputError("points: a study needs at least one point")
    pts = [check_point(p, f"point {i}") for i, p in enumerate(points)]
    names = list(names if names is not None else pts[0])
    for i, p in enumerate(pts):
        if set(p) != set(names):
            raise InputError(f"point {i}: sets {sorted(p)}, the study's inputs are "
                             f"{sorted(names)}")
    if "deviation_scale" in names and shared.deviations is None:
        raise InputError(f"deviation_scale: case {shared.case.name!r} has no [deviations] "
                         "table to scale")
    if not force:
        check_plausible_points(shared.case, pts)
    if shared.root_stress is not False:
        # built (or read) once here and handed to every worker with the shared inputs:
        # a worker writes them into its own cache, so none builds them (issue 53)
        from contact.ltca.root_stress import prepare_coefficients

        coefficients = prepare_coefficients(
            shared.case, shared.flank,
            None if shared.root_stress is True else shared.root_stress,
            progress=progress is True)  # a bar on a terminal only: no lines of its own
        shared = dataclasses.replace(shared, coefficients=tuple(coefficients.values()))
    store = None
    done: set[int] = set()
    if output is not None:
        out = Path(output)
        if not out.parent.is_dir():
            raise InputError(f"output: directory {str(out.parent)!r} does not exist")
        manifest = {"fingerprint": shared.fingerprint(), "kind": kind, "inputs": names,
                    "points": [[p[n] for n in names] for p in pts]}
        store = ResultStore(out, manifest, chunk_size=chunk_size,
                            spec=_chunk_spec(shared, names, pts))
        done = store.done()
        if done:
            log.info("resuming %s: %d of %d points already computed", out, len(done),
                     len(pts))
    todo = [i for i in range(len(pts)) if i not in done]
    # analyse_point looked up here, at call time (tests count its calls)
    kept = stream_tasks(
        analyse_point, shared, [(i, pts[i]) for i in todo],
        lambda res: _point_dataset(shared, names, res.index, pts[res.index], res),
        store=store, progress=progress, desc=_PROGRESS_NAMES.get(kind, kind), unit="point",
        total=len(pts),
        initial=len(done), scheduler=scheduler, n_workers=n_workers)
    if store is not None:
        ds = store.combined()
        if ds.sizes["point"] != len(pts):
            raise InputError(f"output: {ds.sizes['point']} of {len(pts)} points in "
                             f"{str(store.parts)!r} after the run (a chunk failed its "
                             "check, see the warning); start the study again to compute "
                             "the missing points")
    else:
        ds = xr.concat(kept, dim="point")
        ds = ds.isel(point=np.argsort(ds["point"].values, kind="stable"))
    torque = np.asarray(shared.torque, float)
    ds = ds.assign_coords(
        torque=("torque", torque, {"units": "N m", "long_name": "pinion torque"}),
        harmonic=("harmonic", np.arange(1, 4), {"units": "1",
                                                "long_name": "mesh harmonic order"}))
    if shared.speed:
        ds = ds.assign_coords(speed=("speed", np.asarray(shared.speed, float),
                                     {"units": "rpm", "long_name": "pinion speed"}))
    else:  # no efficiency stage
        ds = ds.drop_vars(["efficiency", "power_loss"])
    if shared.root_stress is False:
        ds = ds.drop_vars(["root_stress_max"])
    else:
        ds = ds.assign_coords(member=("member", np.array(["pinion", "gear"]),
                                      {"long_name": "gear member"}))
    ds["reason"] = ds["reason"].astype(str)
    return _stamp(ds, shared, kind, len(done))


def check_plausible_points(case: Any, points: Sequence[Mapping[str, float]]) -> None:
    """Refuse a study whose points put the pair beyond the plausible misalignments of its
    blanks (:func:`contact.ltca.plausibility.misalignment_limits`).

    Parameters
    ----------
    case : geometry.case.Case
        The study's case (its misalignment is that of inputs a point does not set).
    points : sequence of mappings
        The points' inputs (:data:`contact.study.points.POINT_INPUTS`; mm, rad).

    Raises
    ------
    InputError
        Naming each input beyond its limit: the limit, the offending values and how many
        points they make, and how to run them anyway (``--force``, ``force=True``).
    """
    from contact.ltca.plausibility import MISALIGNMENT_LIMIT_FRACTION, misalignment_limits

    limits = misalignment_limits(case)
    base = case.misalignment
    beyond: dict[str, list[float]] = {}
    counts: dict[str, int] = {}
    for p in points:
        mis = misalignment_of(base, p)
        for name, limit in limits.items():
            x = float(getattr(mis, name))
            if abs(x) > limit:
                counts[name] = counts.get(name, 0) + 1
                if x not in beyond.setdefault(name, []):
                    beyond[name].append(x)
    if not beyond:
        return
    b = min(case.pinion.blank.face_width, case.gear.blank.face_width)
    parts = []
    for name, xs in beyond.items():
        deg = name == "delta_Sigma"
        shown = [np.degrees(x) if deg else x for x in sorted(xs)]
        unit = "deg" if deg else "mm"
        lim = np.degrees(limits[name]) if deg else limits[name]
        parts.append(f"{name} {', '.join(f'{x:g}' for x in shown[:6])}"
                     f"{' …' if len(shown) > 6 else ''} {unit} ({counts[name]} "
                     f"point{'s' * (counts[name] != 1)}) "
                     f"beyond ±{lim:.3g} {unit}")
    frac = 100 * MISALIGNMENT_LIMIT_FRACTION
    raise InputError(
        "misalignment beyond the blank: " + "; ".join(parts) + f" ({frac:g} % of the face "
        f"width b = {b:.1f} mm, ΔΣ by its displacement at the "
        "outer cone distance; contact.ltca.plausibility): the pattern moves off the tooth "
        "long before, so such a point is most likely a typing slip (a range is START:STOP:N, "
        "a comma list is values). To run them anyway (flagged in the output's "
        "plausibility), pass --force (force=True)")


#: summaries finite at every point whose ``status`` is 0 (every roll position certified,
#: so the LTE of every torque is defined); NaN there is a damaged chunk, not a result
_FINITE_WHEN_OK = ("lte_mean", "lte_peak_to_peak")


def _chunk_spec(shared: StudyInputs, names: Sequence[str],
                pts: Sequence[Mapping[str, float]]) -> ChunkSpec:
    """What the chunks of a study's parts hold (:func:`_point_dataset`): the summaries,
    ``status`` and ``reason``; the points' inputs ``names`` as coordinates; the summaries'
    dims of this study's torques and speeds; finite LTE summaries where ``status`` is 0."""
    sizes = {"torque": len(shared.torque), "harmonic": 3,
             "speed": max(len(shared.speed), 1), "member": 2}

    def dims_of_study(ds: xr.Dataset) -> str | None:
        other = {d: n for d, n in ds.sizes.items() if d != "point"}
        wrong = sorted(d for d in other if sizes.get(d) != other[d])
        if wrong:
            return (f"has dimension(s) {', '.join(wrong)} of other sizes than this "
                    "study's torques, speeds and summaries")
        return None

    return ChunkSpec(points=len(pts), variables=(*SUMMARY_VARIABLES, "status", "reason"),
                     finite=_FINITE_WHEN_OK,
                     coords={n: np.array([float(p[n]) for p in pts]) for n in names},
                     check=dims_of_study)


#: a study kind → its name in the progress lines
_PROGRESS_NAMES = {"sample": "tolerance"}

#: how long [s] a local cluster's closing waits for the client, then for each worker to
#: stop by itself before it is killed (distributed's own wait is 4 s, too short on a
#: loaded machine: "Worker process still alive after 4.0 seconds, killing")
CLOSE_TIMEOUT = 30.0
#: the same after an error or an interrupt (distributed's default: busy workers killed)
_ABORT_TIMEOUT = 5.0


def close_local_cluster(client: Any, cluster: Any, timeout: float = CLOSE_TIMEOUT) -> None:
    """Close a study's client, then its local cluster's workers and the cluster, quietly.

    Parameters
    ----------
    client : distributed.Client
    cluster : distributed.LocalCluster
    timeout : float — [s]
        The wait for the client and for each worker to stop by itself (its nanny kills it
        after 0.8 of it); default :data:`CLOSE_TIMEOUT`.

    Notes
    -----
    The client first (it holds no tasks after the study), then every worker's nanny with
    ``timeout`` — distributed's cluster closes them with 5 s, killing a worker still
    tearing down after 4 s with a warning each — then the cluster, whose workers are
    gone by then. A worker that does not stop within ``timeout`` is still killed (its
    warning is distributed's). Errors while closing are logged at debug level: the
    study's result is already in hand.
    """
    import asyncio

    try:
        client.close(timeout=timeout)
    except Exception as exc:  # closing: the result is in hand
        log.debug("closing the study's client: %s", exc)

    async def stop_workers() -> None:
        await asyncio.gather(*(w.close(timeout=timeout) for w in list(
            cluster.workers.values())), return_exceptions=True)

    try:
        if cluster.workers:
            cluster.sync(stop_workers)
    except Exception as exc:
        log.debug("stopping the local cluster's workers: %s", exc)
    try:
        cluster.close(timeout=timeout)
    except Exception as exc:
        log.debug("closing the local cluster: %s", exc)


def stream_tasks(function: Any, shared: Any, items: Sequence[tuple],
                 to_dataset: Callable[[Any], xr.Dataset], *, store: ResultStore | None,
                 progress: bool, desc: str, unit: str, total: int, initial: int = 0,
                 scheduler: Any = None, n_workers: int | None = None) -> list[xr.Dataset]:
    """Run tasks with :func:`run_tasks` and stream each result, as a dataset, to a store.

    Parameters
    ----------
    function, shared, items, scheduler, n_workers
        As :func:`run_tasks`.
    to_dataset : callable
        A task's result → its dataset (run in the client, as results arrive).
    store : contact.study.store.ResultStore or None
        Where each dataset goes (flushed at the end, also on an interrupt or error);
        None: the datasets are returned.
    progress : bool or {"lines"}
        A progress bar (True) or plain periodic lines (``"lines"``, for output that is not
        a terminal) over ``total`` tasks, ``initial`` done before, named ``desc`` and
        counted in ``unit`` (:func:`geometry.core.progress.progress_reporter`).

    Returns
    -------
    list of xarray.Dataset
        The datasets in the order they finished; empty when a store took them.

    Raises
    ------
    As :func:`run_tasks` (an interrupted study keeps what its store was given).
    """
    from geometry.core.progress import progress_reporter

    kept: list[xr.Dataset] = []
    bar = progress_reporter(progress, total, initial=initial, desc=desc, unit=unit)
    try:
        for res in run_tasks(function, shared, items, scheduler=scheduler,
                             n_workers=n_workers):
            ds = to_dataset(res)
            (store.add if store is not None else kept.append)(ds)
            if bar is not None:
                bar.update()
    finally:
        if store is not None:
            store.flush()
        if bar is not None:
            bar.close()
    return kept


def run_tasks(function: Any, shared: Any, items: Sequence[tuple], *, scheduler: Any = None,
              n_workers: int | None = None, client: Any = None) -> Iterator[Any]:
    """Run ``function(shared, *item)`` for every item on Dask; yield results as they finish.

    Parameters
    ----------
    function : callable
        A module-level function (pickled by reference to the workers).
    shared : object
        Its first argument, the same for every item: scattered once to every worker.
    items : sequence of tuple
        The other arguments of each call.
    scheduler, n_workers
        As :func:`open_client` (ignored when ``client`` is given).
    client : distributed.Client, optional
        An open client to use.

    Yields
    ------
    The results, in the order they complete (in item order for ``"synchronous"``). At
    most two calls per worker thread are in flight, so the scheduler's memory stays flat
    in the number of items.
    """
    if client is None:
        with open_client(scheduler, n_workers) as cl:
            if cl is None:
                for item in items:
                    yield function(shared, *item)
                return
            yield from run_tasks(function, shared, items, client=cl)
        return
    from distributed import as_completed

    shared_future = client.scatter(shared, broadcast=True, hash=False)
    n_threads = max(1, sum(client.nthreads().values()))
    queue = iter(items)
    name = getattr(function, "__name__", "task")

    def submit(item: tuple):
        return client.submit(function, shared_future, *item, pure=False,
                             key=f"{name}-{os.urandom(6).hex()}")

    ac = as_completed([submit(item) for _, item in zip(range(2 * n_threads), queue,
                                                       strict=False)])
    for fut in ac:
        result = fut.result()
        fut.release()
        yield result
        nxt = next(queue, None)
        if nxt is not None:
            ac.add(submit(nxt))


def write_study(ds: xr.Dataset, output: str | os.PathLike[str], shared: StudyInputs) -> Path:
    """Write a study's final result to ``output`` (atomically, the case as its inputs)
    and remove the parts its points streamed to (:class:`~contact.study.store.
    ResultStore`).

    Parameters
    ----------
    ds : xarray.Dataset
        The study's result (e.g. a sweep's grid).
    output : path-like
        The netCDF file.
    shared : StudyInputs
        The study's shared inputs (the case's TOML is stored as ``inputs``).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    geometry.core.io.NetCDFError
        If the file cannot be written (the parts are then kept).
    """
    from geometry.core.io import write_netcdf

    path = write_netcdf(ds, output, inputs=shared.case.to_toml())
    ResultStore.remove_parts(output)
    return path
