"""Figures without global state: a new :class:`Figure` (a :class:`matplotlib.figure.Figure` that
shows itself in Jupyter), the file formats matplotlib can write, and saving a figure with its
text kept as text in vector files.

No pyplot and no ``matplotlib.use``: the caller's backend and open figures are left alone.
"""

import math
import os
import struct
import textwrap
import threading
import zlib
from io import BytesIO
from pathlib import Path

import numpy as np
from matplotlib import figure, rc_context
from matplotlib.backend_bases import FigureCanvasBase
from matplotlib.layout_engine import ConstrainedLayoutEngine
from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg

from ..core.errors import InputError, short, wrong_type
from ..core.output import write_atomic

DPI = 150
"""Default resolution of raster output (dots per inch)."""
MIN_DPI, MAX_DPI = 10, 2000
"""Resolutions save_figure accepts (dots per inch; the command line's --dpi range)."""

VECTOR_TEXT = {"svg.fonttype": "none", "pdf.fonttype": 42, "ps.fonttype": 42}
"""rc settings for saving: SVG text stays <text>, PDF/PS embed TrueType (editable, searchable)."""

RENDERING = threading.Lock()
"""Held while a figure is drawn: ``rc_context`` sets matplotlib's process-wide rcParams for the
draw and restores them, and matplotlib's mathtext parser is not thread-safe (matplotlib 3.7 fails
on ``$v$`` drawn in two threads at once), so the web server's callbacks draw one at a time."""
PNG_COMPRESSION = 1
"""zlib level of the PNG files written, their rows unfiltered: an opaque eigenvalue figure (1050 x
690, written as RGB) in 9 ms and 84 kB here, where Pillow (adaptive row filters) took 17 ms for
94 kB at its level 1 and matplotlib's own writer (RGBA, level 6) 48 ms."""
RENDERERS: dict[tuple, object] = {}
"""``{(width px, height px, dpi): RendererAgg}``: the Agg renderers raster figures are drawn with,
one per canvas size and kept (at most :data:`MAX_RENDERERS`), used only while :data:`RENDERING` is
held. matplotlib keys its caches of text measures and parsed mathtext on the renderer, and makes a
new renderer for every figure saved; drawn with a kept renderer, the next figure of that size finds
its tick labels, axis labels and mathtext measured already (a study's eigenvalue figure: 98 against
117 ms to draw with constrained layout, 70 against 94 ms without)."""
MAX_RENDERERS = 4
"""Most renderers kept in :data:`RENDERERS` (an eigenvalue figure's: 2.9 MB of pixels)."""
UNWRITABLE = {"pgf"}
"""Formats matplotlib lists but that need outside tools (LaTeX) to write."""


DISPLAY_DPI = 100
"""Resolution (dots per inch) of the PNG a figure shows in Jupyter."""


class _KeptRendererCanvas(FigureCanvasAgg):
    """matplotlib's Agg canvas drawing with the renderer of :data:`RENDERERS` for its size, not
    a new one (matplotlib's canvas clears the pixels before each draw)."""

    def get_renderer(self):
        width, height = self.get_width_height(physical=True)
        key = width, height, self.figure.dpi
        if self._lastKey != key:
            self.renderer, self._lastKey = _kept_renderer(*key), key
        return self.renderer


def _kept_renderer(width, height, dpi):
    """The renderer of :data:`RENDERERS` for a ``width`` x ``height`` pixel canvas at ``dpi``
    (made, and the oldest dropped beyond :data:`MAX_RENDERERS`, if missing); hold :data:`RENDERING`."""
    key = width, height, dpi
    if key not in RENDERERS:
        while len(RENDERERS) >= MAX_RENDERERS:
            RENDERERS.pop(next(iter(RENDERERS)))
        RENDERERS[key] = RendererAgg(width, height, dpi)
    return RENDERERS[key]


class Figure(figure.Figure):
    """A :class:`matplotlib.figure.Figure` that displays itself in Jupyter without ``%matplotlib inline``.

    bikemass never registers its figures with pyplot (that would change the caller's state), so
    IPython knows them only through this class's ``_repr_png_``: the figure drawn by matplotlib's
    Agg canvas at :data:`DISPLAY_DPI`, on demand. Everything else is matplotlib's Figure: save it,
    change its axes, or give it to ``pyplot`` as usual.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_eigenvalues(bm.stability(bm.parameters("benchmark")))
    >>> print(isinstance(fig, bm.Figure), len(fig.axes) >= 1)
    True True
    """

    def _repr_png_(self):
        """The figure as PNG bytes (IPython's rich display)."""
        return figure_bytes(self, "png", DISPLAY_DPI)


