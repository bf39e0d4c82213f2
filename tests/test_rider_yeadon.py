"""Bodies from yeadon measurement files (real measured riders, tests/data/yeadon), posed by
bikemass's chain, checked against yeadon posing the same body itself."""

import contextlib
import io
from pathlib import Path

import numpy as np
import pytest

from bikemass.bicycle import bicycle_parameters, load_bicycle
from bikemass.cli.main import main
from bikemass.rider.seating import seat_rider
from bikemass.analysis.engine.stability import analyse
from bikemass.models.whipple import whipple_model

yeadon = pytest.importorskip("yeadon")

DATA = Path(__file__).parent / "data" / "yeadon"
DOCS = Path(__file__).parents[1] / "docs" / "riders.md"
YEADON_TO_BENCHMARK = np.array([[0.0, -1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])  # x left, y back, z up


def _human(path):
    with contextlib.redirect_stdout(io.StringIO()):
        return yeadon.Human(str(path))


def _pose(tmp_path, measurement, extra=""):
    path = tmp_path / f"{Path(measurement).stem}.yaml"
    path.write_text(f"body: {{yeadon: {measurement}}}\nchain: {{hands: hoods}}\n{extra}")
    return path


@pytest.fixture(scope="module")
def jamis():
    return load_bicycle("jamis")


@pytest.fixture(scope="module")
def jason_on_jamis(jamis, tmp_path_factory):
    return seat_rider(str(_pose(tmp_path_factory.mktemp("y"), DATA / "JasonYeadonMeas.txt")), jamis)


def test_measured_rider_on_the_jamis(jason_on_jamis, jamis):
    seated = jason_on_jamis
    assert seated.rider.properties("exact").mass == pytest.approx(_human(DATA / "JasonYeadonMeas.txt").mass,
                                                                  rel=1e-12)
    assert seated.rider.properties("exact").mass == pytest.approx(83.5, rel=1e-12)    # the file's totalmass
    assert max(seated.residuals().values()) <= 1e-3
    weave = analyse(whipple_model(bicycle_parameters(jamis, seated.rider))).weave_speeds
    assert len(weave) >= 1 and 3.0 < weave[0] < 10.0


def test_chain_posing_equals_yeadon_posing(jason_on_jamis):
    """yeadon posed by its own configuration angles at the chain's joint angles gives the same
    centre of mass (relative to the hip joints) and moments of inertia.  Products of inertia:
    yeadon 2.0.1 rotates each solid's inertia into the human frame as R^T I R while it moves
    positions by R (v = R v_local), which flips the sign of a rotated solid's products; its
    solids recombined with R I R^T equal bikemass's tensor."""
    pose = jason_on_jamis.solution.pose
    a = {k: np.radians(v) for k, v in pose.angles.items()}
    h = _human(DATA / "JasonYeadonMeas.txt")
    # yeadon's angles about its x axis (to the left): somersault forward-positive, the others
    # opposite to the chain's flexions except the knee
    config = {"somersault": a["torso_lean"], "CA1extension": -a["shoulder"], "CB1extension": -a["shoulder"],
              "A1A2extension": -a["elbow"], "B1B2extension": -a["elbow"], "PJ1extension": -a["hip"],
              "PK1extension": -a["hip"], "J1J2flexion": a["knee"], "K1K2flexion": a["knee"]}
    with contextlib.redirect_stdout(io.StringIO()):
        for k, v in config.items():
            h.set_CFG(k, v)
    ours = jason_on_jamis.rider.properties("exact")
    hip = np.array([pose.root[0], 0.0, pose.root[1]])
    R = YEADON_TO_BENCHMARK
    np.testing.assert_allclose(R @ np.ravel(h.center_of_mass), ours.com - hip, rtol=0, atol=1e-12)
    theirs = R @ np.asarray(h.inertia) @ R.T
    np.testing.assert_allclose(np.diag(theirs), np.diag(ours.inertia), rtol=1e-12)
    assert abs(theirs[0, 2] - ours.inertia[0, 2]) > 0.01          # the transposed rotation shows here
    solids = [s for seg in h.segments for s in seg.solids]
    com = sum(s.mass * np.ravel(s.center_of_mass) for s in solids) / h.mass
    rotated = sum(s._rot_mat @ np.asarray(s.rel_inertia) @ s._rot_mat.T
                  + s.mass * (np.eye(3) * (d @ d) - np.outer(d, d))
                  for s in solids for d in [np.ravel(s.center_of_mass) - com])
    np.testing.assert_allclose(R @ rotated @ R.T, ours.inertia, rtol=0, atol=1e-10)


@pytest.mark.parametrize("content,needle", [
    (None, "body.yeadon: a yeadon measurement file, "),
    ("measurementconversionfactor: .01\ntotalmass: 80\nLs1L: 10\n",
     "body.yeadon: a yeadon measurement file (95 measurements, docs/riders.md): "),
    ("totalmass: 80\n", "measurementconversionfactor: a positive factor"),
    ("measurementconversionfactor: 1\nheight: 1.8\n", "height: not one of yeadon's 95 measurement names"),
    ("- a\n- b\n", "no 'name: value' lines"),
])
def test_bad_yeadon_file_is_one_line(capsys, tmp_path, content, needle):
    meas = tmp_path / "meas.txt"
    if content is not None:
        meas.write_text(content)
    code = main(["rider", str(_pose(tmp_path, meas.name)), "--bike", "jamis"])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and needle in err, err


# -- height/mass body against yeadon (docs/riders.md) -----------------------------------------

MEASURED = (("JasonYeadonMeas.txt", "male"), ("CharlieYeadonMeas.txt", "male"), ("LukeYeadonMeas.txt", "male"),
            ("AureliaYeadonMeas.txt", "female"), ("yeadon_sample_male1.txt", "male"),
            ("yeadon_sample_female1.txt", "female"))
ANKLE_HEIGHT = 0.039
"""Ankle height / stature (Drillis & Contini): yeadon measures no ankle-to-floor length."""


POSTURE = {"torso_lean": 45.0, "neck": 0.0, "shoulder": 75.0, "elbow": 20.0, "hip": 100.0, "knee": 65.0}
"""The common posture (deg): about a road rider's on the hoods (Jason on the Jamis: 47, 0, 78, 20, 103, 67)."""


def _posed(body, spec):
    from bikemass.core.config import Node
    from bikemass.rider import Rider
    from bikemass.rider.chain import ChainPose
    from bikemass.rider.pose import read_pose
    pose = ChainPose(body.chain, np.zeros(2), POSTURE)
    _, parts = read_pose(Node(pose.placement_form("posed", spec), str(DATA / "posed.yaml"), None))
    return Rider("posed", "posed", parts).properties("exact")


def comparison_rows():
    """Per measured rider: the yeadon body and a height/mass body of the same height (from the
    yeadon lengths), mass and sex, both in :data:`POSTURE` with the hip joints at the origin.
    CoM (mm) relative to the hip joints, inertia about the CoM (kg m^2)."""
    from bikemass.core.config import Node
    from bikemass.rider.body import load_body

    rows = []
    for name, sex in MEASURED:
        h = _human(DATA / name)
        m = h.meas
        height = (m["Ls5L"] + m["Ls8L"] + (m["Lj5L"] + m["Lk5L"]) / 2) / (1 - ANKLE_HEIGHT)
        measured = {"yeadon": str(DATA / name)}
        yeadon_body = load_body(Node(measured, str(DATA / "posed.yaml"), "body"))
        mass = yeadon_body.anthropometry and sum(s.mass * (2 if s.pair else 1)
                                                 for s in yeadon_body.anthropometry.segments.values())
        spec = {"height": float(height), "mass": float(mass), "sex": sex}
        stature_body = load_body(Node(spec, str(DATA / "posed.yaml"), "body"))
        props = {"yeadon": _posed(yeadon_body, measured), "stature": _posed(stature_body, spec)}
        cells = [name.replace("YeadonMeas.txt", "").replace("yeadon_sample_", "").replace(".txt", ""), sex,
                 height, mass]
        for quantity in ("x", "z", "Ixx", "Iyy", "Izz", "Ixz"):
            if quantity in ("x", "z"):
                i = "xyz".index(quantity)
                y, s = (props[k].com[i] * 1000 for k in ("yeadon", "stature"))
            else:
                i, j = ("xyz".index(quantity[1]), "xyz".index(quantity[2]))
                y, s = (props[k].inertia[i, j] for k in ("yeadon", "stature"))
            cells += [y, s]
        rows.append(cells)
    return rows


def render(rows):
    head = ("| rider | sex | H (m) | m (kg) | CoM x (mm) y / s | CoM z (mm) y / s | Ixx y / s | Iyy y / s "
            "| Izz y / s | Ixz y / s |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    lines = [head]
    for r in rows:
        pairs = [f"{r[4 + 2 * k]:.0f} / {r[5 + 2 * k]:.0f}" if k < 2 else f"{r[4 + 2 * k]:.2f} / {r[5 + 2 * k]:.2f}"
                 for k in range(6)]
        lines.append(f"| {r[0]} | {r[1]} | {r[2]:.3f} | {r[3]:.2f} | " + " | ".join(pairs) + " |")
    return "\n".join(lines)


def test_comparison_in_the_docs_is_the_real_output():
    table = render(comparison_rows())
    assert table in DOCS.read_text(), "\n" + table


def test_yeadons_own_notes_are_one_line_each_naming_the_file(capsys, tmp_path):
    """yeadon's sample ``female1`` (its misc/samplemeasurements) makes yeadon reshape eight
    stadium solids; each note is one warning line naming the file (yeadon's text ends in a
    newline, which used to be printed as a literal backslash-n)."""
    from bikemass.rider.yeadon_body import _human_of
    _human_of.cache_clear()
    pose = _pose(tmp_path, DATA / "yeadon_sample_female1.txt")
    assert main(["rider", str(pose), "--bike", "bmc-roadmachine@51", "--format", "json"]) == 0
    lines = capsys.readouterr().err.strip().splitlines()
    stadium = [line for line in lines if "Stadium" in line]
    assert len(stadium) == 8
    for line in stadium:
        assert line.startswith("bikemass: warning: ") and "yeadon_sample_female1.txt: yeadon: Stadium" in line
        assert not line.endswith("\\n")
