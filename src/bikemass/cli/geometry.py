"""``bikemass geometry``: the derived geometry chart of bicycles (chart or keypoints, every size)."""

from ..core.errors import InputError
from . import dialect
from .figure_options import figure_options, write_figure


def register(sub):
    p = sub.add_parser(
        "geometry", help="geometry chart of bicycles: wheelbase, trail, stack, reach, angles, ...",
        description="The geometry chart of each BIKE, whether it was written as a chart or as keypoints: "
                    "wheelbase, front centre, trail, mechanical trail, wheel flop, stack, reach, head and "
                    "seat angles, effective top tube, chainstay, BB drop and height, standover, fork offset "
                    "(definitions: docs/bicycles.md). A size run gives every size unless --size picks one. "
                    "Table and CSV in mm and degrees; JSON and YAML in metres and degrees.")
    p.add_argument("bikes", metavar="BIKE", nargs="+",
                   help="shipped bicycle name, bicycle YAML (chart or keypoints) or parameter file; "
                        "BIKE@SIZE picks one size of a size run")
    p.add_argument("--size", "--bike-size", dest="bike_size", metavar="SIZE",
                   help="the size to report of size-run files (default: every size)")
    dialect.add_output(p, what="the chart (table and csv in mm and deg; json and yaml in m and deg, "
                               "keyed by each BIKE as given; a size run: by size within it)")
    dialect.add_plot(p, "the side view of the (one) bicycle with its chart dimensions", options=False)
    p.set_defaults(run=run_geometry)


def charts(bikes, size=None):
    """``{BIKE: chart}`` or, for a size run without ``size``, ``{BIKE: {size: chart}}`` (m, deg)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..bicycle.derived_chart import derived_chart
    from ..bicycle.loader import bicycle_sizes, load_bicycle

    out = {}
    for bike in bikes:
        sizes = bicycle_sizes(bike) if size is None else ()
        if sizes:
            out[bike] = {s: derived_chart(load_bicycle(bike, s)) for s in sizes}
        else:
            out[bike] = derived_chart(load_bicycle(bike, size))
    return out


def _columns(result):
    """(column name, chart) pairs, size runs flattened to ``BIKE@SIZE``."""
    for bike, value in result.items():
        if "wheelbase" in value:
            yield bike, value
        else:
            for s, chart in value.items():
                yield f"{bike}@{s}", chart


def chart_table(result, csv=False):
    """Rows = chart keys (mm, deg), columns = bicycles."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..bicycle.derived_chart import ANGLES, CHART_ORDER
    from ..core.output import table

    columns = list(_columns(result))

    def cell(key, chart):
        v = chart[key]
        if v is None:
            return None
        return v if key in ANGLES else 1000 * v

    rows = [[key, "deg" if key in ANGLES else "mm"] + [cell(key, c) for _, c in columns] for key in CHART_ORDER]
    headers = ["quantity", "unit"] + [name for name, _ in columns]
    if csv:
        lines = [",".join(headers)] + [",".join("" if v is None else (f"{v:.3f}" if isinstance(v, float) else str(v))
                                                for v in r) for r in rows]
        return "\n".join(lines) + "\n"
    return table(headers, rows, floatfmt="{:.1f}")


def run_geometry(args):
    if args.plot and len(args.bikes) != 1:
        raise InputError("--plot", args.plot, "one BIKE to draw (got several)")
    if args.plot:
        _plot(args)
    result = charts(args.bikes, args.bike_size)

    def render(fmt):
        if fmt in ("json", "yaml"):
            # lazy: the library loads numpy; bikemass --help must not
            from ..bicycle.derived_chart import ANGLES, CHART_ORDER
            return dialect.document(result, fmt, {k: "deg" if k in ANGLES else "m" for k in CHART_ORDER})
        return chart_table(result, csv=fmt == "csv")
    dialect.emit(args, render)
    return 0


def _plot(args):
    # lazy: plots/ load matplotlib; only the figure needs it
    from ..plots.chart import plot_chart
    from ..bicycle.loader import bicycle_sizes, load_bicycle

    options = figure_options(args, args.plot)
    bike = args.bikes[0]
    sizes = bicycle_sizes(bike) if args.bike_size is None else ()
    if sizes:
        raise InputError(bike, "--size", f"one size to draw: one of {', '.join(sizes)}")
    write_figure(plot_chart(load_bicycle(bike, args.bike_size)), args.plot, options)
