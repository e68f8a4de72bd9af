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
    "studies_at_scale", "duty_cycle", "mesh_interface_overview",
    "correction_and_optimisation", "shell_vs_fe", "contact_problem", "solver_comparison",
    "layout")))


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
