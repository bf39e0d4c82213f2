"""The web server as a network service (issue 35): one client does not stall the others, the
Host header is checked (DNS rebinding), every answer carries the security headers and no
framework banner, uploads are kept apart, broken script paths are 4xx, the API's warnings are
the command line's, and ``bikemass serve`` starts, refuses and stops as a command should.

Servers listen on the loopback address only, on a free port."""

import contextlib
import io
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest
import yaml

pytest.importorskip("dash")

from bikemass.cli.main import main  # noqa: E402
from bikemass.core.errors import InputError  # noqa: E402
from bikemass.core.paths import frames_dir  # noqa: E402
from bikemass.web import create_app  # noqa: E402
from bikemass.web.engine import HANDLING_SPEEDS  # noqa: E402
from bikemass.web.guard import allowed_host  # noqa: E402
from bikemass.web.serving import make_server  # noqa: E402
from bikemass.web.state import PageState  # noqa: E402

SRC = Path(__file__).resolve().parents[1] / "src"
HEADERS = {"X-Content-Type-Options": "nosniff", "X-Frame-Options": "DENY"}


@pytest.fixture(scope="module")
def app():
    return create_app()


@pytest.fixture(scope="module")
def client(app):
    return app.server.test_client()


@contextlib.contextmanager
def serving(app):
    """The app on a loopback port of its own; yields the base URL; waits for answers in flight."""
    httpd = make_server(app, "127.0.0.1", 0, quiet=True)
    httpd.daemon_threads = False       # server_close() then waits for the requests being answered
    httpd.block_on_close = True
    thread = threading.Thread(target=httpd.serve_forever)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.port}"
    finally:
        httpd.shutdown()
        httpd.server_close()
        thread.join()


def fetch(url, headers=None):
    """``(status, headers, body)`` of a GET, 4xx and 5xx included."""
    try:
        with urllib.request.urlopen(urllib.request.Request(url, headers=headers or {}), timeout=120) as reply:
            return reply.status, reply.headers, reply.read()
    except urllib.error.HTTPError as err:
        return err.code, err.headers, err.read()


# -- one client does not stall the others ---------------------------------------------------------

@pytest.mark.slow
def test_a_cached_answer_does_not_wait_for_uncached_handling_requests():
    """8 uncached /api/handling requests in flight over HTTP, none able to finish (the test holds the
    engine's lock, as a long computation would); a cached /api/stability must still come back, with
    all 8 still waiting (issue 35: before, it queued behind them, 5.6 s with 16). No clock: an answer
    that needed the lock could not come while the test holds it (bench_web.py measures the time)."""
    app = create_app()
    cached = "/api/stability?bike=benchmark&rider=none"
    with serving(app) as base:
        first = fetch(base + cached)
        assert first[0] == 200
        done, again = [], []

        def handling(i):
            status = fetch(f"{base}/api/handling?bike=benchmark&rider=none&c={0.07 + 0.002 * i!r}")[0]
            done.append(status)
        threads = [threading.Thread(target=handling, args=(i,)) for i in range(8)]
        reader = threading.Thread(target=lambda: again.append(fetch(base + cached)))
        lock = app.engine._lock
        with lock:
            for t in threads:
                t.start()
            reader.start()
            reader.join(60)
            answered, in_flight = not reader.is_alive(), 8 - len(done)
        reader.join()
        for t in threads:
            t.join()
    assert answered, "the cached answer waited for the engine's lock"
    assert again[0][0] == 200 and json.loads(again[0][2]) == json.loads(first[2])
    assert in_flight == 8, "a handling request finished without the engine's lock: nothing was held up"
    assert done == [200] * 8


def _page_request(app, fragment):
    """A request of the page's callback whose outputs include ``fragment``, for the benchmark."""
    from test_web_hostile import PAGE, _body
    body = json.dumps(_body(app, fragment, **PAGE, **{"bode-speed": "5", "bode-input": "steer-torque",
                                                     "bode-output": "roll-angle"}))
    return lambda c: c.post("/_dash-update-component", data=body, content_type="application/json")


