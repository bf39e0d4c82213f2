"""The leaning rider: BicycleParameters' MooreRiderLean2012Model (Moore's own Autolev derivation) as
the peer, both ways; the stiff-joint limit; the rider split at the hips for every kind of rider."""

import math
import warnings

import numpy as np
import pytest
import yaml

from bikemass.bicycle import bicycle_parameters
from bikemass.scenario.catalog import load_bicycle, seated_rider
from bikemass.core.errors import InputError
from bikemass.models.family import build
from bikemass.models.members.rider_lean.parameters import LeanJoint
from bikemass.rider.lean_split import hip_axis_z, rider_lean_parameters
from bikemass.models.moore2012 import NAMES, from_moore_values, moore_yaml, to_moore_values

models = pytest.importorskip("bicycleparameters.models")
psets = pytest.importorskip("bicycleparameters.parameter_sets")
dicts = pytest.importorskip("bicycleparameters.parameter_dicts")
BROWSER_JASON = dict(dicts.mooreriderlean2012_browser_jason)
SPEEDS = [float(v) for v in range(1, 11)]
YEADON = __import__("pathlib").Path(__file__).parent / "data" / "yeadon" / "JasonYeadonMeas.txt"


def _peer_eigenvalues(values, speed):
    """The non-zero eigenvalues of MooreRiderLean2012Model (6 of its 12 are structurally zero)."""
    model = models.MooreRiderLean2012Model(psets.MooreRiderLean2012ParameterSet(dict(values)))
    A, _ = model.form_state_space_matrices(v=speed)
    ev = np.linalg.eigvals(A)
    return ev[np.abs(ev) > 1e-9 * np.max(np.abs(ev))]


def _assert_same_roots(mine, peer, rtol):
    assert len(mine) == len(peer) == 6
    for z in peer:
        assert np.min(np.abs(mine - z)) <= rtol * abs(z), (z, mine)


@pytest.mark.parametrize("joint", [{}, {"k9": 128.0, "c9": 50.0}], ids=["free joint", "de Lorenzo joint"])
def test_browser_jason_equals_moore_rider_lean_2012_to_1e_8(joint):
    values = {**BROWSER_JASON, **joint}
    model = build("rider-lean", from_moore_values(values))
    for v in SPEEDS:
        _assert_same_roots(np.linalg.eigvals(model.dynamic_matrix(v)), _peer_eigenvalues(values, v), 1e-8)


@pytest.fixture(scope="module")
def jamis_relaxed():
    bike = load_bicycle("jamis")
    return bike, seated_rider(bike, "relaxed")


def test_a_bikemass_rider_exported_to_bicycleparameters_gives_the_same_eigenvalues(jamis_relaxed):
    lean = rider_lean_parameters(*jamis_relaxed, joint=LeanJoint(128.0, 50.0))
    model = build("rider-lean", lean)
    values = to_moore_values(lean, speed=5.0)
    for v in SPEEDS:
        _assert_same_roots(np.linalg.eigvals(model.dynamic_matrix(v)), _peer_eigenvalues(values, v), 1e-8)


def test_the_yaml_is_what_bicycleparameters_reads_and_writes(jamis_relaxed, tmp_path):
    lean = rider_lean_parameters(*jamis_relaxed)
    ours = tmp_path / "ours.yml"
    ours.write_text(moore_yaml(lean, speed=4.0))
    read = psets.MooreRiderLean2012ParameterSet._from_yaml(str(ours))
    assert read.parameters == to_moore_values(lean, speed=4.0) and read.parameters["v"] == 4.0
    theirs = tmp_path / "theirs.yml"
    read.to_yaml(str(theirs))
    assert yaml.safe_load(theirs.read_text()) == yaml.safe_load(ours.read_text())
    assert yaml.safe_load(ours.read_text())["parameterization"] == "MooreRiderLean2012"


def test_conversion_round_trips():
    back = to_moore_values(from_moore_values(BROWSER_JASON), speed=BROWSER_JASON["v"])
    assert set(back) == set(NAMES)
    for k, v in BROWSER_JASON.items():
        assert back[k] == pytest.approx(v, rel=1e-13, abs=1e-15), k


