"""A user's stop (Ctrl-C, the CLI's SIGTERM) that arrives inside a numba kernel's call
reaches the command as ``SystemError: CPUDispatcher(...) returned a result with an
exception set`` chained to the KeyboardInterrupt; the handlers that take any Exception as
one failed trial re-raise it (:func:`geometry.core.errors.raise_if_interrupted`). Round
18: `ltca synthesize` ran on for 120 s after SIGTERM, 73 more lines, until SIGKILL."""

from __future__ import annotations

import pytest

from geometry.core.errors import raise_if_interrupted


def _wrapped(stop: BaseException) -> SystemError:
    """The SystemError Python's C API raises for a call that returned with an exception
    set: the exception as its cause (as numba's dispatcher reports its callback's)."""
    try:
        try:
            raise stop
        except BaseException as inner:
            raise SystemError("CPUDispatcher(<function newton>) returned a result with an "
                              "exception set") from inner
    except SystemError as exc:
        return exc


def test_the_stop_in_the_chain_is_raised_again():
    stop = KeyboardInterrupt("signal 15")
    with pytest.raises(KeyboardInterrupt) as got:
        raise_if_interrupted(_wrapped(stop))
    assert got.value is stop
    # only as the implicit context (raised while handling it) too
    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt:
            raise RuntimeError("during handling")  # noqa: B904 — the implicit chain
    except RuntimeError as exc:
        with pytest.raises(KeyboardInterrupt):
            raise_if_interrupted(exc)


def test_a_failure_without_a_stop_passes():
    assert raise_if_interrupted(_wrapped(ValueError("no mean point"))) is None
    assert raise_if_interrupted(ValueError("plain")) is None
    # a chain that loops ends
    a, b = ValueError("a"), ValueError("b")
    a.__context__, b.__context__ = b, a
    assert raise_if_interrupted(a) is None


def test_a_development_trial_does_not_swallow_the_stop():
    """The development's "one failing design never ends the development" handler: a trial
    whose synthesis fails is recorded as failed, one stopped by the user stops the
    development."""
    from contact.optimize import development as dev

    targets = dev.DevelopmentTargets()
    evals: list = []
    evaluate = dev.evaluator(None, targets, {}, dev.KeptTeeth(), [].append, evals, "drive",
                             targets.max_evaluations)

    def failing():
        raise _wrapped(ValueError("no mean point"))

    def stopped():
        raise _wrapped(KeyboardInterrupt("signal 15"))

    failed = evaluate({"path_angle": -45.0}, "bearing", failing, 10, ())
    assert not failed.met and "SystemError" in failed.reason and len(evals) == 1
    with pytest.raises(KeyboardInterrupt):
        evaluate({"path_angle": -50.0}, "bearing", stopped, 10, ())


def test_a_study_point_and_a_duty_cycle_bin_do_not_swallow_the_stop(monkeypatch):
    """``analyse_point`` and ``analyse_bin`` ("a failing point / bin never stops the
    study"): a wrapped failure is a failed point (status 2), a wrapped stop stops (run
    synchronously, ``--scheduler synchronous``, they run in the command's process)."""
    import contact.pipeline
    from contact.catalogue import resolve_case
    from contact.ltca import LTCAOptions
    from contact.study.duty_cycle import DutyInputs, analyse_bin
    from contact.study.duty_cycle_inputs import DutyCycle
    from contact.study.engine import analyse_point
    from contact.study.points import StudyInputs

    raised: list[BaseException] = []

    def analysis(*args, **kw):
        raise _wrapped(raised[-1])

    monkeypatch.setattr(contact.pipeline, "run_analysis", analysis)
    case = resolve_case(None)
    options = LTCAOptions(rolls_per_cycle=4, segments=8)
    point = StudyInputs(case, (250.0,), speed=(1500.0,), options=options)
    duty = DutyInputs(case, DutyCycle(torque=[250.0], pinion_speed=[1500.0],
                                      revolutions=[1e6]), options)
    raised.append(ValueError("no mean point"))
    assert analyse_point(point, 0, {}).status == 2
    assert int(analyse_bin(duty, 0)["status"].values[0]) == 2
    raised.append(KeyboardInterrupt("signal 2"))
    with pytest.raises(KeyboardInterrupt):
        analyse_point(point, 0, {})
    with pytest.raises(KeyboardInterrupt):
        analyse_bin(duty, 0)
