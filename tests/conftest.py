"""Test-suite configuration.

BLAS is limited to one thread: the suite's matrices are small, and on a shared
2-core machine a multi-threaded BLAS oversubscribes the cores (a shell-model build
measured 0.02 s single-threaded and 0.3–0.7 s threaded under load).
"""

from threadpoolctl import threadpool_limits

threadpool_limits(limits=1, user_api="blas")
