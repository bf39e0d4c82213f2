"""Typed edits (issue 32, item 5): a design change travels as a typed value (a float in SI, a
:class:`~bikemass.core.units.Quantity`, a solved pose), never as ``"<number> <unit>"`` text made
and parsed again inside ``src/``.

The contract test reads the source and holds it; the other tests check that a change made the
typed way gives what the same change gives written by hand into a file and read fresh (the
file route, independent of the edit code: only the file reader is shared)."""

import ast
import math
import re
from pathlib import Path

import numpy as np
import pytest
import yaml

import bikemass as bm
from bikemass.bicycle import bicycle_parameters, load_bicycle
from bikemass.bicycle.chart import CHECKED_KEYS
from bikemass.core.output import dumps
from bikemass.core.paths import frames_dir
from bikemass.core.plain import file_form
from bikemass.core.units import DIMENSIONS, Quantity, UnitError, convert, dimension_of
from bikemass.models.parameters import NAMES

SRC = Path(bm.__file__).parent

ALLOWED = {
    ("core/units.py", "f'{self.value!r} {self.unit}'"):
        "Quantity.text: the one rendering of a typed value as file text (core.plain.file_form, used only "
        "by file writers); nothing in src parses it back",
}
"""(file under src/bikemass, the expression) -> why it may write a number with its unit as text."""


def _unit_text(node):
    """A string constant ``" <unit>"`` or ``"<unit>"`` (a unit of :data:`DIMENSIONS`; the reader takes
    ``"72deg"`` as it takes ``"72 deg"``)."""
    return (isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value.strip() != ""
            and node.value == node.value.rstrip() and dimension_of(node.value.lstrip()) is not None)


def _unit_expression(node):
    """An expression giving a unit: a name holding "unit", a unit constant, or a choice of two."""
    if isinstance(node, ast.IfExp):
        return _unit_expression(node.body) and _unit_expression(node.orelse)
    if isinstance(node, ast.Constant):
        return isinstance(node.value, str) and dimension_of(node.value) is not None
    return "unit" in ast.unparse(node)


def _full_digits(node):
    """A formatted value written with every digit (``{x!r}``, ``{x!s}``, ``{x}``): what text made to
    be read again writes; a display uses a format spec (``{x:.1f}``) and is left alone."""
    return isinstance(node, ast.FormattedValue) and (node.conversion in (ord("r"), ord("s"))
                                                     or node.format_spec is None)


def number_with_unit_texts(source):
    """``[(line, expression)]`` of the places in Python ``source`` that write a number in full
    followed by its unit as text: ``f"{x!r} deg"``, ``f"{x!r} {unit}"``, ``repr(x) + " m"``,
    ``"{!r} rad".format(x)``, ``"%r m" % x``."""
    found = []
    for node in ast.walk(ast.parse(source)):
        hit = False
        if isinstance(node, ast.JoinedStr):
            v = node.values
            hit = (len(v) == 2 and _full_digits(v[0]) and _unit_text(v[1])) or (
                len(v) == 3 and _full_digits(v[0]) and isinstance(v[1], ast.Constant) and v[1].value == " "
                and isinstance(v[2], ast.FormattedValue) and _unit_expression(v[2].value))
        elif isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add) and _unit_text(node.right):
            left = node.left
            hit = isinstance(left, (ast.Name, ast.Attribute, ast.Subscript)) or (
                isinstance(left, ast.Call) and isinstance(left.func, ast.Name) and left.func.id in ("repr", "str"))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            match = re.fullmatch(r"(?:\{(?:![rs])?\}|%[rsg]) (\S+)", node.value)
            hit = match is not None and dimension_of(match.group(1)) is not None
        if hit:
            found.append((node.lineno, ast.unparse(node)))
    return sorted(found)


def test_contract_no_design_value_is_written_as_text_with_its_unit_in_src():
    """Contract: no module of ``src/bikemass`` (the generated code aside) writes a number in full
    with its unit as text, except the file writers of :data:`ALLOWED`, each with its reason; an
    entry of ALLOWED that no longer matches is an error too (the list stays true)."""
    found, used = [], set()
    for path in sorted(SRC.rglob("*.py")):
        rel = path.relative_to(SRC).as_posix()
        if rel.startswith("generated/"):
            continue
        for line, expression in number_with_unit_texts(path.read_text(encoding="utf-8")):
            if (rel, expression) in ALLOWED:
                used.add((rel, expression))
            else:
                found.append(f"{rel}:{line}: {expression}")
    assert found == [], "a number written as text with its unit (pass a Quantity or an SI float):\n" + \
        "\n".join(found)
    assert set(ALLOWED) - used == set()


