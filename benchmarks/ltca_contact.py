"""qpbenchmark entry point: ``qpbenchmark benchmarks/ltca_contact.py run``.

qpbenchmark loads the class named after this file (``LtcaContact``); it is
defined in :mod:`contact.qp.qpbenchmark_export`. Needs ``pip install 'hypoid-ltca[bench]'``.
"""

from contact.qp.qpbenchmark_export import LtcaContact

__all__ = ["LtcaContact"]
