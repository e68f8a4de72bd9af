"""The report as a sheet an engineer hands on (issue 56 items 4, 5): the verdict box that
opens it, the machine-settings sheet, the loaded pattern in mm with the contact ratio, the
figures' size and the efficiency plot's colours.

References independent of the code under test: the machine settings are read from the
case file with ``tomllib``; the pattern's extent is recomputed from the stored pressure
envelope and the case file's face width; the contact ratio from the per-pair load shares
(``/ltca/load_share`` > 0), not from ``pairs_in_contact`` that the page reads; the
verdict's findings are those of the issue (flank 1.8 GPa above σ_Hlim 1.5 GPa at
500 N·m, heel edge contact at 50 N·m). One analysis of the default case on one mesh cycle
of 6 rolls (~1 s); the page drawn without figures except where figures are the subject.
"""

from __future__ import annotations

import tomllib

import html5lib
import numpy as np
import pytest

from contact.catalogue import DEFAULT_CASE, bundled_case_path, resolve_case
from contact.ltca import LTCAOptions
from contact.pipeline import run_analysis
from contact.plots.machine_sheet import machine_sheet
from contact.plots.report import render_report, report_context

NS = {"h": "http://www.w3.org/1999/xhtml"}


@pytest.fixture(scope="module")
def tree():
    return run_analysis(resolve_case(None), [50.0, 500.0],
                        options=LTCAOptions(rolls_per_cycle=6, cycles=1), geometry=False,
                        theoretical=False, mesh_interface=False)


@pytest.fixture(scope="module")
def page(tree):
    return html5lib.HTMLParser(strict=True).parse(render_report(tree, figures=[]))


def _text(el) -> str:
    return "".join(el.itertext()).strip()


def test_the_page_opens_with_the_verdict(page):
    body = page.find("h:body", NS)
    sections = body.findall("h:section", NS)
    assert sections[0].get("id") == "verdict"
    assert "attention" in sections[0].get("class").split()
    assert _text(sections[0].find("h:h2", NS)) == "Verdict: ATTENTION"
    items = {li.get("data-check"): _text(li) for li in sections[0].iter(f"{{{NS['h']}}}li")}
    assert "flank_pressure" in items and "σ_Hlim 1500 MPa" in items["flank_pressure"]
    assert "at 500 N·m" in items["flank_pressure"]  # the page's spelling of N·m
    heel = [t for k, t in ((li.get("data-check"), _text(li)) for li in
                           sections[0].iter(f"{{{NS['h']}}}li")) if k == "edge_contact"]
    assert any(t.startswith("attention at 50 N·m") and "heel" in t for t in heel), heel


def _case_file(name: str = DEFAULT_CASE) -> dict:
    text = bundled_case_path(name).read_text(encoding="utf-8")
    return tomllib.loads(text)


def test_machine_settings_are_the_case_files(page):
    raw = _case_file()
    rows = page.findall(".//h:table[@id='machine-pinion']/h:tbody/h:tr", NS)
    table = {_text(r[0]): [_text(c) for c in r[1:]] for r in rows}
    for field, label, unit in (("radial_setting", "radial setting S_r", "mm"),
                               ("cradle_angle", "cradle angle q_c", "deg"),
                               ("ratio_of_roll", "ratio of roll R_a", "1")):
        got = table[label]
        assert got[0] == unit
        for k, flank in enumerate(("concave", "convex")):
            assert float(got[1 + k]) == pytest.approx(raw["pinion"]["machine"][flank][field],
                                                      abs=1e-4), (field, flank)
    blade = table["point radius r_p"]
    assert float(blade[1]) == pytest.approx(raw["pinion"]["cutter"]["concave"]["point_radius"],
                                            abs=1e-4)
    # the pinion's modified roll: one row per coefficient given, none for the motions absent;
    # printed to 4 significant digits (machine_sheet's "{x:.4g}"), whose rounding is at most
    # half a unit of the 4th digit: 5e-4 relative (0.003113 for 2C = 0.0031126)
    assert float(table["modified roll 2C"][1]) == pytest.approx(
        raw["pinion"]["machine"]["concave"]["modified_roll"][0], rel=5e-4)
    assert "vertical motion V1" not in table
    gear = page.findall(".//h:table[@id='machine-gear']/h:tbody/h:tr", NS)
    assert gear and "helical motion H1" not in {_text(r[0]) for r in gear}