def test_bad_values_name_the_key():
    with pytest.raises(InputError, match=r"x.yml: values.k9: a required parameter that is missing"):
        from_moore_values({k: v for k, v in BROWSER_JASON.items() if k != "k9"}, "x.yml")
    with pytest.raises(InputError, match=r"values.mg: a finite number, got 'heavy'"):
        from_moore_values({**BROWSER_JASON, "mg": "heavy"})
    with pytest.raises(InputError, match=r"values.lam: no such parameter"):
        from_moore_values({**BROWSER_JASON, "lam": 0.3})
    with pytest.raises(InputError, match=r"values: d1, d2, d3, rf, rr of a bicycle whose front wheel reaches"):
        from_moore_values({**BROWSER_JASON, "rf": 2.0})


def test_a_stiff_hip_gives_back_the_whipple_bicycle_of_the_rigid_rider(jamis_relaxed):
    lean = rider_lean_parameters(*jamis_relaxed, joint=LeanJoint(stiffness=1e9, damping=0.0))
    stiff, rigid = build("rider-lean", lean), build("whipple", lean.rigid())
    for v in SPEEDS:
        _assert_same_roots_subset(np.linalg.eigvals(stiff.dynamic_matrix(v)),
                                  np.linalg.eigvals(rigid.dynamic_matrix(v)), 1e-5)


def _assert_same_roots_subset(many, few, rtol):
    for z in few:
        assert np.min(np.abs(many - z)) <= rtol * abs(z), (z, many)


def _person(tmp_path):
    path = tmp_path / "person.yaml"
    path.write_text("body: {height: 1.80 m, mass: 74 kg, sex: male}\nchain: {hands: hoods}\n")
    return str(path)


def _yeadon(tmp_path):
    path = tmp_path / "jason.yaml"
    path.write_text(f"body: {{yeadon: {YEADON}}}\nchain: {{hands: hoods}}\n")
    return str(path)


UPPER_PARTS = {"head", "torso", "upper_arm_right", "upper_arm_left", "lower_arm_right", "lower_arm_left"}
RIDERS = ["no-hands", "relaxed", "on-hoods", "aerobars", "aero-tuck", "person", "yeadon"]


