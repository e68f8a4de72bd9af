"""CPU time of each stage of an analysis, measured in the process that runs it.

:class:`StageClock` wraps the functions that make up an analysis where the steps of
:mod:`contact.chain` look them up (:func:`contact.pipeline.run_analysis` and a study
point, :func:`contact.study.engine.analyse_point`, run those steps) and adds up the CPU
time (``time.process_time``: this process, all its threads) spent in each, exclusive of
the stages nested in it (the transitions inside the UTCA, the compliance assembly and the
contact solves inside the LTCA). CPU time, not wall time: the machines these benchmarks
run on are shared, and another process's load moves wall times far more than CPU times.
Used by ``benchmarks/ltca.py`` and
``benchmarks/sweep.py`` (also inside Dask workers, :func:`worker_clock`).
"""

from __future__ import annotations

import functools
import importlib
import time
from collections import defaultdict

#: (module, attribute, stage): the functions timed, where the analysis looks them up; a
#: method is given as "Class.method". Stages not nested in another are the analysis's own.
STAGES = (
    ("contact.chain", "geometry_datasets", "geometry (4 flanks)"),
    ("contact.utca.easeoff", "ease_off", "ease-off"),
    ("contact.utca", "unloaded_tca", "UTCA curves and dataset"),
    ("contact.utca.datasets", "transitions", "UTCA transitions"),
    ("contact.ltca", "loaded_tca", "LTCA other (screening, results, dataset)"),
    ("contact.ltca.mesh_cycle", "segment_geometry", "LTCA segment geometry"),
    ("contact.ltca.pool", "CompliancePool.assemble", "LTCA compliance assembly"),
    ("contact.ltca.roll_loop", "weber_solve", "LTCA contact solves (Weber)"),
    ("contact.ltca.root_stress", "root_stress", "root stress (FE coefficients, superposition)"),
    ("friction.efficiency", "efficiency_analysis", "efficiency"),
    ("contact.load_capacity.methods", "rate", "rating (ISO 10300)"),
    ("contact.load_capacity.scuffing_micropitting", "scuffing_micropitting",
     "scuffing and micropitting"),
    ("contact.load_capacity.iso_flash_temperature", "iso_flash_temperature_variants",
     "ISO flash temperature"),
    ("contact.study.engine", "point_summary", "study summary"),
)


class StageClock:
    """Exclusive CPU seconds per stage of the analyses run while installed.

    Attributes
    ----------
    cpu : dict of str to float — [s]
        CPU time per stage (exclusive of nested stages).
    """

    def __init__(self, extra: tuple[tuple[str, str, str], ...] = ()) -> None:
        self.cpu: dict[str, float] = defaultdict(float)
        self._stack: list[list] = []
        self._patches: list[tuple[object, str, object]] = []
        self._stages = STAGES + tuple(extra)  # finer stages, nested in STAGES' (as they)

    def install(self) -> StageClock:
        """Wrap every function of :data:`STAGES` and the ``extra`` stages given.

        Raises
        ------
        LookupError
            A module or function of :data:`STAGES` is not there (moved or renamed): a
            stage silently left out would read zero (issue 75: four stages did, after the
            steps moved from ``contact.pipeline`` to ``contact.chain``).
        """
        for module, attr, stage in self._stages:
            owner = importlib.import_module(module)
            *path, name = attr.split(".")
            for part in path:
                owner = getattr(owner, part)
            if not callable(getattr(owner, name, None)):
                raise LookupError(f"stage clock: {module}.{attr} is not there (moved?); "
                                  f"update benchmarks/stage_clock.py STAGES")
            self._wrap(owner, name, stage)
        return self

    def remove(self) -> None:
        """Put the original functions back."""
        for owner, name, fn in reversed(self._patches):
            setattr(owner, name, fn)
        self._patches.clear()

    def reset(self) -> None:
        self.cpu.clear()

    def _wrap(self, owner, name: str, stage: str) -> None:
        fn = getattr(owner, name)
        clock = self

        @functools.wraps(fn)
        def timed(*args, **kwargs):
            clock._enter(stage)
            try:
                return fn(*args, **kwargs)
            finally:
                clock._leave()

        setattr(owner, name, timed)
        self._patches.append((owner, name, fn))

    def _enter(self, stage: str) -> None:
        now = time.process_time()
        if self._stack:
            self.cpu[self._stack[-1][0]] += now - self._stack[-1][1]
        self._stack.append([stage, now])

    def _leave(self) -> None:
        now = time.process_time()
        stage, start = self._stack.pop()
        self.cpu[stage] += now - start
        if self._stack:
            self._stack[-1][1] = now


_WORKER_CLOCK: StageClock | None = None


def worker_clock(action: str) -> dict[str, float]:
    """Run in a Dask worker (``client.run(worker_clock, "install")``): ``"install"`` a
    clock in the worker process, ``"read"`` its stage times, ``"remove"`` it. Returns the
    stage times [s] and, under ``"process"``, the worker process's whole CPU time [s]."""
    global _WORKER_CLOCK
    if action == "install" and _WORKER_CLOCK is None:
        _WORKER_CLOCK = StageClock().install()
    out = dict(_WORKER_CLOCK.cpu) if _WORKER_CLOCK is not None else {}
    if action == "remove" and _WORKER_CLOCK is not None:
        _WORKER_CLOCK.remove()
        _WORKER_CLOCK = None
    out["process"] = time.process_time()
    return out
