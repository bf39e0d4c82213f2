"""The web page's callback requests, checked before Dash parses them.

Dash answers each change on the page through ``POST /_dash-update-component`` with a JSON
body naming the callback (``output``), its ``inputs``, ``state``, ``outputs`` and
``changedPropIds``.  A body Dash did not write (``{}``, nesting 100,000 deep, ``NaN``, a
number where a name goes, ``null`` file contents, 50 MB) must be refused, not crash the
server: :func:`guard_requests` bounds the body's size (``413``) before a byte is parsed,
refuses what is not JSON, is nested deeper than :data:`MAX_DEPTH` or holds ``NaN``/
``Infinity``, and checks the body against the callback it names: the outputs, inputs and
state it declares, each value of the type its component gives (``400`` with
``{"error": "<one line>"}``).
"""

import json

from flask import jsonify, request

from ..core.errors import one_line
from ..core.gate import flow_depth_line

CALLBACK_PATH = "_dash-update-component"
MAX_BODY = 3_000_000
"""Largest callback body (bytes): an upload of the largest size, base64-encoded (4/3), and the
page's other values."""
MAX_DEPTH = 16
"""Deepest JSON nesting of a callback body (Dash's own bodies nest 5 levels)."""


class BadRequest(ValueError):
    """A callback body that Dash's page did not write; the message is one line."""


def guard_requests(app, value_checks):
    """Check every callback request to the Dash ``app`` before Dash reads it.

    Parameters
    ----------
    app : dash.Dash
        The application; its Flask server gets a body limit (:data:`MAX_BODY`) and the check.
    value_checks : dict
        ``{"<component id or pattern type>.<property>": (check, what)}``: ``check(value)`` is
        True for a value that component may send, ``what`` says what was expected.  A value of
        a property not listed must be a string, a number, a boolean or null.
    """
    server = app.server
    server.config["MAX_CONTENT_LENGTH"] = MAX_BODY
    path = app.config.routes_pathname_prefix + CALLBACK_PATH

    @server.before_request
    def check_callback():
        if request.path != path:
            return None
        try:
            body = parse_body(request.get_data(cache=True))    # over MAX_BODY: 413 before reading
            check_body(body, app.callback_map, value_checks)
        except BadRequest as exc:
            return jsonify({"error": one_line(f"callback request: {exc}", 600)}), 400
        return None


def parse_body(data):
    """The JSON of a callback body (bytes); BadRequest unless UTF-8 JSON without NaN or Infinity,
    nested at most :data:`MAX_DEPTH` levels (measured before parsing)."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise BadRequest("a UTF-8 body") from None
    if flow_depth_line(text, MAX_DEPTH) is not None:
        raise BadRequest(f"JSON nested at most {MAX_DEPTH} levels deep")

    def refuse(constant):
        raise BadRequest(f"finite numbers, got {constant}")
    try:
        return json.loads(text, parse_constant=refuse)
    except BadRequest:
        raise
    except (ValueError, RecursionError):
        raise BadRequest("a JSON body") from None


def check_body(body, callback_map, value_checks):
    """BadRequest unless ``body`` is a call of a callback in ``callback_map`` as Dash writes it."""
    if not isinstance(body, dict):
        raise BadRequest("a JSON object")
    output = body.get("output")
    if not isinstance(output, str) or output not in callback_map:
        raise BadRequest("'output' naming a callback of this page")
    changed = body.get("changedPropIds", [])
    if not isinstance(changed, list) or not all(isinstance(c, str) for c in changed):
        raise BadRequest("'changedPropIds' as a list of strings")
    _check_outputs(output, body.get("outputs"))
    callback = callback_map[output]
    for part in ("inputs", "state"):
        declared, given = callback[part], body.get(part, [])
        if not isinstance(given, list) or len(given) != len(declared):
            raise BadRequest(f"'{part}': the {len(declared)} this callback takes")
        for want, item in zip(declared, given):
            _check_item(want, item, value_checks)


def declared_outputs(output):
    """``[(id, property), ...]`` of a callback's ``output`` key as Dash writes it: one
    ``id.property``, or several as ``..a.x...b.y..``; ``@<hash>`` (a duplicate output) dropped;
    a pattern id stays its JSON text."""
    parts = output[2:-2].split("...") if output.startswith("..") else [output]
    return [tuple(part.split("@", 1)[0].rsplit(".", 1)) for part in parts]


def _same_id(declared, given):
    if declared.startswith("{"):
        return isinstance(given, dict) and given.get("type") == json.loads(declared).get("type")
    return given == declared


def _check_outputs(output, outputs):
    """The ``outputs`` spec of a body: one entry per declared output (a list for a pattern)."""
    declared = declared_outputs(output)
    given = [outputs] if len(declared) == 1 and not isinstance(outputs, list) else outputs
    if not isinstance(given, list) or len(given) != len(declared):
        raise BadRequest(f"'outputs': the {len(declared)} this callback gives")
    for (ident, prop), spec in zip(declared, given):
        entries = spec if isinstance(spec, list) and ident.startswith("{") else [spec]
        for entry in entries:
            if not (isinstance(entry, dict) and _same_id(ident, entry.get("id"))
                    and isinstance(entry.get("property"), str) and entry["property"].split("@", 1)[0] == prop):
                raise BadRequest(f"'outputs' entries for {ident}.{prop} as Dash writes them")


def _check_item(want, item, value_checks):
    """One input or state entry: the declared component's property, its value of the right type;
    a pattern (``{"type": ..., "key": ALL}``) is a list of such entries."""
    ident, prop = want["id"], want["property"]
    if isinstance(ident, str) and ident.startswith("{"):
        kind = json.loads(ident).get("type")
        if not isinstance(item, list):
            raise BadRequest(f"a list of {kind} values for {prop}")
        for entry in item:
            if not (isinstance(entry, dict) and isinstance(entry.get("id"), dict)
                    and entry["id"].get("type") == kind and entry.get("property") == prop):
                raise BadRequest(f"{kind}.{prop} entries as Dash writes them")
            _check_value(f"{kind}.{prop}", entry.get("value"), value_checks)
        return
    if not (isinstance(item, dict) and item.get("id") == ident and item.get("property") == prop):
        raise BadRequest(f"the input {ident}.{prop} as Dash writes it")
    _check_value(f"{ident}.{prop}", item.get("value"), value_checks)


def _check_value(name, value, value_checks):
    check, what = value_checks.get(name, (_scalar, "a string, number, boolean or null"))
    if not check(value):
        raise BadRequest(f"{name}: {what}, got a {type(value).__name__}")


def _scalar(value):
    return value is None or isinstance(value, (str, int, float, bool))
