"""Time the web page's JSON API against the equivalent command-line run, a cached answer against
the HTTP floor of the same server, and a cached answer while other clients' computations run.

Run by hand:  python benchmarks/bench_web.py [--quick]
Starts the page's server in this process (loopback, a free port, the server ``bikemass serve``
uses), then times

* ``bikemass stability jamis --rider relaxed --stiffness steel --format json`` as a new
  process (what a user would otherwise run), best of 3 (``--quick``: skipped);
* ``GET /api/stability?bike=jamis&rider=relaxed&stiffness=steel`` on a fresh server (the
  first request builds the meshes and the beam model) and then cached, best of 20;
* the floor: a route of the same server answering the same JSON text from a dict (the HTTP,
  Werkzeug and Flask cost of any answer), best of 20;
* the cached answer while 8 uncached ``/api/handling`` requests (about 1 s of computation each)
  are in flight (issue 35: 5.6 s before, with 16; it must come within 1 s);
* a benchmark-level change (a typed-over trail) and a geometry change (a chart bicycle's
  head angle, which rebuilds the frame and its beam stiffness), each a new configuration.

Prints each time, the cached answer beside turn 3's 6.5 ms (issue 37) and the floor, and the
ratios to the command line.
"""

import json
import subprocess
import sys
import threading
import time
import urllib.request

QUERY = "bike=jamis&rider=relaxed&stiffness=steel"
TURN_3_CACHED = 6.5e-3
"""Turn 3's cached API answer (s), measured on this machine (issue 37's table)."""


def seconds(fn):
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def main(quick=False):
    from flask import Response

    from bikemass.web import create_app
    from bikemass.web.serving import make_server

    command = [sys.executable, "-m", "bikemass.cli.main", "stability", "jamis", "--rider", "relaxed",
               "--stiffness", "steel", "--format", "json"]
    cli = None if quick else min(seconds(lambda: subprocess.run(command, check=True, capture_output=True))
                                 for _ in range(3))

    app = create_app()
    floor_text = {}

    @app.server.route("/floor")
    def floor():
        return Response(floor_text["text"], mimetype="application/json")

    httpd = make_server(app, "127.0.0.1", 0, quiet=True)
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{httpd.port}"

    def raw(path):
        with urllib.request.urlopen(base + path, timeout=600) as reply:
            return reply.read()

    cold = seconds(lambda: raw(f"/api/stability?{QUERY}"))
    floor_text["text"] = raw(f"/api/stability?{QUERY}")
    cached = [seconds(lambda: raw(f"/api/stability?{QUERY}")) for _ in range(20)]
    floors = [seconds(lambda: raw("/floor")) for _ in range(20)]
    if not quick:
        cli_weave = json.loads(subprocess.run(command, check=True, capture_output=True).stdout)["weave_speeds"]
        assert json.loads(floor_text["text"])["weave_speeds"] == cli_weave

    threads = [threading.Thread(target=raw, args=(f"/api/handling?bike=benchmark&rider=none&c={0.07 + 0.002 * i!r}",))
               for i in range(8)]
    for t in threads:
        t.start()
    lock = app.engine._lock
    while lock.acquire(blocking=False):             # until a handling computation holds the engine's lock
        lock.release()
        time.sleep(0.005)
    busy = seconds(lambda: raw(f"/api/stability?{QUERY}"))
    still_running = sum(t.is_alive() for t in threads)
    for t in threads:
        t.join()

    trail = seconds(lambda: raw(f"/api/stability?{QUERY}&c=0.0612"))
    raw("/api/stability?bike=bmc-roadmachine&size=56&rider=none&stiffness=steel")
    geometry = seconds(lambda: raw("/api/stability?bike=bmc-roadmachine&size=56&rider=none&stiffness=steel"
                                   "&chart.head_tube_angle=71.5"))
    httpd.shutdown()

    best, floor_best = min(cached), min(floors)
    median = sorted(cached)[len(cached) // 2]
    print(f"cached answer: best {best * 1e3:.2f} ms, median {median * 1e3:.2f} ms of 20 "
          f"({len(floor_text['text']) / 1e3:.0f} kB JSON)")
    print(f"  / turn 3's 6.5 ms: {best / TURN_3_CACHED:.2f}   / the floor (same text, same server, "
          f"{floor_best * 1e3:.2f} ms): {best / floor_best:.2f}")
    print(f"cached answer with {still_running} of 8 uncached handling requests in flight: {busy * 1e3:.1f} ms "
          f"(issue 35: within 1 s)")
    rows = [("API, first request (cold caches)", cold), ("API, cached", best),
            ("API, typed-over trail (new parameters)", trail), ("API, chart head angle (new frame + beam S)", geometry)]
    if cli is not None:
        print(f"{'command line (new process)':44s} {cli * 1e3:8.1f} ms")
    for what, t in rows:
        ratio = f"   ratio to command line {t / cli:.4f}" if cli is not None else ""
        print(f"{what:44s} {t * 1e3:8.1f} ms{ratio}")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
