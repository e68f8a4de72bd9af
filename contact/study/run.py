"""How a study runs: the analysis options every point shares and where the points run.

:func:`contact.study.sweep`, :func:`contact.study.sample` and
:func:`contact.study.vh_check` take one :class:`StudyRun` instead of repeating seven
keywords; the keywords themselves still work for one release (with a DeprecationWarning)
through :func:`study_run`.

Public names
------------
StudyRun     the LTCA options, flank, efficiency conditions, output file and Dask settings
study_run    a StudyRun from ``run`` and the deprecated keywords of the entry points
"""

from __future__ import annotations

import dataclasses
import os
import warnings
from dataclasses import dataclass
from typing import Any

from contact.ltca import LTCAOptions
from friction.operating import OperatingConditions
from geometry.core.errors import InputError

__all__ = ["RUN_FIELDS", "StudyRun", "study_run"]


@dataclass(frozen=True)
class StudyRun:
    """How a study runs its points.

    Parameters
    ----------
    options : contact.ltca.LTCAOptions, optional
        The LTCA's sampling and models (default ``LTCAOptions()``).
    flank : str, optional
        The pinion flank in contact: ``"drive"`` (default) or ``"coast"``.
    operating : friction.operating.OperatingConditions, optional
        Lubricant, oil temperature, roughness and friction model of the efficiency stage
        (default the case's ``[operating]`` table where a speed is given).
    output : path-like, optional
        Stream the points to ``OUTPUT.parts/`` as they finish and write the result to
        ``OUTPUT`` (netCDF); an interrupted study started again resumes.
    scheduler : None, "synchronous", address or distributed.Client
        Where the points run (:func:`contact.study.engine.open_client`): None a
        LocalCluster of ``n_workers`` processes; ``"synchronous"`` this process; an
        address (``tcp://…``) or a client an existing cluster.
    n_workers : int, optional
        Workers of the LocalCluster (default one per core).
    progress : bool or {"lines"}
        A progress bar over the points (True), or plain periodic lines for output that is
        not a terminal (``"lines"``: :mod:`geometry.core.progress`). Default False.
    root_stress : bool or contact.compliance.fe.FEOptions
        Also the peak tooth-root stress of both members at every point
        (``root_stress_max`` over (point…, torque, member) [MPa]; :func:`contact.run_analysis`'s
        ``root_stress``: True the default FE model — with ``options.compliance == "fe"``
        that of the compliance —, or an FEOptions; False off). Default None, not set:
        the sweeps and the sample compute it (:attr:`study_root_stress` True), as
        ``ltca sweep`` and ``ltca tolerance`` (``--root-stress`` on; before api83 the
        API's default was off). :func:`contact.study.duty_cycle.run_duty_cycle` reads it
        where set (True or FEOptions); its own default is True, as ``ltca duty-cycle``'s.
    force : bool
        Run points whose misalignment is beyond the plausible range of the pair's blanks
        (flagged in the output's ``plausibility``); default False refuses them before any
        work (:func:`contact.study.engine.check_plausible_points`).

    Raises
    ------
    InputError
        ``options``, ``operating``, ``progress`` or ``root_stress`` of the wrong type
        (named).
    """

    options: LTCAOptions | None = None
    flank: str | None = None
    operating: OperatingConditions | None = None
    output: str | os.PathLike[str] | None = None
    scheduler: Any = None
    n_workers: int | None = None
    progress: bool | str = False
    root_stress: Any = None
    force: bool = False

    @property
    def study_root_stress(self) -> Any:
        """The root stress a sweep or a sample computes: :attr:`root_stress` where set,
        else True (``ltca sweep``'s and ``ltca tolerance``'s ``--root-stress``)."""
        return True if self.root_stress is None else self.root_stress

    def __post_init__(self) -> None:
        if not (isinstance(self.progress, bool) or self.progress == "lines"):
            raise InputError(f"progress: must be True, False or 'lines', got {self.progress!r}")
        if self.options is not None and not isinstance(self.options, LTCAOptions):
            raise InputError("options: must be a contact.ltca.LTCAOptions or None, got "
                             f"{type(self.options).__name__}")
        if self.operating is not None and not isinstance(self.operating, OperatingConditions):
            raise InputError("operating: must be a friction.operating.OperatingConditions or "
                             f"None, got {type(self.operating).__name__}")
        if self.root_stress is not None and not isinstance(self.root_stress, bool):
            from contact.compliance.fe import FEOptions

            if not isinstance(self.root_stress, FEOptions):
                from contact.compliance.fe.options import level_hint

                raise InputError("root_stress: must be None, True, False or a "
                                 f"contact.compliance.fe.FEOptions, got {self.root_stress!r}"
                                 f"{level_hint(self.root_stress)}")


#: the keywords the entry points took before :class:`StudyRun`
RUN_FIELDS = tuple(f.name for f in dataclasses.fields(StudyRun))


def study_run(run: StudyRun | None, legacy: dict[str, Any], where: str) -> StudyRun:
    """The :class:`StudyRun` of an entry point's call.

    Parameters
    ----------
    run : StudyRun or None
        The call's ``run`` (None: the defaults).
    legacy : dict
        The call's other keywords: each must be a field of :class:`StudyRun` (deprecated
        spelling, warned once per call); they replace ``run``'s values.
    where : str
        The entry point, for the messages.

    Returns
    -------
    StudyRun

    Raises
    ------
    InputError
        An unknown keyword, or ``run`` that is no StudyRun.
    """
    if run is not None and not isinstance(run, StudyRun):
        raise InputError(f"run: must be a contact.study.StudyRun or None, got "
                         f"{type(run).__name__}")
    run = run or StudyRun()
    unknown = sorted(set(legacy) - set(RUN_FIELDS))
    if unknown:
        raise InputError(f"{where}: unknown keyword(s) {', '.join(unknown)}; the run "
                         f"settings are StudyRun({', '.join(RUN_FIELDS)})")
    if legacy:
        warnings.warn(f"{where}({', '.join(f'{k}=' for k in legacy)}): pass "
                      f"run=StudyRun({', '.join(f'{k}=…' for k in legacy)}) instead; the "
                      "keywords go in the next release", DeprecationWarning, stacklevel=3)
        run = dataclasses.replace(run, **legacy)
    return run
