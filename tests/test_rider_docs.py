"""The worked example of docs/riders.md runs and prints what the page says."""

import re
from pathlib import Path

import numpy as np

from bikemass.cli.main import main
from bikemass.rider import load_rider

DOC = (Path(__file__).parents[1] / "docs" / "riders.md").read_text()


def example_pose():
    block = DOC.split("<!-- example-pose")[1]
    return re.search(r"```yaml\n(.*?)```", block, re.S).group(1)


def test_worked_example_loads_and_matches_the_page(tmp_path):
    """The library's numbers of the example; what `bikemass rider upright.yaml` prints is
    compared with the page's block (numerically, to the shown digits) by tests/test_docs.py."""
    path = tmp_path / "upright.yaml"
    path.write_text(example_pose())
    rider = load_rider(str(path))
    props = rider.properties()
    np.testing.assert_allclose(props.com, [0.2988, 0.0, -1.2281], atol=5e-5)      # as printed on the page
    np.testing.assert_allclose(props.inertia[[0, 1, 2, 0], [0, 1, 2, 2]], [12.8228, 13.2058, 2.5057, -2.2536],
                               atol=5e-5)
    assert {p.body for p in rider.parts if p.name.startswith("lower_arm")} == {"front_frame"}


def test_error_example_is_the_real_message(tmp_path, capsys):
    path = tmp_path / "upright.yaml"
    path.write_text(example_pose().replace("angle: -45.220 deg, mirror: true", "angle: -45.220 deg"))
    assert main(["rider", str(path)]) == 2
    err = capsys.readouterr().err
    expected = [l for l in DOC.splitlines() if l.startswith("bikemass: error: upright.yaml")][0]
    assert err.strip() == expected.replace("upright.yaml", str(path), 1)
