"""The analysis report as a browser shows and prints it (issue 38 part 2, issue 56 item 5):
Chromium, headless, driven by Playwright, on a small ``ltca run --report`` page.

Checked: the page lays out without horizontal overflow at a desktop width (1280 px) and a
narrow one (800 px) — at 800 px the wide tables reflow (every cell of the summary table,
efficiency and power loss included, inside the window, none in a scroll box); the figures
sit in a grid (at 1280 px at least two share a row) and a multi-panel figure spans it; the
figures are drawn at 150 dpi and shown at their own size (natural pixels / CSS pixels =
150/96); a click enlarges a figure and Escape closes it; the verdict box opens the page;
the visible text spells the micro-radian one way (µrad). In print (the page's print
stylesheet, A4 and Letter): nothing overflows the printable width, each section starts a
page, and the PDF Chromium prints has as many pages as that needs and no more than a
bound (the figures one or two to a page).

Skipped, saying why, where Chromium or Playwright (``pip install playwright``; its own
browser download is never used) is not installed — CI installs neither. Chromium is
``HYPOID_LTCA_CHROMIUM`` (a path) if set, else ``chromium``, ``chromium-browser`` or
``google-chrome`` on the PATH, else ``/usr/bin/chromium``; started as this machine's
notes require (headless, no sandbox as root, no GPU, no network services, a fresh profile
directory). Cheap enough: one run at 4 rolls per mesh cycle (~10 s), a few page loads and
two PDFs.
"""

from __future__ import annotations

import os
import re
import shutil
import struct
from pathlib import Path

import pytest

from contact.cli import main


def _chromium() -> str | None:
    given = os.environ.get("HYPOID_LTCA_CHROMIUM")
    if given:
        return given if Path(given).exists() else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return "/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None


CHROMIUM = _chromium()
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]

pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="no Chromium installed (apt-get install chromium, or "
    "HYPOID_LTCA_CHROMIUM=/path/to/chromium)")

#: [CSS px] the printable width of A4 (210 mm) and Letter (215.9 mm) less the page's
#: 12 mm side margins (the report's @page), at 96 px per inch
PRINT_WIDTH = {"A4": round((210.0 - 24.0) / 25.4 * 96), "Letter": round((215.9 - 24.0)
                                                                        / 25.4 * 96)}


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    d = tmp_path_factory.mktemp("browser")
    html = d / "report.html"
    assert main(["run", "--torque", "50", "250", "--rolls-per-cycle", "4", "--segments",
                 "10", "--no-progress", "-o", str(d / "ltca.nc"), "--report",
                 str(html)]) == 0
    return html


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    sync = pytest.importorskip("playwright.sync_api",
                               reason="pip install playwright (drives the installed Chromium)")
    profile = tmp_path_factory.mktemp("chromium-profile")
    with sync.sync_playwright() as p:
        b = p.chromium.launch_persistent_context(
            str(profile), executable_path=CHROMIUM, headless=True, args=FLAGS[1:])
        try:
            yield b
        finally:
            b.close()


def _png_size(data: bytes) -> tuple[int, int]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


#: elements wider than the window (closed <details> apart, whose content is not shown)
OVERFLOW = """() => [...document.querySelectorAll('body *')].filter(
    e => e.getBoundingClientRect().right > window.innerWidth + 1
         && !e.closest('details:not([open])') && !e.closest('#lightbox')
         && e.getBoundingClientRect().width > 0).map(e => e.tagName + '#' + e.id
                                                        + '.' + e.className)"""


