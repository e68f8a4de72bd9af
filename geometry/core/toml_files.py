"""TOML input files: read with a refusal that names the file, written as TOML 1.0 text.

Reading is :mod:`tomllib`'s; a missing, unreadable, binary or invalid file is refused in one
line naming it (:func:`read_toml`). Writing covers what the toolkit writes (case files,
:meth:`geometry.case.Case.to_toml`): scalars, lists, tables and arrays of tables
(:func:`dump_toml`).
"""

from __future__ import annotations

import json
import math
import os
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from geometry.core.errors import InputError

__all__ = ["dump_toml", "read_toml", "toml_key", "toml_value"]


def read_toml(path: str | os.PathLike[str], what: str) -> dict[str, Any]:
    """Parse a TOML input file, refusing a bad one in one line that names it.

    Parameters
    ----------
    path : path-like
    what : str
        What the file is, for the messages (``"case file"``, ``"basic file"``).

    Returns
    -------
    dict
        The parsed document (TOML 1.0, :mod:`tomllib`).

    Raises
    ------
    InputError
        The file is missing, unreadable, not UTF-8 text or not valid TOML.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{what}: no such file {str(p)!r}")
    try:
        return tomllib.loads(p.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{what} {str(p)!r}: invalid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{what} {str(p)!r}: not UTF-8 text (byte {exc.start}); a TOML "
                         "file is expected") from None
    except OSError as exc:
        raise InputError(f"{what} {str(p)!r}: cannot be read ({exc.strerror or exc})") from None



def toml_value(v: Any) -> str:
    """One value as TOML 1.0 text: booleans, integers, floats (±inf allowed, NaN refused),
    strings (JSON-escaped, a TOML basic string) and lists of these.

    Raises
    ------
    InputError
        A NaN or a value of another type (``to_toml: …``).
    """
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            raise InputError(f"to_toml: non-finite value {v!r}")
        if math.isinf(v):  # TOML 1.0 floats include inf (an [optimize] limit: no limit)
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    raise InputError(f"to_toml: cannot write a value of type {type(v).__name__}")


def toml_key(k: str) -> str:
    """A bare key where TOML allows one, else a quoted key."""
    # every character alphanumeric or one of "-_" (str.isalnum of the rest: one call)
    rest = k.replace("-", "").replace("_", "")
    if k and (not rest or rest.isalnum()):
        return k
    return json.dumps(k)


def dump_toml(doc: Mapping[str, Any], prefix: str = "") -> str:
    """A document (nested mappings, lists of mappings as arrays of tables) as TOML text.

    Values first, then tables in the mapping's order; the inverse of :mod:`tomllib` for the
    documents the toolkit writes (case files: :meth:`geometry.case.Case.to_toml`).

    Raises
    ------
    InputError
        A value TOML cannot hold (:func:`toml_value`), its key and table named ("to_toml:
        non-finite value nan at [rating] coast_design_torque").
    """
    lines: list[str] = []
    tables = []
    for k, v in doc.items():
        if isinstance(v, Mapping):
            tables.append((k, v))
        elif isinstance(v, list) and v and all(isinstance(x, Mapping) for x in v):
            tables.append((k, v))
        else:
            try:
                text = toml_value(v)
            except InputError as exc:
                # the value's key named (its table too): a case's NaN was refused as
                # "to_toml: non-finite value nan" alone, which the FM 14x19 at Sigma 60's
                # `ltca synthesize` then reported as its unloaded contact's failure
                # (branch unseen98)
                where = f"[{prefix}] {toml_key(k)}" if prefix else toml_key(k)
                raise InputError(f"{exc} at {where}") from None
            lines.append(f"{toml_key(k)} = {text}")
    for k, v in tables:
        name = f"{prefix}.{toml_key(k)}" if prefix else toml_key(k)
        if isinstance(v, list):
            for item in v:
                lines.append(f"\n[[{name}]]")
                lines.append(dump_toml(item, name).rstrip("\n"))
        else:
            lines.append(f"\n[{name}]")
            body = dump_toml(v, name).rstrip("\n")
            if body:
                lines.append(body)
    return "\n".join(line for line in lines) + "\n"
