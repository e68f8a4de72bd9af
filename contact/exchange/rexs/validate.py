"""Validation of REXS files: the published file schema and the attribute database.

Two checks, both required of a valid file (docs/exchange.md):

1. **the file schema** — ``data/rexs-file.xsd`` for XML (through ``lxml``), the JSON schema
   ``data/rexs-file.json`` for JSON (through ``jsonschema``); both are the optional extra
   ``hypoid-ltca[exchange]``. Without them the syntax is checked by the standard library
   and the schema's required items (model version, application, date; component, relation
   and reference ids, types and roles) by this module, and the log says the full schema
   check was skipped.
2. **the attribute database** of the file's version (:mod:`contact.exchange.rexs.database`):
   known component types, every attribute mapped to its component's type, its unit as the
   database spells it, its value type, range and enumeration; relations of a known type
   whose (component type, role) pairs form an allowed combination, with an order where the
   database requires one; every referenced id present. ``custom_*`` attributes (REXS's
   place for what the standard lacks) are exempt from the mapping, not from the unit list.

Public
------
RexsValidationError      InputError listing the problems (the first in its message)
schema_problems          problems of a text against the file schema
database_problems        problems of a model against its version's database
check_text               both checks of a text; raises RexsValidationError
validate_file            both checks of a file; the list of problems (empty: valid)
"""

from __future__ import annotations

import json
import logging
import re
import xml.etree.ElementTree as ET
from pathlib import Path

from contact.exchange.rexs.database import VERSIONS, data_file, load_database
from contact.exchange.rexs.files import file_format, model_from_text
from contact.exchange.rexs.model import ARRAY_TYPES, Component, Model
from geometry.core.errors import InputError

__all__ = ["RexsValidationError", "check_text", "database_problems", "schema_problems",
           "validate_file"]

log = logging.getLogger(__name__)

#: the widened model.version pattern of the JSON schema (data/README.md: the published
#: pattern predates REXS 2.0.0's three-part version string)
JSON_VERSION_PATTERN = r"^\d+\.\d+(\.\d+)?$"


class RexsValidationError(InputError):
    """A REXS text failed the schema or database check; ``problems`` lists every problem,
    the message states the first (and how many more)."""

    def __init__(self, problems: list[str], what: str = "REXS file") -> None:
        self.problems = list(problems)
        more = f" (and {len(problems) - 1} more)" if len(problems) > 1 else ""
        super().__init__(f"{what}: {problems[0]}{more}")


# ------------------------------------------------------------------------- file schema
def _xsd_problems(text: str) -> list[str]:
    try:
        from lxml import etree
    except ImportError:
        log.info("lxml not installed (pip install hypoid-ltca[exchange]): REXS XML checked "
                 "for syntax and required items only, not against rexs-file.xsd")
        return _xml_required(text)
    schema = etree.XMLSchema(etree.fromstring(data_file("rexs-file.xsd")))
    try:
        doc = etree.fromstring(text.encode("utf-8"))
    except etree.XMLSyntaxError as exc:
        return [f"not well-formed XML ({exc})"]
    if schema.validate(doc):
        return []
    return [f"rexs-file.xsd, line {e.line}: {e.message}" for e in schema.error_log]


def _xml_required(text: str) -> list[str]:
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        return [f"not well-formed XML ({exc})"]
    out = []
    if root.tag != "model":
        return [f"the root element must be <model>, got <{root.tag}>"]
    for key in ("version", "applicationId", "applicationVersion", "date"):
        if root.get(key) is None:
            out.append(f"<model> lacks its required attribute {key!r}")
    for tag, keys in (("relations/relation", ("id", "type")), ("relations/relation/ref",
                      ("id", "role")), ("components/component", ("id", "type")),
                      ("components/component/attribute", ("id",))):
        for el in root.iterfind(tag):
            out += [f"<{el.tag}> lacks its required attribute {k!r}" for k in keys
                    if el.get(k) is None]
    return out


def _json_problems(text: str) -> list[str]:
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as exc:
        return [f"not valid JSON ({exc})"]
    schema = json.loads(data_file("rexs-file.json"))
    schema["properties"]["model"]["properties"]["version"]["pattern"] = JSON_VERSION_PATTERN
    try:
        import jsonschema
    except ImportError:
        log.info("jsonschema not installed (pip install hypoid-ltca[exchange]): REXS JSON "
                 "checked for the schema's required items only")
        return _json_required(doc)
    validator = jsonschema.validators.validator_for(schema)(schema)  # its declared draft
    errors = sorted(validator.iter_errors(doc), key=lambda e: list(e.absolute_path))
    return [f"rexs-file.json, at {'/'.join(str(p) for p in e.absolute_path) or 'root'}: "
            f"{e.message}" for e in errors]


def _json_required(doc) -> list[str]:
    m = doc.get("model") if isinstance(doc, dict) else None
    if not isinstance(m, dict):
        return ["the document must be an object with a 'model' object"]
    out = [f"model lacks its required item {k!r}" for k in
           ("version", "applicationId", "applicationVersion", "date", "relations",
            "components") if k not in m]
    if "version" in m and not re.match(JSON_VERSION_PATTERN, str(m["version"])):
        out.append(f"model.version {m['version']!r} is not a version number")
    for c in m.get("components", []) or []:
        out += [f"a component lacks its required item {k!r}" for k in ("id", "type",
                "attributes") if k not in c]
    for r in m.get("relations", []) or []:
        out += [f"a relation lacks its required item {k!r}" for k in ("id", "type", "refs")
                if k not in r]
    return out


