"""``bikemass serve``: the local web page (Dash) and its JSON API."""

import threading

from ..core.errors import InputError
from .options import whole

DEFAULT_PORT = 8050
LOOPBACK = "127.0.0.1"


def register(sub):
    serve = sub.add_parser(
        "serve", help="a local web page: edit a bicycle and its rider, see parameters and stability",
        description="Start a web application on this machine. Open the printed address in a browser: "
                    "choose or upload a bicycle, a rider and a frame stiffness, type over any benchmark "
                    "parameter, and see the critical speeds, the eigenvalues and the side view. The "
                    "page's state is in its address (e.g. /?bike=jamis&rider=relaxed&stiffness=steel); "
                    "/api/stability and /api/params answer the same query with the JSON of "
                    "'bikemass stability' and 'bikemass params'. Needs the 'web' extra: "
                    "pip install 'bikemass[web]'.")
    serve.add_argument("--port", type=whole("a TCP port number"), default=DEFAULT_PORT, help=f"TCP port (default {DEFAULT_PORT})")
    serve.add_argument("--host", default=LOOPBACK,
                       help=f"address to listen on (default {LOOPBACK}: this machine only; "
                            "0.0.0.0 exposes the page to the network)")
    serve.set_defaults(run=run_serve)


def run_serve(args):
    if not 0 < args.port < 65536:
        raise InputError("--port", args.port, "a TCP port between 1 and 65535")
    try:
        # lazy: the web page loads dash; only bikemass serve needs it
        from ..web import create_app
        app = create_app()
    except ImportError as exc:
        raise InputError("serve", "(extra)", f"the web extra: pip install 'bikemass[web]' ({exc.name} "
                         "is missing)") from None

    # lazy: the web page loads dash; only bikemass serve needs it
    from ..web.state import PageState

    def warm():
        """The default page with each stiffness choice of its bicycle computed before the first visit."""
        app.engine.warm([PageState(stiffness=s) for s in app.engine.materials(PageState().bike)])
    # not a daemon: a daemon thread stopped inside native code at exit aborts the interpreter
    threading.Thread(target=warm).start()
    print(f"bikemass: serving on http://{args.host}:{args.port}/ (Ctrl-C stops)", flush=True)
    try:
        app.run(host=args.host, port=args.port, debug=False)
    except OSError as exc:
        raise InputError("--port", args.port, f"a free port ({exc.strerror})") from None
    return 0
