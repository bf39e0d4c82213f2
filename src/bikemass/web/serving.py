"""The HTTP server of ``bikemass serve``: Werkzeug's threaded server, one thread a request,
saying ``Server: bikemass`` (no framework nor Python version: nothing to fingerprint)."""

import socket

from werkzeug.serving import WSGIRequestHandler
from werkzeug.serving import make_server as werkzeug_server

from .guard import SERVER


class Handler(WSGIRequestHandler):
    """Werkzeug's request handler without its ``Server: Werkzeug/... Python/...`` banner."""

    def version_string(self):
        return SERVER


class QuietHandler(Handler):
    """:class:`Handler` that logs no request (tests and benchmarks)."""

    def log_request(self, *args):
        pass


def make_server(app, host, port, quiet=False):
    """A threaded server of the Dash ``app`` on ``host``:``port`` (0 = a free port), bound and
    ready for ``serve_forever``; OSError if the address cannot be bound (the socket is bound here:
    Werkzeug's own binding prints the error and exits 1)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as sock:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind((host, port))
        sock.listen(128)
        # the server works on a duplicate of the socket; this one is closed on leaving
        return werkzeug_server(host, sock.getsockname()[1], app.server, threaded=True,
                               request_handler=QuietHandler if quiet else Handler, fd=sock.fileno())
