"""Running a check again in a process whose OpenBLAS uses another CPU's kernels.

A result that depends on a machine's last digit (a contact set, a vertex's cell, an
iteration count chosen by round-off) passes on the machine that stored it and fails on a
new user's CPU (issue 31). Forcing ``OPENBLAS_CORETYPE`` to a generic kernel of the
architecture in a subprocess makes it fail on any machine. Used by
``tests/test_golden_run.py`` (the golden file's summary) and ``tests/test_sweep_guard.py`` (the
sweep guard).

The code run must print, as its first line, ``kernel`` and the kernels OpenBLAS took
(:data:`PRINT_KERNEL`), and ``AGREES`` when its comparison found no difference.
"""

from __future__ import annotations

import os
import platform
import subprocess
import sys

import pytest

#: OpenBLAS kernels forced in the other-kernel run: the first of each list that is not the
#: kernel this machine chose (generic kernels that run on any CPU of the architecture)
OTHER_KERNELS = {"x86_64": ("Prescott", "Nehalem"), "AMD64": ("Prescott", "Nehalem"),
                 "aarch64": ("ARMV8", "NEOVERSEN1"), "arm64": ("ARMV8", "NEOVERSEN1")}

#: the first lines of the code run: print the kernels OpenBLAS took
PRINT_KERNEL = """
from threadpoolctl import threadpool_info
arch = [i.get("architecture") for i in threadpool_info() if i["internal_api"] == "openblas"]
print("kernel", arch)
"""


def openblas_kernel() -> str | None:
    """The kernel numpy's OpenBLAS chose in this process (None: not OpenBLAS)."""
    from threadpoolctl import threadpool_info

    arch = [i.get("architecture") for i in threadpool_info() if i["internal_api"] == "openblas"]
    return arch[0] if arch else None


def run_on_other_kernel(code: str, timeout: float = 600) -> str:
    """Run ``code`` (it begins with :data:`PRINT_KERNEL`) with ``OPENBLAS_CORETYPE`` forced to
    a kernel other than this machine's; its stdout. Skips the test where that does not
    apply; fails if the run fails or OpenBLAS did not take the kernel."""
    kernel = openblas_kernel()
    if kernel is None:
        pytest.skip("numpy's BLAS is not OpenBLAS: OPENBLAS_CORETYPE does not apply")
    choices = OTHER_KERNELS.get(platform.machine())
    if choices is None:
        pytest.skip(f"no generic OpenBLAS kernel listed for {platform.machine()}")
    other = next(k for k in choices if k.lower() != kernel.lower())
    env = {**os.environ, "OPENBLAS_CORETYPE": other}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, timeout=timeout)
    assert out.returncode == 0, out.stderr[-3000:]
    # OpenBLAS names some forced kernels by their family (Prescott runs as 'Katmai')
    assert kernel.lower() not in out.stdout.splitlines()[0].lower(), \
        f"OpenBLAS did not take OPENBLAS_CORETYPE={other}: {out.stdout.splitlines()[0]}"
    return out.stdout
