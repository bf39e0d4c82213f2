"""The JSON API and the downloads behind the page (Flask routes on the Dash server).

``GET /api/stability?<state>`` returns the document of ``bikemass stability
--format json``, ``GET /api/params?<state>`` that of ``bikemass params
--format json`` and ``GET /api/handling?<state>`` that of ``bikemass handling --speeds
3,4,5,6,7,8,10 --format json`` (the rider in the loop), each with the ``warnings`` the command
line gives (a list, empty when there are none); ``/download/<file>?<state>`` serves the parameter set (YAML,
JSON, BicycleParameters), the eigenvalues (CSV) and the bicycle and pose YAML.
A bad query answers 400 with ``{"error": "<one line>"}``.  A JSON answer is kept as its text
(:meth:`~.engine.Engine.answer`), so asking again costs a lookup, not the engine's lock.
"""

import yaml
from flask import Response, current_app, jsonify, request

from ..analysis.eigen_table import eig_table
from ..core.errors import InputError
from ..core.gate import read_text
from ..core.output import strict_json, with_units, written
from ..core.paths import resolve
from ..core.plain import file_form, plain
from ..models.parameter_export import format_parameters
from ..models.parameters import parameter_units
from ..rider import poses_dir
from .state import PageState

DOWNLOADS = {
    "parameters.yaml": ("application/x-yaml", "the benchmark parameter set (YAML)"),
    "parameters.json": ("application/json", "the benchmark parameter set (JSON)"),
    "Benchmark.txt": ("text/plain", "the parameter set as a BicycleParameters file"),
    "eigenvalues.csv": ("text/csv", "eigenvalues against speed (CSV)"),
    "bicycle.yaml": ("application/x-yaml", "the bicycle file"),
    "pose.yaml": ("application/x-yaml", "the rider's pose file"),
}
"""Download file names -> (MIME type, what the page calls them)."""


def stability_document(evaluation):
    """The ``bikemass stability --format json`` document of an :class:`~.engine.Evaluation`."""
    return written(with_units(plain({"frame": evaluation.frame, **evaluation.stability.to_dict()}),
                              evaluation.stability.units()))


def parameters_document(params):
    """The ``bikemass params --format json`` document of a parameter set."""
    return written(with_units(params.to_dict(), parameter_units()))


def handling_document(result):
    """The ``bikemass handling --format json`` document of a :class:`HandlingResult`."""
    return written(with_units(result.to_dict(), result.unit_block()))


def download(engine, filename, state):
    """``(bytes, mime type)`` of the download ``filename`` for ``state``; InputError if unknown."""
    if filename not in DOWNLOADS:
        raise InputError("URL", "download", f"one of {', '.join(DOWNLOADS)}")
    mime = DOWNLOADS[filename][0]
    title = f"{state.bike} with rider {state.rider} (bikemass web page)"
    if filename == "parameters.yaml":
        text = format_parameters(engine.parameters(state), "yaml")
    elif filename == "parameters.json":
        text = format_parameters(engine.parameters(state), "json")
    elif filename == "Benchmark.txt":
        text = format_parameters(engine.parameters(state), "bicycleparameters", title)
    elif filename == "eigenvalues.csv":
        text = eig_table(engine.evaluate(state).stability.modes, csv=True)
    elif filename == "bicycle.yaml":
        text = engine.download_source(state)
    else:
        rider = engine.rider(state.rider_key)
        if isinstance(rider, dict):
            return yaml.safe_dump(file_form(rider), sort_keys=False).encode(), mime
        if rider is None:
            raise InputError("URL", "rider", "a rider (this configuration has none)")
        text = read_text(resolve(rider.pose, poses_dir(), "pose"))
    return text.encode(), mime


def register_routes(server, engine):
    """Add the API and download routes to the Flask ``server``."""
    def state_or_error():
        return PageState.from_query(request.args.to_dict())

    def answer(make):
        try:
            return make(state_or_error())
        except InputError as exc:
            return jsonify({"error": str(exc)}), 400

    def with_warnings(route, document, compute, state):
        dumps = current_app.json.dumps
        text = engine.answer(compute, state, key=(route, state),      # strict JSON: a NaN is null
                             render=lambda value, lines: dumps(strict_json({**document(value), "warnings": lines})))
        return Response(text, mimetype="application/json")

    @server.route("/api/stability")
    def api_stability():
        return answer(lambda s: with_warnings("stability", stability_document, engine.evaluate, s))

    @server.route("/api/params")
    def api_params():
        return answer(lambda s: with_warnings("params", parameters_document, engine.parameters, s))

    @server.route("/api/handling")
    def api_handling():
        return answer(lambda s: with_warnings("handling", handling_document, engine.handling, s))

    @server.route("/download/<filename>")
    def api_download(filename):
        def send(state):
            if filename not in DOWNLOADS:
                raise InputError("URL", "download", f"one of {', '.join(DOWNLOADS)}")
            data, mime = engine.answer(download, engine, filename, state, key=("download", filename, state))[0]
            name = f"{state.bike}-{filename}" if filename != "Benchmark.txt" else f"{state.bike}Benchmark.txt"
            return Response(data, mimetype=mime,
                            headers={"Content-Disposition": f'attachment; filename="{name}"'})
        return answer(send)