def test_the_scanner_finds_each_form_it_forbids():
    """The scanner of the contract test, on a sample: every round-trip form found, displays with
    a format spec and messages with words around the number not."""
    sample = '\n'.join([
        'a = f"{x!r} rad"', 'b = f"{x} m"', 'c = f"{x!r} {unit}"', "d = f\"{x!r} {'deg' if k else 'm'}\"",
        'e = repr(x) + " deg"', 'f = "{!r} mm".format(x)', 'g = "%r kg" % x',
        'h = f"{x:.1f} deg"', 'l = f"{x!r}deg"', 'i = f"got {x!r} m"', 'j = f"{label} {part}"', 'k = ", ".join(s) + " m/s"'])
    assert [line for line, _ in number_with_unit_texts(sample)] == [1, 2, 3, 4, 5, 6, 7, 9]


def test_a_quantity_reads_as_its_text_does():
    """``convert`` of a Quantity equals ``convert`` of its ``"<number> <unit>"`` text bit for bit (the
    same arithmetic), for every unit of every dimension, on seeded random numbers; a Quantity of
    another dimension is refused as its text is, and ``file_form`` writes the text (its repr too, so
    that a message naming a bad value reads as it did when the value was text)."""
    rng = np.random.default_rng(32)
    for dimension, (si, table) in DIMENSIONS.items():
        for unit in table:
            if unit == "" or dimension_of(unit) != dimension:
                continue
            for x in rng.uniform(-1e3, 1e3, 5):
                q = Quantity(x, unit)
                for target in (si, unit):
                    assert convert(q, dimension, target) == convert(f"{float(x)!r} {unit}", dimension, target)
                assert file_form({"v": [q]}) == {"v": [f"{float(x)!r} {unit}"]}
    assert repr(Quantity(500.0, "kg")) == "'500.0 kg'"        # an error message names it as a file's text
    with pytest.raises(UnitError, match="a length"):
        convert(Quantity(72.0, "deg"), "length", "m")
    with pytest.raises(UnitError):
        Quantity(1.0, "furlong")


def _parameters(bicycle):
    p = bicycle_parameters(bicycle)
    return np.array([getattr(p, k) for k in NAMES])


def _fargo_md_by_hand(tmp_path, head_angle_text):
    """The Salsa Fargo's size MD written out by hand as a one-size chart bicycle file with the head
    angle ``head_angle_text`` and the published checks (wheelbase, top tube, ...) left out, read fresh."""
    document = yaml.safe_load((frames_dir() / "salsa_fargo.yaml").read_text())
    index = document.pop("sizes").index("MD")

    def one(value):
        return value[index] if isinstance(value, list) else value
    for block in ("chart", "cockpit"):
        document[block] = {k: one(v) for k, v in document[block].items() if k not in CHECKED_KEYS}
    document["crank_length"] = one(document["crank_length"])
    document["chart"]["head_tube_angle"] = head_angle_text
    path = tmp_path / "fargo_md.yaml"
    path.write_text(yaml.safe_dump(document, sort_keys=False))
    return load_bicycle(str(path))


@pytest.mark.parametrize("degrees", [67.0, 69.5, 71.25])
def test_a_chart_head_angle_change_equals_the_chart_written_by_hand(tmp_path, degrees):
    """A chart head-angle change of the Salsa Fargo MD (whose chart has a ``units: {angle: deg}``
    block), given as an SI float (rad), as user text and as a Quantity, gives the 26 benchmark
    parameters of the same chart written by hand into a file and read fresh: 1e-12 relative (the
    float in radians differs from degrees times pi/180 by at most a rounding, about 1e-16)."""
    reference = _parameters(_fargo_md_by_hand(tmp_path, f"{degrees} deg"))
    scenario = bm.Scenario("salsa-fargo@MD", None)
    for value in (math.radians(degrees), f"{degrees} deg", Quantity(degrees, "deg")):
        p = scenario.build({"chart.head_tube_angle": value}).parameters
        np.testing.assert_allclose([getattr(p, k) for k in NAMES], reference, rtol=1e-12, atol=1e-15,
                                   err_msg=repr(value))


