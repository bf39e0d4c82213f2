"""Hostile input to the Python API: every refusal is a bm.InputError (wrong types an InputError
that is also a TypeError), never a bare TypeError/ValueError/ZeroDivisionError from inside, and
parameter sets the model is not defined for are refused instead of analysed."""

import math
import warnings

import numpy as np
import pytest

import bikemass as bm
from bikemass.core.errors import InputTypeError


@pytest.fixture(scope="module")
def meijaard():
    return bm.parameters("benchmark")


@pytest.mark.parametrize("value", [None, 5, math.nan, [1, 2], b"jamis", object()])
def test_wrong_types_are_input_errors(value):
    for call in (bm.load_bicycle, bm.frame_structure, bm.geometry_chart, bm.load_parameter_text):
        with pytest.raises(InputTypeError):
            call(value)
    with pytest.raises(bm.InputError, match="rider: \\(argument\\): a rider is"):
        bm.parameters("jamis", value if value is not None else 5)


@pytest.mark.parametrize("change", [{"mB": -85.0}, {"c": math.nan}, {"w": math.inf}, {"w": 0.0},
                                    {"lam": -math.pi / 2}, {"lam": math.pi / 2}, {"g": 0.0}, {"w": "1"}])
def test_impossible_parameters_are_refused_by_every_analysis(meijaard, change):
    bad = meijaard.replace(**change)
    key = next(iter(change))
    for call in (bm.stability, bm.eigenvalues, bm.matrices, bm.sensitivity):
        with pytest.raises(bm.InputError, match=f"params: {key}: "):
            call(bad)


def test_valid_parameters_still_give_the_benchmark(meijaard):
    """Meijaard et al. (2007): weave 4.292382 m/s, capsize 6.024262 m/s."""
    result = bm.stability(meijaard)
    assert result.weave_speeds[0] == pytest.approx(4.2923825, abs=1e-6)
    assert result.capsize_speeds[0] == pytest.approx(6.0242620, abs=1e-6)


@pytest.mark.parametrize("speeds", [[], [-5, 0, 5], [0, math.nan, 5], [5, 1, 3], np.ones((3, 3)), "0:10:1", [1, 1, 2]])
def test_bad_speed_arrays(meijaard, speeds):
    with pytest.raises(bm.InputError, match="speeds"):
        bm.stability(meijaard, speeds=speeds)


@pytest.mark.parametrize("args", [(10, 0, 1), (0, 10, 0), (0, 10, -1), (0, 1000, 1e-9), (0, math.nan, 1), ("0", "10", "1")])
def test_bad_speed_grids(args):
    with pytest.raises(bm.InputError, match="speeds"):
        bm.speeds(*args)


@pytest.mark.parametrize("marginal", [-1, 0, math.nan, math.inf, "2", True])
def test_bad_marginal(meijaard, marginal):
    with pytest.raises(bm.InputError, match="marginal"):
        bm.stability(meijaard, marginal=marginal)


def test_misspelt_choices_are_input_errors():
    bike = bm.load_bicycle("jamis")
    for call, match in ((lambda: bm.parameters(bike, "relaxed", combine="sum"), "combine"),
                        (lambda: bm.parameters(bike, "relaxed", method="foo"), "method"),
                        (lambda: bm.stiffness(bike, "steel", source="x"), "source"),
                        (lambda: bm.stiffness(bike, "steel", procedure="x"), "procedure"),
                        (lambda: bm.frame_modes(bike, support="x"), "support"),
                        (lambda: bm.pose_rider(bike, hands="feet"), "hands")):
        with pytest.raises(bm.InputError, match=match):
            call()
    with pytest.raises(InputTypeError, match="bm.stiffness"):
        bm.stability(bm.parameters("benchmark"), stiffness="steel")


def test_tiny_frame_elements_are_refused_before_meshing():
    """1e-9 m elements would be ~4e9 beam elements (tens of GB): refused by count."""
    bike = bm.load_bicycle("jamis")
    with pytest.raises(bm.InputError, match=r"element_size: 1e-09: a model of at most 5000 beam elements, got \d+"):
        bm.frame_modes(bike, element_size=1e-9)
    with pytest.raises(bm.InputError, match="element_size"):
        bm.frame_modes(bike, element_size=math.inf)
    with pytest.raises(bm.InputError, match="count"):
        bm.frame_modes(bike, count=True)


