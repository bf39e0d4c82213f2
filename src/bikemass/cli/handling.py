"""``bikemass tf``, ``bode``, ``simulate``, ``mode-shapes`` and ``handling``: inputs and outputs of
the bicycle, and the Hess-Moore-Hubbard rider in the loop (docs/handling.md)."""

import math

from ..core.choices import Format
from ..models.registry import BASE, MEMBERS
from . import dialect
from .bicycle import allow_off_contact_option
from .options import number
from .sizes import add_size_option, every_size

DEFAULT_FREQUENCIES = "0.1:100:1000"
STATE_SPACE_FORMATS = (*dialect.TABULAR, "mat", "npz")
"""``state-space``'s formats: the dialect's and the two binary ones (MATLAB, numpy), which need ``-o``."""
SPEED = number(0, 1000, what="a forward speed in m/s")
"""``--speed``: one forward speed (m/s)."""


def register(sub):
    tf = _command(
        sub, "tf", help="transfer function (zeros, poles, gain) from an input to an output at one speed",
        description="The transfer function G(s) = gain * prod(s - z) / prod(s - p) of the linear bicycle "
                    "from steer or roll torque to roll, steer, their rates, the heading or the lateral "
                    "position (rear contact; front-lateral: front contact), at one speed.")
    _input_output(tf)
    _data(tf, "the zeros, poles and gain")
    dialect.add_control(tf)
    tf.set_defaults(run=every_size(run_tf))

    bode = _command(
        sub, "bode", help="frequency response (magnitude in dB, phase in degrees) and the Bode plot",
        description="The frequency response G(jw) = C (jwI - A)^-1 B from an input to an output at one "
                    "speed: magnitude (dB) and phase (degrees, unwrapped) at N frequencies spaced "
                    "logarithmically from START to STOP rad/s (Hz with --hz).")
    _input_output(bode)
    bode.add_argument("--frequencies", metavar="START:STOP:N", default=None,
                      help=f"N frequencies from START to STOP rad/s (Hz with --hz), logarithmic (default "
                           f"{DEFAULT_FREQUENCIES} rad/s)")
    bode.add_argument("--hz", action="store_true",
                      help="frequencies in Hz (f = w / 2 pi) instead of rad/s: --frequencies, the table's and "
                           "the document's frequencies and the plot's frequency axis")
    _data(bode, "the magnitude and phase at every frequency")
    dialect.add_plot(bode, "the Bode plot")
    dialect.add_control(bode)
    bode.set_defaults(run=every_size(run_bode))

    sim = _command(
        sub, "simulate", help="time response from initial conditions, steps and impulses (exact, matrix exponential)",
        description="The states of the linear bicycle (roll, steer, their rates, heading, lateral position "
                    "of the rear contact) at 0, DT, 2 DT, ..., T: from initial conditions and steps or impulses "
                    "of the inputs, exact at the samples (the matrix exponential).")
    sim.add_argument("--initial", action="append", metavar="STATE=VALUE",
                     help="initial value of a state in its unit (rad, rad/s, m), e.g. roll-rate=0.5; "
                          "several comma-separated or the option repeated; others start at 0")
    dialect.late_help(sim.add_argument("--input", action="append", metavar="INPUT=KIND:SIZE", help="an input"),
                      lambda: "an input as step:SIZE (N m from t = 0) or impulse:SIZE (N m s at t = 0), e.g. "
                              f"steer-torque=step:1; the inputs: {signal_help(0)}")
    sim.add_argument("--duration", type=number(0, 1e6, open_low=True, what="a duration in s"), default=5.0,
                     metavar="T", help="end time, s (default 5)")
    sim.add_argument("--step", type=number(0, 1e6, open_low=True, what="a time step in s"), default=0.01,
                     metavar="DT", help="time step of the samples, s (default 0.01)")
    sim.add_argument("--nonlinear", action="store_true",
                     help="the nonlinear Whipple bicycle instead (integrated numerically; --model whipple, rigid "
                          "frame): adds forward-speed (m/s), pitch-angle (rad), x (m) and energy (J); a fall "
                          "(roll 60 degrees) ends the run with a warning; --plot draws it beside the linear run")
    dialect.add_output(sim, what="the samples")
    dialect.add_plot(sim, "every state against time")
    dialect.add_control(sim)
    sim.set_defaults(run=every_size(run_simulate))

    shapes = _command(
        sub, "mode-shapes", help="each mode's eigenvector as amplitude and phase of roll, steer, heading, lateral",
        description="The modes of the linear bicycle at one speed (weave, capsize, caster), each eigenvector "
                    "scaled so its largest mechanical coordinate is 1 at phase 0: the amplitude and phase of "
                    "roll, steer, heading and lateral position; --plot draws them as phasors.")
    dialect.add_output(shapes, what="the mode shapes")
    dialect.add_plot(shapes, "the mode shapes as phasors")
    dialect.add_control(shapes)
    shapes.set_defaults(run=every_size(run_mode_shapes))

    space = _command(
        sub, "state-space", help="the state space A, B, C, D (named, with units) at one speed: .mat, .npz, JSON, CSV",
        description="The linear model's state space x' = A x + B u, y = C x + D u at one speed, with the names "
                    "and units of its states, inputs and outputs, and (where the model has mechanical "
                    "coordinates q) its second-order form M q'' + C(v) q' + K(v) q = F u, C(v) and K(v) as "
                    "polynomials in speed: for MATLAB (.mat), numpy (.npz), any language (JSON, YAML, CSV: one "
                    "row per matrix entry). Layout: docs/handling.md, 'State spaces out'.")
    dialect.late_help(space.add_argument("--outputs", metavar="NAME,...", help="the outputs"),
                      lambda: "the outputs y, comma-separated (default: every state, then every further "
                              "output): " + signal_help(1))
    space.add_argument("-o", dest="output", metavar="FILE",
                       help="write the state space to FILE (format from --format, else the suffix: .mat, .npz, "
                            ".json, .yaml, .csv; .mat and .npz need -o)")
    space.add_argument("--format", choices=STATE_SPACE_FORMATS, default=None,
                       help=f"{', '.join(STATE_SPACE_FORMATS)} (default table; JSON and YAML carry a units block)")
    dialect.add_quiet(space)
    space.set_defaults(default_format=Format.TABLE.value, format_choices=STATE_SPACE_FORMATS,
                       run=every_size(run_state_space))

    hand = _command(
        sub, "handling", one_speed=False,
        help="the Hess-Moore-Hubbard rider in the loop: gains, closed-loop stability, HQM",
        description="The rider of Hess, Moore & Hubbard (2012) on the bicycle at each speed: the five "
                    "loop gains by the published procedure (or from --gains), the closed loop's stability "
                    "and the peak of the handling quality metric (Level 1 below 5, Level 3 above 8).")
    hand.add_argument("--speeds", metavar="V1,V2,...",
                      help="forward speeds in m/s, comma-separated (an item START:STOP:STEP is a grid); "
                           "default: the speeds of the --gains file")
    hand.add_argument("--gains", metavar="FILE.csv",
                      help="given gains: a CSV with the header speed,kDelta,kPhiDot,kPhi,kPsi,kY "
                           "(the published tables' form) holding every speed asked for")
    hand.add_argument("--tuning", choices=("hmh2012", "bmd2016"), default="hmh2012",
                      help="how gains are tuned where none are given: hmh2012 (default; Hess, Moore & Hubbard "
                           "2012: each inner loop's neuromuscular peak 10 dB above its valley) or bmd2016 (Moore, "
                           "Hubbard & Hess 2016: a pole pair of each inner loop on the damping lines 0.1289 and "
                           "0.0855; finds the negative k_delta of their optimal bicycles); both cross the outer "
                           "loops over at 2, 1 and 0.5 rad/s")
    _data(hand, "the gains, stability and HQM peaks (CSV: a gains file with more columns)")
    dialect.add_plot(hand, "the HQM against frequency and its peak against speed")
    hand.add_argument("--lane-change", metavar="FILE",
                      help="also draw the double lane change at every speed into FILE (.png, .pdf, ...)")
    hand.add_argument("--nonlinear", action="store_true",
                      help="with --lane-change: draw the rider (the same gains) steering the nonlinear Whipple "
                           "bicycle beside the linear run at every speed (--model whipple, rigid frame)")
    hand.set_defaults(run=every_size(run_handling))


def _command(sub, name, one_speed=True, **texts):
    """The sub-command ``name`` (``texts``: its ``help`` and ``description``) with the options every
    handling command shares: BIKE, ``--rider``, ``--allow-off-contact``, ``--combine``,
    ``--stiffness``, ``--model``, ``--tyres``, ``--bike-size`` and (``one_speed``) ``--speed``."""
    p = sub.add_parser(name, **texts)
    dialect.add_bike(p)
    dialect.add_rider(p)
    allow_off_contact_option(p)
    dialect.add_combine(p)
    dialect.add_stiffness(p)
    dialect.add_model(p)
    add_size_option(p, "--bike-size")
    if one_speed:
        p.add_argument("--speed", type=SPEED, required=True, metavar="V", help="forward speed, m/s")
    return p


def _input_output(p):
    """``--input`` and ``--output`` (the signals), their help listing every name a model of the family
    takes (:func:`signal_help`)."""
    dialect.late_help(p.add_argument("--input", required=True, metavar="INPUT", help="the input"),
                      lambda: "the input: " + signal_help(0))
    dialect.late_help(p.add_argument("--output", dest="response", required=True, metavar="OUTPUT",
                                     help="the output"),
                      lambda: "the output: " + signal_help(1))


def signal_help(which):
    """The inputs (``which`` 0) or the outputs (1) of the family's models, named with their units: the
    Whipple bicycle's (marked where no member has one), then what each member adds (a combination
    takes what its members add) (:func:`~bikemass.scenario.scenario.model_signals`)."""
    # lazy: the model family loads numpy; bikemass --help must not
    from ..scenario.scenario import model_signals

    base = model_signals(BASE)[which]
    members = {m: model_signals(m)[which] for m in MEMBERS}
    only = {s for s in base if not any(s in signals for signals in members.values())}
    text = ", ".join(f"{name} ({unit}{f'; --model {BASE} only' if (name, unit) in only else ''})"
                     for name, unit in base)
    added = [f"{m} adds {', '.join(f'{name} ({unit})' for name, unit in signals if (name, unit) not in base)}"
             for m, signals in members.items() if set(signals) - set(base)]
    return text + (f"; with --model, {'; '.join(added)}" if added else "")