MAX_INCHES = 1000.0
"""Largest figure side accepted (inches)."""
MAX_PIXELS = 200_000_000
"""Most pixels of a raster figure written (width x height at its dpi): about 800 MB of RGBA."""


def _pair(value, what, expected, ok):
    """``value`` as a tuple of two finite floats passing ``ok(a, b)``, else InputError."""
    try:
        a, b = (float(x) for x in value)
    except (TypeError, ValueError):
        raise InputError(what, short(value), expected) from None
    if not (math.isfinite(a) and math.isfinite(b) and ok(a, b)):
        raise InputError(what, short(value), expected)
    return a, b


def check_limits(limits, what):
    """Axis limits ``(low, high)`` (two finite, different numbers) or ``None``; InputError otherwise."""
    if limits is None:
        return None
    return _pair(limits, what, "axis limits (low, high): two finite, different numbers", lambda a, b: a != b)


def new_figure(size):
    """An empty :class:`Figure` of ``size`` = (width, height) in inches
    (each above 0 and at most :data:`MAX_INCHES`), laid out by matplotlib's constrained layout."""
    size = _pair(size, "size", f"a figure size (width, height) in inches, each in (0, {MAX_INCHES:g}]",
                 lambda a, b: 0 < a <= MAX_INCHES and 0 < b <= MAX_INCHES)
    return Figure(figsize=size, layout="constrained")


def figure_formats():
    """``{suffix: description}`` of the image formats a figure can be saved as."""
    return {k: v for k, v in FigureCanvasBase.get_supported_filetypes().items() if k not in UNWRITABLE}


def figure_format(path):
    """The format of figure file ``path`` from its suffix; InputError (a ValueError) naming the
    formats if unknown."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in figure_formats():
        raise InputError(path, "(figure file)", "an image file name ending in "
                         + ", ".join(f".{k}" for k in sorted(figure_formats())))
    return suffix


TITLE_MARGIN = 8.0
"""Points kept free between a title and the figure's edge."""


def _titles(fig):
    """Every title text of ``fig``: its suptitle and each axes' centre, left and right titles."""
    texts = [fig._suptitle] if getattr(fig, "_suptitle", None) is not None else []
    for ax in fig.axes:
        texts += [ax.title, getattr(ax, "_left_title", None), getattr(ax, "_right_title", None)]
    return [t for t in texts if t is not None and t.get_visible() and t.get_text().strip()]


def _room(text, box, width):
    """Width (pixels) ``text`` may take on a figure ``width`` pixels wide where it now spans
    ``box``: all of it less the margins, kept about the text's anchor (centred, left or right)."""
    align = text.get_horizontalalignment()
    if align == "center":
        centre = (box.x0 + box.x1) / 2
        return 2 * min(centre, width - centre)
    return width - box.x0 if align == "left" else box.x1


EARLY_FIT = 0.8
"""A title narrower than this share of the room its axes' place gives it before layout is taken
to fit without laying the figure out (constrained layout moves an axes' centre by a few per cent)."""


def _fits_before_layout(text, renderer, fig, margin):
    """Whether ``text`` surely fits: its width (which layout does not change) well inside the room
    its anchor leaves as placed before layout (a suptitle: the figure's centre; an axes title: the
    axes' centre, left or right edge as the title is aligned)."""
    width = text.get_window_extent(renderer).width
    whole = fig.bbox.width
    axes = getattr(text, "axes", None)
    box = axes.get_position() if axes is not None and text is not getattr(fig, "_suptitle", None) else None
    align = text.get_horizontalalignment()
    if box is None:
        room = whole - 2 * margin
    elif align == "left":
        room = (1 - box.x0) * whole - margin
    elif align == "right":
        room = box.x1 * whole - margin
    else:
        room = 2 * min(box.x0 + box.x1, 2 - box.x0 - box.x1) / 2 * whole - 2 * margin
    return width <= EARLY_FIT * room