@pytest.mark.parametrize("kwargs, match", [({"vmax": 0}, "vmax"), ({"vmax": -1}, "vmax"), ({"vmax": math.nan}, "vmax"),
                                           ({"names": ("qq",)}, "names"), ({"names": "c"}, "names"),
                                           ({"stiffness": np.eye(3)}, "stiffness"),
                                           ({"stiffness": -np.eye(2)}, "stiffness")])
def test_sensitivity_arguments(meijaard, kwargs, match):
    with pytest.raises(bm.InputError, match=match):
        bm.sensitivity(meijaard, **kwargs)


def test_geometry_sensitivity_arguments():
    with pytest.raises(bm.InputError, match="step"):
        bm.geometry_sensitivity(bm.Scenario("jamis"), ["geometry.trail"], step=0)
    with pytest.raises(InputTypeError, match="scenario"):
        bm.geometry_sensitivity("jamis", ["geometry.trail"])


def test_uncertainty_key_must_be_a_string():
    with pytest.raises(bm.InputError, match="spreads: 5: an input key"):
        bm.uncertainty("benchmark", {5: 0.1})


@pytest.mark.parametrize("kwargs, match", [({"workers": 0}, "--workers: 0"), ({"workers": -2}, "--workers: -2"),
                                           ({"workers": "2"}, "--workers: 2"), ({"progress": 5}, "progress")])
def test_sweep_arguments_are_checked_before_any_work(tmp_path, kwargs, match):
    """workers=0 once made a cluster without workers and waited for ever."""
    spec = tmp_path / "s.yaml"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.08]\n")
    with pytest.raises(bm.InputError, match=match):
        bm.sweep(spec, tmp_path / "out", **kwargs)
    assert not (tmp_path / "out").exists()
    for spec_arg, out in ((None, tmp_path / "o"), ({"bike": "benchmark"}, tmp_path / "o"), (spec, None)):
        with pytest.raises(InputTypeError):
            bm.sweep(spec_arg, out)


def test_save_figure_arguments(tmp_path, meijaard):
    fig = bm.plot_eigenvalues(bm.stability(meijaard, speeds=bm.speeds(0, 2, 0.5)))
    for path in (tmp_path / "x.docx", tmp_path, tmp_path / "noext"):
        with pytest.raises(bm.InputError, match="an image file name ending in"):
            bm.save_figure(fig, path)
    for dpi in (0, 10 ** 6, "150"):
        with pytest.raises(bm.InputError, match="dpi"):
            bm.save_figure(fig, tmp_path / "x.png", dpi=dpi)
    with pytest.raises(InputTypeError, match="fig"):
        bm.save_figure(None, tmp_path / "x.png")
    assert list(tmp_path.iterdir()) == []


def _deep(levels):
    top = cur = {}
    for _ in range(levels):
        cur["a"] = {}
        cur = cur["a"]
    return top


def test_deep_and_self_containing_mappings_are_refused_without_recursion():
    looped = {}
    looped["a"] = looped
    for value in (_deep(5000), looped):
        for call in (bm.load_bicycle, bm.load_rider, lambda v: bm.seated_rider("jamis", v)):
            with pytest.raises(bm.InputError, match="nested at most 64 levels deep"):
                call(value)


@pytest.mark.parametrize("kwargs, match", [({"crank": math.nan}, "crank: nan"), ({"crank": "x"}, "crank"),
                                           ({"fixed": [1, 2]}, "fixed"), ({"fixed": {"elbow": 1e9}}, "fixed.elbow"),
                                           ({"fixed": {"elbow": True}}, "fixed.elbow")])
def test_pose_angles_are_checked(kwargs, match):
    with pytest.raises(bm.InputError, match=match):
        bm.pose_rider("jamis", **kwargs)


def test_plot_arguments(meijaard):
    result = bm.stability(meijaard, speeds=bm.speeds(0, 2, 0.5))
    for call, match in ((lambda: bm.plot_eigenvalues(None), "result"),
                        (lambda: bm.plot_eigenvalues(result, size=(-1, 2)), "size"),
                        (lambda: bm.plot_eigenvalues(result, size=(1e6, 1e6)), "size"),
                        (lambda: bm.plot_eigenvalues(result, xlim=(math.nan, 1)), "xlim"),
                        (lambda: bm.plot_eigenvalues(result, ylim=(1, 1)), "ylim"),
                        (lambda: bm.plot_critical_speeds([]), "results"),
                        (lambda: bm.plot_critical_speeds({}), "results"),
                        (lambda: bm.plot_side_view(None), "bicycle"),
                        (lambda: bm.plot_side_view("jamis", rider=5), "rider"),
                        (lambda: bm.plot_frame_modes(None), "modes"),
                        (lambda: bm.plot_chart(None), "bicycle")):
        with pytest.raises(bm.InputError, match=match):
            call()
    assert len(bm.plot_side_view("benchmark").axes) == 1          # a name is loaded as load_bicycle does