@pytest.mark.parametrize("what", ["api", "weave-speed", "side-view", "size.options", "bode-figure", "hqm-figure"])
def test_a_cached_answer_is_served_while_the_engine_is_busy(app, client, what):
    """The lock held by another thread (a computation in progress): a cached answer still comes,
    from the JSON API and from each of the page's callbacks."""
    if what == "api":
        def ask(c):
            return c.get("/api/params?bike=jamis&rider=relaxed&stiffness=steel")
    else:
        ask = _page_request(app, what)
    first = ask(client).get_json()
    assert first
    held, release = threading.Event(), threading.Event()

    def busy():
        with app.engine._lock:
            held.set()
            release.wait(60)
    thread = threading.Thread(target=busy)
    thread.start()
    try:
        assert held.wait(60)
        again = {}
        reader = threading.Thread(target=lambda: again.update(ask(client).get_json()))
        reader.start()
        reader.join(30)
        answered = not reader.is_alive()
    finally:
        release.set()
        thread.join()
        reader.join()
    assert answered and again == first


# -- Host header, headers, banner -----------------------------------------------------------------

@pytest.mark.parametrize("host, ok", [
    ("127.0.0.1:8050", True), ("localhost:8050", True), ("LOCALHOST.", True), ("[::1]:8050", True),
    ("192.168.1.20:8050", True), ("evil.example", False), ("evil.example:8050", False),
    ("127.0.0.1.evil.example", False), ("localhost.evil.example:8050", False), ("", False)])
def test_the_host_header_must_name_this_server(host, ok):
    assert allowed_host(host) is ok
    assert allowed_host("mybox.lan:8050", ("mybox.lan",)) and not allowed_host("other.lan", ("mybox.lan",))


@pytest.mark.parametrize("path", ["/api/params?bike=benchmark&rider=none", "/?bike=benchmark&rider=none",
                                  "/download/parameters.yaml?bike=benchmark&rider=none"])
def test_another_host_name_is_refused_421_in_one_line(client, path):
    """A DNS-rebinding page (evil.example resolving to 127.0.0.1) gets nothing."""
    reply = client.get(path, headers={"Host": "evil.example:8050"})
    assert reply.status_code == 421
    message = reply.get_json()["error"]
    assert "evil.example" in message and "\n" not in message and b"mB" not in reply.data
    assert client.get(path, headers={"Host": "127.0.0.1:8050"}).status_code == 200


def test_every_answer_carries_the_security_headers_and_no_banner(app):
    with serving(app) as base:
        page = fetch(base + "/?bike=benchmark&rider=none")
        scripts = [line.split('src="', 1)[1].split('"', 1)[0] for line in page[2].decode().split("<script")
                   if 'src="' in line.split(">", 1)[0]]
        answers = [page, fetch(base + "/api/params?bike=benchmark&rider=none"),
                   fetch(base + "/api/params?bike=nonesuch"), fetch(base + "/_dash-component-suites/dash/nope.js"),
                   fetch(base + scripts[0]), fetch(base + "/api/params", {"Host": "evil.example"})]
    assert [a[0] for a in answers] == [200, 200, 400, 404, 200, 421]
    for status, headers, _ in answers:
        assert {k: headers[k] for k in HEADERS} == HEADERS, status
        policy = headers["Content-Security-Policy"]
        assert "frame-ancestors 'none'" in policy and "default-src 'self'" in policy
        assert headers["Server"] == "bikemass" and "Python" not in headers.get_all("Server")[0]


def test_the_policy_lets_the_pages_inline_scripts_run_by_hash(client):
    """Dash writes two inline scripts (its renderer's start and the pages' setup); the policy
    names each by its SHA-256 (computed here independently), and no 'unsafe-inline' script."""
    import base64
    import hashlib
    import re
    reply = client.get("/?bike=benchmark&rider=none")
    inline = re.findall(r"<script(?![^>]*src=)[^>]*>(.*?)</script>", reply.data.decode(), re.S)
    assert inline
    script_src = [d for d in reply.headers["Content-Security-Policy"].split(";") if "script-src" in d][0]
    for text in inline:
        digest = base64.b64encode(hashlib.sha256(text.encode()).digest()).decode()
        assert f"'sha256-{digest}'" in script_src
    assert "unsafe-inline" not in script_src and "unsafe-eval" not in script_src


