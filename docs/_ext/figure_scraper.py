"""sphinx-gallery image scraper for the Figures bikemass returns.

bikemass builds its figures with matplotlib's object API and never registers them with pyplot
(docs/figures.md), so sphinx-gallery's own matplotlib scraper, which asks pyplot for its open
figures, sees none. This scraper instead collects every :class:`matplotlib.figure.Figure` a code
block of the example has bound to a name (or left as its last expression) and that no earlier
block has shown, in the order they were created, and saves each as a PNG beside the example.
"""

import weakref
from pathlib import PurePosixPath

from matplotlib.figure import Figure
from sphinx_gallery.scrapers import figure_rst

DPI = 90
"""Resolution of the gallery's images (dots per inch): sharp on screen, light to build."""

_shown = weakref.WeakSet()
"""Figures already placed under an earlier block (of any example)."""


def _figures(namespace):
    """The Figures in ``namespace`` (its values, and Figures in its lists, tuples and dicts)."""
    found = []
    for value in list(namespace.values()):
        items = value.values() if isinstance(value, dict) else value if isinstance(value, (list, tuple)) else (value,)
        found += [v for v in items if isinstance(v, Figure)]
    return list(dict.fromkeys(found))


def scrape(block, block_vars, gallery_conf, **kwargs):
    """The reST of the figures a code block made (sphinx-gallery's scraper interface)."""
    namespace = dict(block_vars["example_globals"])
    new = [f for f in _figures(namespace) if f not in _shown]
    paths = []
    for fig, path in zip(new, block_vars["image_path_iterator"]):
        path = PurePosixPath(path)
        fig.savefig(path, dpi=DPI)
        _shown.add(fig)
        paths.append(path)
    if not paths:
        return ""
    titles = ", ".join(fig.get_suptitle() or "" for fig in new).strip(", ")
    return figure_rst(paths, gallery_conf["src_dir"], titles)


def _get_sg_image_scraper():
    """The scraper, for ``image_scrapers = ("figure_scraper",)`` (sphinx-gallery's interface)."""
    return scrape