def test_raster_size_is_bounded(tmp_path, meijaard):
    """100 x 100 in at 2000 dpi would be 4e10 pixels: refused before rendering."""
    fig = bm.plot_eigenvalues(bm.stability(meijaard, speeds=bm.speeds(0, 2, 0.5)), size=(100, 100))
    with pytest.raises(bm.InputError, match="pixels"):
        bm.save_figure(fig, tmp_path / "big.png", dpi=2000)
    assert list(tmp_path.iterdir()) == []


def test_web_api_refuses_typed_over_parameters_off_the_model():
    pytest.importorskip("dash")
    from bikemass.web import create_app
    client = create_app().server.test_client()
    for query, error in (("mB=-85", "URL: mB: a positive number, got -85"),
                         ("lam=2", "URL: lam: a steer-axis tilt in (-pi/2, pi/2) rad (the steer axis not horizontal), got 2"),
                         ("c=1e300", "URL: c: a finite number in SI units (m, kg, kg m^2, rad) of magnitude at most 1e+12")):
        for endpoint in ("/api/params", "/api/stability"):
            reply = client.get(f"{endpoint}?bike=benchmark&rider=none&stiffness=infinite&{query}")
            assert reply.status_code == 400 and reply.get_json() == {"error": error}


@pytest.mark.parametrize("given", [[1], "tyres.yaml", 5])
def test_member_inputs_that_are_no_mapping_are_an_input_type_error(given):
    with pytest.raises(InputTypeError, match="member_inputs"):
        bm.Scenario("benchmark", model="tyre", member_inputs=given)


@pytest.mark.parametrize("changes, error, match", [
    (["c"], bm.InputTypeError, "a mapping"), (42, bm.InputTypeError, "a mapping"),
    ({42: 1.0}, bm.InputTypeError, "dotted path"), ({"c": [1.0]}, bm.InputError, "c: a number"),
    ({"rider.posture.elbow": None}, bm.InputTypeError, "rider.posture.elbow"),
    ({"rider.posture.elbow": [1.0, 2.0]}, bm.InputError, "posture.elbow: a number in SI"),
])
def test_bad_changes_to_a_scenario_are_input_errors(changes, error, match):
    """``Scenario.build`` of changes that are not a mapping of dotted keys to values is one InputError
    (an InputTypeError for the wrong Python type), not Python's AttributeError or a cache's TypeError."""
    with pytest.raises(error, match=match):
        bm.Scenario("jamis", "relaxed").build(changes)


def test_a_location_changed_from_python_as_a_list_a_tuple_or_an_array_is_the_same():
    """A segment's location given as a list, a tuple or an array is one change (a tuple was refused as
    not a list; a list failed as a cache key); the head moved 8 mm forward moves the rear body's mass
    centre by the head's mass times 8 mm over mB."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        scenario = bm.Scenario("jamis", "relaxed", allow_off_contact=True)
        base = scenario.build().parameters
        moved = [scenario.build({"rider.segments.head.location": value}).parameters
                 for value in ([0.410, 0.0, -1.895], (0.410, 0.0, -1.895), np.array([0.410, 0.0, -1.895]))]
    head = next(part for part in bm.load_rider("relaxed").parts if part.name == "head")
    for p in moved:
        assert p.xB - base.xB == pytest.approx(head.mass * 0.008 / base.mB, abs=1e-9)


def test_a_crank_length_no_bicycle_has_is_warned(tmp_path):
    """``crank_length: 170`` (a bare number: 170 m, meant as mm) ran through every command without a word: a crank
    length outside 0.05..0.3 m is warned about, naming the file and the key; the Jamis's 170 mm says nothing."""
    from bikemass.core.errors import BikemassWarning
    from bikemass.core.paths import frames_dir
    text = (frames_dir() / "jamis.yaml").read_text()
    assert "  crank_length: 170 mm" in text
    bad = tmp_path / "jamis.yaml"
    bad.write_text(text.replace("  crank_length: 170 mm", "  crank_length: 170"))
    with pytest.warns(BikemassWarning, match=r"jamis.yaml: contacts.crank_length: 170 m is outside 0.05..0.3 m"):
        bm.load_bicycle(str(bad))
    with warnings.catch_warnings():
        warnings.simplefilter("error", BikemassWarning)
        bm.load_bicycle(str(frames_dir() / "jamis.yaml"))
