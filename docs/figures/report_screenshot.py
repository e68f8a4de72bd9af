"""The default run's HTML report as a real browser shows it (once, not in CI).

Run from the repository root, after ``apt-get install -y chromium``::

    python -m contact run --plots figs --report docs/figures/default/report.html
    for f in figs/kolivand2009_fm_11x41_reference_T50-250-500_*.png; do
        mv "$f" "docs/figures/default/${f#figs/kolivand2009_fm_11x41_reference_T50-250-500_}"; done
    python docs/figures/report_screenshot.py

(``--plots`` names the figures after the case and the torques; the docs link them without
them.)

renders ``docs/figures/default/report.html`` in headless Chromium (a tall window at half
scale, so the whole page is one image) and writes ``docs/figures/report_screenshot.png``,
cropped below the page's last line. Its purpose is a check by eye that the page shows
every figure in a browser; the page's HTML is checked by ``tests/test_report.py``.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

HERE = Path(__file__).resolve().parent


def main() -> int:
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if browser is None:
        print("no chromium on PATH (apt-get install -y chromium)", file=sys.stderr)
        return 1
    page = HERE / "default" / "report.html"
    with tempfile.TemporaryDirectory() as tmp:
        shot = Path(tmp) / "shot.png"
        subprocess.run([browser, "--headless", "--disable-gpu", "--no-sandbox",
                        "--disable-quic", "--no-first-run",
                        "--disable-background-networking", "--disable-component-update",
                        "--disable-sync", f"--user-data-dir={tmp}/profile",
                        "--hide-scrollbars", "--force-device-scale-factor=0.5",
                        "--window-size=1300,12000", f"--screenshot={shot}", page.as_uri()],
                       check=True, capture_output=True, timeout=120)
        img = Image.open(shot).convert("RGB")
    grey = np.asarray(img.convert("L"))
    last = int(np.nonzero(grey.min(axis=1) < 250)[0].max())
    out = HERE / "report_screenshot.png"
    img.crop((0, 0, img.width, min(last + 20, img.height))).save(out, optimize=True)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
