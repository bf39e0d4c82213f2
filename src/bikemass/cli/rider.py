"""``bikemass rider POSE`` and ``bikemass riders``: rider mass, centre of mass and inertia."""

import warnings

from ..core.choices import Overlap
from ..core.errors import BikemassWarning, shown
from . import dialect
from .bicycle import allow_off_contact_option

TABLE_3_4_ROWS = (("mass (kg)", lambda p: p.mass),
                  ("x (m)", lambda p: p.com[0]), ("y (m)", lambda p: p.com[1]),
                  ("z (m)", lambda p: p.com[2]),
                  ("Ixx (kg m^2)", lambda p: p.inertia[0, 0]), ("Ixz (kg m^2)", lambda p: p.inertia[0, 2]),
                  ("Iyy (kg m^2)", lambda p: p.inertia[1, 1]), ("Izz (kg m^2)", lambda p: p.inertia[2, 2]))
"""The rows of the thesis's Table 3-4 (Ixy = Iyz = 0 for a symmetric rider)."""


def register(sub):
    one = sub.add_parser("rider", help="mass, centre of mass and inertia of a rider pose",
                         description="Mass properties of a rider: a shipped pose (no-hands, relaxed, "
                                     "on-hoods, aerobars, aero-tuck; <pose>-thesis = the published "
                                     "Table 3-4 rider) or a pose YAML file (docs/riders.md).")
    one.add_argument("pose", metavar="POSE", help="shipped pose name or pose YAML file")
    one.add_argument("--bike", metavar="BIKE",
                     help="seat the rider on this bicycle (its contacts: section) and report the contacts")
    one.add_argument("--segments", action="store_true",
                     help="json/yaml: add each segment's mass, centre of mass and inertia")
    allow_off_contact_option(one)
    _common_options(one)
    one.set_defaults(run=run_rider)
    many = sub.add_parser("riders", help="Table 3-4 style table of all shipped poses",
                          description="Mass properties of all shipped rider poses, as Table 3-4 of "
                                      "Williams (2015); --compare sets them against the published table.")
    _common_options(many)
    many.add_argument("--compare", action="store_true",
                      help="compare each pose with its published Table 3-4 rider (<pose>-thesis)")
    many.set_defaults(run=run_riders)


def _common_options(p):
    dialect.add_output(p)
    p.add_argument("--as-printed", action="store_true",
                   help="use Table 3-3 as printed (errata not applied; see docs/thesis.md)")
    dialect.add_method(p)
    p.add_argument("--overlap", choices=Overlap.values(), default=Overlap.SUM.value,
                   help="overlapping segments summed as in the thesis (default) or counted once")


def _clean(x, digits=4):
    """Float rounded for display (after :func:`bikemass.core.output.as_shown`), without a minus sign
    on a rounded zero."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import as_shown
    return round(as_shown(x), digits) + 0.0


def _seated(args):
    """(rider, SeatedRider or None) of ``args.pose`` (seated on ``args.bike`` if given)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..rider import load_rider
    if args.bike is None:
        return load_rider(args.pose, as_printed=args.as_printed), None
    # lazy: the library loads numpy; bikemass --help must not
    from ..bicycle import load_bicycle
    from ..rider.seating import seat_rider
    seated = seat_rider(args.pose, load_bicycle(args.bike), args.as_printed, args.allow_off_contact)
    for line in seated.warnings:
        warnings.warn(line, BikemassWarning, stacklevel=2)
    return seated.rider, seated


