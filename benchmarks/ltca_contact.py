"""qpbenchmark entry point: ``qpbenchmark benchmarks/ltca_contact.py run``.

qpbenchmark loads the class named after this file (``LtcaContact``); it is
defined in :mod:`contact.qpbenchmark_set`. Needs ``pip install 'hypoid-ltca[bench]'``.
"""

from contact.qpbenchmark_set import LtcaContact

__all__ = ["LtcaContact"]
