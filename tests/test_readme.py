"""The README's Python examples run as written (each asserts its key numbers)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parent.parent / "README.md"
BLOCKS = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)


def test_readme_opens_with_the_two_commands():
    text = README.read_text(encoding="utf-8")
    first = re.search(r"```bash\n(.*?)```", text, flags=re.S).group(1).strip().splitlines()
    assert first[0].startswith("pip install . && ltca ")
    assert first[1] == "pip install '.[test]' && pytest"
    ci = (README.parent / ".ci" / "run").read_text(encoding="utf-8")
    assert first[1] in ci


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_python_block(code):
    exec(compile(code, str(README), "exec"), {"__name__": "readme"})


def _layout_section() -> str:
    text = README.read_text(encoding="utf-8")
    return text[text.index("## Layout"):text.index("## References")]


def test_layout_answers_a_newcomers_three_questions_with_paths_that_exist():
    """Where is the QP, where does a backend go, where is the roll loop: each answered by
    a path in the layout section, and the path is there."""
    layout = _layout_section()
    root = README.parent
    for question, path in (("Where is the QP?", "contact/qp/problem.py"),
                           ("Where does a new solver backend go?", "contact/qp/solvers/"),
                           ("Where is the LTCA roll loop?", "contact/ltca/roll_loop.py")):
        answer = layout[layout.index(question):].split("\n- ")[0]
        assert f"`{path}" in answer, question
        assert (root / path).exists(), path


def test_layout_names_every_subpackage_of_contact():
    layout = _layout_section()
    root = README.parent / "contact"
    for pkg in sorted(p.parent.name for p in root.glob("*/__init__.py")):
        assert f"{pkg}/" in layout, pkg
