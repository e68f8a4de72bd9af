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
* the application layer ordered (issue 31), each level importing only its own and those
  below, with no cycle between its parts::

      commands, cli                      (the ``ltca`` command)
        └── plots (figures, report)
              └── study, optimize, wear  (studies and loops over analyses)
                    └── pipeline, chain  (one whole analysis and its steps)
                          └── load_capacity  (rating, durability, scuffing,
                                              micropitting: the chain's last step)
                                └── catalogue  (the bundled cases)

* ``friction`` reads no output of ``contact``'s load-capacity package (``/rating``,
  ``/scuffing_micropitting``): no group of it is named in ``friction``'s source (issue 63:
  the load-capacity package reads the chain's datasets, never the other way round);
* ``geometry.core`` (the toolkit's low layer) imports nothing else of the toolkit;
* no private name (``_x``) imported from another module, and no private module imported
  from outside its own package — in the packages and in the bundled ``cases/`` scripts.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("contact", "geometry", "friction")

#: the toolkit's low layer, no gear in it (errors, validators, Hertz line contact, dataset
#: conventions and netCDF files, atomic and TOML files, version, caches, registries'
#: helpers): the qp layer may use it and nothing else of geometry
GEOMETRY_LOW = {"geometry.core"}

#: contact's layers and what each may import (besides itself, contact.errors and,
#: for all but qp, the whole of geometry)
LAYER_DEPENDS = {
    "contact.qp": set(),
    "contact.utca": set(),
    "contact.compliance": set(),
    "contact.ltca": {"contact.qp", "contact.utca", "contact.compliance"},
}
#: the application layer's levels, lowest first: each unit (a module or subpackage) may
#: import units of its own level and those below, never above; no cycle between units
APPLICATION_LEVELS = (
    ("catalogue", {"contact.catalogue"}),
    ("load capacity", {"contact.load_capacity"}),
    ("pipeline, chain", {"contact", "contact.pipeline", "contact.chain",
                         "contact.chain_contract"}),
    ("exchange", {"contact.exchange"}),
    ("study, optimize, wear", {"contact.study", "contact.optimize", "contact.wear"}),
    ("plots, report", {"contact.plots"}),
    ("commands, cli", {"contact.commands", "contact.cli", "contact.__main__"}),
)
APPLICATION = set().union(*(units for _, units in APPLICATION_LEVELS))


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


#: syntax trees by source text: the checks below walk the whole toolkit four times (each
#: parse of it ~2 s of CPU); keyed by the text, not the path, so that a probe's text read
#: through a patched ``Path.read_text`` is parsed as its own (the trees are only read)
_TREES: dict[str, ast.Module] = {}


def _parse(text: str) -> ast.Module:
    """``ast.parse(text)``, each distinct text parsed once."""
    if text not in _TREES:
        _TREES[text] = ast.parse(text)
    return _TREES[text]


def _imports(path: Path) -> list[tuple[str, str, int]]:
    """(imported module, imported name or '', line) of every import in a file."""
    tree = _parse(path.read_text(encoding="utf-8"))
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
    if _application_unit(module) is not None:
        return "application"
    raise AssertionError(f"{module}: in no layer of contact (add it to tests/test_layers.py)")


def _application_unit(module: str) -> str | None:
    """The unit of the application layer a module belongs to (None: not in it)."""
    for unit in sorted(APPLICATION, key=len, reverse=True):
        if module == unit or (unit != "contact" and module.startswith(unit + ".")):
            return unit
    return None


def _level(unit: str) -> int:
    return next(i for i, (_, units) in enumerate(APPLICATION_LEVELS) if unit in units)


def _application_edges() -> dict[str, set[str]]:
    """unit → the application units it imports (module-level and in functions)."""
    edges: dict[str, set[str]] = {}
    for path in _sources():
        this = _module_name(path)
        mine = _application_unit(this) if this.startswith("contact") else None
        if mine is None:
            continue
        for mod, name, _ in _imports(path):
            theirs = _application_unit(_full(mod, name)) if mod.startswith("contact") else None
            if theirs is not None and theirs != mine:
                edges.setdefault(mine, set()).add(theirs)
    return edges


def _application_violations() -> list[str]:
    """Upward imports between the application's levels and cycles between its units."""
    bad = []
    edges = _application_edges()
    for unit, targets in sorted(edges.items()):
        for target in sorted(targets):
            if _level(target) > _level(unit):
                bad.append(f"{unit} ({APPLICATION_LEVELS[_level(unit)][0]}) imports {target} "
                           f"({APPLICATION_LEVELS[_level(target)][0]}): an upward import")
    # cycles: depth-first search for a back edge
    state: dict[str, int] = {}

    def visit(unit: str, trail: list[str]) -> None:
        state[unit] = 1
        for target in sorted(edges.get(unit, ())):
            if state.get(target) == 1:
                cycle = [*trail[trail.index(target):], target] if target in trail else \
                    [unit, target]
                bad.append("import cycle: " + " -> ".join(cycle))
            elif target not in state:
                visit(target, [*trail, target])
        state[unit] = 2

    for unit in sorted(edges):
        if unit not in state:
            visit(unit, [unit])
    return bad


def _case_scripts() -> list[Path]:
    return sorted((ROOT / "cases").rglob("*.py"))


def _script_violations() -> list[str]:
    """The bundled ``cases/`` scripts import no private name or module of the packages."""
    bad = []
    for path in _case_scripts():
        tree = _parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and \
                    node.module.split(".")[0] in PACKAGES:
                names = [a.name for a in node.names]
                private = [n for n in names if n.startswith("_") and not n.startswith("__")]
                if private or any(p.startswith("_") and not p.startswith("__")
                                  for p in node.module.split(".")):
                    bad.append(f"{path.relative_to(ROOT)}:{node.lineno}: imports "
                               f"{node.module} {', '.join(names)} (private)")
    return bad


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
            if this.startswith("geometry.core") and not mod.startswith("geometry.core"):
                bad.append(f"{at} (geometry.core, the low layer, imports nothing above it)")
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


#: the groups the load-capacity package (contact.load_capacity) writes: friction names none
LOAD_CAPACITY_GROUPS = ("rating", "scuffing_micropitting")


def _load_capacity_reads() -> list[str]:
    """Every text constant of a ``friction`` source that names a load-capacity group
    (``"rating"``, ``"/rating/flash_temperature"``, ``"scuffing_micropitting"`` …): a
    friction module reading the load-capacity package's output by name."""
    bad = []
    for path in sorted((ROOT / "friction").rglob("*.py")):
        tree = _parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                first = node.value.strip("/").split("/")[0]
                if first in LOAD_CAPACITY_GROUPS:
                    bad.append(f"{path.relative_to(ROOT)}:{node.lineno}: names the "
                               f"load-capacity group {node.value!r}")
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


def test_application_layer_is_ordered_without_cycles():
    bad = _application_violations()
    assert not bad, "\n".join(bad)


def test_friction_reads_no_load_capacity_output():
    bad = _load_capacity_reads()
    assert not bad, "\n".join(bad)


def test_load_capacity_is_one_unit_of_the_application():
    """Rating, durability, scuffing and micropitting are one subpackage of contact (issue
    63), a unit of the application layer: its modules are placed, and none is left in
    friction or at contact's top."""
    assert _application_unit("contact.load_capacity.iso10300.rating") == "contact.load_capacity"
    assert _application_unit("contact.load_capacity.durability") == "contact.load_capacity"
    for gone in ("contact/rating", "contact/durability", "friction/flash_temperature.py",
                 "friction/iso_flash_temperature.py", "friction/micropitting.py"):
        assert not (ROOT / gone).exists(), gone


def test_the_load_capacity_check_is_not_vacuous(monkeypatch):
    """A friction module reading ``tree["rating"]`` is reported."""
    import test_layers as me

    fake = ROOT / "friction" / "_probe.py"
    real = Path.rglob

    def rglob(self, pattern):
        found = list(real(self, pattern))
        return [*found, fake] if self == ROOT / "friction" else found

    monkeypatch.setattr(Path, "rglob", rglob)
    monkeypatch.setattr(Path, "read_text", _reader(fake, 'x = tree["rating"]["S_H"]\n',
                                                   Path.read_text))
    assert any("_probe.py:1" in v and "'rating'" in v for v in me._load_capacity_reads())


def _reader(fake: Path, text: str, read):
    def reader(self, *args, **kwargs):
        return text if self == fake else read(self, *args, **kwargs)

    return reader


def test_case_scripts_import_no_private_names():
    bad = _script_violations()
    assert not bad, "\n".join(bad)


def test_application_rules_catch_an_upward_import_and_a_cycle(monkeypatch):
    """The application checks are not vacuous: the pipeline importing the study engine is
    both an upward import and a cycle (the engine runs the pipeline's analysis); a case
    script importing a private name is reported."""
    import test_layers as me

    real = me._application_edges
    monkeypatch.setattr(me, "_application_edges", lambda: {
        **real(), "contact.pipeline": {"contact.study"}})
    found = me._application_violations()
    assert any("contact.pipeline (pipeline, chain) imports contact.study" in v
               for v in found)
    assert any(v.startswith("import cycle") and "contact.pipeline" in v
               and "contact.study" in v for v in found)
    fake = ROOT / "cases" / "_probe_script.py"
    monkeypatch.setattr(me, "_case_scripts", lambda: [fake])
    monkeypatch.setattr(Path, "read_text", _script_reader(fake, Path.read_text))
    assert any("_probe_script.py:1" in v and "_intersect" in v for v in me._script_violations())


def _script_reader(fake: Path, read):
    def reader(self, *args, **kwargs):
        if self == fake:
            return "from geometry.machine.flank import _intersect\n"
        return read(self, *args, **kwargs)

    return reader


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