@pytest.mark.parametrize("path", [
    "/_dash-component-suites/dash/%252f..%252f..%252f..%252fetc%252fpasswd",
    "/_dash-component-suites/dash/deps/%252e%252e%252fsecret.js",
    "/_dash-component-suites/nosuchpackage/x.js"])
def test_script_paths_dash_does_not_serve_are_4xx(client, path):
    reply = client.get(path)
    assert 400 <= reply.status_code < 500 and b"Traceback" not in reply.data and b"registered" not in reply.data


# -- uploads kept apart ---------------------------------------------------------------------------

def _benchmark_yaml(**changes):
    return yaml.safe_dump({**yaml.safe_load((frames_dir() / "benchmark.yaml").read_text()), **changes}).encode()


def test_an_upload_reaches_neither_another_upload_nor_its_name():
    import hashlib
    engine = create_app().engine
    content = _benchmark_yaml(name="alice's bicycle")
    alice = engine.add_upload("alice.yaml", content)
    again = engine.add_upload("alice.yaml", content)
    secret = alice.removeprefix("upload-")
    assert again != alice and hashlib.sha256(content).hexdigest()[:16] not in alice
    assert len(secret) >= 32                          # 128 random bits: not guessable
    for base in (f"../{secret}/upload.yaml", f"../{again.removeprefix('upload-')}/upload.yaml",
                 f"../{hashlib.sha256(content).hexdigest()[:16]}/upload.yaml"):
        with pytest.raises(InputError) as err:
            engine.add_upload("mallory.yaml", f"base: {base}\n".encode())
        message = str(err.value)
        assert message.startswith("mallory.yaml: ") and "alice" not in message and "\n" not in message
    assert engine.parameters(PageState(bike=alice, rider="none")).w == pytest.approx(1.02, abs=1e-12)


def test_a_download_needs_the_uploads_secret_name(app, client):
    alice = app.engine.add_upload("alice.yaml", _benchmark_yaml(name="alice's bicycle"))
    assert client.get(f"/download/bicycle.yaml?bike={alice}&rider=none").status_code == 200
    guessed = "upload-" + "0" * 32
    reply = client.get(f"/download/bicycle.yaml?bike={guessed}&rider=none")
    assert reply.status_code == 400 and b"alice" not in reply.data


def test_a_forgotten_upload_answers_no_more_even_when_cached():
    from bikemass.web.engine import MAX_UPLOADS
    app = create_app()
    client = app.server.test_client()
    first = app.engine.add_upload("first.yaml", _benchmark_yaml(name="first"))
    assert client.get(f"/api/stability?bike={first}&rider=none").status_code == 200
    for i in range(MAX_UPLOADS):
        app.engine.add_upload(f"b{i}.yaml", _benchmark_yaml(name=f"copy {i}"))
    reply = client.get(f"/api/stability?bike={first}&rider=none")
    assert reply.status_code == 400 and "uploaded to this server" in reply.get_json()["error"]


def test_a_refused_shipped_link_is_named_from_the_data_folder(tmp_path, monkeypatch):
    """Shipped data reached through a symbolic link (BIKEMASS_DATA a link to the real folder), one of
    whose bicycles links outside it: refused, named ``frames/...``, never by the install path."""
    real, outside = tmp_path / "real", tmp_path / "outside"
    (real / "frames").mkdir(parents=True)
    outside.mkdir()
    shipped = frames_dir().parent
    for name in ("bodies", "reference"):
        (real / name).symlink_to(shipped / name)
    for f in frames_dir().glob("*.yaml"):
        (real / "frames" / f.name).write_bytes(f.read_bytes())
    (outside / "linked.yaml").write_bytes((frames_dir() / "benchmark.yaml").read_bytes())
    (real / "frames" / "linked.yaml").symlink_to(outside / "linked.yaml")
    (tmp_path / "data").symlink_to(real)
    monkeypatch.setenv("BIKEMASS_DATA", str(tmp_path / "data"))
    reply = create_app().server.test_client().get("/api/stability?bike=linked&rider=none")
    assert reply.status_code == 400
    message = reply.get_json()["error"]
    assert message.startswith("frames/linked.yaml: ") and str(tmp_path) not in message


