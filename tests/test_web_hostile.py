"""The web page under hostile input: uploads that name other files, malformed callback bodies,
and what the page promises when input is bad (docs/web.md): warnings in every JSON answer, the
last good results kept, a size run uploaded and downloaded per size, the frame's own material.
Flask's test client; no browser."""

import base64
import json

import pytest
import yaml

pytest.importorskip("dash")

from bikemass.cli.main import main  # noqa: E402
from bikemass.core.errors import InputError  # noqa: E402
from bikemass.models.parameters import NAMES  # noqa: E402
from bikemass.core.paths import frames_dir  # noqa: E402
from bikemass.web import create_app  # noqa: E402
from bikemass.web.engine import MAX_UPLOADS  # noqa: E402
from bikemass.web.page import CHART_KEYS  # noqa: E402
from bikemass.web.state import HANDS, PageState  # noqa: E402

SECRET = "hunter2-do-not-echo"


@pytest.fixture(scope="module")
def app():
    return create_app()


@pytest.fixture(scope="module")
def client(app):
    return app.server.test_client()


@pytest.fixture()
def secrets(tmp_path):
    """Files an attacker would like to read: YAML and parameter text with a password in them."""
    (tmp_path / "env.yaml").write_text(f"PASSWORD: {SECRET}\nsteel: {{E: {SECRET}, nu: 0.3, density: 1}}\n")
    (tmp_path / "env.txt").write_text(f"PASSWORD = {SECRET}\n")
    (tmp_path / "ok.yaml").write_text(yaml.safe_dump(yaml.safe_load((frames_dir() / "benchmark.yaml").read_text())))
    return tmp_path


def _jamis_with(**changes):
    document = yaml.safe_load((frames_dir() / "jamis.yaml").read_text())
    return yaml.safe_dump({**document, **changes}).encode()


@pytest.mark.parametrize("make", [
    lambda d: _jamis_with(materials=str(d / "env.yaml")),
    lambda d: _jamis_with(materials="../" * 12 + str(d / "env.yaml").lstrip("/")),
    lambda d: f"name: measured\nparameters: {d / 'env.txt'}\n".encode(),
    lambda d: f"name: measured\nparameters: {d / 'ok.yaml'}\n".encode(),
    lambda d: ("name: measured\nparameters: " + "../" * 12 + str(d / "ok.yaml").lstrip("/") + "\n").encode(),
    lambda d: f"base: {d / 'ok.yaml'}\n".encode(),
    lambda d: ("base: " + "../" * 12 + str(d / "ok").lstrip("/") + "\n").encode(),
], ids=["materials-absolute", "materials-dotdot", "parameters-absolute-secret", "parameters-absolute-bicycle",
        "parameters-dotdot", "base-absolute", "base-dotdot"])
def test_an_upload_reaches_no_other_file_and_echoes_none(app, secrets, make):
    with pytest.raises(InputError) as err:
        app.engine.add_upload("mine.yaml", make(secrets))
    message = str(err.value)
    assert message.startswith("mine.yaml: ") and "\n" not in message
    assert SECRET not in message and "PASSWORD" not in message and "bikemass-web-" not in message


def test_the_same_files_are_read_from_the_command_line(secrets, tmp_path, capsys):
    """Confinement is the web page's: a measured bicycle on disk may name any parameter file."""
    measured = tmp_path / "measured.yaml"
    measured.write_text(f"name: measured\nparameters: {secrets / 'ok.yaml'}\n")
    assert main(["params", str(measured)]) == 0


def test_an_upload_error_names_the_upload_not_the_servers_folder(app):
    with pytest.raises(InputError) as err:
        app.engine.add_upload("broken.yaml", _jamis_with(geometry={"wheelbase": "1 furlong"}))
    assert str(err.value).startswith("broken.yaml: geometry") and "/tmp" not in str(err.value)


def test_a_size_run_uploads_and_its_sizes_are_offered(app, client):
    run = (frames_dir() / "bmc_roadmachine.yaml").read_bytes()
    name = app.engine.add_upload("roadmachine.yaml", run)
    sizes = app.engine.sizes(name)
    assert len(sizes) > 3
    ours = client.get(f"/api/params?bike={name}&size={sizes[-1]}&rider=none").get_json()
    shipped = client.get(f"/api/params?bike=bmc-roadmachine&size={sizes[-1]}&rider=none").get_json()
    assert ours == shipped


