"""The analysis report as a browser shows it (issue 38, part 2): Debian's Chromium,
headless, driven by Playwright, on a small ``ltca run --report`` page.

Checked: the page lays out without horizontal overflow at a desktop width (1280 px) and
a narrow one (800 px); the figures sit in a grid (at 1280 px at least two share a row);
the full-page screenshot is a real PNG of the viewport's width and of a height well under
the single 7,300 px column the page was (the grid halves it: < 6,000 px); the visible
text spells the micro-radian one way (µrad, never the files' ASCII "urad").

Skipped, saying why, where Chromium (``/usr/bin/chromium``: ``apt-get install chromium``)
or Playwright (``pip install playwright``; its own browser download is never used) is not
installed — CI installs neither. Chromium is started as this machine's notes require
(headless, no sandbox as root, no GPU, no network services, a fresh profile directory).
Cheap enough: one run at 4 rolls per mesh cycle (~10 s) and two page loads.
"""

from __future__ import annotations

import shutil
import struct
from pathlib import Path

import pytest

from contact.cli import main

CHROMIUM = shutil.which("chromium") or (
    "/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]

pytestmark = pytest.mark.skipif(CHROMIUM is None,
                                reason="no Chromium installed (apt-get install chromium)")


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
                               reason="pip install playwright (drives Debian's Chromium)")
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
            wide: [...document.querySelectorAll('body *')].filter(
                e => e.getBoundingClientRect().right > window.innerWidth + 1
                     && !e.closest('.scroll') && !e.closest('details:not([open])')
                     && e.getBoundingClientRect().width > 0).map(e => e.tagName + '#' + e.id),
            text: document.body.innerText,
            imgs: [...document.images].every(i => i.complete && i.naturalWidth > 0),
        })""")
        assert m["scroll"] <= m["inner"], (m["scroll"], m["wide"][:5])
        assert not m["wide"], m["wide"][:5]
        assert m["imgs"], "an embedded figure did not decode"
        if width >= 1280:
            assert len(set(m["tops"])) < len(m["tops"]), "figures not in a grid"
        assert "urad" not in m["text"] and "µrad" in m["text"]
        shot = page.screenshot(full_page=True)
        w, h = _png_size(shot)
        assert w == width and h == m["height"]
        if width >= 1280:
            assert h < 6000, h
    finally:
        page.close()
