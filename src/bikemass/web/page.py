"""The Dash page: controls on the left, results on the right, state in the URL.

The layout is built per request from the URL's query (so a link opens its
configuration); every change of a control recomputes through the cached
:class:`~.engine.Engine` and writes the new state back into the URL.
"""

import base64
import io

from ..errors import InputError
from ..parameters import DESCRIPTIONS, NAMES
from .api import DOWNLOADS
from .state import COMBINE_CHOICES, STIFFNESS_CHOICES, PageState

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


def create_app(engine=None):
    """The Dash application (its Flask server has the JSON API and downloads)."""
    from dash import Dash

    from .api import register_routes
    from .engine import Engine

    engine = engine or Engine()
    import dash

    app = Dash(__name__, title="bikemass", update_title=None, serve_locally=True, use_pages=True,
               pages_folder="", index_string=INDEX, suppress_callback_exceptions=True)
    dash.register_page("explorer", path="/", title="bikemass", layout=lambda **query: _layout(query))
    app.layout = dash.page_container
    _callbacks(app, engine)
    register_routes(app.server, engine)
    app.server.json.sort_keys = False
    app.engine = engine
    return app


def _shipped():
    from ..paths import available, frames_dir
    from ..rider import shipped_poses
    return available(frames_dir()), ["none"] + shipped_poses()


def _layout(query):
    """The page for the URL query ``query`` (a mapping of strings); a bad query shows its error."""
    from dash import dcc, html

    try:
        state, error = PageState.from_query(query), ""
    except InputError as exc:
        state, error = PageState(), str(exc)
    bikes, riders = _shipped()
    bike_options = bikes + [b for b in [state.bike] if b not in bikes]
    overrides = dict(state.overrides)
    controls = html.Div(className="controls", children=[
        html.Label("Bicycle", htmlFor="bike"),
        dcc.Dropdown(id="bike", options=bike_options, value=state.bike, clearable=False),
        dcc.Upload(id="upload", children=html.A("or upload a bicycle file (YAML, chart, BicycleParameters)"),
                   max_size=1_000_000, style={"fontSize": "12px", "cursor": "pointer"}),
        html.Label("Rear-frame stiffness", htmlFor="stiffness"),
        dcc.Dropdown(id="stiffness", options=list(STIFFNESS_CHOICES), value=state.stiffness, clearable=False),
        html.Label("Rider", htmlFor="rider"),
        dcc.Dropdown(id="rider", options=riders, value=state.rider, clearable=False),
        html.Label("Rider + rear frame"),
        dcc.RadioItems(id="combine", value=state.combine, inline=True, options=[
            {"label": " parallel-axis (exact) ", "value": "exact"},
            {"label": " thesis Eq. 3.6", "value": "thesis"}]),
        html.Details(open=True, children=[
            html.Summary("Benchmark parameters: type a value to override, empty = computed"),
            html.Table(className="params", children=[
                html.Tr([html.Td(name, title=DESCRIPTIONS[name]),
                         html.Td(dcc.Input(id={"type": "param", "name": name}, type="text", debounce=True,
                                           value=_shown(overrides.get(name)), inputMode="decimal")),
                         html.Td(DESCRIPTIONS[name].split("[")[-1].rstrip("]"))])
                for name in NAMES])]),
    ])
    results = html.Div(className="results", children=[
        html.Div(id="error", className="error", children=error),
        dcc.Loading(type="dot", children=html.Div(className="numbers", children=[
            _number("weave speed", "weave-speed"), _number("capsize speed", "capsize-speed"),
            _number("stable speeds", "stable-range"), _number("total mass", "total-mass")])),
        html.Div(className="grid2", children=[
            html.Div(className="figure", children=dcc.Loading(html.Img(id="eig-figure", alt="eigenvalues"))),
            html.Div(className="figure", children=dcc.Loading(html.Img(id="side-view", alt="side view")))]),
        html.Div(className="grid2", children=[
            html.Div(className="figure", children=[html.H4("Frame stiffness S (N m/rad)"),
                                                    html.Pre(id="stiffness-matrix")]),
            html.Div(className="figure", children=[html.H4("Downloads"),
                                                    html.Div(id="downloads", className="downloads")])]),
    ])
    return html.Div([
        dcc.Location(id="url", refresh=False),
        dcc.Store(id="uploaded"),
        html.Header([html.H1("bikemass"), html.Span("a bicycle and its rider: parameters and stability")]),
        html.Div(className="columns", children=[controls, results]),
    ])


def _shown(value):
    return "" if value is None else repr(value)