def test_the_size_run_download_is_that_size_with_its_edits(client, tmp_path, capsys):
    query = "bike=bmc-roadmachine&size=47&rider=none&stiffness=infinite&chart.stack=520"
    document = yaml.safe_load(client.get(f"/download/bicycle.yaml?{query}").data)
    assert "sizes" not in document and document["chart"]["stack"] == "520.0 mm"
    f = tmp_path / "bicycle.yaml"
    f.write_text(yaml.safe_dump(document))
    assert main(["params", str(f), "--format", "json"]) == 0
    from_file = json.loads(capsys.readouterr().out)
    api = client.get(f"/api/params?{query}").get_json()
    assert {k: from_file[k] for k in NAMES} == pytest.approx({k: api[k] for k in NAMES}, rel=1e-12)
    other = yaml.safe_load(client.get("/download/bicycle.yaml?bike=bmc-roadmachine&size=56&rider=none").data)
    assert other["chart"]["stack"] != document["chart"]["stack"]


def test_the_frames_own_material_is_offered_and_used(app, client):
    assert app.engine.materials("specialized-diverge", "56")[:2] == ["infinite", "carbon"]
    assert {"steel", "titanium", "aluminum", "carbon"} <= set(app.engine.materials("jamis"))
    reply = client.get("/api/stability?bike=specialized-diverge&size=56&rider=none&stiffness=carbon")
    assert reply.status_code == 200
    own = _jamis_with(materials={"unobtainium": {"E": "150 GPa", "nu": 0.3, "density": "5 g/cm^3"}},
                      material="unobtainium")
    name = app.engine.add_upload("own.yaml", own)
    assert app.engine.materials(name)[1] == "unobtainium"
    assert client.get(f"/api/stability?bike={name}&rider=none&stiffness=unobtainium").status_code == 200
    refused = client.get(f"/api/stability?bike={name}&rider=none&stiffness=rubber")
    assert refused.status_code == 400 and "stiffness: one of infinite, unobtainium" in refused.get_json()["error"]


def test_uploads_kept_are_bounded(app):
    engine = create_app().engine
    names = [engine.add_upload(f"b{i}.yaml", _jamis_with(name=f"copy {i}")) for i in range(MAX_UPLOADS + 4)]
    with pytest.raises(InputError, match="a file uploaded to this server"):
        engine.sizes(names[0])
    assert engine.sizes(names[-1]) == ()


@pytest.mark.parametrize("query, fragment", [
    ("bike=benchmark&rider=none&c=-0.05", "negative trail c = -0.05 m"),
    ("bike=benchmark&rider=none&rR=300", "wheel radius rR = 300 m is more than 1.5 m"),
    ("bike=benchmark&rider=none&IByy=30", "IByy: the B inertia breaks the triangle inequality"),
])
@pytest.mark.parametrize("route", ["stability", "params"])
def test_json_answers_carry_the_warnings_the_command_line_gives(client, query, fragment, route):
    for _ in range(2):                        # the second answer comes from the caches
        reply = client.get(f"/api/{route}?{query}").get_json()
        assert [line for line in reply["warnings"] if fragment in line], reply["warnings"]


def test_a_measured_set_warns_through_the_api_as_on_the_command_line(app, client, capsys):
    from test_parameter_sets import BROWSER_TXT
    name = app.engine.add_upload("BrowserBenchmark.txt", BROWSER_TXT.read_bytes())
    reply = client.get(f"/api/params?bike={name}&rider=none").get_json()
    assert main(["params", str(BROWSER_TXT), "--format", "json"]) == 0
    cli = json.loads(capsys.readouterr().out)["warnings"]
    assert [w.replace(str(BROWSER_TXT), "BrowserBenchmark.txt") for w in cli] == reply["warnings"]


# --------------------------------------------------------------- Dash callback bodies
def _callback(app, fragment):
    return next(key for key in app.callback_map if fragment in key)


def _entry(item, values):
    ident, prop = item["id"], item["property"]
    if ident.startswith("{"):
        kind = json.loads(ident)["type"]
        keys = CHART_KEYS if kind == "chart" else NAMES
        return [{"id": {"key": k, "type": kind}, "property": prop, "value": values.get((kind, k), "")} for k in keys]
    return {"id": ident, "property": prop, "value": values.get(f"{ident}.{prop}", values.get(ident))}


