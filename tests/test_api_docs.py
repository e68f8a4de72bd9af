"""The public API's docstrings keep CONTRIBUTING.md's promise, and the docs' Python
examples pass ruff (issue 63 item 3).

What is checked, for every public name of ``contact``, ``friction`` and ``geometry``
(their ``__all__``: the names docs/api.md documents):

* numpydoc's validation with the checks ``docs/conf.py`` turns on for the site's build
  (``numpydoc_validation_checks``: a docstring and a summary, every parameter documented
  and typed and none extra, a Returns section with a description); the build runs them too
  (tests/test_docs_site.py, ``-W``), this test names every failure at once and in seconds;
* **units**: every parameter whose type is a real quantity (``float``, ``array_like``,
  ``ndarray``) states its unit in brackets in its entry (``— [mm]``; ``[1]`` for a
  dimensionless one);
* **errors**: a function whose own body raises an exception has a Raises section;
* **source**: every public *model* (a function or class that computes physics or
  implements a published method: ``MODELS``) cites its source — an equation, table or
  section of the seed, a standard, or an author and year — in its summary, Notes or
  References; every other public name is a tool (``TOOLS``: files, registries, options,
  errors, figures, studies' plumbing) and the two lists cover the API.

The names that do not pass yet are listed, each with why, in ``docs/conf.py``
(``NUMPYDOC_PENDING``) and here (``UNITS_PENDING``, ``RAISES_PENDING``,
``SOURCE_PENDING``); a listed name that passes fails the test, so the lists only shrink.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import re
import runpy
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from doc_pages import ALL_PAGES, DOCS, ROOT, python_blocks

numpydoc = pytest.importorskip("numpydoc")
from numpydoc.docscrape import ClassDoc, FunctionDoc  # noqa: E402
from numpydoc.validate import validate  # noqa: E402

PACKAGES = ("contact", "friction", "geometry")

#: the public models: each cites its source (module docstring)
MODELS = {
    "contact.ContactProblem", "contact.contact_residuals", "contact.solve_contact",
    "contact.ease_off", "contact.unloaded_tca", "contact.loaded_tca",
    "contact.influence_coefficients", "contact.fe_compliance_matrix", "contact.fillet_stress",
    "contact.shell_assembler", "contact.iso10300_rating", "contact.iso10300_capacity",
    "contact.rate_load_capacity",
    "contact.scuffing_micropitting",
    "contact.run_duty_cycle", "contact.sensitivity", "contact.vh_check", "contact.develop",
    "friction.GroundSurface", "friction.efficiency_analysis", "friction.friction_coefficient",
    "friction.load_kolivand2009_fit", "friction.pressure_viscosity_coefficient",
    "friction.solve_line_contact", "friction.solve_stochastic_line_contact",
    "friction.stochastic_summary", "friction.viscosity",
    "geometry.BevelGearDesign", "geometry.blank_geometry", "geometry.corrective_settings",
    "geometry.synthesize",
}
#: the public tools: no physics of their own, so no source to cite
TOOLS = {
    # the analysis and the studies: chains of the models above, each model cites its own
    "contact.run_analysis", "contact.AnalysisChain", "contact.ChainState",
    "contact.available_steps", "contact.sweep", "contact.sample", "contact.StudyRun",
    "contact.verdict", "contact.DutyCycle", "contact.read_duty_cycle",
    "contact.example_duty_cycle",
    "contact.DevelopmentTargets", "contact.OptimizeProblem", "contact.synthesize_case",
    "geometry.corrected_case",
    # options, results, constants and errors
    "contact.LTCAOptions", "contact.FEOptions", "contact.ContactSolution",
    "contact.DEFAULT_CASE", "contact.DEFAULT_SOLVER", "contact.DEFAULT_TOLERANCE",
    "contact.ContactError", "contact.NotPositiveDefiniteError", "contact.ProblemInputError",
    "contact.SolverNotFoundError", "friction.DEFAULT_FRICTION_MODEL",
    "friction.LineContactCondition", "friction.OperatingConditions", "friction.Lubricant",
    "geometry.Case", "geometry.Misalignment", "geometry.InputError", "geometry.LTCAError",
    "geometry.ModelUnavailableError",
    # files and cases
    "contact.bundled_cases", "contact.bundled_case_path", "contact.resolve_case",
    "contact.read_netcdf", "contact.write_netcdf", "contact.read_deviations",
    "contact.write_report", "contact.clear_caches", "friction.load_lubricant",
    "friction.available_lubricants", "geometry.load_case", "geometry.load_basic",
    "contact.export_rexs", "contact.import_rexs", "contact.validate_rexs",
    # registries
    "contact.available_solvers", "contact.register_backend", "contact.unregister_backend",
    "contact.available_compliance_models", "contact.register_compliance_model",
    "contact.unregister_compliance_model", "contact.available_rating_methods",
    "contact.register_rating_method", "contact.unregister_rating_method",
    "friction.available_friction_models", "friction.register_friction_model",
    "friction.unregister_friction_model",
    # figures
    "contact.contact_pattern_figure", "contact.load_share_figure", "contact.map_figure",
    "contact.transmission_error_figure", "contact.plot_analysis", "contact.save_png",
}

#: a citation: the seed's equations, tables, figures and sections, a standard, an author
#: and year, a journal reference
SOURCE = re.compile(r"\bseed\b|\bEqs?\.|\bTable\b|\bFig\.|§|\b(ISO|AGMA|ANSI|DIN|VDI|"
                    r"ASME)\b|\bet al\.?|\b(1[89]|20)\d\d\b|Kolivand|Litvin|Johnson|Weber")
UNIT = re.compile(r"\[[^\]]+\]")
QUANTITY = re.compile(r"\b(float|array_like|ndarray)\b")

#: public names whose entries miss a unit, each with why (only shrinks)
UNITS_PENDING: dict[str, str] = {}
#: public names that raise without a Raises section, each with why (only shrinks)
RAISES_PENDING: dict[str, str] = {}
#: public models without a source, each with why (only shrinks)
SOURCE_PENDING: dict[str, str] = {}


def _public() -> list[tuple[str, object]]:
    names = []
    for package in PACKAGES:
        module = importlib.import_module(package)
        names += [(f"{package}.{n}", getattr(module, n)) for n in module.__all__
                  if not n.startswith("_")]
    return names


def _documented() -> list[tuple[str, object]]:
    return [(name, obj) for name, obj in _public() if inspect.isclass(obj) or callable(obj)]


def _doc(obj):
    return ClassDoc(obj) if inspect.isclass(obj) else FunctionDoc(obj)


def _conf() -> dict:
    return runpy.run_path(str(DOCS / "conf.py"))


def _check_pending(failing: dict[str, str], pending: dict[str, str]) -> None:
    new = {k: v for k, v in failing.items() if k not in pending}
    fixed = sorted(set(pending) - set(failing))
    assert not new, "\n".join(f"{k}: {v}" for k, v in sorted(new.items()))
    assert not fixed, f"these pass now: remove them from the pending list: {fixed}"


def _autodoc_text(name: str, obj) -> str:
    """The docstring the site shows: autodoc takes a ``#:`` comment above the name in the
    module that defines the object (an alias ``x = f`` with a comment) before ``__doc__``."""
    from sphinx.errors import PycodeError
    from sphinx.pycode import ModuleAnalyzer

    try:
        comments = ModuleAnalyzer.for_module(obj.__module__).find_attr_docs()
    except PycodeError:  # no source to analyse: the docstring it is
        comments = {}
    lines = comments.get(("", name.rsplit(".", 1)[-1]))
    return "\n".join(lines) if lines else inspect.getdoc(obj) or ""


def test_numpydoc_validation_of_the_public_api():
    """numpydoc's checks of docs/conf.py on the docstring the site shows of every name."""
    from numpydoc.docscrape_sphinx import get_doc_object

    conf = _conf()
    checks = conf["numpydoc_validation_checks"]
    assert {"PR01", "PR02", "RT01", "RT03"} <= checks
    failing = {}
    for name, obj in _documented():
        what = "class" if inspect.isclass(obj) else "function"
        report = validate(get_doc_object(obj, what=what, doc=_autodoc_text(name, obj)))
        errors = [f"{code} {message}" for code, message in report["errors"] if code in checks]
        if errors:
            failing[name] = "; ".join(errors)
    _check_pending(failing, conf["NUMPYDOC_PENDING"])


