"""Every ```python block of every documentation page runs (issue 63 item 3: "every Python
block on every page executed in the docs build or the tests").

The pages are the README and every page of the site (``doc_pages.ALL_PAGES``: a new page
is collected without being listed anywhere). A page's blocks run in order in one
namespace, as a reader runs them one after the other, from an empty temporary directory;
each block asserts the numbers it shows. A block that would be costly at the resolution
it shows says, in an HTML comment right above its fence, how the test runs it cheaper
(``<!-- docs-test: replace OLD => NEW -->``: fewer rolls, torques or points, never another
result; or a step whose result the block neither shows nor asserts left out: the root
stress, an FE build of the page's design, tested in tests/test_root_stress.py and
tests/test_fe_*.py, as tests/test_readme_walkthrough.py runs ``ltca run``), or why it
does not run (``<!-- docs-test: skip REASON -->``, reported as a skip with its reason,
and listed in ``SKIPPED`` so that a new skip is a reviewed change).

The gallery's scripts (``docs/examples/plot_*.py``) are executed by the site's build
(sphinx-gallery; tests/test_docs_site.py runs the quickest, the published build all).
"""

from __future__ import annotations

import matplotlib
import pytest
from doc_pages import ALL_PAGES, ROOT, python_blocks

#: the blocks left out, ``page:line``-free (page name → number of skipped blocks) with the
#: reason in the page's own directive. Empty: every block runs.
SKIPPED: dict[str, int] = {}

PAGES = [p for p in ALL_PAGES if python_blocks(p)]


def _prepared(code: str, directives: list[tuple[str, str]]) -> str:
    for kind, argument in directives:
        if kind == "replace":
            old, new = (s.strip() for s in argument.split("=>"))
            assert old in code, f"docs-test replace: {old!r} is not in the block"
            code = code.replace(old, new)
    return code


def test_every_page_is_collected():
    """The README and every page of the site are read, and the pages with Python blocks
    are the ones this test runs; the skips are the reviewed ones."""
    names = {p.name for p in ALL_PAGES}
    assert "README.md" in names
    assert names >= {p.name for p in (ROOT / "docs").glob("*.md")}
    skipped = {p.name: sum(any(k == "skip" for k, _ in d) for _, _, d in python_blocks(p))
               for p in PAGES}
    assert {k: v for k, v in skipped.items() if v} == SKIPPED


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(ROOT)) for p in PAGES])
def test_page_python_blocks_run(page, tmp_path, monkeypatch):
    """The page's blocks, in order, in one namespace, from a scratch directory."""
    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    # a page runs as in a new shell: an earlier test of this process may have left
    # MALLOC_TRIM_THRESHOLD_ in os.environ (distributed's in-process clusters set it), and
    # a variable in the environment wins over the Dask configuration docs/study.md shows
    # (its block asserts the workers start without it; it failed in the full suite only)
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    namespace: dict = {"__name__": "docs_page"}
    skipped = []
    for line, code, directives in python_blocks(page):
        reasons = [r for k, r in directives if k == "skip"]
        if reasons:
            skipped.append(f"{page.name}:{line}: {reasons[0]}")
            continue
        where = f"{page.relative_to(ROOT)}:{line}"
        exec(compile(_prepared(code, directives), where, "exec"), namespace)
    if skipped:
        pytest.skip("; ".join(skipped))
