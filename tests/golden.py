"""The golden file of the default ``ltca run``: how it is made and how a run is compared.

``tests/data/golden_default_run.json`` summarises, as text, the netCDF that ``ltca run``
(no arguments: the bundled default case at the seed's Table 3.1 conditions, the efficiency
stage at 1500 rpm) writes: one line per group, variable and attribute, sorted by path, so
a new output variable adds a line and a review reads the diff (issue 63). It guards every
refactoring that must not change results: a new run must reproduce every entry but the
timings and the file's creation stamp.

What a line holds
-----------------
``"/ltca"`` (a group)
    its dimensions and their sizes.
``"/ltca@title"``, ``"/ltca/force@units"`` (an attribute of a group or a variable)
    its value as netCDF stores it (text, integer, float or a list of them); a text longer
    than :data:`LONG_TEXT` characters (the case as TOML, its source) by its length and
    the SHA-256 of its UTF-8 bytes.
``"/ltca/force"`` (a variable)
    its ``dims``, ``shape`` and ``dtype``, and:

    * integers, text (and any array of up to :data:`SMALL` elements): the ``values``
      themselves when there are at most :data:`SMALL`, else the ``sha256`` of their
      canonical bytes (little-endian integers; text as the JSON list of its strings);
    * floats of more than :data:`SMALL` elements: the positions of NaN and ±inf (their
      counts and the SHA-256 of a code per element) and, over the finite elements, the
      statistics of :func:`float_summary`: ``min``, ``max``, ``sum``, ``sum_abs``, ``l2``
      and, for every dimension, the ``bits`` sums (the sum over the elements whose index
      along that dimension has bit *b* set, for every bit *b* of its largest index;
      Σ i·x along the dimension is Σ_b 2^b·bits[b]). Sums are :func:`math.fsum`, exactly
      rounded, so a statistic does not depend on the order of summation or on the
      array's alignment in memory: identical arrays give identical statistics on any
      machine.

How a float variable is compared (:func:`differences`)
------------------------------------------------------
With the variable's tolerance (:func:`tolerance`: ``rtol`` of its largest magnitude
``S = max(|min|, |max|)`` or the absolute ``atol`` of :data:`ACROSS_MACHINES`) the old
netCDF golden file allowed each element to move by ``τ = max(rtol·S, atol)``. The
summary keeps that for the extremes and adds a bound on the total movement:

* ``min`` and ``max`` to ``τ``: each is 1-Lipschitz in the largest element change, so a
  run whose every element moved by at most ``τ`` never fails them;
* ``sum``, ``sum_abs``, ``l2`` and each ``bits`` sum to
  ``b = τ + ρ·Σ|x| + N·atol`` (``N`` finite elements, ``ρ = rtol·``:data:`AGGREGATE_SHARE`):
  each is a sum of the elements with weights 0 or 1 (``l2`` is 1-Lipschitz in the
  elements' L2 norm, below their L1 norm), so it moves by at most the L1 norm of the
  change, Σ|d|; the bound admits one element moved by the whole ``τ`` plus every
  element's round-off at ``ρ`` of its magnitude on average (measured below).

What that sees, and the argument the tests check (``tests/test_golden_run.py``):

* a change of the largest (smallest) element by more than ``τ`` moves ``max`` (``min``)
  by more than ``τ`` (when it grows away from the rest; shrinking, by at least its margin
  over the next element);
* a change of **any one element** by ``δ`` moves ``sum`` by exactly ``δ`` (to the
  exactly rounded sum's last bit): seen when ``|δ| > b``;
* a **swap of two elements** ``x_a ≠ x_b``: their positions differ in the index of at
  least one dimension, hence in at least one bit *b* of it, and that ``bits`` sum moves by
  exactly ``±(x_a − x_b)`` (one of the two is in its set, the other not): seen when
  ``|x_a − x_b| > b``; a shift of the pattern along a dimension moves its ``bits`` sums
  the same way;
* a new NaN, a NaN gone, a changed shape or dtype: always.

``b`` exceeds ``τ`` by ``ρ·Σ|x|``: a small element is checked to ``b`` (for the default
run's ``/ltca/force``, Σ|x| ≈ 1090·S, so b ≈ 1.1e-7·S at rtol 1e-9, 0.15 mN of the
largest 1404 N), the extremes to ``τ``. A change the old file saw and these statistics
do not is one that moves no extreme, no sum and no bit sum by more than ``b`` — e.g.
one small element moved by ``τ < |δ| ≤ b``, or several by amounts that cancel in every
one of them. That is the price of a text file instead of every number.

Measured on this machine (SkylakeX kernels against ``OPENBLAS_CORETYPE=Prescott``, one
default run each, issue 63), over the summarised variables: the largest element change
was ≤ 1.3e-10·S but for the film thickness and its ratios (1.1e-9·S, tolerance 1e-7) and
``placement_error`` (1e-6·S = 1e-13 mm, an absolute tolerance), the total
Σ|d| ≤ 4.9e-12·Σ|x| (``specific_film_thickness``; ``plastic_load_share`` 4.8e-12, the rest
≤ 4.4e-12) but for ``placement_error``; the sums moved by up to 1.7e-9·S
(``/ltca/pressure_max``: its 5808 loaded elements' round-off adds up beyond ``τ``), which
is why their bound carries ``ρ·Σ|x|`` and not ``τ`` alone. With ``ρ = rtol/10`` (a
factor 20 above the largest Σ|d|/Σ|x|) the statistic that came nearest its bound moved
by 0.03 of it (``/ltca/plastic_load_share``'s sum, whose bound is mostly ``τ``); the
extremes moved by ≤ 0.015 of ``τ``.

With ``rtol = 0`` (``--check``: bit for bit on the machine that wrote the file) ``τ`` and
``ρ`` are 0 and every statistic must be identical, but the contact residuals'
(:data:`RESIDUAL_ATOL`).

History
-------
The file was a zlib netCDF of the whole run (3.6 MB) until issue 63: first written before
the restructuring of ``contact/`` into its layers (issue 20), which reproduced it;
rewritten when the default case became the reference design
``kolivand2009_fm_11x41_reference`` (issue 19), an intended change of every result; and
when ``kolivand2009`` became the default friction model (issue 34: ``/friction`` and the
summary's efficiency changed, every other variable identical); and when ``kolivand2009``
was refitted to the stochastic mixed-EHL solver and fed the total slide-to-roll ratio
(issue 51: ``/friction`` — its new ``slide_to_roll_total`` — and the summary's efficiency
changed, every other variable within the tolerances below); and when the default run
gained the tooth-root stress (issue 53: ``/ltca/root_stress``, ``root_stress_max``), the
ISO 10300 rating (issue 52: the ``/rating`` group; the cases' ``inputs`` gained their
``[design]`` and ``[rating]`` tables), scuffing and micropitting (issue 52: new
``/friction`` variables) and version 0.2.0 — every variable of the previous file
unchanged (``--check`` listed only new variables, groups and attributes); and for 0.3.0,
whose run stores the standard's flash temperature method as ``/rating/flash_temperature``
(the group added, every other group and value kept, the version attribute adopted).
Issue 63 replaced the netCDF by this text summary, written from a run of the tree of
that day (whose results the round's other changes had moved). Issue 74 made
``thermal_eyring`` the default friction model: the entries of ``/friction``,
``/scuffing_micropitting``, the root's ``summary`` and ``id`` and every ``inputs``
attribute (the cases' ``friction_model`` line) were taken from a ``--write`` run; every
other entry was kept as it was (that run reproduced them within the tolerances below, at
round-off: 1e-16–1e-14 relative), so the diff shows the switch alone. Issue 71 made
``FEOptions.slot_bottom = "edge_radius"`` the FE model's default (a separately cut
pinion's slot bottom rounded by the blades' edge radius where its two cuts cross): only
``/ltca/root_stress`` (the pinion's stations away from its peak, −12.8 … +7.5 %),
``root_stress_max`` (the pinion's peaks by ≤ 1.7e-3 MPa) and the ``fe_cache_keys``
attribute were taken from a ``--write`` run, every other entry kept. Issue 71's
``lte_range`` step (the LTE judged between the run's torques, on by default in
``ltca run``) added ``/ltca/lte_torque``, ``lte_range_peak_to_peak`` and
``lte_range_source`` and the ``/ltca`` group's ``lte_torque`` dimension, taken from a
``--write`` run; every other entry was kept (that run reproduced them at round-off).
Issue 71's safeguarded second-order step (branch newton91: a Newton step that raises a
pair's cost UTE_seed + ½ K t² is halved) was taken from a ``--write`` run: on the default
case it moved the UTE at one roll by 7e-4 µrad and with it the transitions and the rolls
(round-off), the LTE mean by ≤ 3.4e-4 µrad, its harmonics by ≤ 1e-3 µrad, the
efficiency by ≤ 3.1e-8; the LTE p-p, flank and edge peaks at round-off.

Usage
-----
Check a working tree bit for bit (every statistic identical, the residuals excepted)::

    python tests/golden.py --check

Regenerate it only when a change of results is intended and reviewed (``git diff``
then shows which groups, variables and attributes changed)::

    python tests/golden.py --write

When only the attributes the writer stamps change (e.g. the ACDD attributes, issue 21; the
module names in the provenance text when ``geometry/`` got its subpackages, issue 31),
take the new run's attributes into the golden file, its values kept, only after the
values were found identical::

    python tests/golden.py --adopt-attributes

Each runs ``ltca run`` once (about a minute); ``--from FILE`` uses a file ``ltca run``
wrote instead.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import xarray as xr

GOLDEN = Path(__file__).parent / "data" / "golden_default_run.json"
#: the layout of the golden file's entries (bumped when an entry changes meaning)
FORMAT = 1
#: arrays of at most this many elements are stored as their values, compared element by
#: element (a summary scalar, a per-torque or per-member result, a coordinate)
SMALL = 64
#: text attributes longer than this are stored as their length and SHA-256 (the case as
#: TOML, 10.7 k characters, and its source); shorter ones as the text (the summaries)
LONG_TEXT = 1000
#: ρ / rtol: the round-off every element may carry, on average, relative to its own
#: magnitude, in the bound of the sums (module docstring: measured 4.9e-12 at rtol 1e-9)
AGGREGATE_SHARE = 0.1

#: attributes that record when and how fast, not what
_SKIP_ATTRS = ("history", "date_created", "date_modified", "date_metadata_modified")
#: variables that are timings [s]
_SKIP_VARS = ("solve_time", "compliance_time")
#: [1] the relative residuals of the contact conditions are round-off (~1e-16): they vary
#: from run to run in their last bits even on one machine (numpy's vectorised sums depend on
#: the arrays' alignment), so they are compared to this absolute tolerance, 1e5 below the
#: certification tolerance (contact.DEFAULT_TOLERANCE, 1e-7)
RESIDUAL_ATOL = 1e-12


class Tolerance(NamedTuple):
    """How a float variable or attribute is compared across machines (``rtol > 0``)."""

    rtol: float  #: [1] of the variable's largest magnitude (an attribute: of its value)
    atol: float  #: in the variable's units
    why: str


#: float variables (by path, or by name in every group) and attributes (by name) whose
#: comparison across CPUs and BLAS builds cannot be the default ``rtol`` of the variable's
#: largest magnitude. Measured with ``OPENBLAS_CORETYPE`` forced to Zen, Sandybridge,
#: Nehalem and Prescott against the file written with SkylakeX kernels (issue 31): every
#: other variable and attribute agreed to ≤ 2e-10 of its scale.
ACROSS_MACHINES: dict[str, Tolerance] = {
    "/friction/friction_coefficient": Tolerance(
        1e-7, 0.0,
        "a friction coefficient is a function of its segment's own load (kolivand2009: "
        "the Eyring traction over the segment's Hertz zone and powers of p_h; xu2007: "
        "p_h^1.03), not of the largest load: at the lightest loaded "
        "segments (force ~1e-3 of the largest) the forces' round-off, ~1e-11 of the largest "
        "force, is ~1e-8 of the segment's own, and μ there moved by 4-5e-9 of the largest μ; "
        "1e-7 keeps a factor 20"),
    "/friction/film_thickness": Tolerance(
        1e-7, 0.0,
        "[µm] a minimum film thickness is a power of its segment's own load "
        "(Dowson-Higginson h ∝ w^-0.13, and the thermal factor through p_h), not of the "
        "largest load: at the lightest loaded segments the forces' round-off (~1e-8 of the "
        "segment's own force) moved h by 1.4e-9 µm of the largest 0.72 µm (2e-9) on CI's "
        "forced Katmai kernels (issue 31); 1e-7 keeps the factor of friction_coefficient"),
    "/friction/lambda_ratio": Tolerance(
        1e-7, 0.0,
        "[1] the film thickness over the composite roughness (see film_thickness): "
        "1.3e-9 of the largest 0.64 measured"),
    "/scuffing_micropitting/specific_film_thickness": Tolerance(
        1e-7, 0.0,
        "[1] λ_GF = h_min / Ra of the segment (issue 52): the film thickness's tolerance (see "
        "film_thickness), 1.3e-9 of the largest 1.12 measured on forced kernels"),
    "/scuffing_micropitting/specific_film_thickness_min": Tolerance(
        1e-7, 0.0, "[1] the least specific_film_thickness of a torque (see that entry)"),
    "placement_error": Tolerance(
        0.0, 1e-9,
        "[mm] a convergence diagnostic, not a result: the residual of the conjugate point's "
        "last Newton step (accepted below 1e-7 mm, contact.utca.easeoff), round-off of that "
        "step's arithmetic (1e-13 mm measured); 1e-9 mm is 1 % of the acceptance tolerance, "
        "and a different iteration count would move the ease-off by far more than the "
        "default rtol, so it shows there"),
    "meshing_residual": Tolerance(
        0.0, 1e-12,
        "[1] the equation-of-meshing residual at a solved point (~1e-12): round-off of the "
        "last Newton step, 1e-15 measured; the identity is asserted at 1e-10 by the "
        "geometry tests, so 1e-12 is 1 % of that bound"),
    "max_placement_error_mm": Tolerance(
        0.0, 1e-9, "the largest placement_error of the file (see placement_error)"),
    "max_abs_meshing_residual": Tolerance(
        0.0, 1e-12, "the largest |meshing_residual| of a flank (see meshing_residual)"),
}


def tolerance(where: str, rtol: float) -> Tolerance:
    """The tolerance of a float variable at ``where`` (``/group/name``) or of an attribute
    (its name): :data:`ACROSS_MACHINES`' entry for its path or name, the contact residuals'
    :data:`RESIDUAL_ATOL`, else ``rtol`` of its scale. With ``rtol = 0`` (bit for bit on the
    machine that wrote the file) only the residuals' round-off is allowed."""
    name = where.rpartition("/")[2]
    if name.startswith("residual_"):
        return Tolerance(rtol, RESIDUAL_ATOL, "the contact residuals are round-off")
    if rtol == 0.0:
        return Tolerance(0.0, 0.0, "bit for bit")
    return ACROSS_MACHINES.get(where, ACROSS_MACHINES.get(name, Tolerance(rtol, 0.0, "")))