def test_quantity_parameters_state_their_units():
    failing = {}
    for name, obj in _documented():
        missing = [p.name for p in _doc(obj)["Parameters"] if QUANTITY.search(p.type)
                   and not UNIT.search(" ".join([p.type, *p.desc]))]
        if missing:
            failing[name] = f"no [unit]: {missing}"
    _check_pending(failing, UNITS_PENDING)


def _raises(obj) -> bool:
    """The object's own code raises an exception (a ``raise X``; for a class, in its
    constructor or ``__post_init__``)."""
    targets = ([getattr(obj, m) for m in ("__init__", "__post_init__") if m in vars(obj)]
               if inspect.isclass(obj) else [obj])
    for target in targets:
        try:
            tree = ast.parse(textwrap.dedent(inspect.getsource(target)))
        except (OSError, TypeError):
            continue
        if any(isinstance(node, ast.Raise) and node.exc is not None
               for node in ast.walk(tree)):
            return True
    return False


def test_what_raises_has_a_raises_section():
    failing = {name: "raises, no Raises section" for name, obj in _documented()
               if _raises(obj) and not _doc(obj)["Raises"]}
    _check_pending(failing, RAISES_PENDING)


def test_every_public_name_is_a_model_or_a_tool():
    names = {name for name, _ in _public()} - {f"{p}.__version__" for p in PACKAGES}
    assert not MODELS & TOOLS
    unclassified = sorted(names - MODELS - TOOLS)
    assert not unclassified, f"classify these in MODELS or TOOLS: {unclassified}"


def test_models_cite_their_source():
    public = dict(_public())
    failing = {}
    for name in sorted(MODELS & set(public)):
        doc = _doc(public[name])
        text = " ".join([*doc["Summary"], *doc["Extended Summary"], *doc["Notes"],
                         *doc["References"]])
        if not SOURCE.search(text):
            failing[name] = "no source in its summary, Notes or References"
    _check_pending(failing, SOURCE_PENDING)


def test_readme_python_examples_pass_ruff(tmp_path):
    """Every ```python block of every page (the README and docs/*.md), written to its own
    file, passes ``ruff check`` with the project's configuration."""
    blocks = [code for page in ALL_PAGES for _, code, _ in python_blocks(page)]
    assert blocks, "no python examples"
    for i, block in enumerate(blocks):
        (tmp_path / f"readme_example_{i}.py").write_text(block)
    ruff = shutil.which("ruff") or str(Path(sys.executable).parent / "ruff")
    res = subprocess.run([ruff, "check", "--config", str(ROOT / "pyproject.toml"),
                          "--no-cache", str(tmp_path)], capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr
