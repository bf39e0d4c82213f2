"""The Dash page: controls on the left, results on the right, state in the URL.

The layout is built per request from the URL's query (so a link opens its
configuration); every change of a control recomputes through the cached
:class:`~.engine.Engine` and writes the new state back into the URL.
"""

import base64

import dash
import numpy as np
from dash.exceptions import DependencyException
from flask import jsonify
from dash import ALL, Dash, Input, Output, State, ctx, dcc, html, no_update
from ..bicycle.derived_chart import ANGLES, CHART_ORDER, derived_chart
from ..core.errors import InputError
from ..core.paths import available, frames_dir
from ..models.parameters import DESCRIPTIONS, NAMES
from ..models.registry import BASE, SPECS
from ..plots.figure import figure_bytes
from ..plots.side_view import plot_side_view
from ..plots.stability import plot_eigenvalues
from ..rider import shipped_poses
from ..scenario.scenario import model_signals
from .api import DOWNLOADS, register_routes
from .engine import UPLOAD_LIMIT, Engine, HANDLING_SPEEDS
from .state import BODY_RIDER, CHART_ANGLES, CHART_KEYS, HANDS, MODEL_CHOICES, SEXES, SOURCE, PageState
from ..analysis.handling.frequency import frequency_response
from ..analysis.handling.figures import plot_bode, plot_handling
from .guard import guard_hosts, guard_requests, secure_headers

STYLE = """
body { font-family: system-ui, sans-serif; margin: 0; color: #222; background: #fafafa; }
header { background: #263238; color: white; padding: 10px 18px; }
header h1 { font-size: 20px; margin: 0; display: inline; }
header span { margin-left: 14px; opacity: 0.8; font-size: 14px; }
.columns { display: flex; gap: 16px; padding: 12px 18px; align-items: flex-start; }
.controls { flex: 0 0 330px; background: white; padding: 12px; border: 1px solid #ddd; border-radius: 6px; }
.results { flex: 1 1 auto; min-width: 0; }
.controls label { display: block; font-weight: 600; margin: 10px 0 3px; font-size: 13px; }
.numbers { display: flex; gap: 12px; flex-wrap: wrap; }
.number { background: white; border: 1px solid #ddd; border-radius: 6px; padding: 8px 14px; min-width: 150px; }
.number .what { font-size: 12px; color: #555; }
.number .value { font-size: 20px; font-weight: 600; }
.figure { background: white; border: 1px solid #ddd; border-radius: 6px; margin-top: 12px; padding: 6px; }
.figure img { width: 100%; }
.error { color: #b00020; font-weight: 600; margin: 8px 0; min-height: 1em; }
.warnings { color: #8a5a00; margin: 4px 0; font-size: 13px; }
.stale-note { display: none; color: #b00020; font-size: 13px; margin: 4px 0; }
.stale .stale-note { display: block; }
.stale .numbers, .stale .figure, img.stale { opacity: 0.45; }
table.params { border-collapse: collapse; font-size: 12px; width: 100%; }
table.params td { padding: 1px 4px; border-bottom: 1px solid #eee; }
table.params input { width: 150px; font-size: 12px; padding: 2px 4px; }
.downloads a { display: inline-block; margin: 3px 8px 3px 0; font-size: 13px; }
.grid2 { display: grid; grid-template-columns: 1fr 1fr; gap: 12px; }
@media (max-width: 1100px) { .columns { flex-direction: column; } .controls { flex-basis: auto; width: 95%; }
  .grid2 { grid-template-columns: 1fr; } }
"""

INDEX = """<!DOCTYPE html>
<html lang="en"><head>{%metas%}<title>{%title%}</title>{%css%}<style>""" + STYLE + """</style></head>
<body>{%app_entry%}<footer>{%config%}{%scripts%}{%renderer%}</footer></body></html>"""


def _text(limit):
    return lambda value: isinstance(value, str) and len(value) <= limit


def _optional(check):
    return lambda value: value is None or check(value)


def _number_or_text(value):
    return (isinstance(value, (int, float)) and not isinstance(value, bool)) or _text(100)(value)


MODEL_NOTE = "; ".join([f"{BASE}: Meijaard et al. (2007)"]
                       + [f"{spec.name}: {spec.summary}" for spec in SPECS] + ["docs/models.md"])
"""The line under the model selector."""


def _options(value):
    return isinstance(value, list) and len(value) <= 200 and all(
        _text(200)(o) or (isinstance(o, dict) and _text(300)(o.get("label")) and _text(200)(o.get("value")))
        for o in value)


VALUE_CHECKS = {
    "bike.value": (_text(200), "a bicycle name"),
    "bike.options": (_options, "a list of bicycle names"),
    "size.value": (_optional(_text(100)), "a size name or null"),
    "rider.value": (_text(200), "a rider name"),
    "height.value": (_optional(_number_or_text), "a number"),
    "mass.value": (_optional(_number_or_text), "a number"),
    "sex.value": (_text(100), "a name"),
    "hands.value": (_text(100), "a name"),
    "stiffness.value": (_text(100), "a material name"),
    "combine.value": (_text(100), "a name"),
    "model.value": (_text(100), "a model name"),
    "chart.value": (_optional(_number_or_text), "a number or nothing"),
    "param.value": (_optional(_number_or_text), "a number or nothing"),
    "upload.contents": (_optional(_text(3_000_000)), "the file's content as a data URL, or null"),
    "upload.filename": (_optional(_text(255)), "a file name of at most 255 characters, or null"),
    "address-error.data": (_optional(_text(2000)), "the address's error, or null"),
}
"""What each control of the page may send (:func:`~.guard.guard_requests` refuses the rest)."""


def create_app(engine=None, hosts=()):
    """The Dash application (its Flask server has the JSON API and downloads); it answers requests
    whose ``Host`` is an IP address, ``localhost`` or one of ``hosts`` (:func:`~.guard.guard_hosts`)."""
    engine = engine or Engine()
    app = Dash(__name__, title="bikemass", update_title=None, serve_locally=True, use_pages=True,
               pages_folder="", index_string=INDEX, suppress_callback_exceptions=True)
    dash.register_page("explorer", path="/", title="bikemass", layout=lambda **query: _layout(query))
    app.layout = dash.page_container
    _callbacks(app, engine)
    register_routes(app.server, engine)
    guard_requests(app, VALUE_CHECKS)
    guard_hosts(app.server, hosts)
    secure_headers(app.server)
    app.server.register_error_handler(DependencyException, _no_such_script)
    app.server.json.sort_keys = False
    app.engine = engine
    return app


def _no_such_script(error):
    """A script path Dash does not serve (``/_dash-component-suites/...%252f..``): 404, one line."""
    return jsonify({"error": "not found: a script of this page"}), 404


def _shipped():
    body = {"label": "a body from height, mass and sex", "value": BODY_RIDER}
    return available(frames_dir()), ["none"] + shipped_poses() + [body]


def _layout(query):
    """The page for the URL query ``query`` (a mapping of strings); a bad query shows its error."""
    try:
        state, error = PageState.from_query(query), ""
    except InputError as exc:
        state, error = PageState(), str(exc)
    bikes, riders = _shipped()
    chart, overrides = dict(state.chart), dict(state.overrides)
    controls = html.Div(className="controls", children=[
        html.Label("Bicycle", htmlFor="bike"),
        dcc.Dropdown(id="bike", options=bikes + [b for b in [state.bike] if b not in bikes],
                     value=state.bike, clearable=False),
        dcc.Upload(id="upload", children=html.A("or upload a bicycle file (YAML, chart, BicycleParameters)"),
                   max_size=UPLOAD_LIMIT, style={"fontSize": "12px", "cursor": "pointer"}),
        html.Label("Size", htmlFor="size"),
        dcc.Dropdown(id="size", options=[state.size] if state.size else [], value=state.size or None,
                     placeholder="one size only"),
        html.Label("Rear-frame stiffness", htmlFor="stiffness"),
        dcc.Dropdown(id="stiffness", options=[state.stiffness], value=state.stiffness, clearable=False),
        html.Label("Model", htmlFor="model"),
        dcc.Dropdown(id="model", options=list(MODEL_CHOICES), value=state.model, clearable=False),
        html.Div(MODEL_NOTE, style={"fontSize": "12px"}),
        html.Label("Rider", htmlFor="rider"),
        dcc.Dropdown(id="rider", options=riders, value=state.rider, clearable=False),
        html.Div(id="body-controls", style={} if state.rider == BODY_RIDER else {"display": "none"}, children=[
            html.Table(className="params", children=[
                html.Tr([html.Td("height"), html.Td(dcc.Input(id="height", type="text", debounce=True,
                                                              value=repr(state.height), style={"width": "130px"})),
                         html.Td("m")]),
                html.Tr([html.Td("mass"), html.Td(dcc.Input(id="mass", type="text", debounce=True,
                                                            value=repr(state.mass), style={"width": "130px"})),
                         html.Td("kg")])]),
            dcc.RadioItems(id="sex", options=list(SEXES), value=state.sex, inline=True),
            html.Label("Hands on the", htmlFor="hands"),
            dcc.Dropdown(id="hands", options=list(HANDS), value=state.hands, clearable=False)]),
        html.Label("Rider + rear frame"),
        dcc.RadioItems(id="combine", value=state.combine, inline=True, options=[
            {"label": " parallel-axis (exact) ", "value": "exact"},
            {"label": " thesis Eq. 3.6", "value": "thesis"}]),
        html.Div(id="chart-editor", children=_editor(
            "Geometry chart: type a value to change the frame", "chart", CHART_KEYS, chart,
            lambda k: "deg" if k in CHART_ANGLES else "mm", lambda k: k.replace("_", " "))),
        _editor("Benchmark parameters: type a value to override, empty = computed", "param", NAMES,
                overrides, lambda k: DESCRIPTIONS[k].split("[")[-1].rstrip("]"), lambda k: k),
    ])
    results = html.Div(id="results", className="results stale" if error else "results", children=[
        dcc.Store(id="address-error", data=error or None),
        html.Div(id="error", className="error", children=error),
        html.Div(STALE_NOTE, id="stale-note", className="stale-note"),
        html.Ul(id="warnings", className="warnings"),
        dcc.Loading(type="dot", children=html.Div(className="numbers", children=[
            _number("weave speed", "weave-speed"), _number("capsize speed", "capsize-speed"),
            _number("stable speeds", "stable-range"), _number("total mass", "total-mass")])),
        html.Div(className="grid2", children=[
            _panel("Eigenvalues against speed", dcc.Loading(html.Img(id="eig-figure", alt="eigenvalues"))),
            _panel("Side view", dcc.Loading(html.Img(id="side-view", alt="side view")))]),
        html.Div(className="grid2", children=[
            _panel("Bodies (benchmark frame: x forward, z down; principal inertias)", html.Div(id="bodies")),
            _panel("Geometry (as built)", html.Div(id="geometry"))]),
        html.Div(className="grid2", children=[
            _panel("Rear-frame stiffness S (N m/rad)", html.Pre(id="stiffness-matrix")),
            _panel("Downloads", html.Div(id="downloads", className="downloads"))]),
        _handling_panel(),
    ])
    return html.Div([
        dcc.Location(id="url", refresh=False),
        html.Header([html.H1("bikemass"), html.Span("a bicycle and its rider: parameters and stability")]),
        html.Div(className="columns", children=[controls, results]),
    ])


BODE_INPUTS, BODE_OUTPUTS = (tuple(name for name, _ in signals) for signals in model_signals(BASE))
"""The Bode plot's choices: the Whipple bicycle's inputs and outputs."""


def _handling_panel():
    """Handling: the Bode plot of one input and output at one speed, and the Hess, Moore & Hubbard
    (2012) rider's handling quality metric against speed."""

    controls = html.Div(className="numbers", children=[
        html.Div(["speed (m/s) ", dcc.Input(id="bode-speed", type="text", value="5", debounce=True,
                                            inputMode="decimal", style={"width": "70px"})]),
        html.Div(["input ", dcc.Dropdown(id="bode-input", options=list(BODE_INPUTS), value="steer-torque",
                                         clearable=False, style={"width": "170px"})]),
        html.Div(["output ", dcc.Dropdown(id="bode-output", options=list(BODE_OUTPUTS), value="roll-angle",
                                          clearable=False, style={"width": "170px"})])])
    return html.Div(className="grid2", children=[
        _panel("Frequency response (Bode plot)",
               html.Div([controls, html.Div(id="bode-error", className="error"),
                         dcc.Loading(html.Img(id="bode-figure", alt="Bode plot"))])),
        _panel(f"Handling: the Hess, Moore & Hubbard (2012) rider at "
               f"{', '.join(f'{v:g}' for v in HANDLING_SPEEDS)} m/s (docs/handling.md)",
               dcc.Loading(html.Div([html.Img(id="hqm-figure", alt="handling quality metric"),
                                     html.Div(id="hqm-summary")])))])


def _editor(summary, kind, keys, values, unit, label):
    """A table of text inputs ``{"type": kind, "key": key}``, empty = the computed value."""
    return html.Details(open=True, children=[
        html.Summary(summary),
        html.Table(className="params", children=[
            html.Tr([html.Td(label(key)),
                     html.Td(dcc.Input(id={"type": kind, "key": key}, type="text", debounce=True,
                                       value=_shown(values.get(key)), inputMode="decimal",
                                       style={"width": "130px"})),
                     html.Td(unit(key))]) for key in keys])])


def _panel(title, content):
    return html.Div(className="figure", children=[html.H4(title), content])


def _shown(value):
    return "" if value is None else repr(value)


def _parse(keys, texts, prefix=""):
    """``{key: float or None}`` from typed texts (empty = None); InputError names a bad one."""
    out = {}
    for key, text in zip(keys, texts):
        text = "" if text is None else str(text).strip()
        try:
            out[key] = float(text) if text else None
        except ValueError:
            raise InputError(SOURCE, prefix + key, "a number") from None
    return out


def _number(what, ident):
    return html.Div(className="number", children=[html.Div(what, className="what"),
                                                  html.Div(id=ident, className="value")])


def _speed_text(speeds, kinds):
    return f"{speeds[0]:.4f} m/s" if speeds else f"none (no {kinds} crossing)"


def _range_text(ranges):
    return ", ".join(f"{a:.3f}-{b:.3f}" for a, b in ranges) + " m/s" if ranges else "none"


def _svg_uri(fig):
    return "data:image/svg+xml;base64," + base64.b64encode(figure_bytes(fig, "svg")).decode()


def _html_table(headers, rows):
    return html.Table(className="params", children=[html.Tr([html.Th(h) for h in headers])]
                      + [html.Tr([html.Td(c) for c in row]) for row in rows])


def _bodies_table(p):
    """Mass, CoM and principal moments of inertia of the four benchmark bodies."""
    com = {"R": (0.0, -p.rR), "B": (p.xB, p.zB), "H": (p.xH, p.zH), "F": (p.w, -p.rF)}
    names = {"R": "rear wheel", "B": "rear frame (+ rider)", "H": "front frame", "F": "front wheel"}
    rows = []
    for body in "RBHF":
        moments = np.linalg.eigvalsh(p.inertia(body))
        rows.append([names[body], f"{getattr(p, 'm' + body):.3f}", f"{com[body][0]:.3f}", f"{com[body][1]:.3f}",
                     "  ".join(f"{m:.4f}" for m in moments)])
    return _html_table(["body", "mass (kg)", "x (m)", "z (m)", "principal I (kg m^2)"], rows)


def _geometry_table(chart):
    rows = [[key.replace("_", " "), f"{chart[key]:.1f} deg" if key in ANGLES else f"{1000 * chart[key]:.1f} mm"]
            for key in CHART_ORDER if chart.get(key) is not None]
    return _html_table(["quantity", "value"], rows)


def _state(bike, size, rider, body, stiffness, combine, chart_texts, param_texts, model=BASE):
    """The :class:`PageState` of the controls' values, checked as a URL's query is; InputError
    names a bad typed value."""
    state = PageState.from_query({"bike": bike, "size": size or "", "rider": rider, "stiffness": stiffness,
                                  "combine": combine, "model": model})
    if rider == BODY_RIDER:
        state = state.with_body(*body)
    state = state.with_chart(_parse(CHART_KEYS, chart_texts, "chart."))
    return state.with_overrides(_parse(NAMES, param_texts))


def _results(engine, state):
    """Everything the page shows for ``state``, the eigenvalue figure drawn (an SVG data URL), computed
    inside :meth:`Engine.answer` and kept there."""
    evaluation = engine.evaluate(state)
    base = engine.base_parameters(state.bicycle_key, state.rider_key, state.combine).to_dict()
    bicycle = engine.bicycle(state.bicycle_key)
    figure = _svg_uri(_eigenvalue_figure(evaluation.stability, state, _bike_shown(engine, state), engine.rider_label(state)))
    return evaluation, base, derived_chart(bicycle), engine.is_chart(state.bike), figure


STALE_NOTE = "The results below are those of the last good configuration, not of the values above."
"""Shown (with the results dimmed) while an error stands."""
FIELDS = {"bike": "Bicycle", "size": "Size", "rider": "Rider", "stiffness": "Rear-frame stiffness",
          "combine": "Rider + rear frame", "model": "Model", "height": "Rider height (m)", "mass": "Rider mass (kg)",
          "sex": "Rider sex", "hands": "Hands on the", "bode speed": "Bode plot speed (m/s)"}
"""The page's name of each field a query key comes from."""


def _field_error(exc, field=None):
    """The one line the page shows for ``exc``: named by the field the user typed in (``field``, or
    the one its key comes from when it names the page's query or the edited chart), not by the
    internal sources ``URL`` and ``<mapping>``; an error about a file (an upload) stays as it is."""
    key = str(exc.key)
    if field is None:
        if str(exc.source) not in (SOURCE, "<mapping>"):
            return str(exc)
        field = (f"Geometry chart, {key.removeprefix('chart.').replace('_', ' ')}" if key.startswith("chart.")
                 else f"Benchmark parameter {key}" if key in NAMES else FIELDS.get(key, key))
    return f"{field}: {exc.expected}"


def _callbacks(app, engine):
    @app.callback(Output("bike", "options"), Output("bike", "value"),
                  Output("error", "children", allow_duplicate=True),
                  Input("upload", "contents"), State("upload", "filename"), State("bike", "options"),
                  prevent_initial_call=True)
    def upload(contents, filename, options):
        shown = filename or "upload.yaml"
        try:
            if not contents or "," not in contents:
                raise InputError(shown, "(file)", "a file's content (the upload was empty)")
            data = base64.b64decode(contents.split(",", 1)[1], validate=True)
            name = engine.add_upload(shown, data)
        except InputError as exc:
            return no_update, no_update, str(exc)
        except ValueError:
            return no_update, no_update, str(InputError(shown, "(file)", "a readable upload (base64 content)"))
        label = {"label": f"{engine.upload_label(name)} (uploaded)", "value": name}
        kept = [o for o in options if (o.get("value") if isinstance(o, dict) else o) != name]
        return kept + [label], name, ""

    @app.callback(Output("size", "options"), Output("size", "value"), Output("size", "disabled"),
                  Output("stiffness", "options"),
                  Output({"type": "chart", "key": ALL}, "value"), Output({"type": "param", "key": ALL}, "value"),
                  Input("bike", "value"), State("size", "value"), State("stiffness", "value"))
    def bike_changed(bike, size, stiffness):
        try:
            sizes = list(engine.answer(_sizes, engine, PageState(bike=bike))[0])
        except InputError:
            sizes = []
        size = size if size in sizes else (sizes[0] if sizes else None)
        try:
            materials = list(engine.answer(_materials, engine, PageState(bike=bike, size=size or ""))[0])
        except InputError:
            materials = [stiffness]
        materials += [stiffness] if stiffness not in materials else []
        if ctx.triggered_id is None:      # the page opened: keep what the URL said
            return sizes, size, not sizes, materials, [no_update] * len(CHART_KEYS), [no_update] * len(NAMES)
        return sizes, sizes[0] if sizes else None, not sizes, materials, [""] * len(CHART_KEYS), [""] * len(NAMES)

    @app.callback(Output("weave-speed", "children"), Output("capsize-speed", "children"),
                  Output("stable-range", "children"), Output("total-mass", "children"),
                  Output("eig-figure", "src"), Output("stiffness-matrix", "children"),
                  Output("bodies", "children"), Output("geometry", "children"),
                  Output("downloads", "children"), Output("url", "search"),
                  Output({"type": "param", "key": ALL}, "placeholder"),
                  Output({"type": "chart", "key": ALL}, "placeholder"),
                  Output("chart-editor", "style"),
                  Output("warnings", "children"),
                  Output("error", "children"), Output("results", "className"), Output("address-error", "data"),
                  Input("bike", "value"), Input("size", "value"), Input("rider", "value"),
                  Input("height", "value"), Input("mass", "value"), Input("sex", "value"), Input("hands", "value"),
                  Input("stiffness", "value"), Input("combine", "value"),
                  Input({"type": "chart", "key": ALL}, "value"), Input({"type": "param", "key": ALL}, "value"),
                  Input("model", "value"), State("address-error", "data"))
    def update(bike, size, rider, height, mass, sex, hands, stiffness, combine, chart_texts, param_texts, model,
               address_error):
        unchanged = (no_update,) * 10 + ([no_update] * len(NAMES), [no_update] * len(CHART_KEYS)) + (no_update,) * 2
        try:
            state = _state(bike, size, rider, (height, mass, sex, hands), stiffness, combine, chart_texts,
                           param_texts, model)
            if address_error and state == PageState():
                # a bad link: the controls show the default page, which the link did not ask for; its
                # error and its address stay until the user changes a control
                return unchanged + (no_update,) * 3
            (evaluation, base, chart, editable, figure), lines = engine.answer(_results, engine, state)
        except InputError as exc:         # the last good results stay (docs/web.md), marked stale
            return unchanged + (_field_error(exc), "results stale", no_update)
        result, p, S = evaluation.stability, evaluation.parameters, evaluation.stiffness
        matrix = "rigid (infinite)" if S is None else "\n".join("  ".join(f"{x:12.1f}" for x in row) for row in S)
        query = state.to_query()
        links = [html.A(DOWNLOADS[name][1], href=f"/download/{name}?{query}", download="")
                 for name in DOWNLOADS if name != "pose.yaml" or state.rider != "none"]
        shown = [_placeholder(k, chart.get(k)) if editable else "" for k in CHART_KEYS]
        message = no_update if ctx.triggered_id is None and not address_error else ""
        return (_speed_text(result.weave_speeds, "weave"), _speed_text(result.capsize_speeds, "capsize"),
                _range_text(result.ranges["strict"]["exact"]), f"{p.mB + p.mH + p.mR + p.mF:.2f} kg",
                figure, matrix, _bodies_table(p), _geometry_table(chart),
                links, "?" + query, [f"{base[n]:.6g}" for n in NAMES], shown,
                {} if editable else {"display": "none"}, [html.Li(f"warning: {line}") for line in lines], message,
                "results", None)

    @app.callback(Output("side-view", "src"), Input("bike", "value"), Input("size", "value"),
                  Input("rider", "value"), Input("height", "value"), Input("mass", "value"),
                  Input("sex", "value"), Input("hands", "value"), Input({"type": "chart", "key": ALL}, "value"))
    def side_view(bike, size, rider, height, mass, sex, hands, chart_texts):
        try:
            state = _state(bike, size, rider, (height, mass, sex, hands), "infinite", "exact", chart_texts,
                           [""] * len(NAMES))
            return engine.answer(_side_view_uri, engine, state)[0]
        except InputError:                # the last good side view stays
            return no_update

    configuration = [Input("bike", "value"), Input("size", "value"), Input("rider", "value"),
                     Input("height", "value"), Input("mass", "value"), Input("sex", "value"), Input("hands", "value"),
                     Input("stiffness", "value"), Input("combine", "value"),
                     Input({"type": "chart", "key": ALL}, "value"), Input({"type": "param", "key": ALL}, "value"),
                     Input("model", "value")]

    @app.callback(Output("bode-figure", "src"), Output("bode-error", "children"), Output("bode-figure", "className"),
                  *configuration, Input("bode-speed", "value"), Input("bode-input", "value"),
                  Input("bode-output", "value"))
    def bode(bike, size, rider, height, mass, sex, hands, stiffness, combine, chart_texts, param_texts, model,
             speed, inp, out):
        """The Bode figure; on an error the last good figure stays, dimmed, and the error names the field."""
        try:
            state = _state(bike, size, rider, (height, mass, sex, hands), stiffness, combine, chart_texts,
                           param_texts, model)
            v = _parse(["bode speed"], [speed])["bode speed"]
            uri = engine.answer(_bode_uri, engine, state, 5.0 if v is None else v, inp, out)[0]
        except InputError as exc:
            field = FIELDS["bode speed"] if str(exc.source) == "speed" or exc.key == "bode speed" else None
            return no_update, _field_error(exc, field), "stale"
        return uri, "", ""

    @app.callback(Output("hqm-figure", "src"), Output("hqm-summary", "children"), Output("hqm-figure", "className"),
                  *configuration)
    def handling_quality(bike, size, rider, height, mass, sex, hands, stiffness, combine, chart_texts,
                         param_texts, model):
        """The HQM figure; on an error the last good figure stays, dimmed, with the error below it."""
        try:
            state = _state(bike, size, rider, (height, mass, sex, hands), stiffness, combine, chart_texts,
                           param_texts, model)
            uri, summary = engine.answer(_handling_uri, engine, state)[0]
        except InputError as exc:
            return no_update, _field_error(exc), "stale"
        return uri, summary, ""

    @app.callback(Output("body-controls", "style"), Input("rider", "value"))
    def body_controls(rider):
        return {} if rider == BODY_RIDER else {"display": "none"}


def _sizes(engine, state):
    """The size names of ``state``'s bicycle (cached by :meth:`~.engine.Engine.answer`)."""
    return tuple(engine.sizes(state.bike))


def _materials(engine, state):
    """The stiffness choices of ``state``'s bicycle and size (cached by :meth:`~.engine.Engine.answer`)."""
    return tuple(engine.materials(state.bike, state.size))


def _side_view_uri(engine, state):
    """The side view of ``state``'s bicycle and seated rider (an SVG data URL)."""
    bicycle = engine.bicycle(state.bicycle_key)
    return _svg_uri(_side_view_figure(bicycle, engine.seated(state.bicycle_key, state.rider_key)))


def _bode_uri(engine, state, speed, inp, out):
    """The Bode figure of ``state`` at ``speed`` (m/s) from ``inp`` to ``out`` (an SVG data URL)."""
    response = frequency_response(engine.model(state), speed, inp, out)
    return _svg_uri(_bode_figure(response, _bike_shown(engine, state)))


def _handling_uri(engine, state):
    """The HQM figure of ``state`` (an SVG data URL) and the summary line."""
    result = engine.handling(state)
    stable = engine.evaluate(state).stability.ranges["strict"]["exact"]
    return _svg_uri(_handling_figure(result, stable, _bike_shown(engine, state), engine.rider_label(state))), _handling_summary(result)


def _placeholder(key, value):
    """A derived chart value as the editor shows it: mm, or degrees for angles."""
    if value is None:
        return ""
    return f"{value:.2f}" if key in CHART_ANGLES else f"{1000 * value:.1f}"


def _bike_shown(engine, state):
    """The bicycle as a figure title names it: its file's ``name:`` (an upload's too), else the file name
    it was uploaded as or the shipped name (an ``upload-<secret>`` name is a key, not a title)."""
    return engine.bike_name(state)


def _eigenvalue_figure(result, state, bike, rider):
    model = "" if state.model == BASE else f", model {state.model}"
    return plot_eigenvalues(result, title=f"{bike}, {rider}, stiffness {state.stiffness}{model}")


def _bode_figure(fr, bike):
    return plot_bode(fr, f"{bike}: {fr.output} / {fr.input} at {fr.speed:g} m/s", size=(6.4, 4.6))


def _handling_figure(result, stable, bike, rider):
    return plot_handling(result, f"{bike}, {rider}: handling quality metric", size=(8.0, 3.4),
                         stable_speeds=stable)


def _handling_summary(result):
    """One line per speed: the HQM peak and level, or why there is none."""
    lines = []
    for v, peak, gains, stable, level in zip(result.speeds, result.hqm_peak, result.gains, result.closed_loop_stable,
                                             result.levels):
        if gains is None:
            lines.append(f"{v:g} m/s: no gains found by the published procedure")
        elif not stable:
            lines.append(f"{v:g} m/s: closed loop unstable, no handling level")
        elif level is None:
            lines.append(f"{v:g} m/s: HQM peak not finite, no handling level")
        else:
            lines.append(f"{v:g} m/s: HQM peak {peak:.2f} (Level {level})")
    return "; ".join(lines)


def _side_view_figure(bicycle, rider):
    title = bicycle.name + (f" + rider {rider.name}" if rider is not None else "")
    return plot_side_view(bicycle, rider, title=title)