def rider_units():
    """Units of :func:`rider_document`'s keys: a :class:`~bikemass.mass.inertia.MassProperties`'
    declared ones and the contacts' residual (m)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.results import declared_units
    from ..mass.inertia import MassProperties
    return {**declared_units(MassProperties), "residual": "m"}


def rider_document(rider, props, seated, method, segments):
    """``{pose, mass, com, inertia}`` + ``segments: {name: {mass, com, inertia}}`` (if ``segments``)
    + ``contacts: {name: {residual}}`` (m, if seated on a bicycle)."""
    data = {"pose": rider.pose, **props.to_dict()}
    if segments:
        data["segments"] = {name: mp.to_dict() for name, _, mp in rider.breakdown(method)}
    if seated is not None:
        data["contacts"] = {name: {"residual": gap} for name, gap in seated.residuals().items()}
    return data


def _contacts_table(seated):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import as_written, table
    rows = [(name, as_written(gap, "m") * 1000, key) for name, (gap, key) in seated.contacts.items()]
    head = (f"On {seated.bicycle.name} ({shown(seated.bicycle.source)}): pose {seated.how}"
            + ("" if seated.solution is None else " by the chain, joint angles (deg): "
               + ", ".join(f"{k} {v:.1f}" for k, v in seated.solution.pose.angles.items())))
    return head + "\n" + table(["contact", "residual (mm)", "bicycle key"], rows, floatfmt="{:.4f}")


def run_rider(args):
    rider, seated = _seated(args)
    props = rider.properties(args.method, args.overlap)
    dialect.emit(args, lambda fmt: _rider_text(args, rider, props, seated, fmt))
    return 0


SEGMENT_HEADERS = ["segment", "frame", "mass (kg)", "x (m)", "y (m)", "z (m)", "Ixx", "Iyy", "Izz", "Ixz"]


def _rider_text(args, rider, props, seated, fmt):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    if fmt in ("json", "yaml"):
        return dialect.document(rider_document(rider, props, seated, args.method, args.segments), fmt, rider_units())
    rows = [[name, body.replace("_frame", ""), mp.mass, *mp.com,
             *(mp.inertia[i, j] for i, j in ((0, 0), (1, 1), (2, 2), (0, 2)))]
            for name, body, mp in rider.breakdown(args.method)]
    if fmt == "csv":                                                    # every digit
        J = props.inertia
        total = ["total", "", props.mass, *props.com, J[0, 0], J[1, 1], J[2, 2], J[0, 2]]
        return dialect.csv_text(SEGMENT_HEADERS[:6] + [f"{h} (kg m^2)" for h in SEGMENT_HEADERS[6:]],
                                rows + [total])
    J = props.inertia
    lines = [f"Rider {rider.name!r} (pose {rider.pose}; method {args.method}, overlap {args.overlap}"
             f"{', as printed' if args.as_printed else ''})",
             f"mass     {props.mass:.3f} kg",
             "com      [" + ", ".join(f"{_clean(v):.4f}" for v in props.com) + "] m",
             "inertia  about the com, kg m^2 (tensor products):"]
    lines += ["         [" + ", ".join(f"{_clean(v):9.4f}" for v in row) + "]" for row in J]
    text = ("\n".join(lines) + "\n\n"
            "Per segment (centre of mass in the benchmark frame; inertia about the segment's own com):\n"
            + table(SEGMENT_HEADERS, [r[:2] + [_clean(v) for v in r[2:]] for r in rows], floatfmt="{:.4f}"))
    if seated is not None and seated.contacts:
        text += "\n" + _contacts_table(seated)
    return text


def run_riders(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..rider import PUBLISHED_SUFFIX, load_rider, shipped_poses

    poses = shipped_poses()
    props = {p: load_rider(p, args.as_printed).properties(args.method, args.overlap) for p in poses}
    if args.compare:
        published = {p: load_rider(p + PUBLISHED_SUFFIX).properties("exact") for p in poses}
        dialect.emit(args, lambda fmt: _comparison_text(poses, props, published, fmt))
    else:
        dialect.emit(args, lambda fmt: _riders_text(poses, props, fmt))
    return 0


def _comparison_text(poses, props, published, fmt):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    if fmt in ("json", "yaml"):
        return dialect.document({"riders": {p: {"bikemass": props[p].to_dict(), "thesis": published[p].to_dict()}
                                            for p in poses}}, fmt, rider_units())
    rows = []
    for p in poses:
        for label, get in TABLE_3_4_ROWS:
            ours, theirs = get(props[p]), get(published[p])
            rel = _clean(100 * (ours - theirs) / abs(theirs), 3) if theirs else None
            rows.append([p, label, _clean(ours), theirs, _clean(ours - theirs), rel])
    headers = ["pose", "quantity", "bikemass", "thesis", "difference", "relative (%)"]
    if fmt == "csv":
        return dialect.csv_text(headers, rows)
    return table(headers, [r[:5] + ["-" if r[5] is None else f"{r[5]:+.3f}"] for r in rows], floatfmt="{:.4f}")


def _riders_text(poses, props, fmt):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    if fmt in ("json", "yaml"):
        return dialect.document({"riders": {p: {"pose": p, **props[p].to_dict()} for p in poses}}, fmt, rider_units())
    if fmt == "csv":
        return dialect.csv_text(["quantity", *poses], [[label, *(get(props[p]) for p in poses)]
                                                       for label, get in TABLE_3_4_ROWS])
    rows = [[label, *(_clean(get(props[p]), 3) for p in poses)] for label, get in TABLE_3_4_ROWS]
    return table(["", *poses], rows)
