"""geometry.core.bisection.largest_found against a threshold known in closed form."""

import math

from geometry.core.bisection import largest_found


def test_the_largest_success_is_found_to_the_interval_over_two_to_the_steps():
    """trial succeeds below √2 (x² < 2): after 30 halvings of [1, 2] the largest success
    lies within 2**-30 below √2 (the bisection's bound), and its result is the trial's."""
    lo, found = largest_found(lambda x: x * x if x * x < 2.0 else None, 1.0, 2.0, 30, 1.0)
    assert 0.0 < math.sqrt(2.0) - lo <= 2.0 ** -30
    assert found == lo * lo


def test_no_success_keeps_the_given_end_and_result():
    """A trial that fails everywhere in (lo, hi): lo and the caller's ``found`` back."""
    assert largest_found(lambda x: None, 0.0, 1.0, 8, "at lo") == (0.0, "at lo")
    assert largest_found(lambda x: None, 0.0, 1.0, 8) == (0.0, None)
