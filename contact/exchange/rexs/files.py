"""REXS files as text: XML (``.rexs``) and JSON (``.rexsj``), both ways.

The layouts are those of the published file schemas (``data/rexs-file.xsd``,
``data/rexs-file.json``): ``model`` with ``relations``, ``components`` and an optional
``load_spectrum``. Floating-point values are written with Python's shortest round-trip
representation (``repr``), so a value read back is the value written, to the last bit.

Public
------
model_to_xml, model_to_json        a Model as text
model_from_xml, model_from_json    text as a Model (syntax errors refused by InputError)
model_to_text, model_from_text     the same, the format chosen by ``"xml"`` / ``"json"``
file_format                        ``"xml"`` or ``"json"`` from a file name's suffix
"""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

from contact.exchange.rexs.database import load_database
from contact.exchange.rexs.model import (
    ARRAY_TYPES,
    MATRIX_TYPES,
    Attribute,
    Component,
    LoadCase,
    LoadSpectrum,
    Model,
    Ref,
    Relation,
)
from geometry.core.errors import InputError

__all__ = ["file_format", "model_from_json", "model_from_text", "model_from_xml",
           "model_to_json", "model_to_text", "model_to_xml"]

#: file suffix → format
SUFFIXES = {".rexs": "xml", ".rexsj": "json"}


def file_format(path: str | Path) -> str:
    """``"xml"`` for ``*.rexs``, ``"json"`` for ``*.rexsj``.

    Raises
    ------
    InputError
        Another suffix (the message names the accepted ones).
    """
    suffix = Path(path).suffix.lower()
    if suffix not in SUFFIXES:
        raise InputError(f"REXS file {str(path)!r}: the name must end in .rexs (XML) or "
                         f".rexsj (JSON), got {suffix or 'no suffix'!r}")
    return SUFFIXES[suffix]


# ------------------------------------------------------------------------------ values
def _text(value: Any, value_type: str) -> str:
    if value_type == "boolean":
        return "true" if value else "false"
    if value_type == "floating_point":
        return repr(float(value))
    return str(value)


def _check_finite(value: Any, where: str) -> None:
    values = value if isinstance(value, (list, tuple)) else [value]
    if values and isinstance(values[0], (list, tuple)):  # a matrix
        values = [v for row in values for v in row]
    for v in values:
        if isinstance(v, float) and not math.isfinite(v):
            raise InputError(f"{where}: must be finite, got {v!r}")


# ------------------------------------------------------------------------------- XML
def _xml_attribute(parent: ET.Element, a: Attribute, where: str) -> None:
    _check_finite(a.value, f"{where} attribute {a.id}")
    el = ET.SubElement(parent, "attribute", {"id": a.id, "unit": a.unit})
    if a.value_type in MATRIX_TYPES:
        mat = ET.SubElement(el, "matrix")
        for row in a.value:
            r = ET.SubElement(mat, "r")
            for v in row:
                ET.SubElement(r, "c").text = _text(v, "floating_point")
    elif a.value_type in ARRAY_TYPES:
        arr = ET.SubElement(el, "array")
        scalar = a.value_type.removesuffix("_array")
        for v in a.value:
            ET.SubElement(arr, "c").text = _text(v, scalar)
    else:
        el.text = _text(a.value, a.value_type)


def model_to_xml(model: Model) -> str:
    """The model as a ``.rexs`` XML document (UTF-8 text with its declaration)."""
    root = ET.Element("model", {
        "applicationId": model.application_id, "applicationVersion": model.application_version,
        "applicationLanguage": model.application_language, "date": model.date,
        "version": model.version})
    rels = ET.SubElement(root, "relations")
    for r in model.relations:
        attrs = {"id": str(r.id), "type": r.type}
        if r.order is not None:
            attrs["order"] = str(r.order)
        rel = ET.SubElement(rels, "relation", attrs)
        for ref in r.refs:
            ET.SubElement(rel, "ref", {"hint": ref.hint, "id": str(ref.id), "role": ref.role}
                          if ref.hint else {"id": str(ref.id), "role": ref.role})
    comps = ET.SubElement(root, "components")
    for c in model.components:
        el = ET.SubElement(comps, "component", {"id": str(c.id), "name": c.name,
                                                "type": c.type})
        for a in c.attributes:
            _xml_attribute(el, a, c.where())
    if model.load_spectrum is not None:
        ls = ET.SubElement(root, "load_spectrum", {"id": str(model.load_spectrum.id)})
        for lc in model.load_spectrum.load_cases:
            lel = ET.SubElement(ls, "load_case", {"id": str(lc.id)})
            for c in lc.components:
                el = ET.SubElement(lel, "component", {"id": str(c.id), "type": c.type})
                for a in c.attributes:
                    _xml_attribute(el, a, f"load case {lc.id} {c.where()}")
    ET.indent(root, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, "unicode") + "\n"