def _data(p, what):
    """``-o FILE`` (here only the short form: ``--output`` names the output signal), ``--format``, ``--quiet``."""
    p.add_argument("-o", dest="output", metavar="FILE",
                   help=f"write {what} to FILE instead of stdout (format from --format, else the suffix)")
    p.add_argument("--format", choices=dialect.TABULAR, default=None,
                   help=f"{', '.join(dialect.TABULAR)} (default table; JSON and YAML carry a units block)")
    dialect.add_quiet(p)
    p.set_defaults(default_format=Format.TABLE.value, format_choices=dialect.TABULAR)


def bicycle_model(args):
    """The :class:`~bikemass.models.linear.LinearModel` of BIKE with ``--rider``, ``--combine``,
    ``--allow-off-contact``, ``--stiffness``, ``--model`` and ``--tyres``: the one place these
    commands build their model (the scenario builder, :func:`bikemass.cli.dialect.scenario`); with
    ``--control`` the closed loop at ``--speed`` (:func:`bikemass.models.control.close_loop`)."""
    model = dialect.scenario(args).build().model
    if getattr(args, "control", None):
        # lazy: the library loads numpy; bikemass --help must not
        from ..models.control import close_loop
        return close_loop(model, args.control).at(args.speed)     # the closed loop at the one speed
    return model


