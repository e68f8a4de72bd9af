"""The documentation pages whose code blocks the tests run (issue 54: the README became a
front page and its manual moved into ``docs/``; the tests of its blocks moved with them).

``PAGES``: the README and the site's pages that were the README's sections (walk-through,
face-hobbed pairs, studies, duty cycle, mesh interface, correction and optimisation,
shell against FE, the contact problem, solver comparison, layout, …) plus the getting
started page. Their ``bash`` blocks run (tests/test_readme_blocks.py,
tests/test_readme_walkthrough.py), their ``python`` blocks execute
(tests/test_readme.py) and pass ruff (tests/test_api_docs.py).
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
README = ROOT / "README.md"
WALKTHROUGH = DOCS / "walkthrough.md"
LAYOUT = DOCS / "layout.md"
PAGES: tuple[Path, ...] = (README, *(DOCS / f"{name}.md" for name in (
    "getting_started", "walkthrough", "capabilities", "face_hobbed_pairs",
    "studies_at_scale", "duty_cycle", "mesh_interface",
    "correction_and_optimisation", "shell_vs_fe", "contact_problem", "solver_comparison",
    "layout")))


#: every page of the documentation: the README and every page of the site (docs/*.md).
#: Their ``python`` blocks run (tests/test_docs_blocks.py) and import only the public API
#: (tests/test_docs_site.py)
ALL_PAGES: tuple[Path, ...] = (README, *sorted(DOCS.glob("*.md")))

#: a directive for the docs test, on the line right before a ```python fence (an HTML
#: comment: the site does not show it): ``<!-- docs-test: replace OLD => NEW -->`` runs
#: the block with OLD replaced by NEW (a smaller case, fewer rolls or torques: only the
#: resolution, never what the block shows), ``<!-- docs-test: skip REASON -->`` leaves the
#: block out with its reason in the test's report
DIRECTIVE = re.compile(r"<!-- docs-test: (replace|skip) (.*?) -->")


def python_blocks(page: Path) -> list[tuple[int, str, list[tuple[str, str]]]]:
    """(line, code, directives) of every ```python block of ``page``, in order; the
    directives are the ``docs-test`` comments on the lines right above the fence."""
    text = page.read_text(encoding="utf-8")
    found = []
    for m in re.finditer(r"```python\n(.*?)```", text, flags=re.S):
        above = text[:m.start()].rstrip("\n").splitlines()
        directives = []
        while above and (d := DIRECTIVE.fullmatch(above[-1].strip())):
            directives.insert(0, (d.group(1), d.group(2)))
            above.pop()
        found.append((text[:m.start()].count("\n") + 1, m.group(1), directives))
    return found


def blocks(language: str, pages=PAGES) -> list[tuple[str, str]]:
    """(``page:line``, code) of every fenced block in ``language`` on the pages."""
    found = []
    for page in pages:
        text = page.read_text(encoding="utf-8")
        found += [(f"{page.relative_to(ROOT)}:{text[:m.start()].count(chr(10)) + 1}",
                   m.group(1))
                  for m in re.finditer(rf"```{language}\n(.*?)```", text, flags=re.S)]
    return found


def text(pages=PAGES) -> str:
    """The pages' text, joined (for tests that look for a documented number)."""
    return "\n".join(p.read_text(encoding="utf-8") for p in pages)
