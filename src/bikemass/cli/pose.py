"""``bikemass pose BIKE``: a rider posed by joint angles on a bicycle's contacts;
``bikemass pose-fit``: the thesis poses against their closest joined-up chain poses."""

import warnings
from argparse import ArgumentTypeError

from ..core.choices import Grip
from ..core.errors import BikemassWarning, InputError
from . import dialect
from .options import angle
from .sizes import add_size_option, every_size

JOINT_HELP = "torso_lean, neck, shoulder, elbow, hip, knee"


def register(sub):
    p = sub.add_parser("pose", help="pose a rider by joint angles on a bicycle (hips, hands, feet)",
                       description="Solve the rider's joint angles (scipy least squares) so that the hips "
                                   "sit on the saddle, the hands on a grip and the feet on the pedals "
                                   "of BIKE's contacts: section; write the pose in the placement form "
                                   "(docs/poses.md).")
    dialect.add_bike(p, "shipped bicycle name or bicycle YAML file with contacts:")
    p.add_argument("--body", default="thesis_rider", help="anthropometry with joints: (default thesis_rider)")
    p.add_argument("--torso-lean", type=angle(180), metavar="DEG",
                   help="fix the torso lean from vertical (deg, forward positive); default: solved "
                        "with the elbows bent 20 deg")
    p.add_argument("--hands", choices=Grip.values(), help="grip of the bicycle (default hoods, else its first grip)")
    p.add_argument("--crank", type=angle(360), metavar="DEG",
                   help="crank angle (deg, 0 = right crank forward, positive pedalling); each foot on "
                        "its pedal.  Default: symmetric legs, feet on the crank axis (as the thesis)")
    p.add_argument("--feet", choices=("ball", "bicycleparameters"), default="ball",
                   help="the point of the lower leg on the crank axis or pedal: ball (the ball of the foot, "
                        "default) or bicycleparameters (BicycleParameters' seating of a yeadon body: the "
                        "shank's line at the heel's level, the foot beyond; docs/riders.md)")
    p.add_argument("--fix", action="append", default=[], metavar="JOINT=DEG",
                   help=f"fix any joint angle ({JOINT_HELP}); repeatable")
    p.add_argument("--name", help="pose name written to the file")
    dialect.add_output(p, what="the report (table) or the solved pose (yaml or json: a placement-form "
                               "pose file, docs/poses.md)")
    dialect.add_plot(p, "the side view of the posed rider on the bicycle", "x forward, m", "height, m")
    add_size_option(p, "--bike-size")
    p.set_defaults(run=every_size(run_pose, many=False))
    f = sub.add_parser("pose-fit", help="thesis poses vs their closest joined-up chain poses",
                       description="For each placement pose, fit the chain's joint angles and hip position "
                                   "(least squares on the segment ends), then compare the joint gaps, the "
                                   "rider's mass properties and BIKE's weave and capsize speeds.")
    f.add_argument("poses", nargs="*", metavar="POSE", help="placement poses (default: the five thesis poses)")
    f.add_argument("--bike", default="jamis-thesis", help="bicycle for the speeds (default jamis-thesis)")
    dialect.add_combine(f)
    dialect.add_output(f, what="the comparison")
    f.set_defaults(run=run_fit)