def _title(args):
    rider = dialect.riderless_label(args) if args.rider == "none" else args.rider
    frame = dialect.frame_name(args)
    model = "" if args.model == "whipple" else f", model {args.model}"
    control = f", control {args.control}" if getattr(args, "control", None) else ""
    return f"{dialect.bike_name(args.bike)}, {rider}, {frame}{model}{control}"


def _output_name(model, name):
    return _named(name, model.output_names, "--output")


def _input_name(model, name):
    return _named(name, model.input_names, "--input")


def _named(name, names, option):
    """``name`` if the model has it (one of ``names``), else InputError naming ``option`` and the choices."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.choices import closest
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    if name not in names:
        raise InputError(option, name, f"one of {', '.join(names)}{closest(name, names)}")
    return name


def run_tf(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.transfer import transfer_function

    model = bicycle_model(args)
    tf = transfer_function(model, args.speed, _input_name(model, args.input), _output_name(model, args.response))

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(tf.to_dict(), tf.units(), fmt)
        if fmt == "csv":
            rows = [["zero", z.real, z.imag, "1/s"] for z in tf.zeros] + \
                   [["pole", p.real, p.imag, "1/s"] for p in tf.poles] + [["gain", tf.gain, 0.0, tf.gain_unit]]
            return dialect.csv_text(["part", "real", "imaginary", "unit"], rows)
        return tf_text(tf, _title(args))
    dialect.emit(args, render)
    return 0


def _root(z):
    return f"{z.real:.6g}" if z.imag == 0 else f"{z.real:.6g} {'+' if z.imag > 0 else '-'} {abs(z.imag):.6g}j"


def _signed(x):
    return f"{'-' if x < 0 else '+'} {abs(x):.6g}"


def factors(roots):
    """``(s + a) (s^2 + b s + c) ...``: a real root one factor, a complex pair one quadratic."""
    out = []
    for z in roots:
        if z.imag == 0:
            out.append("s" if z.real == 0 else f"(s {_signed(-z.real)})")
        elif z.imag > 0:
            out.append(f"(s^2 {_signed(-2 * z.real)} s {_signed(abs(z) ** 2)})")
    return " ".join(out) or "1"


def tf_text(tf, title):
    """The transfer function as text: the factored form, then every zero and pole."""
    lines = [f"{title}: {tf.output} / {tf.input} at {tf.speed:g} m/s",
             f"G(s) = {tf.gain:.8g} {factors(tf.zeros)} / [{factors(tf.poles)}]",
             f"gain: {tf.gain!r} {tf.gain_unit}",
             "zeros (1/s): " + (", ".join(_root(z) for z in tf.zeros) or "none"),
             "poles (1/s): " + (", ".join(_root(p) for p in tf.poles) or "none")]
    return "\n".join(lines) + "\n"


def _frequencies(text, hz=False):
    """``--frequencies`` as angular frequencies (rad/s); with ``hz`` the text is in Hz."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.frequency import log_frequencies
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    scale = 2 * math.pi if hz else 1.0
    if text is None:
        start, stop, count = DEFAULT_FREQUENCIES.split(":")
        return log_frequencies(float(start), float(stop), int(count))
    try:
        start, stop, count = (float(x) for x in text.split(":"))
    except ValueError:
        start = stop = count = float("nan")            # log_frequencies states the rule
    try:
        return log_frequencies(start * scale, stop * scale, int(count) if float(count).is_integer() else count)
    except InputError as exc:
        expected = f"START:STOP:N in Hz, 2 pi START and 2 pi STOP as {exc.expected}" if hz else exc.expected
        raise InputError("--frequencies", text, expected) from None


