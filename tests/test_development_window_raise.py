"""The drive developed again in its LTE window, its design torque raised back towards the
torque it was rated at (``contact.optimize.development._window_raised``; issue 71: a
design torque that holds, no lower than its bearing carries).

Stand-ins for the raise after a capacity cut (``development._regained``: every capacity
criterion, no drive target lost, the mounting tolerance and the LTE limit) and for the LTE
over ``ltca run``'s range: the rule alone, exact. Measured on the FH hypoid 10×33 at
Σ 80° (session 32, docs/synthesis.md "The window re-development raised back"): developed
again at 130.1 N·m, its raise to the ISO capacity 401.3 N·m refused (the light-load
pattern's length at 0.15 of it), bisected to 302.7 N·m.
"""

from __future__ import annotations

import math
import types

import pytest

from contact.optimize import development as dev
from contact.optimize.development_range_lte import range_record


def _stand_in(monkeypatch, keeps_to: float, capacity: float = math.inf):
    """``_regained`` raising to the torque asked where it is at or below ``keeps_to``
    [N·m] (above it a target would be lost: nothing raised), to ``capacity`` where that is
    lower; every torque asked recorded."""
    asked: list[float] = []

    def regained(case, best, targets, setup, teeth, ceiling, text, safety, say):
        asked.append(ceiling)
        if ceiling > keeps_to:
            return best, text, safety
        new = min(ceiling, capacity)
        setup["torques"] = [0.15 * new, new]
        return types.SimpleNamespace(values={"ellipse_length": 0.5}, torque=new), text, 2.0

    monkeypatch.setattr(dev, "_regained", regained)
    monkeypatch.setattr(dev, "range_lte", lambda e, setup, teeth: (
        tuple(setup["torques"]), (19.6, 20.7)))
    return asked


def test_refused_at_the_rated_torque_the_raise_is_bisected(monkeypatch):
    """130.1 N·m, rated 401.3: refused there, then √(130.1·401.3) = 228.5 kept, √(228.5·
    401.3) = 302.8 kept, √(302.8·401.3) = 348.6 refused (targets kept to 310): 302.8 N·m
    (the geometric means exact to 1e-12), its range recorded at the raised torques."""
    asked = _stand_in(monkeypatch, keeps_to=310.0)
    setup = {"torques": [19.5, 130.1], "source": "window"}
    best = types.SimpleNamespace(values={"ellipse_length": 0.5})
    got, safety = dev._window_raised(None, best, None, setup, None, 401.3, 3.2, True,
                                     lambda s: None)
    a1 = math.sqrt(130.1 * 401.3)
    a2 = math.sqrt(a1 * 401.3)
    a3 = math.sqrt(a2 * 401.3)
    assert asked == pytest.approx([401.3, a1, a2, a3], rel=1e-12)
    assert got is not best and got.torque == pytest.approx(a2, rel=1e-12)
    assert safety == 2.0 and setup["torques"][1] == pytest.approx(302.8, abs=0.05)
    assert range_record(setup)["lte"] == (19.6, 20.7)


def test_a_capacity_below_the_aim_ends_the_raise(monkeypatch):
    """Raised to its capacity 200 N·m below the aim 228.5: no higher torque holds, no
    further bisection; nothing raised where the rated torque is within 1 % of the
    window's, the root stress is off, or every raise is refused."""
    asked = _stand_in(monkeypatch, keeps_to=310.0, capacity=200.0)
    setup = {"torques": [19.5, 130.1], "source": "window"}
    best = types.SimpleNamespace(values={})
    got, _ = dev._window_raised(None, best, None, setup, None, 401.3, 3.2, True,
                                lambda s: None)
    assert len(asked) == 2 and got.torque == 200.0
    for ceiling, root_stress in ((131.0, True), (401.3, False), (math.nan, True)):
        asked.clear()
        setup = {"torques": [19.5, 130.1], "source": "window"}
        assert dev._window_raised(None, best, None, setup, None, ceiling, 3.2, root_stress,
                                  lambda s: None) == (best, 3.2)
        assert asked == [] and setup["torques"] == [19.5, 130.1]
    asked = _stand_in(monkeypatch, keeps_to=100.0)
    setup = {"torques": [19.5, 130.1], "source": "window"}
    assert dev._window_raised(None, best, None, setup, None, 401.3, 3.2, True,
                              lambda s: None) == (best, 3.2)
    assert len(asked) == 4 and setup["torques"] == [19.5, 130.1]