def test_a_head_angle_sweep_equals_the_charts_written_by_hand(tmp_path):
    """``bm.sweep`` of the Fargo MD's head angle (the spec in deg): each row's total mass equals the
    hand-written chart's to 1e-12 relative and its weave speed that chart's (the same engine) to
    1e-9 m/s."""
    from bikemass.analysis.engine.critical import critical_speeds
    spec = tmp_path / "spec.yaml"
    spec.write_text("{bike: salsa-fargo@MD, rider: none, vary: {chart.head_tube_angle: [67 deg, 71.25 deg]}}")
    rows = list(bm.sweep(str(spec), str(tmp_path / "out")))
    assert len(rows) == 2
    for row, degrees in zip(rows, (67.0, 71.25)):
        bicycle = _fargo_md_by_hand(tmp_path, f"{degrees} deg")
        p = bicycle_parameters(bicycle)
        assert row["total_mass"] == pytest.approx(p.mR + p.mB + p.mH + p.mF, rel=1e-12)
        weave = critical_speeds(bm.Scenario(bicycle, None).build().model).weave_speed
        assert row["weave_speed"] == pytest.approx(weave, abs=1e-9)


def _part_values(parts):
    out = {}
    for part in parts:
        props = part.exact()
        out[part.name] = np.concatenate([[props.mass], props.com, props.inertia.ravel(),
                                         part.placement.rotation.ravel(), part.placement.translation])
    return out


@pytest.mark.parametrize("lean", [25.0, 40.0])
def test_a_solved_pose_equals_its_pose_file_read_fresh(tmp_path, lean):
    """A pose change (torso lean 25 or 40 deg, crank at 200 deg): the posed rider's parts, made from
    the solved pose itself, equal those of its pose document written as a file (``bikemass pose
    -o``'s form) and read fresh, part by part (placement, mass, com, inertia: 1e-12 relative), and so do the
    benchmark parameters of the Jamis carrying either."""
    posed = bm.pose_rider("jamis", hands="hoods", crank=200.0, fixed={"torso_lean": lean})
    text = dumps(posed.placement, "yaml")
    assert re.search(r"\n    angle: -?\d+\.\d+ deg\n", text)        # written as text for the file
    path = tmp_path / "posed.yaml"
    path.write_text(text)
    fresh = bm.load_rider(str(path))
    ours, theirs = _part_values(posed.rider.parts), _part_values(fresh.parts)
    assert ours.keys() == theirs.keys()
    for name, values in ours.items():
        np.testing.assert_allclose(values, theirs[name], rtol=1e-12, atol=1e-15, err_msg=name)
    with_posed = bm.parameters("jamis", posed.rider)
    with_file = bm.parameters("jamis", str(path))
    np.testing.assert_allclose([getattr(with_posed, k) for k in NAMES], [getattr(with_file, k) for k in NAMES],
                               rtol=1e-12, atol=1e-15)


def test_a_web_chart_edit_equals_its_download_read_fresh(tmp_path):
    """The page's chart edit (stack in mm, head angle in deg, typed values) builds the bicycle its
    ``bicycle.yaml`` download (text) builds when read fresh: 26 parameters to 1e-12 relative."""
    from bikemass.web.engine import edited_chart
    mapping = edited_chart("salsa-fargo", {"stack": 650.0, "head_tube_angle": 70.5}, "MD")
    path = tmp_path / "download.yaml"
    path.write_text(yaml.safe_dump(file_form(mapping), sort_keys=False))
    assert "head_tube_angle: 70.5 deg" in path.read_text()
    np.testing.assert_allclose(_parameters(bm.load_bicycle(mapping)), _parameters(load_bicycle(str(path))),
                               rtol=1e-12, atol=1e-15)


def test_a_changed_design_written_reads_back_as_built(tmp_path):
    """``Inputs.bicycle_document`` (what ``bikemass optimise`` writes for a changed design) read fresh
    from its file gives the bicycle the change built (SI float changes on a chart with a
    ``units:`` block, so written with their units): 26 parameters to 1e-12 relative."""
    scenario = bm.Scenario("salsa-fargo@MD", None)
    changes = (("chart.head_tube_angle", math.radians(70.0)), ("chart.stack", 0.65))
    built = scenario.inputs.bicycle(changes)
    path = tmp_path / "design.yaml"
    path.write_text(yaml.safe_dump(scenario.inputs.bicycle_document(changes), sort_keys=False))
    np.testing.assert_allclose(_parameters(built), _parameters(load_bicycle(str(path))), rtol=1e-12, atol=1e-15)
