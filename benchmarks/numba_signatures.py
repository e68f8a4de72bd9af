"""What numba compiles on a fresh cache, per dispatcher (issue 75: a new design within
30 s of CPU on a fresh numba cache; docs/performance.md "Numba's compiled signatures on a
fresh cache").

Runs the default case's contact analysis (``ltca compile``'s run: geometry, UTCA, LTCA,
no root stress) with ``LTCA_KERNELS=numba`` in this process, or with ``--synthesize FILE``
``ltca synthesize FILE``, and then lists every dispatcher of the four kernel modules
(:data:`geometry.core.kernels.KERNEL_MODULES`) with its compiled signatures
(``dispatcher.signatures``) and its compile CPU, exclusive of the compiles nested in it
(numba's ``numba:compile`` events, :mod:`numba.core.event`; a caller's typing compiles its
callees inside its own event). Run it with an empty cache of its own, e.g.::

    NUMBA_CACHE_DIR=/tmp/n1 python benchmarks/numba_signatures.py

``--command WORDS…``: run ``ltca WORDS…`` as its own process would (``contact.cli.main``
without arguments: the command's own kernel choice, e.g. ``ltca synthesize``'s envelope
only on a fresh cache and ``ltca run``'s NumPy path until the cache holds the kernels;
``LTCA_KERNELS`` left as the environment sets it), e.g. on one fresh cache (issue 75,
docs/performance.md "A new design on a fresh numba cache: what is left to compile")::

    export NUMBA_CACHE_DIR=/tmp/n2 HYPOID_LTCA_CACHE=/tmp/fe2
    python benchmarks/numba_signatures.py --command synthesize \
        tests/data/designs/pc_hypoid_10x43.toml -o /tmp/case.toml -q
    python benchmarks/numba_signatures.py --command run /tmp/case.toml -o /tmp/c.nc -q

``--brief``: the totals and the eight dearest dispatchers only. CPU is this process's
``time.process_time``.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from collections import defaultdict


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--synthesize", metavar="FILE",
                        help="run ltca synthesize FILE instead of the default case's analysis")
    parser.add_argument("--brief", action="store_true", help="totals and the dearest only")
    parser.add_argument("--command", nargs=argparse.REMAINDER, metavar="WORDS",
                        help="run `ltca WORDS...` as its own process (its own kernel choice)")
    args = parser.parse_args(argv)
    if not args.command:
        os.environ["LTCA_KERNELS"] = "numba"

    import numba
    from numba.core import event
    from numba.core.registry import CPUDispatcher

    stack: list[list[float]] = []
    exclusive: dict[str, float] = defaultdict(float)
    events: dict[str, int] = defaultdict(int)

    class Exclusive(event.Listener):
        def on_start(self, ev):
            stack.append([time.process_time(), 0.0])

        def on_end(self, ev):
            start, nested = stack.pop()
            spent = time.process_time() - start
            name = ev.data["dispatcher"].py_func.__qualname__
            exclusive[name] += spent - nested
            events[name] += 1
            if stack:
                stack[-1][1] += spent

    event.register("numba:compile", Exclusive())
    start = time.process_time()
    if args.command:
        from contact.cli import main as ltca

        sys.argv = ["ltca", *args.command]
        status = ltca()  # no arguments: the command is the process (contact.cli.main)
        if status:
            print(f"ltca {' '.join(args.command)} returned {status}", file=sys.stderr)
    elif args.synthesize:
        from contact.cli import main as ltca

        with tempfile.TemporaryDirectory() as tmp:
            ltca(["synthesize", args.synthesize, "-o", os.path.join(tmp, "case.toml")])
    else:
        from contact.pipeline import run_analysis

        run_analysis(None, [250.0], steps={"root_stress": None, "mesh_interface": None,
                                           "efficiency": None, "load_capacity": None})
    cpu = time.process_time() - start

    from geometry.core.kernels import KERNEL_MODULES

    rows = []
    for module_name in KERNEL_MODULES:
        module = sys.modules.get(module_name)
        for name, f in (vars(module) if module is not None else {}).items():
            if isinstance(f, CPUDispatcher) and f.signatures:
                rows.append((f"{module_name.rsplit('.', 1)[-1]}.{name}",
                             exclusive.get(f.py_func.__qualname__, 0.0),
                             events.get(f.py_func.__qualname__, 0), f.signatures))
    print(f"numba {numba.__version__}: {len(rows)} dispatchers, "
          f"{sum(len(r[3]) for r in rows)} signatures, {sum(events.values())} compile "
          f"events, compile CPU {sum(exclusive.values()):.1f} s of {cpu:.1f} s")
    own, own_events = sum(r[1] for r in rows), sum(r[2] for r in rows)
    print(f"  the project's dispatchers {own:.1f} s in {own_events} events; numba's own "
          f"(its implementations of NumPy functions) {sum(exclusive.values()) - own:.1f} s "
          f"in {sum(events.values()) - own_events} events")
    rows.sort(key=lambda r: -r[1])
    for name, spent, count, signatures in rows[:8] if args.brief else rows:
        print(f"  {name}: {spent:.2f} s, {count} events, {len(signatures)} signatures")
        if not args.brief:
            for signature in signatures:
                print(f"      {signature}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
