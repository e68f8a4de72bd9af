"""A computed roll whose screening leaves no segment keeps no pool (no crash deep in the
segment batch): the other rolls' pools are assembled without it, and its solve then says
"no segment within the separation limit" in its status (Round 25's 12×12 miter at a
−60° path angle stopped with "midpoints: must be of shape (N, 3) … got (0, 3)")."""

from types import SimpleNamespace

import numpy as np

from contact.ltca.roll_loop import _assemble_other_pools


class _Screening:
    """Three rolls of (K, S) = (2, 3) segments; roll 2 has none usable near any θ."""

    def __init__(self) -> None:
        self.usable = np.ones((3, 2, 3), dtype=bool)
        self.usable[2] = False
        self.ute = np.zeros(3)

    def near(self, j: int, theta: float) -> np.ndarray:
        return self.usable[j].copy()

    def first_pool(self, j: int) -> np.ndarray:
        return self.usable[j].copy()


class _Pool:
    def __init__(self) -> None:
        self.jobs: list[tuple[int, np.ndarray]] = []

    def assemble(self, jobs: list[tuple[int, np.ndarray]]) -> None:
        assert all(mask.any() for _, mask in jobs), "an empty pool reached the batch"
        self.jobs.extend(jobs)


def _analysis(found: bool) -> SimpleNamespace:
    results = SimpleNamespace(found=np.array([[found, found, found]]),
                              rotation=np.zeros((1, 3)))
    return SimpleNamespace(screening=_Screening(), results=results, pool=_Pool(),
                           setup=SimpleNamespace(torques=np.array([100.0])))


def test_a_roll_with_no_segment_keeps_no_pool_whether_or_not_the_first_roll_was_solved():
    for found in (True, False):
        an = _analysis(found)
        _assemble_other_pools(an, 0, [1, 2])
        # exactly roll 1's pool, every one of its six segments; roll 2 left without one
        assert [j for j, _ in an.pool.jobs] == [1]
        assert int(an.pool.jobs[0][1].sum()) == 6


def test_no_batch_at_all_where_no_other_roll_has_a_segment():
    an = _analysis(True)
    _assemble_other_pools(an, 0, [2])
    assert an.pool.jobs == []
