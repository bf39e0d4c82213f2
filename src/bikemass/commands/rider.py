"""``bikemass rider POSE`` and ``bikemass riders``: rider mass, centre of mass and inertia."""

FORMATS = ("table", "json", "yaml")
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
    from .bicycle import allow_off_contact_option
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
    p.add_argument("--format", choices=FORMATS, default="table", help="output format (default table)")
    p.add_argument("--as-printed", action="store_true",
                   help="use Table 3-3 as printed (errata not applied)")
    p.add_argument("--method", choices=("mesh", "exact"), default="mesh",
                   help="mass properties from trimesh meshes (default) or closed-form solids")
    p.add_argument("--overlap", choices=("sum", "union"), default="sum",
                   help="overlapping segments summed as in the thesis (default) or counted once")


def _clean(x, digits=4):
    """Float rounded for display, without a minus sign on a rounded zero."""
    return round(float(x), digits) + 0.0


def _seated(args):
    """(rider, SeatedRider or None) of ``args.pose`` (seated on ``args.bike`` if given)."""
    import warnings

    from ..errors import BikemassWarning
    from ..rider import load_rider
    if args.bike is None:
        return load_rider(args.pose, as_printed=args.as_printed), None
    from ..bicycle import load_bicycle
    from ..rider.seating import seat_rider
    seated = seat_rider(args.pose, load_bicycle(args.bike), args.as_printed, args.allow_off_contact)
    for line in seated.warnings:
        warnings.warn(line, BikemassWarning, stacklevel=2)
    return seated.rider, seated


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
    from ..errors import _shown
    from ..output import table
    rows = [(name, gap * 1000, key) for name, (gap, key) in seated.contacts.items()]
    head = (f"On {seated.bicycle.name} ({_shown(seated.bicycle.source)}): pose {seated.how}"
            + ("" if seated.solution is None else " by the chain, joint angles (deg): "
               + ", ".join(f"{k} {v:.1f}" for k, v in seated.solution.pose.angles.items())))
    return head + "\n" + table(["contact", "residual (mm)", "bicycle key"], rows, floatfmt="{:.4f}")


def run_rider(args):
    from ..output import dumps, table

    rider, seated = _seated(args)
    props = rider.properties(args.method, args.overlap)
    if args.format != "table":
        print(dumps(rider_document(rider, props, seated, args.method, args.segments), args.format), end="")
        return 0
    I = props.inertia
    lines = [f"Rider {rider.name!r} (pose {rider.pose}; method {args.method}, overlap {args.overlap}"
             f"{', as printed' if args.as_printed else ''})",
             f"mass     {props.mass:.3f} kg",
             "com      [" + ", ".join(f"{_clean(v):.4f}" for v in props.com) + "] m",
             "inertia  about the com, kg m^2 (tensor products):"]
    lines += ["         [" + ", ".join(f"{_clean(v):9.4f}" for v in row) + "]" for row in I]
    print("\n".join(lines) + "\n")
    rows = [[name, body.replace("_frame", ""), mp.mass, *(_clean(v) for v in mp.com),
             *(_clean(mp.inertia[i, j]) for i, j in ((0, 0), (1, 1), (2, 2), (0, 2)))]
            for name, body, mp in rider.breakdown(args.method)]
    print("Per segment (centre of mass in the benchmark frame; inertia about the segment's own com):")
    print(table(["segment", "frame", "mass (kg)", "x (m)", "y (m)", "z (m)",
                 "Ixx", "Iyy", "Izz", "Ixz"], rows, floatfmt="{:.4f}"), end="")
    if seated is not None and seated.contacts:
        print("\n" + _contacts_table(seated), end="")
    return 0


def run_riders(args):
    from ..output import dumps, table
    from ..rider import PUBLISHED_SUFFIX, load_rider, shipped_poses

    poses = shipped_poses()
    props = {p: load_rider(p, args.as_printed).properties(args.method, args.overlap) for p in poses}
    if args.compare:
        published = {p: load_rider(p + PUBLISHED_SUFFIX).properties("exact") for p in poses}
        if args.format != "table":
            data = {p: {"bikemass": props[p].to_dict(), "thesis": published[p].to_dict()} for p in poses}
            print(dumps(data, args.format), end="")
            return 0
        rows = []
        for p in poses:
            for label, get in TABLE_3_4_ROWS:
                ours, theirs = get(props[p]), get(published[p])
                rel = f"{_clean(100 * (ours - theirs) / abs(theirs), 3):+.3f}" if theirs else "-"
                rows.append([p, label, _clean(ours), theirs, _clean(ours - theirs), rel])
        print(table(["pose", "quantity", "bikemass", "thesis", "difference", "relative (%)"], rows,
                    floatfmt="{:.4f}"), end="")
        return 0
    if args.format != "table":
        print(dumps({p: {"pose": p, **props[p].to_dict()} for p in poses}, args.format), end="")
        return 0
    rows = [[label, *(_clean(get(props[p]), 3) for p in poses)] for label, get in TABLE_3_4_ROWS]
    print(table(["", *poses], rows), end="")
    return 0