#: reviewed changes of results since the golden file was written: variable → (largest
#: difference relative to the variable's largest magnitude, why). The bit-for-bit check
#: allows these and no more.
REVIEWED: dict[str, tuple[float, str]] = {}



def _skipped_attr(name: str) -> bool:
    return name in _SKIP_ATTRS or name.startswith("time_")


# --- the summary -------------------------------------------------------------------------


def _sha256(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _plain(value: Any) -> Any:
    """A netCDF attribute value as JSON: numpy scalars and arrays as Python numbers/lists."""
    if isinstance(value, np.ndarray):
        return [_plain(v) for v in value.tolist()] if value.ndim else _plain(value.item())
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


def attribute_entry(value: Any) -> Any:
    """The golden file's entry of an attribute: its value (numbers, short text, lists), or
    ``{"chars": n, "sha256": …}`` of a text longer than :data:`LONG_TEXT` characters."""
    value = _plain(value)
    if isinstance(value, str) and len(value) > LONG_TEXT:
        return {"chars": len(value), "sha256": _sha256(value.encode("utf-8"))}
    return value


def _canonical_bytes(x: np.ndarray) -> bytes:
    """Bytes that identify a non-float array's values on any machine."""
    if x.dtype.kind in "iub":
        return np.ascontiguousarray(x.astype(x.dtype.newbyteorder("<"))).tobytes()
    if x.dtype.kind in "mM":
        return np.ascontiguousarray(x.view(np.int64).astype("<i8")).tobytes()
    return json.dumps([str(v) for v in x.ravel().tolist()], ensure_ascii=False).encode("utf-8")


def _values(x: np.ndarray) -> list:
    if x.dtype.kind in "iubf":
        return x.ravel().tolist()
    return [str(v) for v in x.ravel().tolist()]


def float_summary(x: np.ndarray) -> dict[str, Any]:
    """The statistics of a float array that stand for it in the golden file.

    Parameters
    ----------
    x : numpy.ndarray
        Float array of any shape (NaN and ±inf allowed).

    Returns
    -------
    dict
        ``nonfinite`` (count of NaN and ±inf), ``nonfinite_sha256`` (of a code per element:
        0 finite, 1 NaN, 2 +inf, 3 −inf, as bytes in C order), and over the finite elements
        ``min``, ``max`` (None if there are none), ``sum``, ``sum_abs``, ``l2`` (the
        Euclidean norm) and ``bits``: per dimension of length > 1 the list of
        Σ x[i] over the indices i whose bit b is set, b = 0 … bit length of the largest
        index − 1. Sums are exactly rounded (:func:`math.fsum`). Units: those of ``x``.
    """
    x = np.asarray(x, dtype=np.float64)
    finite = np.isfinite(x)
    codes = np.where(finite, 0, np.where(np.isnan(x), 1, np.where(x > 0, 2, 3)))
    y = np.where(finite, x, 0.0)
    out: dict[str, Any] = {
        "nonfinite": int(x.size - finite.sum()),
        "nonfinite_sha256": _sha256(np.ascontiguousarray(codes, dtype=np.int8).tobytes()),
        "min": float(x[finite].min()) if finite.any() else None,
        "max": float(x[finite].max()) if finite.any() else None,
        "sum": math.fsum(y.ravel().tolist()),
        "sum_abs": math.fsum(np.abs(y).ravel().tolist()),
        "l2": math.sqrt(math.fsum((y * y).ravel().tolist())),
    }
    bits = []
    for axis, n in enumerate(x.shape):
        index = np.arange(n)
        bits.append([math.fsum(np.compress((index >> b) & 1 == 1, y, axis=axis).ravel().tolist())
                     for b in range((n - 1).bit_length())])
    out["bits"] = bits
    return out


def variable_entry(var: xr.Variable) -> dict[str, Any]:
    """The golden file's entry of a variable (module docstring, "What a line holds")."""
    x = np.asarray(var.values)
    entry: dict[str, Any] = {"dims": list(var.dims), "shape": list(x.shape),
                             "dtype": x.dtype.str.lstrip("<>|=")}
    if x.size <= SMALL:
        entry["values"] = _values(x)
    elif x.dtype.kind == "f":
        entry.update(float_summary(x))
    else:
        entry["sha256"] = _sha256(_canonical_bytes(x))
    return entry


def summarise(tree: xr.DataTree) -> dict[str, Any]:
    """The golden file's entries of an analysis tree: ``{path: entry}`` (module docstring),
    timings and time stamps left out."""
    out: dict[str, Any] = {}
    for node in tree.subtree:
        ds = node.to_dataset(inherit=False)
        group = node.path
        prefix = "" if group == "/" else group
        out[group] = {"dims": {str(k): int(v) for k, v in ds.sizes.items()}}
        for k, v in ds.attrs.items():
            if not _skipped_attr(k):
                out[f"{group}@{k}"] = attribute_entry(v)
        for name, var in ds.variables.items():
            if name in _SKIP_VARS:
                continue
            out[f"{prefix}/{name}"] = variable_entry(var)
            for k, v in var.attrs.items():
                if not _skipped_attr(k):
                    out[f"{prefix}/{name}@{k}"] = attribute_entry(v)
    return out


def dumps(summary: Mapping[str, Any]) -> str:
    """The golden file's text: a JSON object, one entry per line, sorted by path."""
    lines = [f"{json.dumps(k, ensure_ascii=False)}: "
             f"{json.dumps(summary[k], ensure_ascii=False, sort_keys=True)}"
             for k in sorted(summary)]
    return "{\n" + ",\n".join(lines) + "\n}\n"


def _header() -> dict[str, Any]:
    return {"#about": "the default `ltca run` summarised by tests/golden.py (its docstring "
                      "says what an entry holds); regenerate with `python tests/golden.py "
                      "--write`", "#format": FORMAT}


def load(path: Path = GOLDEN) -> dict[str, Any]:
    """The entries of a golden file (its ``#`` header removed)."""
    data = json.loads(Path(path).read_text(encoding="utf-8"))
    if data.get("#format") != FORMAT:
        raise ValueError(f"{path}: golden-file format {data.get('#format')!r}, "
                         f"tests/golden.py reads format {FORMAT}")
    return {k: v for k, v in data.items() if not k.startswith("#")}


def store(summary: Mapping[str, Any], path: Path = GOLDEN) -> Path:
    """Write ``summary`` as the golden file at ``path`` (a temporary file, then renamed)."""
    from geometry.core.atomic_files import atomic_path

    with atomic_path(path) as tmp:
        Path(tmp).write_text(dumps({**_header(), **summary}), encoding="utf-8")
    return path


# --- the comparison ----------------------------------------------------------------------


def _as_summary(x: xr.DataTree | Mapping[str, Any]) -> Mapping[str, Any]:
    return summarise(x) if isinstance(x, xr.DataTree) else x


def differences(new: xr.DataTree | Mapping[str, Any], golden: xr.DataTree | Mapping[str, Any],
                *, rtol: float = 0.0) -> list[str]:
    """Every difference between a run and the golden file, timings excepted.

    Parameters
    ----------
    new, golden : xarray.DataTree or dict
        An analysis tree or its :func:`summarise` (the golden file's :func:`load`).
    rtol : float
        Tolerance of a float variable relative to the variable's largest magnitude, and of
        a float attribute relative to its value (0: bit-identical, NaN where NaN, the
        contact residuals to :data:`RESIDUAL_ATOL`); with ``rtol > 0`` the variables and
        attributes of :data:`ACROSS_MACHINES` to their own tolerance; the :data:`REVIEWED`
        changes to their bound. How a summarised variable is compared: module docstring.
        Integers and text must always be identical.

    Returns
    -------
    list of str
        One line per difference, starting with the path (empty when they agree).
    """
    a, b = _as_summary(new), _as_summary(golden)
    paths_a = {k for k in a if "@" not in k}
    paths_b = {k for k in b if "@" not in k}
    groups_a = {k for k in paths_a if k in a and "dims" in a[k] and "shape" not in a[k]}
    groups_b = {k for k in paths_b if k in b and "dims" in b[k] and "shape" not in b[k]}
    out: list[str] = []
    if groups_a != groups_b:
        out.append(f"groups differ: {_new_and_gone(groups_a, groups_b)}")
    for group in sorted(groups_a & groups_b):
        prefix = "" if group == "/" else group
        mine = {k.rpartition("/")[2] for k in paths_a - groups_a if k.rpartition("/")[0] == prefix}
        theirs = {k.rpartition("/")[2] for k in paths_b - groups_b
                  if k.rpartition("/")[0] == prefix}
        if mine != theirs:
            out.append(f"{group}: variables differ: {_new_and_gone(mine, theirs)}")
    for owner in sorted({k.partition("@")[0] for k in a.keys() | b.keys() if "@" in k}):
        if owner not in a or owner not in b:
            continue  # reported as a group or variable
        keys_a = {k for k in a if k.partition("@")[0] == owner and "@" in k}
        keys_b = {k for k in b if k.partition("@")[0] == owner and "@" in k}
        if keys_a != keys_b:
            names = _new_and_gone({k.partition("@")[2] for k in keys_a},
                                  {k.partition("@")[2] for k in keys_b})
            out.append(f"{owner}: attributes differ: {names}")
        for key in sorted(keys_a & keys_b):
            name = key.partition("@")[2]
            if not _same_attribute(a[key], b[key], tolerance(name, rtol)):
                out.append(f"{owner}: attribute {name}: {_short(a[key])} != {_short(b[key])}")
    for path in sorted((paths_a & paths_b) - groups_a - groups_b):
        out += _variable_differences(path, a[path], b[path], rtol)
    for group in sorted(groups_a & groups_b):
        if a[group] != b[group]:
            out.append(f"{group}: dimensions {a[group]['dims']} != {b[group]['dims']}")
    return out


def _new_and_gone(mine: set[str], theirs: set[str]) -> str:
    parts = [f"{what} {sorted(names)}" for what, names in
             (("new", mine - theirs), ("not in the new run", theirs - mine)) if names]
    return "; ".join(parts)


def _short(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 200 else text[:200] + "…"


def _same_attribute(x: Any, y: Any, tol: Tolerance) -> bool:
    """An attribute entry equal, floats (and lists of floats) within ``tol`` of their value."""
    fx, fy = np.asarray(x, dtype=object), np.asarray(y, dtype=object)
    if fx.shape == fy.shape and fx.size and all(isinstance(v, float) for v in fx.ravel()) \
            and all(isinstance(v, float) for v in fy.ravel()):
        u, v = fx.astype(float), fy.astype(float)
        bound = np.maximum(tol.rtol * np.maximum(np.abs(u), np.abs(v)), tol.atol)
        return bool(np.all((np.abs(u - v) <= bound) | (np.isnan(u) & np.isnan(v))))
    return x == y or (isinstance(x, float) and isinstance(y, float)
                      and math.isnan(x) and math.isnan(y))


def _variable_differences(where: str, a: dict, b: dict, rtol: float) -> list[str]:
    if (a["dims"], a["shape"]) != (b["dims"], b["shape"]):
        return [f"{where}: dims {a['dims']}{a['shape']} != {b['dims']}{b['shape']}"]
    if a["dtype"] != b["dtype"]:
        return [f"{where}: dtype {a['dtype']} != {b['dtype']}"]
    if a.keys() != b.keys():
        return [f"{where}: stored as {sorted(a)} != {sorted(b)}"]
    tol = tolerance(where, rtol)
    rt = max(tol.rtol, REVIEWED.get(where, (0.0, ""))[0])
    if "values" in a:
        x, y = np.asarray(a["values"]), np.asarray(b["values"])
        if x.dtype.kind == "f" and y.dtype.kind == "f":
            same_nan = np.array_equal(np.isnan(x), np.isnan(y))
            with np.errstate(invalid="ignore"):  # inf - inf where both are inf
                d = np.nan_to_num(np.abs(x - y), nan=0.0, posinf=np.inf)
            scale = float(np.nanmax(np.abs(y), initial=0.0)) if np.any(~np.isnan(y)) else 0.0
            worst = float(d.max(initial=0.0))
            if not same_nan or worst > max(rt * scale, tol.atol):
                return [f"{where}: differs by {worst:.3g} (largest |value| {scale:.3g}; "
                        f"NaN pattern same: {same_nan})"]
            return []
        return [] if np.array_equal(x, y) else [f"{where}: values differ"]
    if "sha256" in a:
        return [] if a["sha256"] == b["sha256"] else [f"{where}: values differ"]
    if (a["nonfinite"], a["nonfinite_sha256"]) != (b["nonfinite"], b["nonfinite_sha256"]):
        return [f"{where}: NaN/inf pattern differs ({a['nonfinite']} non-finite, "
                f"golden {b['nonfinite']})"]
    if b["max"] is None:
        return []
    scale = max(abs(b["min"]), abs(b["max"]))
    finite = math.prod(b["shape"]) - b["nonfinite"]
    tau, bound = statistic_bounds(scale, b["sum_abs"], finite, rt, tol.atol)
    out = []
    for stat, limit in (("min", tau), ("max", tau), ("sum", bound), ("sum_abs", bound),
                        ("l2", bound)):
        moved = abs(a[stat] - b[stat])
        if not moved <= limit:
            out.append(f"{where}: {stat} differs by {moved:.3g} (bound {limit:.3g}; largest "
                       f"|value| {scale:.3g})")
    for axis, (mine, theirs) in enumerate(zip(a["bits"], b["bits"], strict=True)):
        moved = max((abs(u - v) for u, v in zip(mine, theirs, strict=True)), default=0.0)
        if not moved <= bound:
            out.append(f"{where}: sums over the index bits of {a['dims'][axis]} differ by "
                       f"{moved:.3g} (bound {bound:.3g}; largest |value| {scale:.3g})")
    return out


def statistic_bounds(scale: float, sum_abs: float, finite: int, rtol: float,
                     atol: float) -> tuple[float, float]:
    """The bounds of a summarised float variable's statistics (module docstring).

    Parameters
    ----------
    scale : float
        Largest magnitude of the golden variable, ``S = max(|min|, |max|)`` [its units].
    sum_abs : float
        Σ|x| over its finite elements [its units].
    finite : int
        Number of its finite elements.
    rtol, atol : float
        Its tolerance (:func:`tolerance`) [1], [its units].

    Returns
    -------
    tau, bound : float
        ``τ = max(rtol·S, atol)`` for ``min`` and ``max``; ``τ + ρ·Σ|x| + N·atol`` with
        ``ρ = rtol·AGGREGATE_SHARE`` for the sums and the L2 norm.
    """
    tau = max(rtol * scale, atol)
    return tau, tau + rtol * AGGREGATE_SHARE * sum_abs + finite * atol


# --- making and refreshing the file --------------------------------------------------------


def run_default(directory: Path) -> Path:
    """Run ``ltca run`` exactly as a user types it (no arguments) into ``directory``."""
    from contact.cli import main

    out = Path(directory) / "ltca.nc"
    code = main(["run", "--no-progress", "-o", str(out)])
    if code != 0:
        raise RuntimeError(f"ltca run exited with {code}")
    return out


def shared_default_run(directory: Path) -> Path:
    """The default run's file in ``directory``, run by the first process that asks for it.

    Processes that share ``directory`` (pytest-xdist's workers of one session) wait for
    the first one's run under a lock file (``fcntl``; where there is none, each process
    runs its own) and read its file: the suite runs ``ltca run`` once.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    target = directory / "default_run.nc"
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows: no lock, a run of its own
        fcntl = None
    with open(directory / "default_run.lock", "w") as lock:
        if fcntl is not None:
            fcntl.flock(lock, fcntl.LOCK_EX)
        if not target.exists():
            run = directory / f"run-{os.getpid()}"
            run.mkdir(exist_ok=True)
            run_default(run).replace(target)
    return target


def adopt_attributes(new: xr.DataTree | Mapping[str, Any], path: Path = GOLDEN) -> list[str]:
    """Give the golden file the attributes of ``new`` (groups and variables), its values
    untouched, if ``new`` differs from it in attributes only; else leave it and return
    the differences of values."""
    golden = load(path)
    mine = _as_summary(new)
    values = differences({k: v for k, v in mine.items() if "@" not in k},
                         {k: v for k, v in golden.items() if "@" not in k})
    if values:
        return values
    store({**{k: v for k, v in golden.items() if "@" not in k},
           **{k: v for k, v in mine.items() if "@" in k}}, path)
    return []


def write_golden(path: Path = GOLDEN, run: Path | None = None) -> Path:
    """Run ``ltca run`` (or read ``run``, a file it wrote) and store its summary at ``path``."""
    return store(summarise(_read_run(run)), path)


def _read_run(run: Path | None) -> xr.DataTree:
    import tempfile

    from geometry.core.io import read_netcdf

    if run is not None:
        return read_netcdf(run, tree=True)
    with tempfile.TemporaryDirectory() as tmp:
        return read_netcdf(run_default(Path(tmp)), tree=True).load()


def main(argv: list[str] | None = None) -> int:
    """The command line (module docstring, "Usage"); the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    action = parser.add_mutually_exclusive_group(required=True)
    action.add_argument("--write", action="store_true", help="(re)write the golden file")
    action.add_argument("--check", action="store_true",
                        help="run and compare bit for bit (the residuals to RESIDUAL_ATOL)")
    action.add_argument("--adopt-attributes", action="store_true",
                        help="take a new run's attributes into the golden file if its values "
                             "are identical")
    parser.add_argument("--from", dest="run", type=Path, default=None, metavar="FILE",
                        help="a file `ltca run` (no other arguments) wrote, instead of running")
    args = parser.parse_args(argv)
    if args.run is not None and not args.run.is_file():
        parser.error(f"--from {args.run}: no such file (give a file `ltca run` wrote)")
    if not args.write and not GOLDEN.is_file():
        parser.error(f"{GOLDEN} does not exist: write it first with --write")
    from threadpoolctl import threadpool_limits

    # as the test suite runs (tests/conftest.py): one BLAS thread
    with threadpool_limits(limits=1, user_api="blas"):
        new = _read_run(args.run)
    if args.write:
        print(f"wrote {store(summarise(new))}")
        return 0
    if args.adopt_attributes:
        found = adopt_attributes(new)
        print("\n".join(found) if found else f"adopted the attributes into {GOLDEN}")
        return 1 if found else 0
    found = differences(new, load(), rtol=0.0)
    reviewed = "; ".join(f"{k}: {why}" for k, (_, why) in REVIEWED.items())
    print("\n".join(found) if found else "identical to the golden file"
          + (f" (but the reviewed changes: {reviewed})" if reviewed else ""))
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main())
