"""The JSON API and the downloads behind the page (Flask routes on the Dash server).

``GET /api/stability?<state>`` returns the document of ``bikemass stability
--format json`` and ``GET /api/params?<state>`` that of ``bikemass params
--format json``, each with the ``warnings`` the command line gives (a list, empty
when there are none); ``/download/<file>?<state>`` serves the parameter set (YAML,
JSON, BicycleParameters), the eigenvalues (CSV) and the bicycle and pose YAML.
A bad query answers 400 with ``{"error": "<one line>"}``.
"""

from ..errors import InputError
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
    from ..output import plain, with_units, written
    return written(with_units(plain(evaluation.stability.to_dict())))


def parameters_document(params):
    """The ``bikemass params --format json`` document of a parameter set."""
    from ..output import with_units, written
    return written(with_units(params.to_dict()))


def download(engine, filename, state):
    """``(bytes, mime type)`` of the download ``filename`` for ``state``; InputError if unknown."""
    from ..exporters import format_parameters
    from ..gate import read_text

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
        from ..commands.stability import eig_table
        text = eig_table(engine.evaluate(state).stability.modes, csv=True)
    elif filename == "bicycle.yaml":
        text = engine.download_source(state)
    else:
        rider = engine.rider(state.rider_key)
        if isinstance(rider, dict):
            import yaml
            return yaml.safe_dump(rider, sort_keys=False).encode(), mime
        if rider is None:
            raise InputError("URL", "rider", "a rider (this configuration has none)")
        from ..paths import resolve
        from ..rider import poses_dir
        text = read_text(resolve(rider.pose, poses_dir(), "pose"))
    return text.encode(), mime


def register_routes(server, engine):
    """Add the API and download routes to the Flask ``server``."""
    from flask import Response, jsonify, request

    def state_or_error():
        return PageState.from_query(request.args.to_dict())

    def answer(make):
        try:
            return make(state_or_error())
        except InputError as exc:
            return jsonify({"error": str(exc)}), 400

    def with_warnings(document, compute, state):
        value, lines = engine.answer(compute, state)
        return jsonify({**document(value), "warnings": lines})

    @server.route("/api/stability")
    def api_stability():
        return answer(lambda s: with_warnings(lambda e: stability_document(e), engine.evaluate, s))

    @server.route("/api/params")
    def api_params():
        return answer(lambda s: with_warnings(parameters_document, engine.parameters, s))

    @server.route("/download/<filename>")
    def api_download(filename):
        def send(state):
            data, mime = engine.answer(lambda st: download(engine, filename, st), state)[0]
            name = f"{state.bike}-{filename}" if filename != "Benchmark.txt" else f"{state.bike}Benchmark.txt"
            return Response(data, mimetype=mime,
                            headers={"Content-Disposition": f'attachment; filename="{name}"'})
        return answer(send)
