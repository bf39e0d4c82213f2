"""Units with dimensions: every unit knows its dimension, a wrong one is a one-line error
naming the file, the key and the expected dimension, and a bare angle is refused."""

import json
import math
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings, strategies as st

from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.cli.main import main
from bikemass.core.units import DIMENSIONS, INCH, POUND, UnitError, convert, dimension_of, to_si

ROOT = Path(__file__).parents[1]
FIXTURE = Path(__file__).parent / "data" / "shipped_parameters.json"


def test_units_convert_to_si():
    assert to_si("1.25 in", "length") == pytest.approx(1.25 * 0.0254, rel=1e-15)
    assert to_si("0.474 lb", "mass") == pytest.approx(0.474 * 0.45359237, rel=1e-15)
    assert to_si("205 GPa", "pressure") == 205e9
    assert to_si("7.85 g/cm^3", "density") == pytest.approx(7850, rel=1e-15)
    assert to_si("72 deg", "angle") == pytest.approx(math.pi * 0.4, rel=1e-15)
    assert to_si("72°", "angle") == to_si("72 deg", "angle")
    assert to_si("1.25in", "length") == to_si("1.25 in", "length")
    assert to_si(3, "length") == 3.0 and INCH == 0.0254 and POUND == 0.45359237
    assert to_si("30000 psi", "pressure") == pytest.approx(206.8427e6, rel=1e-6)   # 30 ksi
    assert to_si("1 lb in^2", "inertia") == pytest.approx(2.926397e-4, rel=1e-6)


@pytest.mark.parametrize("value, dimension, named", [
    ("450 g", "length", "a length .* got '450 g' \\(a mass\\)"),
    ("1 kg", "length", "a length"),
    ("3 m", "mass", "a mass .* \\(a length\\)"),
    ("205 GPa", "density", "a density"),
    ("3 furlongs", "length", "an unknown unit"),
    ("0.3 m", "dimensionless", "a plain number"),
    ("abc", "mass", "a mass"),
    (True, "mass", "a mass"),
    ([1], "length", "a length"),
    (10**400, "length", "too large"),
])
def test_wrong_dimension_is_refused_naming_the_expected_one(value, dimension, named):
    with pytest.raises(UnitError, match=named):
        to_si(value, dimension)


def test_a_bare_angle_is_refused_unless_the_format_fixes_it():
    with pytest.raises(UnitError, match="an angle with its unit"):
        to_si(124.28, "angle")
    with pytest.raises(UnitError, match="an angle with its unit"):
        to_si("124.28", "angle")
    assert to_si(0.3, "angle", bare_unit="rad") == 0.3
    assert to_si(18, "angle", bare_unit="deg") == pytest.approx(math.pi / 10, rel=1e-15)


def test_every_unit_belongs_to_exactly_one_dimension():
    for dimension, (si, table) in DIMENSIONS.items():
        assert table[si] == 1.0
        for unit, factor in table.items():
            assert dimension_of(unit) == dimension and factor > 0
            if unit:
                assert to_si(f"2 {unit}", dimension) == pytest.approx(2 * factor, rel=1e-15)


def test_convert_is_exact_in_the_written_unit():
    assert convert("73.809 deg", "angle", "deg") == 73.809
    assert convert("-0.1 rad", "angle", "deg") == pytest.approx(-0.1 * 180 / math.pi, rel=1e-15)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(x=st.floats(-1e6, 1e6, allow_nan=False),
       unit=st.sampled_from([(d, u) for d, (_, t) in DIMENSIONS.items() for u in t if u]))
def test_any_number_with_any_unit_converts_by_its_factor(x, unit):
    dimension, name = unit
    assert to_si(f"{x!r} {name}", dimension) == pytest.approx(x * DIMENSIONS[dimension][1][name],
                                                               rel=1e-15, abs=1e-300)


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(code, out, err):
    assert code == 2 and out == "" and err.count("\n") == 1 and err.startswith("bikemass: error: ")
    return err


def test_bare_angle_in_a_component_is_one_line_naming_file_key_dimension(tmp_path, capsys):
    text = (ROOT / "frames" / "jamis.yaml").read_text()
    assert "angle: 124.28 deg}" in text
    bike = tmp_path / "bike.yaml"
    bike.write_text(text.replace("angle: 124.28 deg}", "angle: 124.28}"))
    err = one_line_error(*run(capsys, "params", bike))
    assert str(bike) in err and ".angle: an angle with its unit" in err and "got 124.28" in err


def test_mass_where_a_pose_location_is_expected(tmp_path, capsys):
    doc = yaml.safe_load((ROOT / "bodies" / "poses" / "relaxed.yaml").read_text())
    doc["segments"]["head"]["location"] = ["1 kg", 0, 0]
    pose = tmp_path / "pose.yaml"
    pose.write_text(yaml.safe_dump(doc))
    err = one_line_error(*run(capsys, "rider", pose))
    assert f"{pose}: segments.head.location[0]: a length" in err and "(a mass)" in err


def test_shipped_parameters_unchanged_by_the_unit_migration():
    """Every shipped bicycle, and the Jamis with every shipped pose, as computed before
    angles carried units (tests/data/shipped_parameters.json, written by the code of
    main at 76a37c0, the last commit before the migration): equal to 1e-12 relative."""
    reference = json.loads(FIXTURE.read_text())
    for bike, expected in reference["bicycles"].items():
        got = scenario_parameters(bike).to_dict()
        assert got == pytest.approx(expected, rel=1e-12, abs=1e-12), bike
    for rider, expected in reference["jamis_with_rider"].items():
        got = scenario_parameters("jamis", rider).to_dict()
        assert got == pytest.approx(expected, rel=1e-12, abs=1e-12), rider


def test_a_damping_per_degree_is_per_radian_times_180_over_pi():
    """``N m s/deg`` is taken as a stiffness's ``N m/deg`` is (it was refused): 1 N m s/deg = 180/pi N m s/rad."""
    from bikemass.core.units import to_si
    assert to_si("1 N m s/deg", "damping") == pytest.approx(180 / math.pi, rel=1e-15)
    assert to_si("0.5 N m s/rad", "damping") == 0.5


@pytest.mark.parametrize("text", ["inf 1/rad", "-inf 1/rad", "nan 1/rad", ".inf m"])
def test_a_value_that_is_not_finite_is_named_as_such(text):
    """``inf 1/rad`` was refused as a unit problem ("a bare number could be either"); the number is what is
    wrong."""
    from bikemass.core.units import UnitError, to_si
    with pytest.raises(UnitError, match="not a finite number"):
        to_si(text, "inverse angle" if "rad" in text else "length")
