"""The import rules of the packages and of ``contact``'s layers (DESIGN.md, issue 20).

Read from the source with ``ast`` (nothing is imported), every ``import`` and
``from … import`` of the three packages — module level and inside functions — must keep:

* the package rules of DESIGN.md: ``geometry`` imports neither ``contact`` nor
  ``friction``; ``friction`` never imports ``contact``; ``contact`` imports ``friction``
  only in its application layer;
* ``contact``'s layers, each importing only those below it:

      application (pipeline, io, plots (a package), cli, commands, study, optimize)
        └── ltca ── utca, compliance, qp
              utca, compliance ── geometry
              qp ── geometry's shared low layer only (no gear in it)

  plus ``contact.errors`` (the exception family), which every layer may use;
* no private name (``_x``) imported from another module, and no private module imported
  from outside its own package.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "geometry", "friction")

#: geometry's modules that hold no gear: errors, validators, Hertz line contact, material
#: data, the dataset convention, atomic file writes (the qp layer may use these and nothing
#: else of geometry)
GEOMETRY_LOW = {"geometry.errors", "geometry.validation", "geometry.hertz",
                "geometry.materials", "geometry.atomic_files",
                "geometry.conventions"}

#: contact's layers and what each may import (besides itself, contact.errors and,
#: for all but qp, the whole of geometry)
LAYER_DEPENDS = {
    "contact.qp": set(),
    "contact.utca": set(),
    "contact.compliance": set(),
    "contact.ltca": {"contact.qp", "contact.utca", "contact.compliance"},
}
APPLICATION = {"contact", "contact.pipeline", "contact.io", "contact.plots", "contact.cli",
               "contact.wear",
               "contact.__main__", "contact._moved", "contact.commands",
               "contact.deviation_files", "contact.output_paths", "contact.study",
               "contact.optimize"}


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _imports(path: Path) -> list[tuple[str, str, int]]:
    """(imported module, imported name or '', line) of every import in a file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    this = _module_name(path)
    package = this if path.name == "__init__.py" else this.rpartition(".")[0]
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, "", node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - node.level + 1]
                mod = ".".join([*base, node.module] if node.module else base)
            else:
                mod = node.module or ""
            out += [(mod, a.name, node.lineno) for a in node.names]
    return out


def _sources() -> list[Path]:
    return sorted(p for pkg in PACKAGES for p in (ROOT / pkg).rglob("*.py"))


def _layer(module: str) -> str:
    """The layer of a module of ``contact`` ('contact.errors' is its own)."""
    if module == "contact.errors":
        return module
    for layer in LAYER_DEPENDS:
        if module == layer or module.startswith(layer + "."):
            return layer
    if module in APPLICATION or module.startswith(("contact.commands.", "contact.plots.",
                                                   "contact.study.", "contact.optimize.")):
        return "application"
    raise AssertionError(f"{module}: in no layer of contact (add it to tests/test_layers.py)")


def _violations() -> list[str]:
    bad = []
    for path in _sources():
        this = _module_name(path)
        top = this.split(".")[0]
        where = f"{path.relative_to(ROOT)}"
        for mod, name, line in _imports(path):
            target_top = mod.split(".")[0]
            if target_top not in PACKAGES:
                continue
            at = f"{where}:{line}: {this} imports {mod}{'.' + name if name else ''}"
            # package rules (DESIGN.md)
            if top == "geometry" and target_top != "geometry":
                bad.append(f"{at} (geometry imports neither contact nor friction)")
            if top == "friction" and target_top == "contact":
                bad.append(f"{at} (friction never imports contact)")
            if top == "contact" and target_top == "friction" and _layer(this) != "application":
                bad.append(f"{at} (contact imports friction only in the application layer)")
            # contact's layers
            if top == "contact" and target_top == "contact":
                mine, theirs = _layer(this), _layer(_full(mod, name))
                allowed = {mine, "contact.errors"}
                if mine != "application":
                    allowed |= LAYER_DEPENDS.get(mine, set())
                if mine != "application" and theirs not in allowed:
                    bad.append(f"{at} (layer {mine} may not import layer {theirs})")
            if top == "contact" and _layer(this) == "contact.qp" and target_top == "geometry":
                full = _full(mod, name)
                if not any(full == m or full.startswith(m + ".") or mod == m
                           for m in GEOMETRY_LOW):
                    bad.append(f"{at} (the qp layer has no gear in it: only "
                               f"{sorted(GEOMETRY_LOW)})")
            # private names and modules (``from pkg import _module`` is a module import)
            full = _full(mod, name)
            if name.startswith("_") and not name.startswith("__") and full == mod:
                bad.append(f"{at} (a private name crosses a module boundary)")
            for i, part in enumerate(full.split(".")):
                if part.startswith("_") and not part.startswith("__"):
                    owner = ".".join(full.split(".")[:i])
                    if not (this == owner or this.startswith(owner + ".")):
                        bad.append(f"{at} (a private module is used outside its package)")
    return bad


def _full(mod: str, name: str) -> str:
    """``mod.name`` when that is a module of the tree (``from contact import pipeline``)."""
    candidate = f"{mod}.{name}" if name else mod
    path = ROOT.joinpath(*candidate.split("."))
    return candidate if (path.with_suffix(".py").exists() or (path / "__init__.py").exists()) \
        else mod


def test_import_rules_hold():
    bad = _violations()
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("layer", sorted(LAYER_DEPENDS))
def test_every_layer_is_a_subpackage(layer):
    assert (ROOT.joinpath(*layer.split(".")) / "__init__.py").is_file()


def test_the_rules_catch_a_violation(tmp_path, monkeypatch):
    """The checker is not vacuous: a qp module importing the ease-off is reported."""
    import test_layers as me

    fake = ROOT / "contact" / "qp" / "_layer_probe.py"
    original = me._sources

    def with_probe():
        return [*original(), fake]

    monkeypatch.setattr(me, "_sources", with_probe)
    monkeypatch.setattr(Path, "read_text", _probe_reader(fake, Path.read_text))
    found = me._violations()
    assert any("_layer_probe" in v and "layer contact.qp may not import layer contact.utca"
               in v for v in found)
    assert any("_layer_probe" in v and "private name" in v for v in found)
    assert any("_layer_probe" in v and "no gear" in v for v in found)


def _probe_reader(fake: Path, read):
    def reader(self, *args, **kwargs):
        if self == fake:
            return ("from contact.utca import ease_off\n"
                    "from contact.qp.problem import _as_float_array\n"
                    "from geometry.case import Case\n")
        return read(self, *args, **kwargs)

    return reader