def fit_titles(fig: figure.Figure) -> list:
    """Wrap every title of ``fig`` (suptitle, axes titles) that is wider than the figure at its
    place, at spaces, into as few lines as fit; return the texts changed.

    A long bicycle name in a title would otherwise run past the figure's edge and be cut off in
    the file. Constrained layout makes room for the extra lines when the figure is drawn. Called
    by :func:`figure_bytes` (every saved or displayed figure); harmless to call again."""
    return _fit_titles(fig, RendererAgg)


def _fit_titles(fig, make_renderer):
    """:func:`fit_titles`, measuring with ``make_renderer(width px, height px, dpi)``."""
    titles = _titles(fig)
    if not titles:
        return []
    renderer = make_renderer(max(1, int(fig.bbox.width)), max(1, int(fig.bbox.height)), fig.dpi)
    margin = TITLE_MARGIN * fig.dpi / 72
    if all(_fits_before_layout(text, renderer, fig, margin) for text in titles):
        return []                                  # the common case, without laying the figure out
    fig.draw_without_rendering()                   # lays the figure out: titles at their places
    changed = []
    for text in titles:
        lines = text.get_text().split("\n")
        box = text.get_window_extent(renderer)
        room = _room(text, box, fig.bbox.width) - 2 * margin
        if box.width <= room:
            continue
        columns = max(map(len, lines))
        while columns > 8 and text.get_window_extent(renderer).width > room:
            columns = max(8, int(columns * 0.9))
            text.set_text("\n".join("\n".join(textwrap.wrap(line, columns, break_on_hyphens=False)) or line
                                     for line in lines))
        changed.append(text)
    return changed


def figure_bytes(fig, fmt="png", dpi=DPI):
    """``fig`` rendered as ``fmt`` (bytes); text stays text in SVG and PDF."""
    width, height = fig.get_size_inches()
    if fmt not in ("pdf", "svg", "svgz", "eps", "ps") and width * height * dpi * dpi > MAX_PIXELS:
        raise InputError("dpi", dpi, f"a figure of at most {MAX_PIXELS} pixels ({width:g} x {height:g} in at "
                         f"{dpi:g} dpi is {width * height * dpi * dpi:.3g})")
    with RENDERING, rc_context(VECTOR_TEXT):
        _fit_titles(fig, _kept_renderer)
        if fmt == "png":
            return _png(_rgba(fig, dpi), fig, dpi)
        buffer = BytesIO()
        fig.savefig(buffer, format=fmt, dpi=dpi)
    return buffer.getvalue()


def _rgba(fig, dpi):
    """``fig`` drawn at ``dpi`` by a :class:`_KeptRendererCanvas`: RGBA bytes."""
    canvas, buffer = fig.canvas, BytesIO()
    _KeptRendererCanvas(fig)                       # attaches itself to fig for this drawing
    try:
        fig.savefig(buffer, format="rgba", dpi=dpi)
    finally:
        fig.set_canvas(canvas)                     # the caller's canvas back (drawn later without the lock)
    return buffer.getvalue()


def _decorations(fig, renderer):
    """Per axes of ``fig``: how far (pixels: left, bottom, right, top) its labels, ticks, legend
    and texts reach past its box, as constrained layout measures them."""
    out = []
    for ax in fig.axes:
        tight, box = ax.get_tightbbox(renderer, for_layout_only=True), ax.bbox
        out.append((0.0,) * 4 if tight is None else
                   (box.x0 - tight.x0, box.y0 - tight.y0, tight.x1 - box.x1, tight.y1 - box.y1))
    return tuple(out)


def _plain(fig):
    """Whether ``fig`` is laid out by constrained layout and holds only subplots (no suptitle,
    figure texts or legends, colorbars or insets): what a kept layout can place."""
    return (isinstance(fig.get_layout_engine(), ConstrainedLayoutEngine) and not fig.legends and not fig.texts
            and getattr(fig, "_suptitle", None) is None and getattr(fig, "_supxlabel", None) is None
            and getattr(fig, "_supylabel", None) is None
            and all(ax.get_subplotspec() is not None and not hasattr(ax, "_colorbar") for ax in fig.axes))