@pytest.mark.parametrize("width", [1280, 800])
def test_report_fits_the_window_and_lays_figures_in_a_grid(browser, page_file, width):
    page = browser.new_page()
    try:
        page.set_viewport_size({"width": width, "height": 900})
        page.goto(page_file.as_uri())
        page.wait_for_load_state("load")
        m = page.evaluate("""() => ({
            scroll: document.documentElement.scrollWidth,
            inner: window.innerWidth,
            height: document.documentElement.scrollHeight,
            tops: [...document.querySelectorAll('#figures figure')].map(
                f => Math.round(f.getBoundingClientRect().top)),
            wide: [...document.querySelectorAll('#figures figure.wide')].map(
                f => Math.round(f.getBoundingClientRect().width)),
            grid: Math.round(document.querySelector('#figures .figures')
                             .getBoundingClientRect().width),
            scale: [...document.querySelectorAll('#figures img')].map(
                i => i.naturalWidth / i.width),
            scrolled: [...document.querySelectorAll('.scroll')].filter(
                s => s.scrollWidth > s.clientWidth + 1).map(s => s.firstElementChild.id),
            cells: [...document.querySelectorAll('#summary-table td')].map(
                c => [c.dataset.key || '', Math.round(c.getBoundingClientRect().right)]),
            first: document.querySelector('body > section').id,
            text: document.body.innerText,
            imgs: [...document.querySelectorAll('#figures img')].every(
                i => i.complete && i.naturalWidth > 0),
        })""")
        wide = page.evaluate(OVERFLOW)
        assert m["scroll"] <= m["inner"], (m["scroll"], wide[:5])
        assert not wide, wide[:5]
        assert not m["scrolled"], m["scrolled"]  # tables reflow: no scroll box scrolls
        assert m["imgs"], "an embedded figure did not decode"
        # 150 dpi shown at the figures' own size (96 CSS px per inch), or scaled down
        assert all(s >= 150 / 96 - 0.01 for s in m["scale"] if s), m["scale"]
        assert m["first"] == "verdict"
        keys = {k for k, _ in m["cells"]}
        assert {"efficiency_mean", "power_loss_mean"} <= keys
        assert all(right <= width for _, right in m["cells"]), m["cells"]
        if width >= 1280:
            assert len(set(m["tops"])) < len(m["tops"]), "figures not in a grid"
            assert m["wide"] and all(w >= m["grid"] - 2 for w in m["wide"]), m["wide"]
        assert "urad" not in m["text"] and "µrad" in m["text"]
        shot = page.screenshot(full_page=True)
        w, h = _png_size(shot)
        assert w == width and h == m["height"]
    finally:
        page.close()


def test_a_click_enlarges_a_figure(browser, page_file):
    page = browser.new_page()
    try:
        page.set_viewport_size({"width": 1280, "height": 900})
        page.goto(page_file.as_uri())
        img = page.locator("#figures figure img").first
        shown = img.bounding_box()["width"]
        img.click()
        box = page.locator("#lightbox")
        assert box.is_visible()
        big = page.locator("#lightbox img").bounding_box()["width"]
        assert big > shown * 1.4, (big, shown)  # its 150 dpi pixels, not the page's size
        page.keyboard.press("Escape")
        assert not box.is_visible()
    finally:
        page.close()


@pytest.mark.parametrize("paper", ["A4", "Letter"])
def test_the_report_prints_one_section_per_page(browser, page_file, paper):
    page = browser.new_page()
    try:
        # the print layout at the paper's printable width: nothing overflows it
        page.set_viewport_size({"width": PRINT_WIDTH[paper], "height": 1000})
        page.goto(page_file.as_uri())
        page.emulate_media(media="print")
        wide = page.evaluate(OVERFLOW)
        assert not wide, wide[:5]
        breaks = page.evaluate("""() => [...document.querySelectorAll('body > *')].filter(
            e => getComputedStyle(e).breakBefore === 'page').map(e => e.id || e.className)""")
        n_figures = page.evaluate("document.querySelectorAll('#figures figure').length")
        pdf = page.pdf(format=paper, print_background=True)
        pages = len(re.findall(rb"/Type\s*/Page(?![s\w])", pdf))
        # every section that breaks starts a page, plus the first page (header, verdict,
        # the pair, operating conditions); at most every figure on a page of its own beside
        # ten pages of text and tables
        assert {"machine-settings", "summary", "figures", "solver"} <= set(breaks), breaks
        assert "verdict" not in breaks
        assert len(breaks) + 1 <= pages <= len(breaks) + 10 + n_figures, (pages, breaks)
    finally:
        page.close()