@pytest.mark.parametrize("rider", RIDERS)
def test_every_rider_splits_at_the_hips_and_recombines_to_its_benchmark_set(rider, tmp_path):
    """Split at the hips and held rigid again, the rider gives the benchmark set bikemass computes for
    the whole rider (the parallel-axis sums done two ways); the upper body is exactly the head, torso
    and arm segments, hinged at the thighs' top planes."""
    if rider == "yeadon":
        pytest.importorskip("yeadon")
    bike = load_bicycle("jamis")
    pose = {"person": _person, "yeadon": _yeadon}.get(rider, lambda _: rider)(tmp_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        seated = seated_rider(bike, pose)
        lean = rider_lean_parameters(bike, seated, method="exact")
        whole = bicycle_parameters(bike, seated, method="exact")
    for k, v in lean.rigid().to_dict().items():
        assert v == pytest.approx(getattr(whole, k), rel=1e-12, abs=1e-12), k
    upper = [p for p in seated.parts if p.name in UPPER_PARTS]
    assert lean.upper.mass == pytest.approx(sum(p.mass for p in upper), rel=1e-12)
    thighs = [p.placement.translation[2] for p in seated.parts if p.name.startswith("thigh")]
    assert len(thighs) == 2 and lean.upper.hip_z == pytest.approx(np.mean(thighs), abs=1e-15)
    assert lean.upper.z < 0 and lean.upper.hip_z < 0     # above the ground (the aero tuck's CoM is below the hips)


def test_a_lumped_rider_cannot_lean():
    bike = load_bicycle("jamis")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        lumped = seated_rider(bike, "relaxed-thesis", allow_off_contact=True)
    with pytest.raises(InputError, match="an upper body to lean"):
        rider_lean_parameters(bike, lumped)


def test_the_hip_joint_default_is_de_lorenzos_and_gravity_stiffness_is_the_derived_models(jamis_relaxed):
    """The default joint is de Lorenzo & Hubbard's k = 128 N m/rad, c = 50 N m s/rad (as Moore 2012
    quotes them).  ``gravity_stiffness`` (m g h) against the model derived by Kane's method
    (sympy, bikemass.models.derive; the generated code knows nothing of the property): at rest the
    hip joint's net stiffness is k - m g h and the roll-lean coupling -m g h, to round-off."""
    lean = rider_lean_parameters(*jamis_relaxed)
    assert (lean.joint.stiffness, lean.joint.damping) == (128.0, 50.0)
    mechanics = build("rider-lean", lean).mechanics
    names = [s.name for s in mechanics.coordinates]
    K = mechanics.stiffness(0.0)
    roll, hip = names.index("roll-angle"), names.index("lean-angle")
    assert K[hip, hip] == pytest.approx(lean.joint.stiffness - lean.gravity_stiffness, rel=1e-12)
    assert K[roll, hip] == pytest.approx(-lean.gravity_stiffness, rel=1e-12)
    assert lean.gravity_stiffness > lean.joint.stiffness      # this rider cannot hold himself on the joint alone
    assert math.isclose(hip_axis_z(jamis_relaxed[1]), lean.upper.hip_z)


HANDS_ON_BARS = """name: Upright, hands on the bars
body: thesis_rider
segments:
  head:      {location: [0.266, 0.000, -1.919], angle: 5 deg}
  torso:     {location: [0.240, 0.000, -1.625], angle: 5 deg}
  upper_arm: {location: [0.240, 0.238, -1.625], angle: -30 deg, mirror: true}
  lower_arm: {location: [0.395, 0.238, -1.356], angle: -60 deg, mirror: true, frame: front}
  thigh:     {location: [0.153, 0.086, -1.084], angle: -45.220 deg, mirror: true}
  lower_leg: {location: [0.529, 0.086, -0.706], angle: 15.043 deg, mirror: true}
"""


def test_forearms_on_the_bars_stay_with_the_front_frame(tmp_path):
    """The docs/riders.md example pose: the lower arms move with the front frame, so they neither lean
    nor join B; the split still recombines to the whole rider's benchmark set."""
    path = tmp_path / "upright.yaml"
    path.write_text(HANDS_ON_BARS)
    bike = load_bicycle("jamis")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rider = seated_rider(bike, str(path), allow_off_contact=True)
        lean = rider_lean_parameters(bike, rider, method="exact")
        whole = bicycle_parameters(bike, rider, method="exact")
        alone = bicycle_parameters(bike, None, method="exact")
    arms = [p for p in rider.parts if p.name.startswith("lower_arm")]
    assert len(arms) == 2 and all(p.body == "front_frame" for p in arms)
    upper = [p for p in rider.parts if p.name in UPPER_PARTS and p.body == "rear_frame"]
    assert lean.upper.mass == pytest.approx(sum(p.mass for p in upper), rel=1e-12)
    assert lean.bicycle.mH == pytest.approx(alone.mH + sum(p.mass for p in arms), rel=1e-12)
    for k, v in lean.rigid().to_dict().items():
        assert v == pytest.approx(getattr(whole, k), rel=1e-12, abs=1e-12), k


def test_a_values_mapping_gives_the_model_in_one_call():
    from bikemass.models.moore2012 import moore_linear_model
    model = moore_linear_model(BROWSER_JASON)
    assert model.name == "rider-lean" and model.input_names == ("roll-torque", "steer-torque", "lean-torque")
    assert moore_linear_model(BROWSER_JASON, model="whipple").name == "whipple"


def test_joint_and_upper_body_refuse_nonsense():
    from bikemass.models.members.rider_lean.parameters import UpperBody
    with pytest.raises(InputError, match="lean joint: damping: a non-negative number"):
        LeanJoint(stiffness=128.0, damping=-1.0)
    with pytest.raises(InputError, match="upper body: mass: a positive number"):
        UpperBody(mass=0.0, x=0.3, z=-1.3, Ixx=2.0, Iyy=2.0, Izz=1.0, Ixz=0.0, hip_z=-1.0)