def _edges_clear(rgba, fig, dpi, pads):
    """Whether nothing is drawn within ``pads`` = (left, bottom, right, top) inches of the edges of
    ``fig``'s pixels ``rgba`` drawn at ``dpi``: those four bands all one colour (the figure's face).

    A label, tick label, legend or title cut at an edge, or reaching into the padding beside it,
    leaves ink there. (Something drawn wholly beyond the edge leaves none; but what sits outside
    an axes is anchored at the axes and drawn outwards, so the text nearer the axes is cut first.)"""
    width, height = _canvas_size(len(rgba) // 4, *(inches * dpi for inches in fig.get_size_inches()))
    pixels = np.frombuffer(rgba, np.uint32).reshape(height, width)
    left, bottom, right, top = (max(1, math.ceil(pad * dpi)) for pad in pads)
    face = pixels[0, 0]
    return all(bool((band == face).all()) for band in
               (pixels[:, :left], pixels[height - bottom:], pixels[:, width - right:], pixels[:top]))


def _reach(fig, dpi, pixels):
    """How far (inches: left, bottom, right, top) the labels, ticks, legend and texts of ``fig``'s
    one axes reach past its box, measured at ``dpi`` on the kept renderer of its ``pixels`` =
    (columns, rows), as it was drawn (:func:`_decorations`)."""
    dpi_before = fig.dpi
    fig.set_dpi(dpi)                               # as savefig draws it (then puts the figure's back)
    try:
        return tuple(r / dpi for r in _decorations(fig, _kept_renderer(*pixels, dpi))[0])
    finally:
        fig.set_dpi(dpi_before)


def _placed(fig, margins):
    """Put ``fig``'s one axes ``margins`` = (left, bottom, right, top) inches from its edges;
    False (nothing moved) if they leave no room."""
    width, height = fig.get_size_inches()
    left, bottom, right, top = margins
    if left + right >= width or bottom + top >= height:
        return False
    fig.axes[0].set_position([left / width, bottom / height, 1 - (left + right) / width, 1 - (bottom + top) / height])
    return True


def png_bytes(fig, dpi=DPI, margins=None):
    """``fig`` as PNG bytes, as :func:`figure_bytes`; with ``margins``, at a layout fixed in advance.

    Constrained layout measures every label of a figure in a drawing pass of its own before the
    figure is drawn, and its solver places the axes (a fifth to a third of drawing a study
    figure). With ``margins`` = (left, bottom, right, top) in inches, a figure of one subplot (no
    suptitle, figure legend or text) is drawn once with its axes that far from the figure's edges,
    and its pixels looked at: if nothing is drawn within the padding constrained layout keeps at
    each edge (``w_pad``, ``h_pad``), that is the figure. Otherwise its labels, ticks, legend and
    texts are measured (as constrained layout measures them), the margins they need more room at
    are widened to it (reach plus padding) and the figure drawn again (and once more, measured
    again, if a text placed at a data point moved outwards as the axes narrowed); only if that
    fails too is it laid out by constrained layout. So every figure fits as constrained layout would fit it,
    and figures of one kind given the same margins have their axes at the same place where their
    labels fit in them.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure (laid out by constrained layout, as :func:`new_figure` makes them).
    dpi : float
        Resolution (dots per inch).
    margins : tuple of float, optional
        (left, bottom, right, top) in inches from the figure's edges to its axes; ``None``:
        constrained layout.

    Returns
    -------
    bytes
        The PNG file's content.

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.plots.figure import png_bytes
    >>> fig = bm.plot_eigenvalues(bm.eigenvalues(bm.parameters("benchmark")))
    >>> png_bytes(fig, 100, margins=(0.8, 0.6, 2.0, 0.4))[:8]
    b'\\x89PNG\\r\\n\\x1a\\n'
    """
    width, height = fig.get_size_inches()
    if width * height * dpi * dpi > MAX_PIXELS:
        return figure_bytes(fig, "png", dpi)      # the error, as figure_bytes words it
    with RENDERING, rc_context(VECTOR_TEXT):
        _fit_titles(fig, _kept_renderer)
        engine = fig.get_layout_engine()
        if margins is not None and len(fig.axes) == 1 and _plain(fig):
            pads = engine.get()
            pads = (pads["w_pad"], pads["h_pad"]) * 2                  # inches: left, bottom, right, top
            fig.set_layout_engine(None)
            for _ in range(3):                     # the kind's margins, then those the labels need (twice:
                                                   # a text at a data point moves as the axes narrow)
                if fig.get_layout_engine() is not None or not _placed(fig, margins):
                    break
                rgba = _rgba(fig, dpi)
                if _edges_clear(rgba, fig, dpi, pads):
                    return _png(rgba, fig, dpi)
                reach = _reach(fig, dpi, _canvas_size(len(rgba) // 4, width * dpi, height * dpi))
                margins = tuple(max(m, r + p) for m, r, p in zip(margins, reach, pads))
            fig.set_layout_engine(engine)          # labels wider than the margins: laid out for themselves
            fig.axes[0].set_in_layout(True)        # (set_position took the axes out of the layout)
        rgba = _rgba(fig, dpi)
    return _png(rgba, fig, dpi)


def _png(rgba, fig, dpi):
    """PNG of the raw RGBA pixels matplotlib drew of ``fig`` at ``dpi``: RGB where every pixel
    is opaque (no alpha channel to store), else RGBA; no row filter, zlib at
    :data:`PNG_COMPRESSION`; the resolution in a ``pHYs`` chunk."""
    width, height = _canvas_size(len(rgba) // 4, *(inches * dpi for inches in fig.get_size_inches()))
    opaque = bool((np.frombuffer(rgba, "<u4") >= 0xFF000000).all())       # alpha, the last byte, 255
    channels = 3 if opaque else 4
    rows = np.zeros((height, 1 + width * channels), np.uint8)            # a 0 (no filter) before each row
    rows[:, 1:].reshape(height, width, channels)[...] = np.frombuffer(rgba, np.uint8).reshape(
        height, width, 4)[:, :, :channels]
    per_metre = int(dpi / 0.0254 + 0.5)
    return b"".join([b"\x89PNG\r\n\x1a\n",
                     _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2 if opaque else 6, 0, 0, 0)),
                     _chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1)),
                     _chunk(b"IDAT", zlib.compress(rows, PNG_COMPRESSION)), _chunk(b"IEND", b"")])


