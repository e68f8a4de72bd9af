"""Contact problems on disk: one ``.npz`` file per problem and a JSON manifest.

A problem set written here (``ltca export-problems``) is what the solver studies read
(``ltca compare-solvers --problems DIR``, ``benchmarks/ltca_contact.py`` for qpbenchmark,
``benchmarks/active_set_real.py``), so a study can be repeated on exactly the same
problems without running the analysis again.

Problem file (:func:`write_problem`): NumPy ``.npz`` with ``compliance`` (N, N) [mm/N],
``separation`` (N,) [mm], ``moment_arm`` (N,) [mm] and ``torque`` () [N·mm] — the
physical :class:`ContactProblem` (seed Eq. 3.12–3.14), unscaled, bit for bit — and, where
some segment has a force limit, ``upper_bound`` (N,) [N] (``inf`` where none).

Manifest (:func:`write_manifest`), ``manifest.json`` in the set's directory::

    {"format": "hypoid-ltca contact problems", "format_version": 1,
     "attrs": {...},                    # who wrote it, when, with which settings
     "problems": [{"name": ..., "file": ..., "n": ..., ...}, ...]}

Each entry holds at least ``name``, ``file`` (relative to the directory) and ``n`` (the
number of variables N); an LTCA export adds the case, misalignment, torque and roll.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from contact.errors import ProblemInputError
from contact.qp.problem import ContactProblem
from geometry.core.atomic_files import atomic_path

__all__ = [
    "MANIFEST",
    "MANIFEST_FORMAT",
    "read_manifest",
    "read_problem",
    "read_problem_set",
    "write_manifest",
    "write_problem",
]

#: File name of the manifest in a problem set's directory.
MANIFEST = "manifest.json"

#: ``format`` field of a manifest (with ``format_version`` 1).
MANIFEST_FORMAT = "hypoid-ltca contact problems"

_KEYS = ("compliance", "separation", "moment_arm", "torque")


def _atomic_write(path: Path, write) -> None:
    """Write through a temporary file in the same directory, then rename over ``path``."""
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        write(fh)


def write_problem(path: str | os.PathLike[str], problem: ContactProblem) -> Path:
    """Write one contact problem as ``.npz`` (atomically: temporary file, then rename).

    Parameters
    ----------
    path : path-like
        Target file; ``.npz`` is appended if missing. Its directory must exist.
    problem : ContactProblem
        Stored unscaled: C [mm/N], s [mm], R [mm], T [N·mm] and, where some segment has
        one, the force limits F_max [N].

    Returns
    -------
    pathlib.Path
        The file written.
    """
    p = Path(path)
    if p.suffix != ".npz":
        p = p.with_name(p.name + ".npz")
    arrays = {k: np.asarray(getattr(problem, k)) for k in _KEYS}
    if problem.has_bounds:
        arrays["upper_bound"] = np.asarray(problem.upper_bound)
    _atomic_write(p, lambda fh: np.savez(fh, **arrays))
    return p


def read_problem(path: str | os.PathLike[str], name: str = "") -> ContactProblem:
    """Read a contact problem written by :func:`write_problem`.

    Parameters
    ----------
    path : path-like
    name : str
        The problem's name (default: the file's stem).

    Returns
    -------
    ContactProblem

    Raises
    ------
    ProblemInputError
        Missing file or key, or an invalid problem (as :class:`ContactProblem`).
    """
    p = Path(path)
    try:
        with np.load(p, allow_pickle=False) as data:
            missing = [k for k in _KEYS if k not in data]
            if missing:
                raise ProblemInputError(f"{p}: problem file lacks {', '.join(missing)}")
            arrays = {k: np.array(data[k]) for k in _KEYS}
            bound = np.array(data["upper_bound"]) if "upper_bound" in data else None
    except (OSError, ValueError) as exc:
        raise ProblemInputError(f"{p}: not a readable problem file ({exc})") from None
    return ContactProblem(arrays["compliance"], arrays["separation"], arrays["moment_arm"],
                          float(arrays["torque"]), name=name or p.stem, upper_bound=bound)


def write_manifest(directory: str | os.PathLike[str], entries: Sequence[Mapping[str, Any]],
                   attrs: Mapping[str, Any] | None = None) -> Path:
    """Write ``manifest.json`` of a problem set (atomically).

    Parameters
    ----------
    directory : path-like
        The set's directory (exists).
    entries : sequence of mapping
        One per problem: ``name``, ``file`` (relative to ``directory``), ``n`` and any
        further JSON-serialisable fields.
    attrs : mapping, optional
        Set-wide information (toolkit version, settings, date).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    ProblemInputError
        An entry lacks ``name``, ``file`` or ``n``, or names repeat.
    """
    names = set()
    for e in entries:
        for key in ("name", "file", "n"):
            if key not in e:
                raise ProblemInputError(f"manifest entry {dict(e)!r}: lacks {key!r}")
        if e["name"] in names:
            raise ProblemInputError(f"manifest: problem name {e['name']!r} repeats")
        names.add(e["name"])
    doc = {"format": MANIFEST_FORMAT, "format_version": 1, "attrs": dict(attrs or {}),
           "problems": [dict(e) for e in entries]}
    path = Path(directory) / MANIFEST
    text = json.dumps(doc, indent=1, ensure_ascii=False).encode("utf-8")
    _atomic_write(path, lambda fh: fh.write(text))
    return path


def read_manifest(directory: str | os.PathLike[str]) -> dict[str, Any]:
    """Read ``manifest.json`` of a problem set.

    Returns
    -------
    dict
        ``format``, ``format_version``, ``attrs`` and ``problems`` (list of dict).

    Raises
    ------
    ProblemInputError
        No manifest, or not one of this format.
    """
    path = Path(directory) / MANIFEST
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ProblemInputError(f"{path}: no manifest (write the set with "
                                "`ltca export-problems ... -o DIR`)") from None
    except (OSError, json.JSONDecodeError) as exc:
        raise ProblemInputError(f"{path}: unreadable manifest ({exc})") from None
    if not isinstance(doc, dict) or doc.get("format") != MANIFEST_FORMAT:
        raise ProblemInputError(f"{path}: format must be {MANIFEST_FORMAT!r}")
    if doc.get("format_version") != 1 or not isinstance(doc.get("problems"), list):
        raise ProblemInputError(f"{path}: format_version must be 1 with a problems list")
    return doc


def read_problem_set(directory: str | os.PathLike[str]) -> list:
    """Every problem of a set written with a manifest, as the solver study's test problems.

    Parameters
    ----------
    directory : path-like

    Returns
    -------
    list of contact.qp.benchmark_problems.TestProblem
        In manifest order; kind from the entry's ``kind`` (default ``ltca``),
        ``reference`` the manifest entry.

    Raises
    ------
    ProblemInputError
        As :func:`read_manifest` and :func:`read_problem`, or a file's N differs from
        its entry's ``n``.
    """
    from contact.qp.benchmark_problems import TestProblem

    d = Path(directory)
    out = []
    for e in read_manifest(d)["problems"]:
        problem = read_problem(d / e["file"], name=e["name"])
        if problem.size != int(e["n"]):
            raise ProblemInputError(f"{e['file']}: N = {problem.size}, the manifest says "
                                    f"{e['n']}")
        out.append(TestProblem(e["name"], e.get("kind", "ltca"), problem, dict(e)))
    return out
