"""``ltca duty-cycle``: a spectrum file in, a /duty_cycle group with units and figures out.

Cheap: one bin, 8 rolls per cycle and 8 segments, in this process (``--scheduler
synchronous``): one analysis of about a second.
"""

from __future__ import annotations

import pytest

from contact.catalogue import resolve_case
from contact.cli import main
from geometry.core.io import read_netcdf

DUTY = """
[duty_cycle]
name = "one-bin test spectrum"
grade = "ME"
miner_rule = "elementary"
torque = [300.0]
speed = [1200.0]
hours = [100.0]
temperature = [80.0]

[duty_cycle.deflection]
torque = [0.0, 500.0]
delta_E = [0.0, 0.02]
delta_P = [0.0, -0.01]
delta_G = [0.0, 0.01]
delta_Sigma = [0.0, 0.005]
"""


def test_duty_cycle_command_writes_group_and_figures(tmp_path, capsys):
    duty = tmp_path / "duty.toml"
    duty.write_text(DUTY, encoding="utf-8")
    out = tmp_path / "d.nc"
    plots = tmp_path / "plots"
    assert main(["duty-cycle", "--duty", str(duty), "--scheduler", "synchronous",
                 "--rolls-per-cycle", "8", "--segments", "8", "-o", str(out),
                 "--plots", str(plots), "--no-progress", "--no-root-stress",
                 "--report", str(tmp_path / "d.html")]) == 0
    text = capsys.readouterr().out
    assert "one-bin test spectrum" in text and "pitting life" in text
    # the bending side is on by default (FE coefficients: minutes to build, so this cheap
    # test turns it off; tests/test_root_stress.py runs it on coarse FE options) and said
    # to be unavailable when off
    assert "bending side unavailable" in text
    # edge contact at 300 N·m on the default design: the summary says its pressures are
    # not pitting damage, with the edges' share and peak pressure (issue 55); so does the
    # report
    assert "edge pressures are NOT counted in the pitting damage" in text
    assert "p_max edge [MPa]" in text
    assert "NOT counted in the pitting damage" in (tmp_path / "d.html").read_text(
        encoding="utf-8")
    tree = read_netcdf(out)
    ds = tree["/duty_cycle"].to_dataset()
    for name in ("damage", "life", "flank_damage", "cycle_efficiency", "energy_in"):
        assert "units" in ds[name].attrs and "long_name" in ds[name].attrs
    assert ds["life"].attrs["units"] == "h" and ds.attrs["grade"] == "ME"
    # a linear table: the bin's ΔE is the case's own plus 0.02 mm × 300/500 (PCHIP of two
    # rows is the straight line; 1e-15 mm rounding)
    own = resolve_case(None).misalignment.delta_E
    assert float(ds["delta_E"][0]) == pytest.approx(own + 0.012, abs=1e-15)
    assert (plots / f"{ds.attrs['case']}_duty_damage.png").stat().st_size > 0
    assert (plots / f"{ds.attrs['case']}_duty_bins.png").stat().st_size > 0
    assert not (tmp_path / "d.nc.parts").exists()
    assert not (plots / f"{ds.attrs['case']}_duty_root_damage.png").exists()
    # the report page: the durability table of both members, one row per bin, the two
    # figures embedded, the bending side said to be unavailable; `ltca report` of the file
    # draws the same page
    html = (tmp_path / "d.html").read_text(encoding="utf-8")
    table = html[html.index('id="durability-table"'):html.index('id="bins-table"')]
    assert table.count("<tr><td") == 2 and "pinion" in table and "gear" in table
    assert f"{float(ds['life'].sel(member='gear')):.4g}" in table
    bins = html[html.index('id="bins-table"'):html.index('id="figures"')]
    assert bins.count("<tr><td") == ds.sizes["bin"] == 1
    assert html.count("data:image/png;base64,") == 2
    assert "Bending side unavailable" in html
    assert main(["report", str(out), "-o", str(tmp_path / "again.html")]) == 0
    again = (tmp_path / "again.html").read_text(encoding="utf-8")
    assert 'id="durability-table"' in again and "analysis report" not in again
    # the efficiency printed per bin and over the cycle, judged by no limit: the verdict
    # says so in the words of ltca run's (issue 71, notchecked83) on both pages
    # (html-escaped apostrophes there)
    from contact.study.verdicts import DUTY_EFFICIENCY, efficiency_not_judged

    said = efficiency_not_judged(DUTY_EFFICIENCY)
    # the console gathers what it prints and judges by no limit in one line (the pages
    # say each reason)
    assert "not judged: efficiency" in " ".join(text.split())
    for page in (html, again):
        assert said.replace("'", "&#x27;") in page or said.replace("'", "&#39;") in page \
            or said in page