def _chunk(kind, data):
    """A PNG chunk: length, type, data, CRC-32 of type and data."""
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def _canvas_size(pixels, width, height):
    """The whole numbers of pixels (columns, rows) next to ``width`` x ``height`` whose product is
    ``pixels``: the size of the canvas matplotlib drew (its rounding of inches x dpi)."""
    for columns in sorted({math.floor(width), math.ceil(width)}):
        for rows in sorted({math.floor(height), math.ceil(height)}):
            if columns * rows == pixels:
                return columns, rows
    raise ValueError(f"a {pixels}-pixel canvas is not {width:g} x {height:g}")


def save_figure(fig: figure.Figure, path: "str | os.PathLike", dpi: float = DPI) -> None:
    """Write a figure to a file, its format from the suffix, atomically: never half-written.

    Vector formats keep their text as text (SVG ``<text>``, TrueType in PDF and PS), set for this
    saving only (``matplotlib.rc_context``), never in the global ``rcParams``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        Any figure (bikemass's or your own).
    path : str or os.PathLike
        The file; its suffix picks the format: anything matplotlib writes (``.png``, ``.pdf``,
        ``.svg``, ...).
    dpi : float
        Resolution of raster output (dots per inch), 10 to 2000.

    Returns
    -------
    None

    Raises
    ------
    InputError
        A suffix matplotlib cannot write, a ``dpi`` out of range, a raster image of more than
        200 million pixels, or a file that cannot be written.
    InputTypeError
        ``fig`` not a Figure.

    See Also
    --------
    plot_eigenvalues, plot_side_view : Figures to save.

    Examples
    --------
    >>> import os, tempfile
    >>> import bikemass as bm
    >>> fig = bm.plot_eigenvalues(bm.eigenvalues(bm.parameters("benchmark")))
    >>> path = os.path.join(tempfile.mkdtemp(), "eigenvalues.svg")
    >>> bm.save_figure(fig, path)
    >>> open(path).read().count("<text") > 0           # the labels stay text
    True
    """
    if not isinstance(fig, figure.Figure):
        raise wrong_type("fig", fig, "a matplotlib Figure")
    if isinstance(dpi, bool) or not isinstance(dpi, (int, float)) or not MIN_DPI <= dpi <= MAX_DPI:
        raise InputError("dpi", dpi, f"a resolution in dots per inch, {MIN_DPI} to {MAX_DPI}")
    write_atomic(path, figure_bytes(fig, figure_format(path), dpi))