def _int(text: str | None, where: str) -> int:
    try:
        return int(text)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InputError(f"{where}: must be an integer, got {text!r}") from None


def _xml_value(el: ET.Element, value_type: str | None, where: str) -> tuple[Any, str]:
    """(value, value type) of an ``attribute`` element; ``value_type`` None (a custom
    attribute) keeps text as a string and an array as numbers."""
    arr = el.find("array")
    if arr is not None:
        items = [c.text or "" for c in arr.findall("c")]
        vt = value_type or "floating_point_array"
        scalar = vt.removesuffix("_array")
        return [_scalar(t, scalar, where) for t in items], vt
    mat = el.find("matrix")
    if mat is not None:
        vt = value_type or "floating_point_matrix"
        if vt not in MATRIX_TYPES:
            raise InputError(f"{where}: a matrix where the database has {vt}")
        return [[_scalar(c.text or "", "floating_point", where) for c in r.findall("c")]
                for r in mat.findall("r")], vt
    if el.find("array_of_arrays") is not None:
        raise InputError(f"{where}: arrays of arrays are not read by this importer")
    text = (el.text or "").strip()
    vt = value_type or "string"
    return _scalar(text, vt, where), vt


def _scalar(text: str, value_type: str, where: str) -> Any:
    try:
        if value_type == "floating_point":
            value = float(text)
            if not math.isfinite(value):
                raise ValueError
            return value
        if value_type in ("integer", "reference_component"):
            return int(text)
        if value_type == "boolean":
            if text not in ("true", "false"):
                raise ValueError
            return text == "true"
    except ValueError:
        raise InputError(f"{where}: {text!r} is not a valid {value_type}") from None
    return text


def _types(version: str) -> dict[str, str]:
    """attribute id → value type, for a version this package bundles (else empty: values
    are then read as text and refused by the validation)."""
    try:
        return {k: a.value_type for k, a in load_database(version).attributes.items()}
    except InputError:
        return {}


def _xml_component(el: ET.Element, types: dict[str, str], where: str,
                   type_: str | None = None) -> Component:
    cid = _int(el.get("id"), f"{where} component id")
    comp = Component(cid, type_ if type_ is not None else el.get("type", ""),
                     el.get("name", ""))
    for a in el.findall("attribute"):
        aid = a.get("id", "")
        value, vt = _xml_value(a, types.get(aid), f"{comp.where()} attribute {aid}")
        comp.attributes.append(Attribute(aid, value, a.get("unit", ""), vt))
    return comp


def model_from_xml(text: str) -> Model:
    """A ``.rexs`` XML document as a Model.

    Raises
    ------
    InputError
        Not well-formed XML, a root other than ``model``, a non-integer id, or a value
        that is not of its attribute's type.
    """
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise InputError(f"REXS XML: not well-formed ({exc})") from None
    if root.tag != "model":
        raise InputError(f"REXS XML: the root element must be <model>, got <{root.tag}>")
    version = root.get("version", "")
    types = _types(version)
    model = Model(version=version, application_id=root.get("applicationId", ""),
                  application_version=root.get("applicationVersion", ""),
                  date=root.get("date", ""),
                  application_language=root.get("applicationLanguage", "en"))
    for r in root.iterfind("relations/relation"):
        order = r.get("order")
        model.relations.append(Relation(
            _int(r.get("id"), "relation id"), r.get("type", ""),
            [Ref(_int(x.get("id"), "ref id"), x.get("role", ""), x.get("hint", ""))
             for x in r.findall("ref")],
            None if order is None else _int(order, "relation order")))
    for c in root.iterfind("components/component"):
        model.components.append(_xml_component(c, types, "REXS XML"))
    ls = root.find("load_spectrum")
    if ls is not None:
        known = {c.id: c.type for c in model.components}
        spec = LoadSpectrum(_int(ls.get("id"), "load_spectrum id"))
        for lc in ls.findall("load_case"):
            case = LoadCase(_int(lc.get("id"), "load_case id"))
            for c in lc.findall("component"):
                cid = _int(c.get("id"), "load case component id")
                case.components.append(_xml_component(c, types, "REXS XML load case",
                                                      known.get(cid, "")))
            spec.load_cases.append(case)
        model.load_spectrum = spec
    return model


