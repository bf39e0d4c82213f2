"""Every member's derivatives of its weave and capsize speeds against a difference of ``bm.stability``.

The member's derivatives come from the complex step through its generated code (no step chosen by
the member); the reference is a Richardson-extrapolated central difference of the critical speeds
that ``bm.stability`` finds (truncation error of order h**4; the crossings are solved to about
1e-12 m/s, so with a relative step of 1e-3 the reference is good to about 1e-8 relative)."""

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