def test_a_face_hobbing_sheet_has_its_cutter_head():
    raw = _case_file("kolivand2009_fh_12x41_reference.toml")
    sheet = machine_sheet(raw)
    head = dict((label, value) for label, _, value in sheet[0]["head"])
    assert head["blade groups z_0"] == f"{raw['pinion']['cutter']['blade_groups']:.0f}"
    labels = [r[0] for r in sheet[0]["rows"]]
    assert "blade offset angle δ_b" in labels and labels.index("point radius r_p") == 0


def test_pattern_in_mm_and_contact_ratio(tree, page):
    lt = tree["ltca"].to_dataset()
    face = _case_file()["gear"]["blank"]["face_width"]
    rows = page.findall(".//h:table[@id='pattern-table']/h:tbody/h:tr", NS)
    assert len(rows) == 2
    for i, row in enumerate(rows):
        cells = [_text(c) for c in row]
        env = np.nan_to_num(lt["pressure_envelope"].isel(torque=i).transpose("u", "v").values)
        iu = np.flatnonzero((env > 0).any(axis=1))
        u = lt["u"].values
        # length along the face width from the outermost loaded nodes (grid 0.025 apart)
        assert float(cells[1]) == pytest.approx((u[iu[-1]] - u[iu[0]]) * face, abs=0.06)
        assert 0 < float(cells[2]) < 15  # height: under the whole depth of a 4 mm module
        # contact ratio: the pairs carrying a share of the torque, on average over the rolls
        share = lt["load_share"].isel(torque=i).values
        ratio = float(np.mean(np.sum(np.nan_to_num(share) > 0, axis=1)))
        assert float(cells[9]) == pytest.approx(ratio, abs=0.005)
    # the heel reached at 50 N·m (heel end 1.00), as the verdict says
    assert _text(rows[0][6]) == "1.00"


def test_figures_are_sized_and_wide_ones_span(tree):
    """The page's figure entries: 150 dpi drawn, shown at their size in CSS px (96 per
    inch); the multi-panel pressure figure spans the grid, the one-panel efficiency not."""
    from contact.plots.analysis import analysis_specs
    from contact.plots.report import WIDE_FIGURE
    from contact.plots.style import DPI

    assert DPI == 150
    specs = {s.name: s for s in analysis_specs(tree)}
    from contact.plots.analysis import RenderedFigure
    from contact.plots.style import png_bytes

    figs = [RenderedFigure(n, specs[n].caption, png_bytes(specs[n].draw()))
            for n in ("pressure", "friction_efficiency")]
    ctx = report_context(tree, figs)
    by = {f["name"]: f for f in ctx["figures"]}
    for f, rf in zip(ctx["figures"], figs, strict=True):
        w = int.from_bytes(rf.png[16:20], "big")
        assert f["width"] == round(w * 96 / 150)
        assert f["wide"] == (w / 150 > WIDE_FIGURE)
    assert by["pressure"]["wide"] and not by["friction_efficiency"]["wide"]


def test_the_efficiency_plot_gives_each_torque_its_colour(tree):
    from contact.plots.curves import TORQUE_MARKERS, efficiency_curve_figure

    fig = efficiency_curve_figure(tree["friction"].to_dataset(), tree["ltca"].to_dataset())
    lines = [ln for ln in fig.axes[0].get_lines() if ln.get_linestyle() == "-"]
    assert len(lines) == 2
    assert len({ln.get_color() for ln in lines}) == 2
    assert [ln.get_marker() for ln in lines] == list(TORQUE_MARKERS[:2])
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert any(lab.startswith("T_p = 50") for lab in labels)
    assert any(lab.startswith("T_p = 500") for lab in labels)
