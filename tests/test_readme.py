"""The README opens with the two commands and is a front page, and the layout page answers
a newcomer's questions with paths that exist (every page's Python blocks run in
tests/test_docs_blocks.py)."""

from __future__ import annotations

import re

from doc_pages import DOCS, LAYOUT, README, ROOT


def test_readme_opens_with_the_two_commands():
    for page in (README, DOCS / "getting_started.md"):
        text = page.read_text(encoding="utf-8")
        first = re.search(r"```bash\n(.*?)```", text, flags=re.S).group(1).strip().splitlines()
        assert first[0].startswith("pip install . && ltca "), page
        assert first[1] == "pip install '.[test]' && pytest", page
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert first[1] in ci


def test_readme_is_a_front_page():
    """Issue 54: the README is a front page of at most 150 lines, with one Python example of
    at most 15 lines; the manual is the site."""
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) <= 150
    python = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(python) == 1 and len(python[0].splitlines()) <= 15
    for link in re.findall(r"\]\((docs/[^)#]+)", text):
        assert (ROOT / link).is_file(), link


def _layout_section() -> str:
    return LAYOUT.read_text(encoding="utf-8")


def test_layout_answers_a_newcomers_three_questions_with_paths_that_exist():
    """Where is the QP, where does a backend go, where is the roll loop: each answered by
    a path in the layout page, and the path is there."""
    layout = _layout_section()
    for question, path in (("Where is the QP?", "contact/qp/problem.py"),
                           ("Where does a new solver backend go?", "contact/qp/solvers/"),
                           ("Where is the LTCA roll loop?", "contact/ltca/roll_loop.py")):
        answer = layout[layout.index(question):].split("\n- ")[0]
        assert f"`{path}" in answer, question
        assert (ROOT / path).exists(), path


def test_layout_names_every_subpackage_of_contact():
    layout = _layout_section()
    root = ROOT / "contact"
    for pkg in sorted(p.parent.name for p in root.glob("*/__init__.py")):
        assert f"{pkg}/" in layout, pkg
