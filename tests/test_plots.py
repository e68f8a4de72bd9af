"""The figure functions of contact.plots on real results: the default case (with the
efficiency stage), a deviated run (wear deviations) and a face-hobbed case.

Each figure is checked on what it must show, against the datasets it was drawn from:
axis labels with units, one colour scale across torques, diverging maps centred on
zero, every swept value in a panel, the edge contact outside the flank. The runs are
small (4 rolls per mesh cycle, 10 segments) so the file stays within CI's budget.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from matplotlib.collections import LineCollection, PathCollection
from matplotlib.text import Annotation
from mpl_toolkits.mplot3d import Axes3D

from contact.catalogue import SEED_TABLE_3_1, resolve_case
from contact.ltca import LTCAOptions
from contact.pipeline import run_analysis
from contact.plots import (
    analysis_figures,
    contact_pattern_figure,
    easeoff_contour_figure,
    easeoff_map_figure,
    easeoff_topography_figure,
    efficiency_map_figure,
    efficiency_map_figures,
    efficiency_roughness_figure,
    efficiency_speed_figure,
    friction_flank_figure,
    load_share_figure,
    map_figure,
    pair_ute_curves,
    plot_analysis,
    pressure_figure,
    transmission_error_figure,
)
from contact.plots.analysis import figure_prefix
from contact.plots.flank import colour_index
from contact.plots.tooth import segment_pieces
from contact.study.efficiency import efficiency_map
from friction.operating import OperatingConditions
from geometry.core.errors import InputError

QUICK = LTCAOptions(rolls_per_cycle=4, segments=10)
ONE_CYCLE = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=10)
UNIT = re.compile(r"\[[^\[\]]+\]$")


@pytest.fixture(scope="module")
def default_tree():
    return run_analysis(resolve_case(None), [50.0, 250.0],
                        misalignment=SEED_TABLE_3_1["misalignment"], options=QUICK,
                        operating=OperatingConditions())


@pytest.fixture(scope="module")
def deviated_tree():
    return run_analysis(resolve_case("kolivand2009_fm_11x41_wear"), [200.0],
                        options=ONE_CYCLE, root_stress=False)


@pytest.fixture(scope="module")
def fh_tree():
    return run_analysis(resolve_case("kolivand2009_fh_12x41"), [200.0], options=ONE_CYCLE)


@pytest.fixture(scope="module")
def emap():
    return efficiency_map(resolve_case(None), [100.0, 300.0], [500.0, 1500.0],
                          roughness=[0.4, 0.8], options=LTCAOptions(rolls_per_cycle=4,
                                                                    segments=10))


def _groups(tree):
    return {g: tree[g].to_dataset() for g in ("easeoff", "utca", "ltca", "friction",
                                              "scuffing_micropitting")
            if g in tree.children}


def _labels_carry_units(fig) -> int:
    """Every non-empty axis label of every visible axes ends in ``[unit]``; the figure has
    at least one labelled x and y axis. Returns the number of labels checked."""
    n, xs, ys = 0, 0, 0
    for ax in fig.axes:
        if not ax.get_visible():
            continue
        labels = [ax.get_xlabel(), ax.get_ylabel()]
        if isinstance(ax, Axes3D):
            labels.append(ax.get_zlabel())
        for lab in labels:
            if lab:
                assert UNIT.search(lab), f"axis label without units: {lab!r}"
                n += 1
        xs += bool(ax.get_xlabel())
        ys += bool(ax.get_ylabel())
    assert xs and ys
    return n


def _case_in_title(fig, tree) -> None:
    text = fig.get_suptitle() or " ".join(ax.get_title() for ax in fig.axes)
    assert tree.attrs["case"] in text


@pytest.mark.parametrize("which", ["default_tree", "deviated_tree", "fh_tree"])
def test_every_analysis_figure_labels_its_axes_with_units(which, request, tmp_path):
    tree = request.getfixturevalue(which)
    names = []
    for nf in analysis_figures(tree):
        _labels_carry_units(nf.figure)
        _case_in_title(nf.figure, tree)
        names.append(nf.name)
    expected = {"easeoff_topography", "easeoff", "contact_pattern", "transmission_error",
                "pressure", "load_share"}
    assert expected <= set(names)
    assert ("friction_flank" in names) == ("friction" in tree.children)
    assert ("deviations_pressure" in names) == ("theoretical" in tree.children)
    if which == "deviated_tree":
        written = plot_analysis(tree, tmp_path)
        # the files are named <case>_<figure> (figure_prefix: runs share a directory)
        assert {p.stem for p in written} == {figure_prefix(tree) + n for n in names}
        assert all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in written)


def _collections(fig, kind):
    return [c for ax in fig.axes for c in ax.collections
            if type(c) is kind and c.get_array() is not None and c.get_array().size]


def _drawn_by_colour(lc) -> dict[int, list]:
    """{colour-map entry: sorted piece midpoints} of a collection drawn by colour group:
    each path holds its pieces as 3 points and a NaN gap, and carries one value."""
    cm, out = lc.get_cmap(), {}
    for path, value in zip(lc.get_paths(), lc.get_array(), strict=True):
        (k,) = colour_index([value], lc.norm, cm)
        assert k not in out  # one path per colour
        mid = path.vertices.reshape(-1, 4, 2)[:, 1]
        out[int(k)] = sorted(map(tuple, np.round(mid, 12)))
    return out


def _by_colour(pieces, values, lc) -> dict[int, list]:
    index = colour_index(values, lc.norm, lc.get_cmap())
    return {int(k): sorted(map(tuple, np.round(pieces[index == k][:, 1], 12)))
            for k in np.unique(index)}


def test_pressure_shares_one_scale_and_draws_edges_outside(default_tree):
    g = _groups(default_tree)
    lt = g["ltca"]
    fig = pressure_figure(g["easeoff"], lt)
    kind = lt["segment_kind"].values
    p = lt["pressure_max"].values
    flank_peak = float(np.nanmax(np.where(kind == "curve", p, np.nan)))
    edge_peak = float(np.nanmax(np.where(kind != "curve", p, np.nan)))
    lines = _collections(fig, LineCollection)
    assert len(lines) == lt.sizes["torque"]
    # one colour scale for every torque, from 0 to the flank's peak over all torques
    assert {(lc.norm.vmin, lc.norm.vmax) for lc in lines} == {(0.0, flank_peak)}
    # every flank segment with a non-zero pressure is drawn, once, in the colour of its
    # own pressure (the pieces are grouped by colour-map entry, one path per entry)
    for i, lc in enumerate(lines):
        flank_p = np.where(kind == "curve", p[i], 0.0)
        pieces, values = segment_pieces(lt, flank_p)
        curve = flank_p[..., kind == "curve"]
        assert len(values) == np.count_nonzero(np.isfinite(curve) & (curve > 0))
        assert _drawn_by_colour(lc) == _by_colour(pieces, values, lc)
    # the edge contact in its own scale, outside the unit square for the gear edges
    edges = _collections(fig, PathCollection)
    assert edges and {(e.norm.vmin, e.norm.vmax) for e in edges} == {(0.0, edge_peak)}
    tip = np.concatenate([e.get_offsets() for e in edges])
    assert np.any(tip[:, 1] > 1.0) or np.any(tip[:, 0] > 1.0)
    assert all(ax.get_title() for ax in fig.axes[:lt.sizes["torque"]])


def test_signed_maps_are_centred_on_zero(default_tree, deviated_tree):
    g = _groups(default_tree)
    fig = friction_flank_figure(g["easeoff"], g["ltca"], g["friction"], ["slide_to_roll"])
    # the values first; over them (where the friction model extrapolates) one red overlay
    lc, *overlay = _collections(fig, LineCollection)
    assert all(o.get_cmap().N == 1 for o in overlay) and len(overlay) <= 1
    sr = g["friction"]["slide_to_roll"].values
    assert np.nanmin(sr) < 0 < np.nanmax(sr)  # signed: the diverging map applies
    assert lc.norm.vmin == -lc.norm.vmax and lc.get_cmap().name == "RdBu_r"
    eo = deviated_tree["easeoff"].to_dataset()
    fig = easeoff_map_figure({"change": eo}, "ease_off_change", diverging=True)
    cs = fig.axes[0].collections[-1]
    assert cs.levels[0] == pytest.approx(-cs.levels[-1])
    assert cs.levels[-1] == pytest.approx(np.nanmax(np.abs(eo["ease_off_change"].values)))


def test_easeoff_views(default_tree):
    eo = default_tree["easeoff"].to_dataset()
    fig = easeoff_topography_figure(eo)
    ax = next(a for a in fig.axes if isinstance(a, Axes3D))
    assert "toe → heel" in ax.get_xlabel() and "root → tip" in ax.get_ylabel()
    # the colour scale spans the ease-off (0 at the mean contact point to its maximum)
    surf = ax.collections[0]
    assert surf.norm.vmax == pytest.approx(float(np.nanmax(eo["ease_off"].values)))
    fig = easeoff_contour_figure(eo)
    ax = fig.axes[0]
    # toe/heel/root/tip written outside the flank: none inside the outline's bounding box
    z, r = eo["axial_position"].values, eo["radial_position"].values
    from matplotlib.path import Path as MplPath

    ring = np.concatenate([np.c_[z[:, 0], r[:, 0]], np.c_[z[-1, :], r[-1, :]],
                           np.c_[z[::-1, -1], r[::-1, -1]], np.c_[z[0, ::-1], r[0, ::-1]]])
    fig.canvas.draw()
    inv = ax.transData.inverted()
    words = {t.get_text(): t for t in ax.texts if t.get_text() in ("toe", "heel", "root", "tip")}
    assert set(words) == {"toe", "heel", "root", "tip"}
    for t in words.values():
        bb = t.get_window_extent()
        corners = inv.transform([[bb.x0, bb.y0], [bb.x1, bb.y0], [bb.x0, bb.y1], [bb.x1, bb.y1]])
        assert not MplPath(ring).contains_points(corners).any(), t.get_text()
    # the masked nodes have a key
    assert any("masked" in t.get_text() for leg in fig.legends for t in leg.get_texts())


def test_transmission_error_figure_draws_the_pairs_and_their_envelope(default_tree):
    g = _groups(default_tree)
    ut, lt = g["utca"], g["ltca"]
    start = float(lt["roll"].values[0])
    curves = pair_ute_curves(ut, start, 2.0)
    # the pairs' curves are one curve shifted by whole mesh cycles (seed §2.3.2.2), and
    # their lower envelope is the UTE: at /utca's own roll samples (where no interpolation
    # enters) it equals /utca's UTE to round-off. (Between the samples a relieved flank's
    # UTE can have features narrower than /utca's 1/30-cycle spacing: on the default case
    # /ltca's UTE, computed at its own rolls, lies up to 1.1 µrad above the interpolated
    # envelope at 50 N·m, so that comparison would test the sampling, not the figure.)
    period = float(ut.attrs["mesh_period"])
    x = (ut["roll"].values - start) / period
    inner = (x > 0.05) & (x < 1.95)
    env = np.min([np.interp(x, cx, cy, left=np.inf, right=np.inf)
                  for cx, cy in curves.values()], axis=0)
    assert inner.sum() >= 10
    np.testing.assert_allclose(env[inner], ut["unloaded_transmission_error"].values[inner],
                               rtol=0, atol=1e-9)
    fig = transmission_error_figure(ut, lt)
    data_axes = [a for a in fig.axes if a.get_visible()]
    assert len(data_axes) == 1 + lt.sizes["torque"]
    for i, ax in enumerate(data_axes[1:]):
        (line,) = [ln for ln in ax.get_lines() if ln.get_label() == "LTE"]
        assert np.array_equal(line.get_ydata(), lt["transmission_error"].values[i])
        assert f"{lt['torque'].values[i]:g} N·m" in ax.get_title()
    assert data_axes[-1].get_xlim() == pytest.approx((0.0, 2.0), abs=1e-12)


def test_patterns_and_load_share_one_panel_per_torque(default_tree):
    g = _groups(default_tree)
    nt = g["ltca"].sizes["torque"]
    fig = contact_pattern_figure(g["easeoff"], g["utca"], g["ltca"])
    panels = [a for a in fig.axes if a.get_visible()]
    assert [a.get_title() for a in panels] == ["unloaded", *(
        f"T_p = {t:g} N·m" for t in g["ltca"]["torque"].values)]
    # the loaded path (load centres) lies on the tooth
    for ax in panels[1:]:
        (path,) = [ln for ln in ax.get_lines() if ln.get_label().startswith("loaded path")]
        assert np.all((path.get_xdata() >= 0) & (path.get_xdata() <= 1))
    fig = load_share_figure(g["ltca"])
    assert len([a for a in fig.axes if a.get_visible()]) == nt
    _labels_carry_units(fig)


def test_map_figure_shows_every_swept_value(emap):
    fig = efficiency_map_figure(emap)
    panels = [a for a in fig.axes if a.get_visible() and a.get_title()]
    assert len(panels) == emap.sizes["roughness"] * emap.sizes["temperature"] == 2
    for ax, rq in zip(panels, emap["roughness"].values, strict=True):
        assert f"{rq:g} µm" in ax.get_title()
        assert ax.get_xlabel() == "pinion speed [rpm]"
    _labels_carry_units(fig)
    # the values written at the sample points are the map's, in %
    written = sorted(float(t.get_text()) for ax in panels for t in ax.texts
                     if isinstance(t, Annotation))
    assert np.allclose(written, sorted(np.round(100 * emap["efficiency"].values.ravel(), 2)),
                       atol=5e-3)
    for f in (efficiency_speed_figure(emap), efficiency_roughness_figure(emap)):
        _labels_carry_units(f)
    speed_panels = [a for a in efficiency_speed_figure(emap).axes if a.get_visible()]
    assert len(speed_panels) == 2  # one per roughness: 0.8 µm is no longer hidden
    assert [nf.name for nf in efficiency_map_figures(emap)] == [
        "efficiency_map", "power_loss_map", "efficiency_vs_speed", "efficiency_vs_roughness"]


def test_map_figure_on_a_study_grid():
    """map_figure on a ΔE × ΔP study at two torques: a panel per torque, one scale, a
    diverging map centred on zero for a signed variable; refusals name the dimension."""
    import xarray as xr

    de = xr.DataArray([-0.1, 0.0, 0.1], dims="dE", attrs={"units": "mm", "long_name": "ΔE"})
    dp = xr.DataArray([-0.05, 0.05], dims="dP", attrs={"units": "mm", "long_name": "ΔP"})
    tq = xr.DataArray([50.0, 500.0], dims="torque", attrs={"units": "N m",
                                                           "long_name": "pinion torque"})
    shift = (de * 10 + dp * 20) * np.log(tq)  # a signed response
    ds = xr.Dataset({"shift": shift.assign_attrs(units="mm", long_name="pattern shift")},
                    coords={"dE": de, "dP": dp, "torque": tq}).transpose("torque", "dP", "dE")
    fig = map_figure(ds, "shift", x="dE", y="dP")
    panels = [a for a in fig.axes if a.get_visible() and a.get_title()]
    assert [a.get_title() for a in panels] == ["pinion torque = 50 N·m",
                                               "pinion torque = 500 N·m"]
    assert panels[0].get_xlabel() == "ΔE [mm]" and panels[0].get_ylabel() == "ΔP [mm]"
    cs = next(c for a in panels for c in a.collections if hasattr(c, "levels"))
    top = float(np.abs(shift).max())
    assert cs.levels[0] == pytest.approx(-top) and cs.levels[-1] == pytest.approx(top)
    with pytest.raises(InputError, match="torque"):
        map_figure(ds, "shift", x="dE", y="dP", facet=[])
    with pytest.raises(InputError, match="'dQ' is not a dimension"):
        map_figure(ds, "shift", x="dQ", y="dP")


# --- issue 38, part 2: what the report's figures show a gear engineer ----------------

def test_panel_subtitles_give_peaks_with_units_not_exponents(default_tree):
    """The pressure panels' subtitles read "flank peak 1792 MPa, edge peak 6298 MPa"
    (were "flank peak 1.79e+03" without a unit)."""
    g = _groups(default_tree)
    fig = pressure_figure(g["easeoff"], g["ltca"])
    titles = [ax.get_title() for ax in fig.axes if "peak" in ax.get_title()]
    assert len(titles) == g["ltca"].sizes["torque"]
    lt = g["ltca"]
    for t, flank in zip(titles, lt["pressure_max_flank"].values, strict=True):
        assert "e+" not in t and "e-" not in t, t
        assert re.search(r"flank peak \d+ MPa", t), t
        assert f"flank peak {flank:.0f} MPa" in t  # the /ltca value, to the MPa


def test_efficiency_legend_covers_no_curve(default_tree):
    """The legend sits under the panel: its box does not overlap the axes."""
    from contact.plots import efficiency_curve_figure

    fig = efficiency_curve_figure(default_tree["friction"].to_dataset(),
                                  default_tree["ltca"].to_dataset())
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    ax = fig.axes[0]
    assert ax.get_legend() is None and fig.legends
    box = fig.legends[0].get_window_extent(renderer)
    assert not box.overlaps(ax.get_window_extent(renderer))


def test_friction_flank_draws_flash_temperature_and_specific_film(default_tree):
    """The flank figure has a panel for the flash temperature [K] and for the specific
    film thickness λ_GF [1] (docs/scuffing_micropitting.md), each in its own sequential
    scale up to the flank's peak at the largest torque."""
    g = _groups(default_tree)
    # the load-capacity step's variables beside the friction stage's (issue 63), as the
    # analysis figures draw them
    sm = g["scuffing_micropitting"]
    fr = g["friction"].assign({n: sm[n] for n in ("flash_temperature",
                                                  "specific_film_thickness")})
    fig = friction_flank_figure(g["easeoff"], g["ltca"], fr)
    titles = [ax.get_title() for ax in fig.axes]
    assert "flash temperature [K]" in titles
    assert "specific film thickness λ_GF [1]" in titles
    flank = g["ltca"]["segment_kind"].values == "curve"
    ax = fig.axes[titles.index("flash temperature [K]")]
    peak = float(np.nanmax(sm["flash_temperature"].isel(torque=-1).values[..., flank]))
    lines = [c for c in ax.collections if isinstance(c, LineCollection) and c.norm.vmax]
    assert lines and lines[0].norm.vmin == 0.0
    assert lines[0].norm.vmax == pytest.approx(peak)


