"""``bikemass serve``: the local web page (Dash) and its JSON API."""

import errno
import ipaddress
import re
import socket
import threading

from ..core.errors import InputError
from .options import whole

DEFAULT_PORT = 8050
LOOPBACK = "127.0.0.1"
PORT_ERRORS = (errno.EADDRINUSE, errno.EACCES)
"""Bind errors that are the port's fault (taken, or privileged); any other is the address's."""


def register(sub):
    serve = sub.add_parser(
        "serve", help="a local web page: edit a bicycle and its rider, see parameters and stability",
        description="Start a web application on this machine. Open the printed address in a browser: "
                    "choose or upload a bicycle, a rider and a frame stiffness, type over any benchmark "
                    "parameter, and see the critical speeds, the eigenvalues and the side view. The "
                    "page's state is in its address (e.g. /?bike=jamis&rider=relaxed&stiffness=steel); "
                    "/api/stability and /api/params answer the same query with the JSON of "
                    "'bikemass stability' and 'bikemass params'. Ctrl-C stops it (exit status 130, "
                    "SIGTERM 143). Needs the 'web' extra: pip install 'bikemass[web]'.")
    serve.add_argument("--port", type=whole("a TCP port number"), default=DEFAULT_PORT, help=f"TCP port (default {DEFAULT_PORT})")
    serve.add_argument("--host", default=LOOPBACK,
                       help=f"address to listen on (default {LOOPBACK}: this machine only; "
                            "0.0.0.0 exposes the page to the network); requests must name the server by "
                            "an IP address, localhost or this name")
    serve.set_defaults(run=run_serve)


def checked_host(host):
    """``host`` if it is an IP address or a name that resolves; InputError (``--host``) otherwise,
    a dotted number that is no IPv4 address (``256.1.1.1``) without asking a resolver."""
    expected = "an IP address or a host name of this machine (e.g. 127.0.0.1, 0.0.0.0)"
    try:
        ipaddress.ip_address(host)
        return host
    except ValueError:
        pass
    if not host or re.fullmatch(r"[\d.]+", host) or len(host) > 253:
        raise InputError("--host", host, expected)
    try:
        socket.getaddrinfo(host, None)
    except (OSError, UnicodeError, ValueError):
        raise InputError("--host", host, f"{expected}; this name does not resolve") from None
    return host


def host_names(host):
    """The names requests may give in ``Host`` for a server on ``host`` (besides IP addresses and
    localhost): the name given, and for every address (0.0.0.0, ::) this machine's names."""
    try:
        unspecified = ipaddress.ip_address(host).is_unspecified
        names = []
    except ValueError:
        unspecified, names = False, [host]
    if unspecified:
        names += [socket.gethostname(), socket.getfqdn()]
    return tuple(dict.fromkeys(n for n in names if n))


def run_serve(args):
    if not 0 < args.port < 65536:
        raise InputError("--port", args.port, "a TCP port between 1 and 65535")
    host = checked_host(args.host)
    try:
        # lazy: the web page loads dash; only bikemass serve needs it
        from ..web import create_app
        app = create_app(hosts=host_names(host))
    except ImportError as exc:
        raise InputError("serve", "(extra)", f"the web extra: pip install 'bikemass[web]' ({exc.name} "
                         "is missing)") from None

    # lazy: the web page loads dash; only bikemass serve needs it
    import socketserver
    from ..web.serving import make_server
    from ..web.state import PageState

    try:
        server = make_server(app, host, args.port)
    except OSError as exc:
        if exc.errno in PORT_ERRORS:
            raise InputError("--port", args.port, f"a free port ({exc.strerror})") from None
        raise InputError("--host", host, f"an address of this machine ({exc.strerror or exc})") from None

    def warm():
        """The default page with each stiffness choice of its bicycle computed before the first visit."""
        app.engine.warm([PageState(stiffness=s) for s in app.engine.materials(PageState().bike)])
    # not a daemon: a daemon thread stopped inside native code at exit aborts the interpreter
    threading.Thread(target=warm).start()
    shown = f"[{host}]" if ":" in host else host
    print(f"bikemass: serving on http://{shown}:{server.port}/ (Ctrl-C stops)", flush=True)
    try:
        # socketserver's loop, not Werkzeug's (which swallows Ctrl-C and would exit 0): the
        # KeyboardInterrupt / Terminated reach the command line, which exits 130 / 143
        socketserver.BaseServer.serve_forever(server)
    finally:
        server.server_close()
    return 0
