"""The options of every command that draws a figure (``--size``, ``--dpi``, ``--xlim``,
``--ylim``), checked before any work, and writing the figure."""

from dataclasses import dataclass

from ..core.errors import InputError


@dataclass(frozen=True)
class FigureOptions:
    """Checked figure options: ``size`` (width, height) in inches or None for the figure's
    own, ``dpi`` of raster output, axis limits ``xlim``/``ylim`` (low, high) or None."""

    size: tuple = None
    dpi: float = 150
    xlim: tuple = None
    ylim: tuple = None

    def limits(self):
        """``{"xlim": .., "ylim": ..}`` of the limits given, as keywords for a plotting function."""
        return {k: v for k, v in (("xlim", self.xlim), ("ylim", self.ylim)) if v is not None}


def add_figure_options(parser, xlim=None, ylim=None):
    """Add ``--size`` and ``--dpi``, and ``--xlim``/``--ylim`` where their help text (what the
    axis shows, with its unit) is given."""
    group = parser.add_argument_group("figure options")
    group.add_argument("--size", metavar="W,H", help="figure width and height in inches (e.g. 7,4.5)")
    group.add_argument("--dpi", metavar="N", default="150", help="resolution of PNG output (default 150)")
    if xlim:
        group.add_argument("--xlim", metavar="LOW:HIGH", help=f"horizontal axis range: {xlim}, e.g. -1:2")
    if ylim:
        group.add_argument("--ylim", metavar="LOW:HIGH", help=f"vertical axis range: {ylim}, e.g. -1:2")


def _numbers(text, option, separator, count, expected):
    try:
        values = tuple(float(x) for x in text.split(separator))
    except ValueError:
        raise InputError(option, text, expected) from None
    if len(values) != count:
        raise InputError(option, text, expected)
    return values


def _limit(args, name):
    text = getattr(args, name, None)
    if text is None:
        return None
    expected = "LOW:HIGH, two numbers with LOW < HIGH"
    low, high = _numbers(text, f"--{name}", ":", 2, expected)
    if not low < high:
        raise InputError(f"--{name}", text, expected)
    return low, high


def figure_options(args, path):
    """:class:`FigureOptions` from parsed ``args``; InputError (one line) for a bad option or a
    figure file ``path`` whose format matplotlib cannot write.  Call before the work."""
    if path is not None:
        # lazy: plots/ load matplotlib; only a figure needs it (no path: no figure, no matplotlib)
        from ..plots.figure import figure_format
        try:
            figure_format(path)
        except ValueError as exc:
            raise InputError(path, "(figure file)", getattr(exc, "expected", str(exc))) from None
    size = None
    if getattr(args, "size", None) is not None:
        expected = "W,H: width and height in inches, both between 1 and 100"
        size = _numbers(args.size, "--size", ",", 2, expected)
        if not all(1 <= s <= 100 for s in size):
            raise InputError("--size", args.size, expected)
    dpi = _numbers(str(getattr(args, "dpi", 150)), "--dpi", ",", 1, "a resolution in dots per inch, 10 to 2000")[0]
    if not 10 <= dpi <= 2000:
        raise InputError("--dpi", args.dpi, "a resolution in dots per inch, 10 to 2000")
    return FigureOptions(size, dpi, _limit(args, "xlim"), _limit(args, "ylim"))


def write_figure(fig, path, options):
    """Save ``fig`` to ``path`` at ``options.dpi`` (atomic; text kept as text in SVG and PDF)."""
    # lazy: plots/ load matplotlib; only the figure needs it
    from ..plots.figure import save_figure
    save_figure(fig, path, options.dpi)
