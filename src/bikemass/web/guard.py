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

:func:`guard_hosts` refuses a request whose ``Host`` header names a server this one is not
(``421``): a page on another site whose name an attacker points at ``127.0.0.1`` (DNS
rebinding) reaches nothing.  :func:`secure_headers` adds the usual security headers to every
answer (no MIME sniffing, no framing, a content security policy the page works with).
"""

import base64
import hashlib
import ipaddress
import json
import re

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


LOCAL_NAMES = ("localhost",)
"""Host names every server answers to (besides IP addresses, which no rebinding can forge)."""


def host_name(host):
    """The name or address of a ``Host`` header (``name:port``, ``[v6]:port``), lower case,
    without the port and a trailing dot."""
    host = host.strip().lower()
    if host.startswith("["):
        return host[1:].split("]", 1)[0]
    return host.rsplit(":", 1)[0].rstrip(".") if host.count(":") == 1 else host.rstrip(".")


def allowed_host(host, names=()):
    """Whether a request with ``Host: host`` is for this server: an IP address, ``localhost``, or
    one of ``names`` (the names the server was started under)."""
    name = host_name(host)
    try:
        ipaddress.ip_address(name)
        return True
    except ValueError:
        return name in LOCAL_NAMES or name in {host_name(n) for n in names}


def guard_hosts(server, names=()):
    """Answer 421 ``{"error": ...}`` to a request whose ``Host`` is not :func:`allowed_host`.

    Parameters
    ----------
    server : flask.Flask
        The application's server (the check runs before any other).
    names : sequence of str
        Host names the server answers to besides IP addresses and ``localhost``.
    """
    names = tuple(names)

    def check_host():
        if not allowed_host(request.host, names):
            shown = one_line(request.host, 100)
            return jsonify({"error": f"Host: {shown}: an address of this server ({', '.join(LOCAL_NAMES + names)} "
                                     "or an IP address)"}), 421
        return None
    server.before_request_funcs.setdefault(None, []).insert(0, check_host)


SCRIPT = re.compile(r"<script(?![^>]*\bsrc=)[^>]*>(.*?)</script>", re.S)
"""An inline script of a page (its text, for the policy's hash)."""
POLICY = ("default-src 'self'; script-src 'self'{hashes}; style-src 'self' 'unsafe-inline'; img-src 'self' data:; "
          "connect-src 'self'; font-src 'self'; object-src 'none'; base-uri 'self'; form-action 'self'; "
          "frame-ancestors 'none'")
"""The content security policy: the page's own scripts (inline ones by hash), styles inline (Dash's
components set them), images as data URLs (the figures), no framing."""
SERVER = "bikemass"
"""What the ``Server`` header says (no framework nor Python version)."""


def script_hashes(html):
    """The CSP hash sources (``'sha256-...'``) of the inline scripts of ``html``."""
    return ["'sha256-" + base64.b64encode(hashlib.sha256(text.encode()).digest()).decode() + "'"
            for text in SCRIPT.findall(html)]


def secure_headers(server):
    """Add ``X-Content-Type-Options: nosniff``, ``X-Frame-Options: DENY``, ``Referrer-Policy``
    and a ``Content-Security-Policy`` (:data:`POLICY`) to every answer of ``server``."""
    @server.after_request
    def headers(response):
        hashes = ""
        if response.mimetype == "text/html" and not response.direct_passthrough:
            hashes = "".join(" " + h for h in script_hashes(response.get_data(as_text=True)))
        response.headers["X-Content-Type-Options"] = "nosniff"
        response.headers["X-Frame-Options"] = "DENY"
        response.headers["Referrer-Policy"] = "same-origin"
        response.headers["Content-Security-Policy"] = POLICY.format(hashes=hashes)
        return response
