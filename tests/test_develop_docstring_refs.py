"""The cross-references of ``contact.develop``'s and ``DevelopmentResult``'s docstrings
name objects that exist (issue 71, round 25b: a script user reading ``help(contact.develop)``
followed ``_static_capacity``, ``coast_development`` and ``_relief_stage`` to nothing — the
first renamed ``static_capacity``, the other two living in other modules — and one target
was broken across two lines)."""

from __future__ import annotations

import importlib
import inspect
import re

import contact
from contact.optimize.development_result import DevelopmentResult

ROLE = re.compile(r":(?:func|meth|attr|data|class|mod|exc):`([^`]+)`")


def _resolves(target: str, owner: object) -> bool:
    """Whether a role's target names an object: a dotted path from an importable module,
    else a name of ``owner``'s module, of ``contact.optimize.development`` (which documents
    ``develop`` and re-exports ``DevelopmentResult`` with the names its docstring uses) or
    an attribute or field of ``owner`` (a class)."""
    name = target.lstrip("~").strip()
    if "<" in name:  # ``text <target>``
        name = name.rsplit("<", 1)[1].rstrip(">")
    parts = name.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        try:
            for part in parts[i:]:
                obj = getattr(obj, part)
        except AttributeError:
            return False
        return True
    scope = [inspect.getmodule(owner),
             importlib.import_module("contact.optimize.development")]
    if inspect.isclass(owner):
        scope.append(owner)
    obj = None
    for start in scope:
        obj = start
        try:
            for part in parts:
                obj = getattr(obj, part)
            return True
        except AttributeError:
            continue
    fields = getattr(owner, "__dataclass_fields__", {})
    return len(parts) == 1 and parts[0] in fields


def _unresolved(owner: object, doc: str) -> list[str]:
    return [t for t in ROLE.findall(doc) if not _resolves(t, owner)]


def test_develop_and_its_result_name_existing_objects():
    """Every ``:func:``/``:meth:``/``:attr:``/``:data:``/``:class:``/``:mod:`` target of
    ``contact.develop``, ``DevelopmentResult`` and its documented methods resolves (exact:
    an import and attribute lookup, no tolerance), and none is broken across lines."""
    owners = [(contact.develop, inspect.getdoc(contact.develop)),
              (DevelopmentResult, DevelopmentResult.__doc__ or "")]
    owners += [(DevelopmentResult, f.__doc__) for f in vars(DevelopmentResult).values()
               if callable(f) and f.__doc__]
    for owner, doc in owners:
        assert not [t for t in ROLE.findall(doc) if "\n" in t], owner
        assert _unresolved(owner, doc) == [], owner


def test_the_resolver_refuses_what_does_not_exist():
    """The check above can fail: a private name no module has, a dotted path to a missing
    attribute."""
    assert not _resolves("_static_capacity", DevelopmentResult)
    assert not _resolves("contact.optimize.development_check._static_capacity",
                         DevelopmentResult)
    assert _resolves("~contact.optimize.development_check.static_capacity", DevelopmentResult)
    assert _resolves("written_case", DevelopmentResult)
