"""``ltca report`` and ``ltca run --report``: one self-contained HTML page per analysis file.

The page is parsed by a spec-conforming HTML parser (html5lib, strict: any parse error
fails); its summary table is compared with the netCDF's values; a file without the
efficiency stage says what is absent; the page from ``run --report`` equals the one
``ltca report`` draws from the file on its own (drawn from the file alone).
"""

from __future__ import annotations

import base64

import html5lib
import numpy as np
import pytest

from contact.cli import main
from contact.plots import analysis_figures
from contact.plots.report import SUMMARY_COLUMNS
from geometry.core.io import read_netcdf

QUICK = ["--torque", "50", "250", "--rolls-per-cycle", "4", "--segments", "10",
         "--no-progress"]
NS = {"h": "http://www.w3.org/1999/xhtml"}


@pytest.fixture(scope="module")
def run_files(tmp_path_factory):
    d = tmp_path_factory.mktemp("report")
    nc, html = d / "ltca.nc", d / "run.html"
    assert main(["run", *QUICK, "-o", str(nc), "--report", str(html)]) == 0
    return nc, html


def _parse(text: str):
    return html5lib.HTMLParser(strict=True).parse(text)


def test_report_is_valid_html_whose_summary_equals_the_file(run_files, tmp_path):
    nc, run_html = run_files
    out = tmp_path / "report.html"
    assert main(["report", str(nc), "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    doc = _parse(text)  # strict: raises on any parse error
    # drawn from the file alone: `run --report` gave the same page
    assert text == run_html.read_text(encoding="utf-8")
    tree = read_netcdf(nc, tree=True)
    lt, fr = tree["ltca"].to_dataset(), tree["friction"].to_dataset()
    rows = doc.findall(".//h:table[@id='summary-table']/h:tbody/h:tr", NS)
    assert len(rows) == lt.sizes["torque"]
    for i, row in enumerate(rows):
        cells = {c.get("data-key"): c for c in row.findall("h:td", NS) if c.get("data-key")}
        assert list(cells) == [k for k, *_ in SUMMARY_COLUMNS]
        expected = {
            "torque": lt["torque"].values[i],
            "lte_mean": lt["lte_mean"].values[i],
            "lte_peak_to_peak": lt["lte_peak_to_peak"].values[i],
            **{f"harmonic_{n + 1}": lt["lte_harmonics"].values[i, n] for n in range(3)},
            "lte_harmonic_rss": lt["lte_harmonic_rss"].values[i],
            "pressure_max_flank": lt["pressure_max_flank"].values[i],
            "pressure_max_edge": lt["pressure_max_edge"].values[i],
            "efficiency_mean": 100 * fr["efficiency_mean"].values[i],
            "power_loss_mean": fr["power_loss_mean"].values[i],
        }
        decimals = {k: d for k, _, _, d in SUMMARY_COLUMNS}
        for key, value in expected.items():
            if not np.isfinite(value):  # e.g. harmonics beyond 4 rolls per cycle's Nyquist
                assert cells[key].get("data-value") == "" and cells[key].text == "–", key
                continue
            # the exact value (repr round-trips a float) and its text at the table's decimals
            assert float(cells[key].get("data-value")) == float(value), key
            assert cells[key].text == f"{float(value):.{decimals[key]}f}", key
        assert "ΔE −0.15, ΔP +0.12 mm" in row.findall("h:td", NS)[0].text
    # every figure embedded as a PNG data URI, nothing fetched from the network
    imgs = doc.findall(".//h:img", NS)
    assert len(imgs) == len(list(analysis_figures(tree)))
    for img in imgs:
        head, data = img.get("src").split(",", 1)
        assert head == "data:image/png;base64"
        assert base64.b64decode(data)[:8] == b"\x89PNG\r\n\x1a\n"
    assert "http://" not in text.replace("http://www.w3.org", "") and "https://" not in text
    # case provenance, the solver's certification and the versions are on the page
    body = "".join(doc.find(".//h:body", NS).itertext())
    assert "Synthesised fields" in body and "pinion.machine.concave" in body
    assert f"Solver {lt.attrs['solver']}" in " ".join(body.split())
    assert "every roll position at every torque has a certified solution" in body
    assert f"hypoid-ltca {tree.attrs['toolkit_version']}" in body
    assert "/friction is absent" not in body


def test_report_of_a_file_without_friction_says_what_is_absent(tmp_path):
    nc = tmp_path / "nofr.nc"
    assert main(["run", "--torque", "100", "--rolls-per-cycle", "4", "--segments", "10",
                 "--no-progress", "--speed", "0", "-o", str(nc)]) == 0
    out = tmp_path / "r.html"
    assert main(["report", str(nc), "-o", str(out)]) == 0
    doc = _parse(out.read_text(encoding="utf-8"))
    absent = " ".join("".join(li.itertext()) for li in
                      doc.findall(".//h:section[@id='absent']//h:li", NS))
    assert "/friction is absent" in absent and "efficiency" in absent
    cells = doc.findall(".//h:table[@id='summary-table']/h:tbody/h:tr/h:td", NS)
    eff = [c for c in cells if c.get("data-key") == "efficiency_mean"]
    assert eff and all(c.text == "–" and c.get("data-value") == "" for c in eff)
    # the friction figures are left out, the others are there
    names = {f.get("id") for f in doc.findall(".//h:figure", NS)}
    assert "fig-pressure" in names and "fig-friction_flank" not in names
    assert np.isfinite(read_netcdf(nc, tree=True)["ltca"]["lte_mean"].values).all()


def test_report_refuses_a_file_that_is_not_an_analysis(tmp_path, capsys):
    import xarray as xr

    from geometry.core.io import write_netcdf

    nc = write_netcdf(xr.Dataset({"x": ("a", np.arange(3.0), {"units": "1",
                                                              "long_name": "x"})}),
                      tmp_path / "other.nc")
    assert main(["report", str(nc), "-o", str(tmp_path / "r.html")]) != 0
    assert "/easeoff" in capsys.readouterr().err
    assert not (tmp_path / "r.html").exists()
