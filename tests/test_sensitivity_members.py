"""Every member's derivatives of its weave and capsize speeds against a difference of ``bm.stability``.

The member's derivatives come from the complex step through its generated code (no step chosen by
the member); the reference is a Richardson-extrapolated central difference of the critical speeds
that ``bm.stability`` finds (truncation error of order h**4; the crossings are solved to about
1e-12 m/s, so with a relative step of 1e-3 the reference is good to about 1e-8 relative)."""

import json

import pytest

import bikemass as bm

STEP = 1e-3
NAMES = ("c", "lam", "w", "rF", "mB", "xB", "IBxx", "IFyy")
CASES = [("rider-lean", "jamis", "relaxed", None), ("tyre", "benchmark", None, None),
         ("rider-lean+tyre", "jamis", "relaxed", None), ("flexible", "jamis", "relaxed", "steel"),
         ("tyre+flexible", "jamis", "on-hoods", "titanium")]


def speeds(scenario, changes=None):
    """(weave, capsize) speeds (m/s): the first crossing of each kind ``bm.stability`` reports."""
    result = bm.stability(scenario.build(changes), speeds=bm.speeds(0, 15, 0.05))
    return result.weave_speeds[0], result.capsize_speeds[0]


def richardson(scenario, name, x):
    """``d (weave, capsize) / d name`` at ``x``: (4 D(h/2) - D(h)) / 3 of central differences D."""
    def central(h):
        (wa, ca), (wb, cb) = speeds(scenario, {name: x + h}), speeds(scenario, {name: x - h})
        return (wa - wb) / (2 * h), (ca - cb) / (2 * h)
    h = STEP * abs(x)
    (w1, c1), (w2, c2) = central(h), central(h / 2)
    return (4 * w2 - w1) / 3, (4 * c2 - c1) / 3


@pytest.mark.parametrize("model, bike, rider, stiffness", CASES)
def test_member_speed_derivatives_equal_a_difference_of_stability(model, bike, rider, stiffness):
    """Issue 32: every member's sensitivity equals a high-precision difference of ``bm.stability`` to
    1e-7 relative (plus 1e-9 m/s per unit of the parameter for derivatives near zero)."""
    scenario = bm.Scenario(bike, rider, stiffness, model=model)
    result = bm.sensitivity(scenario, max_speed=15.0)
    for name in NAMES:
        weave, capsize = richardson(scenario, name, scenario.value(name))
        assert result.d_weave_speed[name] == pytest.approx(weave, rel=1e-7, abs=1e-9), (name, "weave")
        assert result.d_capsize_speed[name] == pytest.approx(capsize, rel=1e-7, abs=1e-9), (name, "capsize")


def test_contract_a_model_keyword_is_the_scenario_of_that_model():
    """``bm.sensitivity(p, model="tyre")`` takes the model as ``bm.stability`` does (it was a TypeError):
    the same as the Scenario of that model, and not the Whipple bicycle's."""
    p = bm.parameters("benchmark")
    keyword = bm.sensitivity(p, model="tyre", names=("c",), max_speed=15.0)
    scenario = bm.sensitivity(bm.Scenario(p, model="tyre"), names=("c",), max_speed=15.0)
    whipple = bm.sensitivity(p, names=("c",), max_speed=15.0)
    assert keyword.d_weave_speed["c"] == scenario.d_weave_speed["c"]
    assert abs(keyword.d_weave_speed["c"] - whipple.d_weave_speed["c"]) > 0.1


OWN_STEP = 1e-4
OWN = [("tyre", "benchmark", None, None, ("CaF", "CgF", "sigmaF", "CaR", "sigmaR", "tpF")),
       ("rider-lean", "jamis", "relaxed", None, ("mU", "zU", "klean", "clean")),
       ("arms", "jamis", "relaxed", None, ("k_arms", "c_arms")),
       ("flexible", "jamis", "relaxed", "steel", ("kr", "kf", "cs"))]


def model_speeds(built, values):
    """(weave, capsize) speeds (m/s) of ``built``'s model at the code parameters ``values``."""
    result = bm.stability(built.with_values(values), speeds=bm.speeds(0, 15, 0.05))
    return result.weave_speeds[0], result.capsize_speeds[0]


