"""The web page's state, JSON API, downloads and uploads (Flask test client, no browser).

The API must answer exactly what the command line prints: the ``test_contract_*`` tests run the
command in-process and compare the parsed numbers (tolerance 1e-12 m/s: the same code path, so
only the JSON round trip may differ; they hold the shell to the library, not the numbers, which
the peer and published-table tests hold).  A typed-over parameter is also checked against a peer,
BicycleParameters' Meijaard2007Model.
"""

import contextlib
import io
import json

import numpy as np
import pytest
import yaml

pytest.importorskip("dash")

from bikemass.cli.main import main  # noqa: E402
from bikemass.core.errors import InputError  # noqa: E402
from bikemass.models.parameters import NAMES  # noqa: E402
from bikemass.web import create_app  # noqa: E402
from bikemass.web.state import PageState  # noqa: E402


@pytest.fixture(scope="module")
def client():
    return create_app().server.test_client()


def cli_json(*argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(list(argv)) == 0
    return json.loads(out.getvalue())


def test_state_round_trips_through_the_query():
    state = PageState(bike="cargo", rider="aero-tuck", stiffness="aluminum", combine="thesis",
                      overrides=(("c", 0.0812), ("mB", 85.25)))
    from urllib.parse import parse_qsl
    assert PageState.from_query(dict(parse_qsl(state.to_query()))) == state


@pytest.mark.parametrize("query, key", [
    ({"stiffness": "../rubber"}, "stiffness"), ({"combine": "guess"}, "combine"),
    ({"c": "nan"}, "c"), ({"lam": "abc"}, "lam"), ({"color": "red"}, "color")])
def test_bad_query_values_name_their_key(query, key):
    with pytest.raises(InputError) as err:
        PageState.from_query(query)
    assert err.value.key == key and "\n" not in str(err.value)


@pytest.mark.parametrize("bike, rider, stiffness", [
    ("jamis", "relaxed", "steel"), ("benchmark", "none", "infinite"), ("cargo-loaded", "no-hands", "aluminum")])
def test_contract_api_stability_is_the_command_lines_json(client, bike, rider, stiffness):
    reply = client.get(f"/api/stability?bike={bike}&rider={rider}&stiffness={stiffness}")
    assert reply.status_code == 200
    ours = reply.get_json()
    cli = cli_json("stability", bike, "--rider", rider, "--stiffness", stiffness, "--format", "json")
    assert ours.pop("warnings") == cli.pop("warnings", [])
    assert ours.keys() == cli.keys()
    for key in ("weave_speeds", "capsize_speeds"):
        np.testing.assert_allclose(ours[key], cli[key], rtol=0, atol=1e-12)
    assert [(c["mode"], c["direction"]) for c in ours["crossings"]] == \
           [(c["mode"], c["direction"]) for c in cli["crossings"]]
    assert ours["weave_speeds"] or ours["capsize_speeds"]


def test_contract_api_params_is_the_command_lines_json(client):
    ours = client.get("/api/params?bike=jamis&rider=relaxed").get_json()
    cli = cli_json("params", "jamis", "--rider", "relaxed", "--format", "json")
    assert list(ours) == [*NAMES, "units", "warnings"] and ours["units"] == cli["units"]
    np.testing.assert_allclose([ours[k] for k in NAMES], [cli[k] for k in NAMES], rtol=1e-15)


def test_a_typed_over_parameter_changes_the_answer_as_a_parameter_file_would(client, tmp_path):
    """Trail 0.02 m on the benchmark: the API against the command line on the edited parameter file
    (contract), and its weave speed against BicycleParameters' Meijaard2007Model of the same set
    (the peer's eigenvalues' crossing found by brentq to 1e-14 m/s; agreement to 1e-8 m/s)."""
    bp_models = pytest.importorskip("bicycleparameters.models")
    bp_sets = pytest.importorskip("bicycleparameters.parameter_sets")
    from scipy.optimize import brentq
    params = cli_json("params", "benchmark", "--format", "json")
    params["c"] = 0.02
    edited = tmp_path / "edited.yaml"
    edited.write_text(yaml.safe_dump(params))
    cli = cli_json("stability", str(edited), "--format", "json")
    ours = client.get("/api/stability?bike=benchmark&rider=none&c=0.02").get_json()
    base = client.get("/api/stability?bike=benchmark&rider=none").get_json()
    np.testing.assert_allclose(ours["weave_speeds"], cli["weave_speeds"], atol=1e-12)
    assert ours["weave_speeds"] != base["weave_speeds"]
    peer = bp_models.Meijaard2007Model(bp_sets.Meijaard2007ParameterSet(
        {**{k: params[k] for k in NAMES}, "v": 1.0}, includes_rider=True))

    def weave_growth(v):
        ev = np.linalg.eigvals(peer.form_state_space_matrices(v=v)[0])
        return max(z.real for z in ev if abs(z.imag) > 1e-6)
    weave = ours["weave_speeds"][0]
    assert weave == pytest.approx(brentq(weave_growth, weave - 0.3, weave + 0.3, xtol=1e-14), abs=1e-8)


@pytest.mark.parametrize("query", ["bike=nonesuch", "bike=../frames/jamis", "rider=/etc/passwd",
                                   "stiffness=rubber", "w=inf"])
def test_bad_queries_answer_400_with_one_line(client, query):
    reply = client.get(f"/api/stability?{query}")
    assert reply.status_code == 400
    message = reply.get_json()["error"]
    assert message and "\n" not in message and "Traceback" not in message


def test_downloads_read_back(client, tmp_path):
    query = "bike=jamis&rider=relaxed&stiffness=steel"
    parameters = yaml.safe_load(client.get(f"/download/parameters.yaml?{query}").data)
    api = client.get(f"/api/params?{query}").get_json()
    assert parameters.pop("units") == api.pop("units") and api.pop("warnings") == []
    assert parameters == pytest.approx(api, rel=1e-15)
    bp = client.get(f"/download/Benchmark.txt?{query}").data.decode()
    values = dict(line.split(" = ") for line in bp.splitlines() if not line.startswith("#"))
    assert {k: float(v) for k, v in values.items()} == pytest.approx(api, rel=1e-15)
    csv = client.get(f"/download/eigenvalues.csv?{query}").data.decode().splitlines()
    assert csv[0].startswith("speed,") and len(csv) == 1 + 601
    bicycle = tmp_path / "bicycle.yaml"
    bicycle.write_bytes(client.get(f"/download/bicycle.yaml?{query}").data)
    written, shipped = cli_json("params", str(bicycle), "--format", "json"), cli_json("params", "jamis", "--format", "json")
    assert written.pop("units") == shipped.pop("units")
    assert written == pytest.approx(shipped, rel=1e-12)
    assert b"segments" in client.get(f"/download/pose.yaml?{query}").data
    assert client.get(f"/download/secrets.txt?{query}").status_code == 400


def test_uploads_load_or_give_one_line(tmp_path):
    engine = create_app().engine
    params = cli_json("params", "benchmark", "--format", "json")
    name = engine.add_upload("mine.yaml", yaml.safe_dump({**params, "c": 0.05}).encode())
    assert engine.parameters(PageState(bike=name, rider="none")).c == 0.05
    derived = engine.add_upload("derived.yaml", b"base: jamis\nname: my jamis\n")
    assert engine.parameters(PageState(bike=derived, rider="none")).w == pytest.approx(
        engine.parameters(PageState(bike="jamis", rider="none")).w)
    exported = create_app().server.test_client().get("/download/Benchmark.txt?bike=jamis&rider=relaxed").data
    measured = engine.add_upload("JamisBenchmark.txt", exported)
    assert engine.parameters(PageState(bike=measured, rider="none")).to_dict() == pytest.approx(
        engine.parameters(PageState(bike="jamis", rider="relaxed")).to_dict(), rel=1e-15)
    for filename, content, fragment in [
            ("escape.yaml", b"base: /etc/passwd\n", "base: a bicycle file or one of: benchmark"),
            ("up.yaml", b"base: ../../frames/jamis.yaml\n", "an uploaded file cannot reach other files"),
            ("big.yaml", b"#" * 2_000_000, "kB"),
            ("mine.exe", b"MZ", "ending in"),
            ("broken.yaml", b"w: [1, 2\n", "YAML")]:
        with pytest.raises(InputError) as err:
            engine.add_upload(filename, content)
        assert fragment in str(err.value) and "\n" not in str(err.value)


def test_chart_edits_and_sizes_rebuild_the_bicycle(client):
    """A head angle typed over the BMC's chart tilts the steer axis by exactly that angle."""
    base = client.get("/api/params?bike=bmc-roadmachine&size=56&rider=none").get_json()
    edited = client.get("/api/params?bike=bmc-roadmachine&size=56&rider=none&chart.head_tube_angle=70.5").get_json()
    assert base["lam"] == pytest.approx(np.radians(90 - 72), abs=1e-12)
    assert edited["lam"] == pytest.approx(np.radians(90 - 70.5), abs=1e-12)
    assert edited["c"] > base["c"]            # slacker head, same offset: more trail
    small = client.get("/api/params?bike=bmc-roadmachine&size=47&rider=none").get_json()
    assert small["w"] < base["w"]
    reply = client.get("/api/params?bike=jamis&rider=none&chart.stack=600")
    assert reply.status_code == 400 and "chart" in reply.get_json()["error"]
    assert client.get("/api/params?bike=bmc-roadmachine&chart.reach=abc").status_code == 400


def test_a_body_rider_from_height_mass_and_sex_is_seated_on_each_bicycle(client):
    """The API's body rider equals the command line's chain pose file of the same person."""
    query = "rider=body&height=1.8&mass=75.0&sex=male&hands=hoods&stiffness=infinite"
    jamis = client.get(f"/api/params?bike=jamis&{query}").get_json()
    cargo = client.get(f"/api/params?bike=cargo&{query}").get_json()
    bare = client.get("/api/params?bike=jamis&rider=none").get_json()
    assert jamis["mB"] - bare["mB"] == pytest.approx(75.0, abs=1e-9)
    pose = client.get(f"/download/pose.yaml?bike=jamis&{query}").data
    assert yaml.safe_load(pose)["body"] == {"height": "1.8 m", "mass": "75.0 kg", "sex": "male"}
    assert jamis["xB"] != pytest.approx(cargo["xB"] * jamis["w"] / cargo["w"], abs=1e-3)
    assert client.get("/api/params?bike=jamis&rider=body&height=4").status_code == 400
    assert client.get("/api/params?bike=jamis&rider=body&sex=robot").status_code == 400


def test_contract_a_body_rider_matches_the_command_line(client, tmp_path):
    query = "bike=jamis&rider=body&height=1.65&mass=58.0&sex=female&hands=tops&stiffness=steel"
    pose = tmp_path / "me.yaml"
    pose.write_bytes(client.get(f"/download/pose.yaml?{query}").data)
    cli = cli_json("stability", "jamis", "--rider", str(pose), "--stiffness", "steel", "--format", "json")
    ours = client.get(f"/api/stability?{query}").get_json()
    np.testing.assert_allclose(ours["weave_speeds"], cli["weave_speeds"], atol=1e-12)