# ------------------------------------------------------------------------------ JSON
def _json_attributes(comp: Component, where: str) -> list[dict[str, Any]]:
    out = []
    for a in comp.attributes:
        _check_finite(a.value, f"{where} attribute {a.id}")
        value = ([list(r) for r in a.value] if a.value_type in MATRIX_TYPES
                 else list(a.value) if a.value_type in ARRAY_TYPES else a.value)
        out.append({"id": a.id, "unit": a.unit, a.value_type: value})
    return out


def model_to_json(model: Model) -> str:
    """The model as a ``.rexsj`` JSON document."""
    doc: dict[str, Any] = {
        "version": model.version, "applicationId": model.application_id,
        "applicationVersion": model.application_version, "date": model.date,
        "applicationLanguage": model.application_language,
        "relations": [
            {"id": r.id, "type": r.type, **({"order": r.order} if r.order is not None else {}),
             "refs": [{"id": x.id, "role": x.role, **({"hint": x.hint} if x.hint else {})}
                      for x in r.refs]}
            for r in model.relations],
        "components": [{"id": c.id, "type": c.type, "name": c.name,
                        "attributes": _json_attributes(c, c.where())}
                       for c in model.components],
    }
    if model.load_spectrum is not None:
        doc["load_spectrum"] = {
            "id": model.load_spectrum.id,
            "load_cases": [{"id": lc.id, "components": [
                {"id": c.id, "attributes": _json_attributes(c, f"load case {lc.id}")}
                for c in lc.components]} for lc in model.load_spectrum.load_cases]}
    return json.dumps({"model": doc}, indent=2, ensure_ascii=False) + "\n"


def _json_component(raw: Any, where: str, type_: str | None = None) -> Component:
    if not isinstance(raw, dict):
        raise InputError(f"{where}: a component must be an object")
    comp = Component(_int(raw.get("id"), f"{where} component id"),
                     type_ if type_ is not None else str(raw.get("type", "")),
                     str(raw.get("name", "")))
    for a in raw.get("attributes", []) or []:
        if not isinstance(a, dict) or "id" not in a:
            raise InputError(f"{comp.where()}: an attribute must be an object with an id")
        keys = [k for k in a if k not in ("id", "unit")]
        if len(keys) != 1:
            raise InputError(f"{comp.where()} attribute {a['id']}: must hold exactly one "
                             f"typed value, got keys {keys}")
        comp.attributes.append(Attribute(str(a["id"]), a[keys[0]], str(a.get("unit", "")),
                                         keys[0]))
    return comp


def model_from_json(text: str) -> Model:
    """A ``.rexsj`` JSON document as a Model.

    Raises
    ------
    InputError
        Not valid JSON, no ``model`` object, or a malformed component or attribute.
    """
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"REXS JSON: not valid JSON ({exc})") from None
    m = doc.get("model") if isinstance(doc, dict) else None
    if not isinstance(m, dict):
        raise InputError("REXS JSON: the document must be an object with a 'model' object")
    model = Model(version=str(m.get("version", "")),
                  application_id=str(m.get("applicationId", "")),
                  application_version=str(m.get("applicationVersion", "")),
                  date=str(m.get("date", "")),
                  application_language=str(m.get("applicationLanguage", "en")))
    for r in m.get("relations", []) or []:
        model.relations.append(Relation(
            _int(r.get("id"), "relation id"), str(r.get("type", "")),
            [Ref(_int(x.get("id"), "ref id"), str(x.get("role", "")), str(x.get("hint", "")))
             for x in r.get("refs", [])], r.get("order")))
    for c in m.get("components", []) or []:
        model.components.append(_json_component(c, "REXS JSON"))
    ls = m.get("load_spectrum")
    if isinstance(ls, dict):
        known = {c.id: c.type for c in model.components}
        spec = LoadSpectrum(_int(ls.get("id"), "load_spectrum id"))
        for lc in ls.get("load_cases", []) or []:
            case = LoadCase(_int(lc.get("id"), "load_case id"))
            for c in lc.get("components", []) or []:
                cid = c.get("id") if isinstance(c, dict) else None
                case.components.append(_json_component(c, "REXS JSON load case",
                                                       known.get(cid, "")))
            spec.load_cases.append(case)
        model.load_spectrum = spec
    return model


def model_to_text(model: Model, fmt: str) -> str:
    """:func:`model_to_xml` (``fmt == "xml"``) or :func:`model_to_json` (``"json"``)."""
    return model_to_xml(model) if fmt == "xml" else model_to_json(model)


def model_from_text(text: str, fmt: str) -> Model:
    """:func:`model_from_xml` or :func:`model_from_json` by ``fmt``."""
    return model_from_xml(text) if fmt == "xml" else model_from_json(text)