def run_bode(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.frequency import frequency_response
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    options = dialect.figure_checked(args)
    w = _frequencies(args.frequencies, args.hz)
    model = bicycle_model(args)
    fr = frequency_response(model, args.speed, _input_name(model, args.input), _output_name(model, args.response), w)
    unit = "Hz" if args.hz else "rad/s"
    shown = fr.frequencies / (2 * math.pi) if args.hz else fr.frequencies

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document({**fr.to_dict(), "frequencies": shown.tolist()},
                                           {**fr.units(), "frequencies": unit}, fmt)
        rows = list(zip(shown.tolist(), fr.magnitude.tolist(), fr.phase.tolist()))
        headers = [f"frequency ({unit})", "magnitude (dB)", "phase (deg)"]
        if fmt == "csv":
            return dialect.csv_text(headers, rows)
        return table(headers, rows, floatfmt="{:.6g}")
    dialect.emit(args, render)
    if args.plot:
        # lazy: matplotlib only for a figure
        from ..analysis.handling.figures import plot_bode
        title = f"{_title(args)}: {fr.output} / {fr.input} at {fr.speed:g} m/s"
        dialect.save_plot(args, plot_bode(fr, title, options.size, hz=args.hz), options)
    return 0


def run_state_space(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.state_space import CSV_HEADERS, state_space
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError

    fmt = dialect.data_format(args)
    if fmt in ("mat", "npz") and not args.output:
        raise InputError("--format", fmt, f"-o FILE.{fmt} (a binary file is not written to the terminal)")
    model = bicycle_model(args)
    outputs = None
    if args.outputs:
        outputs = [_named(name.strip(), model.output_names, "--outputs") for name in args.outputs.split(",")]
        twice = next((name for k, name in enumerate(outputs) if name in outputs[:k]), None)
        if twice:                    # two rows of C with one name: a reader of the file cannot tell them apart
            raise InputError("--outputs", twice, "each output once")
    ss = state_space(model, args.speed, outputs)
    if fmt == "mat":
        dialect.write_data(args, ss.to_mat())
    elif fmt == "npz":
        dialect.write_data(args, ss.to_npz())
    elif fmt in ("json", "yaml"):
        dialect.write_data(args, dialect.result_document(ss.to_dict(), ss.units(), fmt))
    elif fmt == "csv":
        dialect.write_data(args, dialect.csv_text(list(CSV_HEADERS), ss.csv_rows()))
    else:
        dialect.write_data(args, state_space_text(ss, _title(args)))
    return 0


def state_space_text(ss, title):
    """A, B, C, D as labelled text tables (rows and columns named with their units)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.state_space import rate_unit
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    def block(name, matrix, rows, row_units, columns, column_units):
        headers = [name, *(f"{c} ({u})" for c, u in zip(columns, column_units))]
        return table(headers, [[f"{r} ({u})", *map(float, line)] for r, u, line in zip(rows, row_units, matrix)],
                     floatfmt="{:.6g}")
    d_states = [rate_unit(u) for u in ss.state_units]
    parts = [f"{title}: x' = A x + B u, y = C x + D u at {ss.speed:g} m/s (model {ss.model})",
             block("A", ss.A, [f"d/dt {s}" for s in ss.states], d_states, ss.states, ss.state_units),
             block("B", ss.B, [f"d/dt {s}" for s in ss.states], d_states, ss.inputs, ss.input_units),
             block("C", ss.C, ss.outputs, ss.output_units, ss.states, ss.state_units),
             block("D", ss.D, ss.outputs, ss.output_units, ss.inputs, ss.input_units)]
    return "\n".join(parts)


def _pairs(items, option):
    """``["a=1,b=2", "c=3"]`` -> ``[("a", "1"), ("b", "2"), ("c", "3")]``; InputError for a bad item."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    out = []
    for item in items or ():
        for part in item.split(","):
            name, sep, value = part.partition("=")
            if not sep or not name.strip() or not value.strip():
                raise InputError(option, part, "NAME=VALUE")
            out.append((name.strip(), value.strip()))
    return out


def _once(pairs, option):
    """``pairs`` (``[(name, value)]``), InputError if a name is given twice (the option repeated, or
    twice in one list): the last would silently win."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    seen = {}
    for name, value in pairs:
        if name in seen:
            raise InputError(option, f"{name}={value}", f"each name once ({name}={seen[name]} was given too)")
        seen[name] = value
    return pairs


def _initial(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    values = {}
    for name, value in _once(_pairs(args.initial, "--initial"), "--initial"):
        try:
            values[name] = float(value)
        except ValueError:
            raise InputError("--initial", f"{name}={value}", "a number in the state's unit") from None
    return values


def _inputs(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.sampled import KINDS
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.choices import closest
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    applied = {}
    for name, value in _once(_pairs(args.input, "--input"), "--input"):
        kind, sep, size = value.partition(":")
        expected = "INPUT=step:SIZE (N m) or INPUT=impulse:SIZE (N m s)"
        try:
            applied[name] = (kind, float(size))
        except ValueError:
            raise InputError("--input", f"{name}={value}", expected) from None
        if not sep or kind not in KINDS:
            raise InputError("--input", f"{name}={value}", expected + closest(kind, KINDS))
    return applied


def _with_option_names(call, names, typed=None):
    """``call()``, with an InputError about an argument renamed to its option (``initial`` ->
    ``--initial``) and showing what was typed (``typed``: ``{argument: text}``), not the value
    the text was turned into."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    try:
        return call()
    except InputError as exc:
        if exc.source in names:
            key = (typed or {}).get(exc.source, exc.key)
            raise InputError(names[exc.source], key, exc.expected) from None
        raise


def run_simulate(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.time_response import simulate

    options = dialect.figure_checked(args)
    initial, applied = _initial(args), _inputs(args)
    names = {"initial": "--initial", "inputs": "--input", "input": "--input", "step": "--step",
             "duration": "--duration"}
    if getattr(args, "nonlinear", False):
        built = _nonlinear_built(args)
        model = built.model
        r = _with_option_names(lambda: simulate(built.parameters, args.speed, initial, applied, args.duration,
                                                args.step, nonlinear=True), names)
    else:
        model = bicycle_model(args)
        r = _with_option_names(lambda: simulate(model, args.speed, initial, applied, args.duration, args.step),
                               names)

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(r.to_dict(), r.unit_block(), fmt)
        headers = ["time (s)", *(f"{n} ({u})" for n, u in zip(r.names, r.signal_units))]
        rows = [[t, *x] for t, x in zip(r.time.tolist(), r.values.tolist())]
        if fmt == "csv":
            return dialect.csv_text(headers, rows)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import table
        return table(headers, rows, floatfmt="{:.6g}")
    dialect.emit(args, render)
    if args.plot and getattr(args, "nonlinear", False):
        # lazy: matplotlib only for a figure
        from ..analysis.nonlinear.figures import plot_nonlinear_response
        linear = simulate(model, args.speed, initial, applied, args.duration, args.step)
        fig = plot_nonlinear_response(r, linear, f"{_title(args)}: nonlinear and linear from {r.speed:g} m/s",
                                      options.size)
        dialect.save_plot(args, fig, options)
    elif args.plot:
        # lazy: matplotlib only for a figure
        from ..analysis.handling.figures import plot_time_response
        dialect.save_plot(args, plot_time_response(r, f"{_title(args)} at {r.speed:g} m/s", options.size), options)
    return 0


def _nonlinear_built(args):
    """The built scenario of ``--nonlinear``: the Whipple bicycle with a rigid frame, else InputError."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    if args.model != BASE:
        raise InputError("--nonlinear", f"--model {args.model}", f"--model {BASE}: the nonlinear model is the "
                         "Whipple bicycle")
    built = dialect.scenario(args).build()
    if built.stiffness is not None:
        given = f"--stiffness {args.stiffness}" if args.stiffness is not None else "the file's frame stiffness"
        raise InputError("--nonlinear", given, "--stiffness infinite: the nonlinear "
                         "model has a rigid frame")
    return built


def run_mode_shapes(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.mode_shapes import mode_shapes

    options = dialect.figure_checked(args)
    shapes = mode_shapes(bicycle_model(args), args.speed)

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(shapes.to_dict(), shapes.unit_block(), fmt)
        rows = [[label, name, z.real, z.imag, coordinate, shapes.amplitude[i, k], shapes.phase[i, k]]
                for i, (label, name, z) in enumerate(zip(shapes.labels, shapes.names, shapes.eigenvalues))
                for k, coordinate in enumerate(shapes.coordinates)]
        headers = ["mode", "name", "real (1/s)", "imaginary (1/s)", "coordinate", "amplitude", "phase (deg)"]
        if fmt == "csv":
            return dialect.csv_text(headers, rows)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import table
        return (f"{_title(args)} at {shapes.speed:g} m/s: amplitudes per unit of each mode's largest "
                f"mechanical coordinate (phase 0)\n" + table(headers, rows, floatfmt="{:.6g}"))
    dialect.emit(args, render)
    if args.plot:
        # lazy: matplotlib only for a figure
        from ..analysis.handling.figures import plot_mode_shapes
        fig = plot_mode_shapes(shapes, f"{_title(args)}: mode shapes at {shapes.speed:g} m/s", options.size)
        dialect.save_plot(args, fig, options)
    return 0


def _speeds(text):
    """``--speeds`` of handling: comma-separated speeds (m/s), an item ``START:STOP:STEP`` a grid."""
    # lazy: the library loads numpy; bikemass --help must not
    import numpy as np

    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.survey import MAX_SURVEY_SPEEDS
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    expected = "comma-separated speeds in m/s (an item START:STOP:STEP is a grid), increasing"
    values = []
    for item in text.split(","):
        item = item.strip()
        if ":" in item:
            try:
                values.extend(dialect.parse_speeds(item, MAX_SURVEY_SPEEDS).tolist())
            except InputError:
                raise InputError("--speeds", text, f"{expected}; a grid START:STOP:STEP of at most "
                                 f"{MAX_SURVEY_SPEEDS} speeds") from None
            continue
        try:
            values.append(float(item))
        except ValueError:
            raise InputError("--speeds", text, expected) from None
    v = np.array(values)
    if not len(v) or not np.all(np.isfinite(v)) or np.any(v < 0) or np.any(np.diff(v) <= 0):
        raise InputError("--speeds", text, expected)
    return v


def run_handling(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.survey import handling
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError

    options = dialect.figure_checked(args)
    if args.lane_change:
        # lazy: the library loads numpy; bikemass --help must not
        from .figure_options import figure_options
        options = figure_options(args, args.lane_change) if options is None else options
    if args.speeds is None and args.gains is None:
        raise InputError("--speeds", "(missing)", "the speeds in m/s (V1,V2,...), or a --gains file whose speeds are used")
    speeds = None if args.speeds is None else _speeds(args.speeds)
    parameters = None
    if args.nonlinear:
        if not args.lane_change:
            raise InputError("--nonlinear", "(without --lane-change)", "--lane-change FILE: --nonlinear draws the "
                             "lane change on the nonlinear bicycle")
        parameters = _nonlinear_built(args).parameters
    model = bicycle_model(args)
    result = _with_option_names(lambda: handling(model, speeds, args.gains, tuning=args.tuning),
                                {"speeds": "--speeds"}, {"speeds": args.speeds})

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(result.to_dict(), result.unit_block(), fmt)
        if fmt == "csv":
            return handling_csv(result)
        # the gains column says "tuned" for either tuning: the title names one other than the default
        tuned_by = "" if args.tuning == "hmh2012" else f", gains tuned by {args.tuning}"
        return handling_text(result, _title(args) + tuned_by)
    dialect.emit(args, render)
    if args.plot:
        # lazy: matplotlib only for a figure
        from ..analysis.handling.figures import plot_handling
        dialect.save_plot(args, plot_handling(result, f"{_title(args)}: handling quality metric", options.size),
                          options)
    if args.lane_change:
        _draw_lane_changes(args, model, result, options, parameters)
    return 0


def _draw_lane_changes(args, model, result, options, parameters=None):
    """The lane changes at every stable speed into ``args.lane_change``; with ``parameters`` (a
    benchmark parameter set) each beside the nonlinear bicycle's run with the same gains."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.lane_change import lane_change
    # lazy: the library loads numpy; bikemass --help must not
    from ..plots.figure import save_figure
    # lazy: matplotlib only for a figure
    from ..analysis.handling.figures import plot_lane_change
    # lazy: the library loads numpy; bikemass --help must not
    from ..models.plausibility import warn
    runs = []
    for v, g, ok in zip(result.speeds, result.gains, result.closed_loop_stable):
        if ok and v > 0:
            runs.append(lane_change(model, v, g))
            if parameters is not None:
                runs.append(lane_change(parameters, v, g, nonlinear=True))
    left = [f"{v:g}" for v, g, ok in zip(result.speeds, result.gains, result.closed_loop_stable) if g is not None
            and not ok]
    if left:
        warn(f"--lane-change: not drawn at {', '.join(left)} m/s (closed loop unstable: the run diverges)")
    if runs:
        what = "double lane change, linear and nonlinear" if parameters is not None else "double lane change"
        fig = plot_lane_change(runs, f"{_title(args)}: {what}", options.size)
        save_figure(fig, args.lane_change, options.dpi)
    else:
        warn(f"--lane-change: {args.lane_change} not written: no speed above 0 with a stable closed loop")


def handling_csv(result):
    """A gains file (``speed,kDelta,kPhiDot,kPhi,kPsi,kY``) with the results as further columns."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.gains import HEADER, NAMES
    rows = [[v, *(None if g is None else getattr(g, n) for n in NAMES), bool(ok), _finite(p), _finite(w), level]
            for v, g, ok, p, w, level in zip(result.speeds.tolist(), result.gains, result.closed_loop_stable,
                                             result.hqm_peak, result.hqm_peak_frequency, result.levels)]
    return dialect.csv_text([*HEADER, "closed_loop_stable", "hqm_peak", "hqm_peak_frequency (rad/s)", "level"], rows)


def _finite(x):
    return float(x) if math.isfinite(x) else None


def handling_text(result, title):
    """The gains, stability and HQM peak at every speed as a text table: the level ``unstable``
    where the closed loop is (the peak of an unstable loop grades nothing and is not shown),
    ``-`` without gains, and the gains' source with why a speed has no level."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.handling.gains import NAMES
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table
    rows = [[v, *(None if g is None else getattr(g, n) for n in NAMES), "yes" if ok else "no",
             _finite(p) if level else None, _finite(w) if level else None,
             level or ("-" if g is None else "unstable" if not ok else "none"), source]
            for v, g, ok, p, w, level, source in zip(result.speeds.tolist(), result.gains, result.closed_loop_stable,
                                                     result.hqm_peak, result.hqm_peak_frequency, result.levels,
                                                     result.gain_source)]
    headers = ["speed (m/s)", "k_delta", "k_phi_dot", "k_phi", "k_psi", "k_y", "stable", "HQM peak",
               "at (rad/s)", "level", "gains"]
    return (f"{title}: Hess, Moore & Hubbard (2012) rider, lateral feedback {result.lateral}\n"
            + table(headers, rows, floatfmt="{:.4f}"))