def _fixed(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..rider.chain import JOINTS
    fixed = {}
    for item in args.fix:
        joint, _, value = item.partition("=")
        if joint not in JOINTS:
            raise InputError("--fix", item, f"JOINT=DEG with JOINT one of {JOINT_HELP}")
        try:
            fixed[joint] = angle(360)(value)
        except ArgumentTypeError:
            raise InputError("--fix", item, "JOINT=DEG with DEG a number of degrees in [-360, 360]") from None
    if args.torso_lean is not None:
        fixed["torso_lean"] = args.torso_lean
    return fixed


def _report(solution, gaps, hands, crank):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import as_written, table
    from ..rider.chain import JOINTS
    pose = solution.pose
    legs = "symmetric legs, feet on the crank axis" if crank is None else f"crank {crank:g} deg"
    order = sorted(pose.angles, key=lambda j: (JOINTS.index(j.replace("_left", "")), j))
    rows = [(j.replace("_", " "), pose.angles[j], "solved" if j in solution.free else "fixed") for j in order]
    lines = [f"Chain pose: hands {hands}, {legs}; hip joints at x = {pose.root[0]:.4f} m, "
             f"z = {pose.root[1]:.4f} m", "", table(("joint", "angle (deg)", ""), rows, "{:.2f}")]
    rows = [(t.name, t.target[0], t.target[1], as_written(solution.residuals[t.name], "m") * 1000, t.key)
            for t in solution.targets]
    lines += [table(("contact", "x (m)", "z (m)", "residual (mm)", "bicycle key"), rows, "{:.4f}"),
              f"largest gap at a joint: {as_written(max(gaps.values()), 'm') * 1000:.4f} mm"]
    return "\n".join(lines)


def run_pose(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.posing import pose_rider

    options = dialect.figure_checked(args)
    posed = pose_rider(args.bike, args.body, args.hands, args.crank, _fixed(args), args.name, args.feet)
    dialect.emit(args, lambda fmt: _pose_text(args, posed, fmt))
    if args.plot:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..plots.pose import plot_pose
        fig = plot_pose(posed.bicycle, posed.rider, posed.solution, f"{posed.rider.name}: chain pose",
                        options.size, **options.limits())
        dialect.save_plot(args, fig, options)
    return 0


def _pose_text(args, posed, fmt):
    """The report (table, csv) or the placement-form pose file (yaml, json; read back by load_rider)."""
    solution, hands = posed.solution, posed.hands
    if fmt == "table":
        return _report(solution, posed.gaps, hands, args.crank) + "\n"
    if fmt == "csv":
        angles = solution.pose.angles
        return dialect.csv_text(["joint", "angle (deg)", "solved"],
                                [[j, angles[j], j in solution.free] for j in angles])
    # lazy: the library loads numpy; bikemass --help must not
    from ..rider.pose import POSE_UNITS
    text = dialect.document(posed.placement, fmt, POSE_UNITS)
    if fmt == "json":
        return text
    header = "".join(f"# {line}\n" for line in (
        f"Chain pose written by: bikemass pose {args.bike} --hands {hands}"
        + (f" --body {args.body}" if args.body != "thesis_rider" else "")
        + (f" --torso-lean {args.torso_lean:g}" if args.torso_lean is not None else "")
        + (f" --crank {args.crank:g}" if args.crank is not None else "")
        + (f" --feet {args.feet}" if args.feet != "ball" else "")
        + "".join(f" --fix {fixed}" for fixed in args.fix),
        "joint angles (deg): " + ", ".join(f"{k} {v:.3f}" for k, v in sorted(solution.pose.angles.items())),
        "placement form (docs/riders.md): location = top-plane centre (m), angle (deg)"))
    return header + text


FIT_UNITS = {"plane_gaps": "m", "fit_rms": "m", "fit_max": "m", "chain_gap": "m", "weave_speed": "m/s",
             "capsize_speed": "m/s", "com_change": "m", "inertia_change": "kg m^2", "hip_joints": "m",
             "angles": "deg"}
"""Units of the keys of a ``pose-fit`` record (:func:`_fit_record`)."""


def run_fit(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..rider import THESIS_POSES
    from ..study.thesis_fit import compare_with_chain

    fits = {}
    for pose in args.poses or THESIS_POSES:
        r = compare_with_chain(pose, args.bike, args.combine)
        for line in r["warnings"]:
            warnings.warn(f"{pose} chain fit: {line}", BikemassWarning, stacklevel=2)
        fits[pose] = r
    dialect.emit(args, lambda fmt: _fit_text(args, fits, fmt))
    return 0


def _fit_record(r):
    """The ``pose-fit`` result of one pose as plain data (SI, degrees)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..study.thesis_fit import first

    t, c = r["thesis"], r["fitted"]
    (wt, tc), (wc, cc) = ((first(w), first(c)) for w, c in (r["speeds"]["thesis"], r["speeds"]["chain"]))
    return {"plane_gaps": dict(r["plane_gaps"]), "fit_rms": r["rms"], "fit_max": r["max"],
            "chain_gap": max(r["chain_gaps"].values()),
            "weave_speed": {"placement": wt, "chain": wc}, "capsize_speed": {"placement": tc, "chain": cc},
            "hip_joints": list(r["chain"].root), "angles": dict(r["chain"].angles),
            "com_change": (c.com - t.com).tolist(), "inertia_change": (c.inertia - t.inertia).tolist()}


def _fit_text(args, fits, fmt):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import as_written, table
    from ..rider.chain import JOINTS

    records = {pose: _fit_record(r) for pose, r in fits.items()}
    if fmt in ("json", "yaml"):
        return dialect.document({"bike": args.bike, "combine": args.combine, "poses": records}, fmt, FIT_UNITS)
    rows, props, angles = [], [], []
    for pose, f in records.items():
        g, (wt, wc), (tc, cc) = f["plane_gaps"], f["weave_speed"].values(), f["capsize_speed"].values()
        rows.append((pose, g["elbow"] * 1000, g["knee"] * 1000, g["hip"] * 1000, f["fit_rms"] * 1000,
                     f["fit_max"] * 1000, f"{as_written(f['chain_gap'], 'm'):.1e}", wt, wc, wc - wt, tc, cc, cc - tc))
        angles.append((pose, *f["hip_joints"], *(f["angles"][j] for j in JOINTS)))
        t, c = fits[pose]["thesis"], fits[pose]["fitted"]
        d, dI = f["com_change"], f["inertia_change"]
        props.append((pose, d[0] * 1000, d[2] * 1000, *(dI[i][j] for i, j in ((0, 0), (1, 1), (2, 2), (0, 2))),
                      *(100 * (c.inertia[i, i] / t.inertia[i, i] - 1) for i in range(3))))
    headers = ("pose", "elbow", "knee", "hip*", "fit rms", "fit max", "chain gap",
               "weave", "chain", "change", "capsize", "chain", "change")
    if fmt == "csv":
        return dialect.csv_text(["pose", "elbow gap (mm)", "knee gap (mm)", "hip gap (mm)", "fit rms (mm)",
                                 "fit max (mm)", "chain gap (m)", "weave (m/s)", "chain weave (m/s)",
                                 "change (m/s)", "capsize (m/s)", "chain capsize (m/s)", "change (m/s)"], rows)
    return "\n".join([
        f"Placement poses vs closest chain poses; speeds of {args.bike} (combine {args.combine})",
        "Gaps of the placement pose in the x-z plane (mm): elbow, knee, and hip* from the chain's assumed "
        "hip joint (bodies/thesis_rider.yaml joints.hip); fit: distances of the segment ends (mm); "
        "largest gap of the chain pose (m); critical speeds (m/s)",
        table(headers, rows, "{:.3f}"),
        "Closest chain poses: hip joints (m) and joint angles (deg)",
        table(("pose", "hip x", "hip z", *(j.replace("_", " ") for j in JOINTS)), angles, "{:.3f}"),
        "Rider mass properties, chain minus placement pose (CoM in mm, inertia in kg m^2, % of the pose's)",
        table(("pose", "dx", "dz", "dIxx", "dIyy", "dIzz", "dIxz", "Ixx %", "Iyy %", "Izz %"), props, "{:+.3f}"),
    ]) + "\n"