def _body(app, fragment, **values):
    """A callback body as the page writes it; ``values`` by component id (``param_c`` = the c box)."""
    from bikemass.web.guard import declared_outputs
    values = {("param", k[6:]) if k.startswith("param_") else k: v for k, v in values.items()}
    output = _callback(app, fragment)
    spec = app.callback_map[output]
    outputs = [_entry({"id": ident, "property": prop}, {}) for ident, prop in declared_outputs(output)]
    for entry in outputs:
        for item in entry if isinstance(entry, list) else [entry]:
            item.pop("value")
    return {"output": output, "outputs": outputs if len(outputs) > 1 else outputs[0], "changedPropIds": [],
            "inputs": [_entry(i, values) for i in spec["inputs"]],
            "state": [_entry(i, values) for i in spec["state"]]}


PAGE = dict(bike="benchmark", size=None, rider="none", height="1.8", mass="75", sex="male", hands="hoods",
            stiffness="infinite", combine="exact", model="whipple")


def _post(client, body, raw=None):
    data = raw if raw is not None else json.dumps(body)
    return client.post("/_dash-update-component", data=data, content_type="application/json")


def test_a_callback_body_as_the_page_writes_it_is_answered(app, client):
    reply = _post(client, _body(app, "weave-speed", **PAGE, param_c="0.05"))
    assert reply.status_code == 200
    assert "m/s" in reply.get_json()["response"]["weave-speed"]["children"]


@pytest.mark.parametrize("mangle, status", [
    (lambda app, b: {}, 400),
    (lambda app, b: [], 400),
    (lambda app, b: {**b, "output": "nonesuch.children"}, 400),
    (lambda app, b: {**b, "inputs": b["inputs"][:2]}, 400),
    (lambda app, b: {**b, "inputs": None}, 400),
    (lambda app, b: {**b, "changedPropIds": "bike.value"}, 400),
    (lambda app, b: _body(app, "weave-speed", **{**PAGE, "bike": 42}), 400),
    (lambda app, b: _body(app, "weave-speed", **{**PAGE, "bike": ["jamis"]}), 400),
    (lambda app, b: _body(app, "weave-speed", **{**PAGE, "bike": {"a": 1}}), 400),
    (lambda app, b: _body(app, "bike.options", **{"upload.contents": None, "upload.filename": "x.yaml",
                                                  "bike.options": ["jamis"]}), 200),
    (lambda app, b: _body(app, "bike.options", **{"upload.contents": "data:;base64,AAAA",
                                                  "upload.filename": "x" * 300 + ".yaml", "bike.options": []}), 400),
    (lambda app, b: _body(app, "bike.options", **{"upload.contents": 12, "upload.filename": "x.yaml",
                                                  "bike.options": []}), 400),
], ids=["empty", "list", "unknown-output", "too-few-inputs", "null-inputs", "changed-not-list", "bike-number",
        "bike-list", "bike-mapping", "null-contents", "300-character-name", "contents-number"])
def test_malformed_callback_bodies_are_4xx_in_one_line(app, client, mangle, status):
    reply = _post(client, mangle(app, _body(app, "weave-speed", **PAGE)))
    assert reply.status_code == status
    if status == 400:
        error = reply.get_json()["error"]
        assert error.startswith("callback request: ") and "\n" not in error


@pytest.mark.parametrize("raw", [
    "[" * 100_000 + "]" * 100_000, '{"output": ' * 50_000 + "1" + "}" * 50_000,
    '{"output": NaN}', '{"output": Infinity}', "not json", b"\xff\xfe"])
def test_bodies_that_are_not_dash_json_are_400(client, raw):
    reply = _post(client, None, raw=raw)
    assert reply.status_code == 400 and "\n" not in reply.get_json()["error"]


def test_a_50_mb_body_is_refused_before_it_is_read(client):
    reply = _post(client, None, raw=b"{" + b" " * 50_000_000 + b"}")
    assert reply.status_code == 413


def test_a_bad_typed_value_keeps_the_last_good_results(app, client):
    """docs/web.md: an error in a typed value is shown in one line naming the field; the results
    stay (no output but the error and the results' class is sent, so the page keeps what it shows),
    marked stale."""
    reply = _post(client, _body(app, "weave-speed", **PAGE, param_c="abc")).get_json()["response"]
    assert sorted(reply) == ["error", "results"] and reply["results"]["className"] == "results stale"
    assert reply["error"]["children"] == "Benchmark parameter c: a number"
    reply = _post(client, _body(app, "weave-speed", **PAGE, param_mB="-5")).get_json()["response"]
    assert sorted(reply) == ["error", "results"] and reply["results"]["className"] == "results stale"
    assert reply["error"]["children"] == "Benchmark parameter mB: a positive number, got -5"
    side = _post(client, _body(app, "side-view", **{**PAGE, "bike": "nonesuch"}))
    assert side.status_code == 204 or "side-view" not in side.get_json().get("response", {})


