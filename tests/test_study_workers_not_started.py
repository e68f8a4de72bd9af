"""A local cluster whose workers do not start is refused in words, not a traceback
(round 21 of issue 71: a script calling ``contact.run_duty_cycle`` at its top level ended in
distributed's "RuntimeError: Nanny failed to start." — each spawned worker imports the
script again, which Python refuses)."""

from __future__ import annotations

import distributed
import pytest

from contact.study import engine
from geometry.core.errors import InputError


def test_workers_that_do_not_start_name_the_two_ways(monkeypatch):
    def refused(*args, **kwargs):
        raise RuntimeError("Nanny failed to start.")

    monkeypatch.setattr(distributed, "LocalCluster", refused)
    with pytest.raises(InputError) as err, engine.open_client(None, 1):
        pass
    text = str(err.value)
    assert text.startswith("scheduler: the local cluster's worker processes failed to "
                           "start (Nanny failed to start.)")
    assert 'if __name__ == "__main__":' in text
    assert 'StudyRun(scheduler="synchronous")' in text