def test_extrapolation_marks_in_a_colour_no_colour_map_uses(default_tree):
    """The friction model's extrapolated segments are marked in EXTRAPOLATED (magenta),
    which is far from every colour of the maps on the figure (RdBu_r's red end clashed
    with the old crimson): colour distance > 0.3 in RGB to every map entry."""
    from matplotlib import colormaps
    from matplotlib.colors import to_rgb

    from contact.plots.style import DIVERGING, EDGE, EXTRAPOLATED, SEQUENTIAL

    g = _groups(default_tree)
    fig = friction_flank_figure(g["easeoff"], g["ltca"], g["friction"], ["slide_to_roll"])
    overlay = [c for c in _collections(fig, LineCollection) if c.get_cmap().N == 1]
    mark = np.array(to_rgb(EXTRAPOLATED))
    if overlay:
        assert np.allclose(overlay[0].get_cmap()(0.5)[:3], mark)
    for name in (DIVERGING, SEQUENTIAL, EDGE):
        rgb = colormaps[name](np.linspace(0, 1, 256))[:, :3]
        assert np.min(np.linalg.norm(rgb - mark, axis=1)) > 0.3, name


def test_tolerance_histogram_labels_off_the_bars_and_integer_draws():
    """Percentile values in the panel title (no annotation over the bars); the y ticks
    count draws, integers only."""
    import xarray as xr

    from contact.study.figures import tolerance_figure

    rng = np.random.default_rng(0)
    n = 40
    ds = xr.Dataset(
        {"lte_peak_to_peak": (("sample", "torque"), rng.normal(25, 4, (n, 1)),
                              {"units": "urad", "long_name": "LTE peak-to-peak"}),
         "status": ("sample", np.zeros(n, np.int8))},
        coords={"torque": ("torque", [250.0], {"units": "N m"})},
        attrs={"case": "test", "method": "sobol"})
    fig = tolerance_figure(ds)
    ax = fig.axes[0]
    assert not [t for t in ax.texts + ax.findobj(Annotation)]
    p = np.percentile(ds["lte_peak_to_peak"].values, (5, 50, 95))
    assert f"P50 {p[1]:.4g}" in ax.get_title()
    ticks = [t for t in ax.get_yticks() if ax.get_ylim()[0] <= t <= ax.get_ylim()[1]]
    assert all(float(t).is_integer() for t in ticks), ticks


def test_efficiency_figure_marks_only_rolls_the_extrapolation_matters_for():
    """A roll is marked where flagged segments make ≥ 5 % of its sliding loss (issue 61:
    every roll was marked, since every roll has an edge outside any line-contact box): a
    flagged segment with 10 % of the loss marks its roll, one with 1 % does not, and a roll
    without loss is not marked."""
    import xarray as xr

    from contact.plots.curves import EXTRAPOLATED_LOSS_SHARE, _extrapolated_rolls

    loss = np.array([[[[9.0, 1.0]], [[99.0, 1.0]], [[0.0, 0.0]]]])   # (torque, roll, pair, seg)
    flag = np.array([[[[0, 1]], [[0, 1]], [[0, 1]]]], dtype=np.int8)
    dims = ("torque", "roll", "pair", "segment")
    fr = xr.Dataset({"sliding_loss": (dims, loss), "friction_model_extrapolated": (dims, flag)})
    assert EXTRAPOLATED_LOSS_SHARE == 0.05
    assert _extrapolated_rolls(fr, 0).tolist() == [True, False, False]