@pytest.mark.parametrize("model, bike, rider, stiffness, names", OWN)
def test_a_members_own_parameters_derivatives_equal_a_difference_of_stability(model, bike, rider, stiffness, names):
    """A member's own parameters (the tyres' coefficients, the upper body's, the arms', the flexible frame's)
    are rows of its sensitivity by default, each in the unit its code declares, and equal a Richardson
    difference of ``bm.stability`` of the model at changed values to 1e-7 relative, or 1e-11 m/s over the
    step absolute (the crossings are solved to about 1e-12 m/s: the reference's own noise, where a
    derivative is near 0, such as the capsize speed's by a relaxation length).  The step is 1e-4 relative
    (1e-4 in SI for a parameter at 0): the capsize speed curves strongly in the upper body's height, and
    at 1e-3 the Richardson reference is still 3e-7 off (at 1e-4 the difference converges on the exact
    value)."""
    scenario = bm.Scenario(bike, rider, stiffness, model=model)
    built = scenario.build()
    result = bm.sensitivity(scenario, max_speed=15.0)
    base = built.values()
    assert tuple(result.params) == tuple(base)                  # every parameter of the code, in its order
    for name in names:
        x = base[name]

        def central(h):
            (wa, ca), (wb, cb) = (model_speeds(built, {**base, name: x + s}) for s in (h, -h))
            return (wa - wb) / (2 * h), (ca - cb) / (2 * h)
        h = OWN_STEP * abs(x) if x else OWN_STEP
        (w1, c1), (w2, c2) = central(h), central(h / 2)
        weave, capsize = (4 * w2 - w1) / 3, (4 * c2 - c1) / 3
        assert result.d_weave_speed[name] == pytest.approx(weave, rel=1e-7, abs=1e-11 / h), (name, "weave")
        assert result.d_capsize_speed[name] == pytest.approx(capsize, rel=1e-7, abs=1e-11 / h), (name, "capsize")


def test_a_members_own_parameters_carry_their_units_and_are_checked():
    """The units of a member's own parameters are those its generated code declares (the table's unit
    column); a name that is not a parameter of the model is refused in one line listing them."""
    result = bm.sensitivity(bm.Scenario("benchmark", model="tyre"), names=("c", "CaF", "sigmaF", "CmgF"),
                            max_speed=15.0)
    assert [result.unit_of(n) for n in ("c", "CaF", "sigmaF", "CmgF")] == ["m", "1/rad", "m", "m/rad"]
    assert list(result.tables()["parameters"].columns["unit"]) == ["m", "1/rad", "m", "m/rad"]
    with pytest.raises(bm.InputError, match="tyre model's parameter names.*CaF"):
        bm.sensitivity(bm.Scenario("benchmark", model="tyre"), names=("CaF", "klean"))
    with pytest.raises(bm.InputError, match="benchmark parameter names"):
        bm.sensitivity(bm.parameters("benchmark"), names=("CaF",))


def test_contract_the_command_line_gives_a_members_own_parameters_as_rows(capsys):
    """`bikemass sensitivity benchmark --model tyre`: after the 26 names, a row for each of the tyres'
    parameters with the unit its code declares, the same numbers as ``bm.sensitivity`` (contract: the
    command line is a shell over it); such a name under --inputs (an input of the scenario) chains to
    its own row."""
    import csv
    import io
    from bikemass.cli.main import main
    assert main(["sensitivity", "benchmark", "--model", "tyre", "--format", "csv"]) == 0
    rows = {r["input"]: r for r in csv.DictReader(io.StringIO(capsys.readouterr().out))}
    library = bm.sensitivity(bm.Scenario("benchmark", model="tyre"))
    assert list(rows)[2:] == list(library.params)
    assert rows["CaF"]["unit"] == "1/rad" and rows["sigmaF"]["unit"] == "m" and rows["CmgF"]["unit"] == "m/rad"
    assert float(rows["CaF"]["d_weave_speed (m/s per unit)"]) == pytest.approx(library.d_weave_speed["CaF"],
                                                                               rel=1e-15)
    assert main(["sensitivity", "benchmark", "--model", "tyre", "--inputs", "CaF", "--format", "json"]) == 0
    chained = json.loads(capsys.readouterr().out)["inputs"]["CaF"]       # an input of the scenario: its own row
    assert chained["weave_speed"] == pytest.approx(library.d_weave_speed["CaF"], rel=1e-9)


def test_names_are_taken_from_any_iterable_and_an_empty_one_is_refused():
    """``names=iter(["c"])`` gave no rows (the check used the iterator up) and ``names=()`` passed: an iterable is
    read once, and an empty one is refused, for the Whipple bicycle and a member alike."""
    for system in (bm.parameters("benchmark"), bm.Scenario("benchmark", model="tyre")):
        assert list(bm.sensitivity(system, names=iter(["c"]), max_speed=15.0).d_weave_speed) == ["c"]
        with pytest.raises(bm.InputError, match="names"):
            bm.sensitivity(system, names=())