def schema_problems(text: str, fmt: str) -> list[str]:
    """Problems of a REXS text against the published file schema (empty: none).

    Parameters
    ----------
    text : str
        The file's content.
    fmt : {"xml", "json"}

    Returns
    -------
    list of str
        One sentence per problem.

    Source: ``data/rexs-file.xsd``, ``data/rexs-file.json`` (fva-net/rexs-api-cpp).
    """
    return _xsd_problems(text) if fmt == "xml" else _json_problems(text)


# -------------------------------------------------------------------------- database
def _attribute_problems(comp: Component, db, where: str) -> list[str]:
    out = []
    for a in comp.attributes:
        at = f"{where}, attribute {a.id}"
        if a.unit not in db.units:
            out.append(f"{at}: unit {a.unit!r} is not a REXS unit")
        if a.id.startswith("custom_"):
            continue
        if a.id not in db.attributes:
            out.append(f"{at}: unknown attribute (REXS {db.version})")
            continue
        if not db.has(comp.type, a.id):
            out.append(f"{at}: not an attribute of {comp.type} (REXS {db.version})")
            continue
        spec = db.attributes[a.id]
        if a.unit != spec.unit:
            out.append(f"{at}: unit {a.unit!r} is not the database's {spec.unit!r}")
        if a.value_type != spec.value_type:
            out.append(f"{at}: a {a.value_type} value where the database has "
                       f"{spec.value_type}")
            continue
        values = a.value if spec.value_type in ARRAY_TYPES else [a.value]
        if spec.value_type in ("floating_point", "integer", "floating_point_array",
                               "integer_array"):
            bad = [v for v in values if isinstance(v, (int, float))
                   and not isinstance(v, bool) and not spec.in_range(float(v))]
            if bad:
                out.append(f"{at}: {bad[0]!r} outside its range {spec.range_text()}")
        if spec.value_type in ("enum", "enum_array"):
            bad = [v for v in values if v not in spec.enum_values]
            if bad:
                out.append(f"{at}: {bad[0]!r} is not one of {list(spec.enum_values)}")
    return out


def database_problems(model: Model) -> list[str]:
    """Problems of a model against the attribute database of its version (empty: none).

    Checks component types, the component–attribute mapping, units, value types, ranges,
    enumerations, relation types, roles and orders, and that every id a relation or a load
    case names exists. Each problem is one sentence naming the component type and id and the
    attribute.

    Source: FVA REXS attribute database of ``model.version`` (data/README.md).
    """
    if model.version not in VERSIONS:
        return [f"REXS version {model.version!r} is not supported; supported: "
                f"{', '.join(VERSIONS)}"]
    db = load_database(model.version)
    out: list[str] = []
    types: dict[int, str] = {}
    for c in model.components:
        if c.id in types:
            out.append(f"component id {c.id} is given twice")
        types[c.id] = c.type
        if c.type not in db.components:
            out.append(f"component id {c.id}: unknown component type {c.type!r} "
                       f"(REXS {db.version})")
            continue
        out += _attribute_problems(c, db, c.where())
    rel_ids: set[int] = set()
    for r in model.relations:
        where = f"relation {r.type} id {r.id}"
        if r.id in rel_ids:
            out.append(f"relation id {r.id} is given twice")
        rel_ids.add(r.id)
        spec = db.relations.get(r.type)
        if spec is None:
            out.append(f"{where}: unknown relation type (REXS {db.version})")
            continue
        missing = [x.id for x in r.refs if x.id not in types]
        if missing:
            out.append(f"{where}: refers to component id {missing[0]}, which the file "
                       "does not hold")
            continue
        pairs = {(types[x.id], x.role) for x in r.refs}
        if not any(pairs <= set(combo) for combo in spec.combinations):
            got = ", ".join(f"{t} as {role}" for t, role in sorted(pairs))
            out.append(f"{where}: {got} is no allowed combination of its roles")
        if spec.ordered and r.order is None:
            out.append(f"{where}: the database requires an order for this relation type")
    if model.load_spectrum is not None:
        for lc in model.load_spectrum.load_cases:
            for c in lc.components:
                if c.id not in types:
                    out.append(f"load case {lc.id}: component id {c.id} is not in the file")
                    continue
                c.type = types[c.id]
                if c.type in db.components:
                    out += _attribute_problems(c, db, f"load case {lc.id}, {c.where()}")
    return out


def check_text(text: str, fmt: str, what: str = "REXS file") -> Model:
    """Both checks of a REXS text; the model read from it.

    Raises
    ------
    RexsValidationError
        Any problem (the first named in the message, all in ``problems``).
    """
    problems = schema_problems(text, fmt)
    if problems:
        raise RexsValidationError(problems, what)
    model = model_from_text(text, fmt)
    problems = database_problems(model)
    if problems:
        raise RexsValidationError(problems, what)
    return model


def validate_file(path: str | Path) -> list[str]:
    """The problems of a ``.rexs`` / ``.rexsj`` file (empty: valid against the file schema
    and the attribute database of its version).

    Parameters
    ----------
    path : path-like
        ``*.rexs`` (XML) or ``*.rexsj`` (JSON).

    Returns
    -------
    list of str
        One sentence per problem, naming the component type, id and attribute.

    Raises
    ------
    InputError
        The file cannot be read or its name has neither suffix.
    """
    fmt = file_format(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"REXS file {str(path)!r}: cannot be read ({exc})") from None
    problems = schema_problems(text, fmt)
    if problems:
        return problems
    try:
        model = model_from_text(text, fmt)
    except InputError as exc:
        return [str(exc)]
    return database_problems(model)
