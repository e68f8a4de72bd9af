"""The number of draws of a Monte Carlo tolerance study: one default and one accepted
range for :func:`contact.study.sample` and ``ltca tolerance -n`` (issue 71: the API
required ``n`` where the command defaults to 256, and refused ``n`` < 2 where the command's
parser accepted ``-n 1``). A module of constants only, which the command's parser imports
without NumPy, SciPy or xarray.

Public names
------------
DEFAULT_SAMPLES  the default number of draws
SAMPLES_RANGE    the accepted numbers of draws, both ends included
samples_message  the refusal both say
"""

from __future__ import annotations

__all__ = ["DEFAULT_SAMPLES", "SAMPLES_RANGE", "samples_message"]

#: the default number of draws: 2^8, a power of two (where scrambled Sobol' points keep
#: their balance, scipy.stats.qmc.Sobol) and a P5/P95 each resting on ~13 draws
DEFAULT_SAMPLES = 256

#: the accepted numbers of draws, both ends included: at least 2 (one draw has no spread,
#: no percentile and no sensitivity), at most 10^7 (the bound of the command's work)
SAMPLES_RANGE = (2, 10_000_000)


def samples_message(value: object) -> str:
    """The refusal of a number of draws outside :data:`SAMPLES_RANGE`, the same text for
    the API (after ``n: ``) and the command's parser (after ``argument -n: ``).

    Parameters
    ----------
    value : object
        What was given.

    Returns
    -------
    str
        ``must be an integer in [2, 10000000], got VALUE``.
    """
    low, high = SAMPLES_RANGE
    return f"must be an integer in [{low}, {high}], got {value!r}"