def _parse_overrides(values):
    """``{name: float or None}`` from the typed texts; InputError names a bad one."""
    from .state import SOURCE

    out = {}
    for name, text in zip(NAMES, values):
        text = (text or "").strip()
        if not text:
            out[name] = None
            continue
        try:
            out[name] = float(text)
        except ValueError:
            raise InputError(SOURCE, name, f"a number in SI units ({DESCRIPTIONS[name]})") from None
    return out


def _number(what, ident):
    from dash import html
    return html.Div(className="number", children=[html.Div(what, className="what"),
                                                  html.Div(id=ident, className="value")])


def _speed_text(speeds, kinds):
    return f"{speeds[0]:.4f} m/s" if speeds else f"none (no {kinds} crossing)"


def _range_text(ranges):
    return ", ".join(f"{a:.3f}-{b:.3f}" for a, b in ranges) + " m/s" if ranges else "none"


def _svg_uri(fig):
    buffer = io.BytesIO()
    fig.savefig(buffer, format="svg", bbox_inches="tight")
    return "data:image/svg+xml;base64," + base64.b64encode(buffer.getvalue()).decode()


def _callbacks(app, engine):
    from dash import ALL, Input, Output, State, ctx, no_update

    @app.callback(Output("bike", "options"), Output("bike", "value"), Output("error", "children",
                                                                              allow_duplicate=True),
                  Input("upload", "contents"), State("upload", "filename"), State("bike", "options"),
                  prevent_initial_call=True)
    def upload(contents, filename, options):
        try:
            data = base64.b64decode(contents.split(",", 1)[1])
            name = engine.add_upload(filename or "upload.yaml", data)
        except InputError as exc:
            return no_update, no_update, str(exc)
        except (ValueError, IndexError):
            return no_update, no_update, f"{filename}: (file): a readable upload"
        label = {"label": f"{engine.upload_label(name)} (uploaded)", "value": name}
        return [o for o in options if o != name] + [label], name, ""

    @app.callback(Output("weave-speed", "children"), Output("capsize-speed", "children"),
                  Output("stable-range", "children"), Output("total-mass", "children"),
                  Output("eig-figure", "src"), Output("stiffness-matrix", "children"),
                  Output("downloads", "children"), Output("url", "search"),
                  Output({"type": "param", "name": ALL}, "placeholder"),
                  Output("error", "children"),
                  Input("bike", "value"), Input("rider", "value"), Input("stiffness", "value"),
                  Input("combine", "value"), Input({"type": "param", "name": ALL}, "value"))
    def update(bike, rider, stiffness, combine, values):
        from dash import html

        state = PageState(bike=bike, rider=rider, stiffness=stiffness, combine=combine)
        blank = ("-",) * 4 + ("", "", [], no_update, [None] * len(NAMES))
        try:
            state = state.with_overrides(_parse_overrides(values))
            evaluation = engine.evaluate(state)
            base = engine.base_parameters(state.bike, state.rider, state.combine).to_dict()
        except InputError as exc:
            return blank + (str(exc),)
        result, p = evaluation.stability, evaluation.parameters
        figure = _eigenvalue_figure(result, state)
        S = evaluation.stiffness
        matrix = "rigid (infinite)" if S is None else "\n".join("  ".join(f"{x:12.1f}" for x in row) for row in S)
        query = state.to_query()
        links = [html.A(DOWNLOADS[name][1], href=f"/download/{name}?{query}", download="")
                 for name in DOWNLOADS if name != "pose.yaml" or state.rider != "none"]
        mass = p.mB + p.mH + p.mR + p.mF
        message = no_update if ctx.triggered_id is None else ""
        return (_speed_text(result.weave_speeds, "weave"), _speed_text(result.capsize_speeds, "capsize"),
                _range_text(result.ranges["strict"]["exact"]), f"{mass:.2f} kg", _svg_uri(figure), matrix,
                links, "?" + query, [f"{base[n]:.6g}" for n in NAMES], message)

    @app.callback(Output("side-view", "src"), Input("bike", "value"), Input("rider", "value"))
    def side_view(bike, rider):
        try:
            return _svg_uri(_side_view_figure(engine.bicycle(bike), engine.rider(rider)))
        except InputError:
            return ""



def _eigenvalue_figure(result, state):
    from ..plots.stability import plot_eigenvalues
    return plot_eigenvalues(result, title=f"{state.bike}, rider {state.rider}, stiffness {state.stiffness}")


def _side_view_figure(bicycle, rider):
    from ..bicycle.drawing import plot_side_view
    title = bicycle.name + (f" + rider {rider.name}" if rider is not None else "")
    return plot_side_view(bicycle, rider, title=title)