def test_a_typed_chart_value_is_named_by_its_field_not_an_internal_source(app, client):
    """Issue 35: ``<mapping>: chart.head_tube_angle`` named the edited chart, not where the value was
    typed: the API names the query key, the page the field."""
    reply = client.get("/api/stability?bike=bmc-roadmachine&size=56&rider=none&chart.head_tube_angle=150")
    assert reply.status_code == 400
    assert reply.get_json()["error"].startswith("URL: chart.head_tube_angle: an angle from the horizontal")
    body = _body(app, "weave-speed", **{**PAGE, "bike": "bmc-roadmachine", "size": "56"})
    for group in body["inputs"]:
        for item in group if isinstance(group, list) else []:
            if item["id"] == {"key": "head_tube_angle", "type": "chart"}:
                item["value"] = "150"
    reply = _post(client, body).get_json()["response"]
    message = reply["error"]["children"]
    assert message.startswith("Geometry chart, head tube angle: an angle from the horizontal")
    assert "<mapping>" not in message and "URL" not in message


def test_an_upload_through_the_page_names_the_file_as_uploaded(app, client):
    content = "data:application/x-yaml;base64," + base64.b64encode(b"w: [1, 2\n").decode()
    body = _body(app, "bike.options", **{"upload.contents": content, "upload.filename": "broken.yaml",
                                          "bike.options": ["jamis"]})
    reply = _post(client, body).get_json()["response"]
    assert reply["error"]["children"].startswith("broken.yaml: line ")


def test_states_name_no_paths():
    with pytest.raises(InputError, match="stiffness"):
        PageState.from_query({"stiffness": "/etc/passwd"})


def test_figure_titles_name_the_rider_as_the_command_lines_do(app):
    """The web page's titles say who rides as ``Scenario.rider_label`` (the command line's titles) does: a
    bicycle file with no rider has ``no rider``, the benchmark's set ``rider in the parameter set`` (its
    rider is in its parameters), a pose ``rider <pose>`` and a body its sex, height and mass."""
    engine = app.engine
    assert engine.rider_label(PageState(bike="jamis", rider="none")) == "no rider"
    assert engine.rider_label(PageState(bike="benchmark", rider="none")) == "rider in the parameter set"
    assert engine.rider_label(PageState(bike="jamis", rider="relaxed")) == "rider relaxed"
    body = PageState(bike="jamis", rider="body").with_body(1.65, 60.0, "female", HANDS[0])
    assert engine.rider_label(body) == "a female rider of 1.65 m and 60 kg"


def test_figures_name_an_upload_by_its_name_not_its_secret_name(app):
    """An upload's figures carry the bicycle's ``name:`` (issue 35: not a file name, never ``upload-<secret>``),
    and the file name it was uploaded as where the file has no ``name:``."""
    from bikemass.web.page import _bike_shown, _eigenvalue_figure
    name = app.engine.add_upload("my bike.yaml", (frames_dir() / "benchmark.yaml").read_bytes())
    state = PageState(bike=name, rider="none")
    assert _bike_shown(app.engine, state) == "Benchmark (Meijaard et al. 2007)"
    figure = _eigenvalue_figure(app.engine.evaluate(state).stability, state, _bike_shown(app.engine, state),
                                app.engine.rider_label(state))
    titles = [figure._suptitle.get_text() if figure._suptitle else ""] + [a.get_title() for a in figure.axes]
    # the benchmark's set holds its rider: the title says so, as the command line's does
    assert any(" ".join(t.split()).startswith("Benchmark (Meijaard et al. 2007), rider in the parameter set")
               for t in titles)
    assert not any("upload-" in t for t in titles)
    text = "\n".join(line for line in (frames_dir() / "benchmark.yaml").read_text().splitlines()
                     if not line.startswith("name:"))
    unnamed = app.engine.add_upload("no name.yaml", text.encode())
    assert _bike_shown(app.engine, PageState(bike=unnamed, rider="none")) in ("no name.yaml", "no name")