# -- the API warns as the command line does ---------------------------------------------------------

def test_api_handling_carries_the_command_lines_warnings(client, tmp_path):
    """Trail -0.9 m: the negative-trail warning and the speeds without gains, as ``bikemass handling``
    prints them for the same parameter file (the file's name in place of the page's ``URL``)."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["params", "benchmark", "--format", "json"]) == 0
    params = {k: v for k, v in json.loads(out.getvalue()).items() if k not in ("units", "warnings")}
    edited = tmp_path / "edited.yaml"
    edited.write_text(yaml.safe_dump({**params, "c": -0.9}))
    out = io.StringIO()
    speeds = ",".join(f"{v:g}" for v in HANDLING_SPEEDS)
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        assert main(["handling", str(edited), "--speeds", speeds, "--format", "json"]) == 0
    cli = [line.replace(str(edited), "URL") for line in json.loads(out.getvalue())["warnings"]]
    assert len(cli) >= 2
    for _ in range(2):                                 # the second answer is the cached one
        reply = client.get("/api/handling?bike=benchmark&rider=none&c=-0.9").get_json()
        assert reply["warnings"] == cli


# -- the serve command ------------------------------------------------------------------------------

def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _serve(*argv):
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    return subprocess.Popen([sys.executable, "-m", "bikemass.cli.main", "serve", *argv], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env)


@pytest.mark.parametrize("argv, key", [(["--host", "256.1.1.1"], "--host"), (["--host", "1.2.3.4.5"], "--host"),
                                       (["--host", "nonesuch.invalid"], "--host"), (["--port", "70000"], "--port"),
                                       (["--host", "192.0.2.1"], "--host")])      # TEST-NET-1: not this machine's
def test_a_bad_address_is_one_line_exit_2(argv, key):
    proc = _serve(*argv)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith(f"bikemass: error: {key}: ") and "Traceback" not in err


def _started(proc):
    line = proc.stdout.readline()
    assert line.startswith("bikemass: serving on http://127.0.0.1:"), line + proc.stderr.read()


@pytest.mark.slow
def test_ctrl_c_ends_serve_with_status_130():
    proc = _serve("--port", str(_free_port()))
    _started(proc)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130 and err.strip().splitlines()[-1] == "bikemass: error: interrupted"


@pytest.mark.slow
def test_two_sigterms_close_together_end_serve_every_time():
    """Issue 35: 1 in 6 runs hung after two SIGTERMs 1 ms apart (the handler waited for its own
    lock).  Six tries, each must end (within 10 s) with status 143."""
    for attempt in range(6):
        proc = _serve("--port", str(_free_port()))
        _started(proc)
        time.sleep(0.05 * attempt)                   # land the signals in different places
        proc.send_signal(signal.SIGTERM)
        time.sleep(0.001)
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            pytest.fail(f"serve hung after two SIGTERMs (attempt {attempt + 1})")
        _, err = proc.communicate()
        # 143: the command line's "terminated"; -15: the second SIGTERM came after the command
        # line had put the default handlers back (while the interpreter exits), which kills
        assert proc.returncode in (143, -signal.SIGTERM) and "Traceback" not in err, err


def test_the_stop_handler_never_waits_for_its_own_lock():
    """The mechanism of the hang: a signal arriving while the main thread is inside the handler,
    holding the handler's lock.  Called so in a thread of its own, the handler must return at once
    (the first stop is on its way), not wait for a lock its own thread holds; and a signal while a
    stop is on its way (its retry timer pending) raises nothing more."""
    from bikemass.core.stopping import _Handler
    handler, returned = _Handler(), []

    def inside():
        with handler.lock:
            returned.append(handler(signal.SIGTERM, None))
    thread = threading.Thread(target=inside, daemon=True)
    thread.start()
    thread.join(10)
    assert returned == [None] and handler.timer is None
    handler.timer = pending = object()        # a stop raised, its retry not yet due
    assert handler(signal.SIGTERM, None) is None and handler.timer is pending
    handler.timer = None
