"""REXS in and out for users: :func:`export_rexs`, :func:`import_rexs` (docs/exchange.md).

Every file written passes the file schema and the attribute-database check first (a file
that would not is never written: :class:`~contact.exchange.rexs.validate.RexsValidationError`
instead); every file read passes them before it is mapped.
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from contact.exchange.rexs.files import file_format, model_to_text
from contact.exchange.rexs.mapping import (
    case_to_model,
    has_manufacturing,
    model_to_basic_dict,
    model_to_case_dict,
)
from contact.exchange.rexs.model import Model
from contact.exchange.rexs.validate import check_text
from geometry.case import Case, case_from_dict
from geometry.core.atomic_files import atomic_path
from geometry.core.errors import InputError
from geometry.core.toml_files import dump_toml

__all__ = ["ImportedStage", "export_rexs", "import_rexs", "read_rexs", "write_rexs"]


def write_rexs(model: Model, path: str | os.PathLike[str]) -> Path:
    """Write a model as ``.rexs`` (XML) or ``.rexsj`` (JSON), by the path's suffix, after
    checking the text against the file schema and the attribute database.

    Parameters
    ----------
    model : Model
    path : path-like
        ``*.rexs`` or ``*.rexsj``; its directory must exist.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        Another suffix.
    RexsValidationError
        The text fails a check (nothing is written).
    """
    fmt = file_format(path)
    text = model_to_text(model, fmt)
    check_text(text, fmt, what=f"REXS file {os.fspath(path)!r} (not written)")
    path = Path(path)
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path


def read_rexs(path: str | os.PathLike[str]) -> Model:
    """A ``.rexs`` / ``.rexsj`` file as a Model, checked against the file schema and the
    attribute database of its version.

    Raises
    ------
    InputError
        Unreadable, wrong suffix.
    RexsValidationError
        A check fails (the message names the component, id and attribute).
    """
    fmt = file_format(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"REXS file {os.fspath(path)!r}: cannot be read ({exc})") from None
    return check_text(text, fmt, what=f"REXS file {os.fspath(path)!r}")


def export_rexs(case: Case | str | os.PathLike[str] | None, path: str | os.PathLike[str], *,
                version: str = "2.0.0",
                analysis: str | os.PathLike[str] | None = None) -> Model:
    """Write a case's bevel stage (and an analysis' results) as a REXS file.

    Parameters
    ----------
    case : geometry.Case, str, os.PathLike or None
        A case, a case file's path or a bundled case's name (None: the default case;
        :func:`contact.resolve_case`).
    path : path-like
        ``*.rexs`` (XML) or ``*.rexsj`` (JSON).
    version : {"1.7", "2.0.0"}
        REXS version.
    analysis : path-like, optional
        A netCDF file ``ltca run`` wrote for this case: its results go into the slots REXS
        has (:mod:`contact.exchange.rexs.results`).

    Returns
    -------
    Model
        What was written.

    Raises
    ------
    InputError
        Unknown case (the resolver's message), unsupported version, wrong suffix, an
        analysis file of another case.
    RexsValidationError
        The model fails a check (a bug: reported, nothing written).

    Source: FVA REXS attribute databases 1.7 and 2.0.0 (data/README.md); mapping in
    docs/exchange.md.
    """
    from contact.catalogue import resolve_case

    case = resolve_case(case)
    file_format(path)  # the suffix refused before any work
    doc = tomllib.loads(case.to_toml())
    model = case_to_model(doc, version)
    if analysis is not None:
        from contact.exchange.rexs.results import add_results

        add_results(model, case, analysis)
    write_rexs(model, path)
    return model


@dataclass(frozen=True)
class ImportedStage:
    """What :func:`import_rexs` made of a REXS file.

    ``case`` (a validated Case) where the stage has manufacturing settings, else ``basic``
    (a basic design file mapping for ``ltca synthesize``, validated by
    :func:`geometry.synthesis.basic_design.basic_from_dict`); ``model`` the file's model.
    """

    model: Model
    case: Case | None = None
    basic: dict[str, Any] | None = None

    @property
    def kind(self) -> str:
        """``"case"`` or ``"basic"``."""
        return "case" if self.case is not None else "basic"

    def to_toml(self) -> str:
        """The case file or basic design file as TOML text."""
        return self.case.to_toml() if self.case is not None else dump_toml(self.basic)


def import_rexs(path: str | os.PathLike[str]) -> ImportedStage:
    """Read a REXS bevel stage: a case where it has manufacturing settings, else a basic
    design file.

    Parameters
    ----------
    path : path-like
        ``*.rexs`` or ``*.rexsj``, REXS 1.7 or 2.0.0, with exactly one ``bevel_stage``.

    Returns
    -------
    ImportedStage
        ``.case`` (a Case) or ``.basic`` (a basic design mapping), ``.to_toml()`` its file.

    Raises
    ------
    InputError
        Invalid file (schema, database), a missing or inconsistent item — one sentence
        naming the REXS component type, id and attribute (a case field refused by the case
        validation is named by the REXS attribute it came from).
    """
    model = read_rexs(path)
    if not has_manufacturing(model):
        from geometry.synthesis.basic_design import basic_from_dict

        basic = model_to_basic_dict(model)
        try:
            basic_from_dict(basic, fit=False)
        except InputError as exc:
            raise InputError(f"REXS file {os.fspath(path)!r}: its blank data make no valid "
                             f"basic design: {exc}") from None
        return ImportedStage(model, basic=basic)
    doc, origin = model_to_case_dict(model)
    try:
        case = case_from_dict(doc)
    except InputError as exc:
        text = str(exc)
        field = max((k for k in origin if text.startswith(k)), key=len, default=None)
        where = f"REXS {origin[field]}" if field else f"REXS file {os.fspath(path)!r}"
        raise InputError(f"{where}: {text}") from None
    return ImportedStage(model, case=case)
