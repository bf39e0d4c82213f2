"""Time the web page's JSON API against the equivalent command-line run.

Run by hand:  python benchmarks/bench_web.py
Starts the page's server in this process (loopback, a free port), then times

* ``bikemass stability jamis --rider relaxed --stiffness steel --format json`` as a new
  process (what a user would otherwise run), best of 5;
* ``GET /api/stability?bike=jamis&rider=relaxed&stiffness=steel`` on a fresh server (the
  first request builds the meshes and the beam model) and then warm (cached), best of 5;
* a benchmark-level change (a typed-over trail) and a geometry change (a chart bicycle's
  head angle, which rebuilds the frame and its beam stiffness), each a new configuration.

Prints each time and its ratio to the command line (issue 17 asks for < 0.3 warm).
"""

import json
import subprocess
import sys
import threading
import time
import urllib.request

QUERY = "bike=jamis&rider=relaxed&stiffness=steel"


def seconds(fn):
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def main():
    from werkzeug.serving import WSGIRequestHandler, make_server

    from bikemass.web import create_app

    class Quiet(WSGIRequestHandler):
        def log_request(self, *args):
            pass

    command = [sys.executable, "-m", "bikemass.cli.main", "stability", "jamis", "--rider", "relaxed",
               "--stiffness", "steel", "--format", "json"]
    cli = min(seconds(lambda: subprocess.run(command, check=True, capture_output=True)) for _ in range(5))
    cli_weave = json.loads(subprocess.run(command, check=True, capture_output=True).stdout)["weave_speeds"]

    httpd = make_server("127.0.0.1", 0, create_app().server, threaded=True, request_handler=Quiet)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{httpd.server_port}"

    def get(path):
        with urllib.request.urlopen(base + path) as reply:
            return json.load(reply)

    cold = seconds(lambda: get(f"/api/stability?{QUERY}"))
    warm = min(seconds(lambda: get(f"/api/stability?{QUERY}")) for _ in range(5))
    assert get(f"/api/stability?{QUERY}")["weave_speeds"] == cli_weave
    trail = seconds(lambda: get(f"/api/stability?{QUERY}&c=0.0612"))
    get("/api/stability?bike=bmc-roadmachine&size=56&rider=none&stiffness=steel")
    geometry = seconds(lambda: get("/api/stability?bike=bmc-roadmachine&size=56&rider=none&stiffness=steel"
                                   "&chart.head_tube_angle=71.5"))
    httpd.shutdown()

    print(f"{'command line (new process)':44s} {cli * 1e3:8.1f} ms")
    for what, t in (("API, first request (cold caches)", cold), ("API, warm (cached)", warm),
                    ("API, typed-over trail (new parameters)", trail),
                    ("API, chart head angle (new frame + beam S)", geometry)):
        print(f"{what:44s} {t * 1e3:8.1f} ms   ratio to command line {t / cli:.3f}")


if __name__ == "__main__":
    main()
