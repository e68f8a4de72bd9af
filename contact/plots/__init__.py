"""Figures of the toolkit's results, and the one-page HTML report of an analysis.

Every ``*_figure`` function takes result datasets (the groups of ``ltca run``'s netCDF,
or the output of :func:`contact.study.efficiency.efficiency_map` / a study) and returns a
:class:`matplotlib.figure.Figure` (made without ``pyplot``; write it with
:func:`save_png`). Titles name the case and its operating point; torques that are
compared share one colour scale; signed quantities are drawn with a diverging map
centred on zero, magnitudes with the perceptually uniform ``viridis``. The gear flank
is drawn on the normalised tooth (face width toe → heel × profile root → tip), the
ease-off also on the projection plane [mm].

Modules
-------
contact.plots.style     colour maps, labels, titles, saving
contact.plots.tooth     the normalised tooth and the projection plane
contact.plots.flank     ease-off, contact patterns, pressure, friction on the flank
contact.plots.curves    transmission error, load sharing, efficiency over the mesh cycles
contact.plots.dynamics  the mesh interface for dynamic models
contact.plots.maps      ``map_figure`` for any swept study; efficiency maps
contact.plots.analysis  every figure of an analysis or efficiency map, named; PNG writing
contact.plots.report    the self-contained HTML report of an analysis file

For a study (e.g. ΔE × ΔP at several torques, a Dataset with coordinates carrying
``long_name`` and ``units``)::

    from contact.plots import map_figure, save_png
    save_png(map_figure(study, "lte_peak_to_peak", x="delta_E", y="delta_P",
                        facet="torque"), "lte_pp.png")
"""

from contact.plots.analysis import (
    FigureSpec,
    NamedFigure,
    RenderedFigure,
    analysis_figures,
    analysis_specs,
    efficiency_map_figures,
    plot_analysis,
    plot_efficiency_map,
    plot_utca,
    render_analysis,
    render_figures,
)
from contact.plots.curves import (
    efficiency_curve_figure,
    load_share_figure,
    pair_ute_curves,
    te_comparison_figure,
    transmission_error_figure,
)
from contact.plots.dynamics import mesh_interface_figure
from contact.plots.flank import (
    FRICTION_FLANK_PLOTS,
    contact_pattern_figure,
    easeoff_contour_figure,
    easeoff_map_figure,
    easeoff_topography_figure,
    friction_flank_figure,
    pressure_figure,
    segment_map_figure,
    segment_panels_figure,
)
from contact.plots.maps import (
    efficiency_map_figure,
    efficiency_roughness_figure,
    efficiency_speed_figure,
    map_figure,
)
from contact.plots.style import png_bytes, save_png

__all__ = [
    "FRICTION_FLANK_PLOTS",
    "FigureSpec",
    "NamedFigure",
    "RenderedFigure",
    "analysis_figures",
    "analysis_specs",
    "contact_pattern_figure",
    "easeoff_contour_figure",
    "easeoff_map_figure",
    "easeoff_topography_figure",
    "efficiency_curve_figure",
    "efficiency_map_figure",
    "efficiency_map_figures",
    "efficiency_roughness_figure",
    "efficiency_speed_figure",
    "friction_flank_figure",
    "load_share_figure",
    "map_figure",
    "mesh_interface_figure",
    "pair_ute_curves",
    "plot_analysis",
    "plot_efficiency_map",
    "plot_utca",
    "png_bytes",
    "pressure_figure",
    "render_analysis",
    "render_figures",
    "save_png",
    "segment_map_figure",
    "segment_panels_figure",
    "te_comparison_figure",
    "transmission_error_figure",
]
