"""sphinx-gallery scraper of the toolkit's figures (docs/conf.py's ``image_scrapers``).

``contact``'s ``*_figure`` functions build a :class:`matplotlib.figure.Figure` without
pyplot (no global state in the library), which sphinx-gallery's matplotlib scraper does
not see; each new one in an example's namespace is saved and shown as a pyplot figure
would be.
"""

from __future__ import annotations


def _toolkit_figures(block, block_vars, gallery_conf):
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst

    seen = block_vars.setdefault("toolkit_figures_seen", set())
    paths = []
    for value in list(block_vars["example_globals"].values()):
        if isinstance(value, Figure) and id(value) not in seen and value.canvas.manager is None:
            seen.add(id(value))
            path = next(block_vars["image_path_iterator"])
            value.savefig(path, dpi=100)
            paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


def _get_sg_image_scraper():
    """The scraper, as sphinx-gallery asks a module named in ``image_scrapers``."""
    return _toolkit_figures
