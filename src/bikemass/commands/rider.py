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


def run_rider(args):
    from ..output import dumps, table
    from ..rider import load_rider

    rider = load_rider(args.pose, as_printed=args.as_printed)
    props = rider.properties(args.method, args.overlap)
    if args.format != "table":
        print(dumps({"pose": rider.pose, **props.to_dict()}, args.format), end="")
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
