"""How much the thesis's unjoined segments matter: each Table 3-3 pose against its closest chain pose.

``closest_chain_pose`` fits every joint angle and the hip position of the chain to a
placement pose (least squares on the x-z positions of every segment's two ends);
``compare_with_chain`` gives both riders' mass properties and the weave and capsize
speeds of a bicycle carrying each (default: the published Jamis, ``jamis-thesis``,
rider parts combined with the parallel-axis theorem).
"""

from dataclasses import replace

import numpy as np

from ..core.config import Node, load_yaml
from ..core.paths import resolve
from ..rider.anthropometry import find_anthropometry
from ..rider.chain import joint_gaps, load_chain_body
from ..rider.pose import angle_deg
from ..rider import poses_dir
from ..rider.solve import fit_to_placements
from ..rider import Rider
from ..rider.pose import pose_parts
from ..rider.body import load_body
from ..analysis.engine.stability import analyse
from ..rider.seating import SeatedRider
from ..scenario.scenario import Scenario
from ..bicycle import load_bicycle
from ..rider import load_rider


def pose_placements(pose):
    """(``{segment: (location, angle)}`` of a placement pose's right copies, its anthropometry path)."""
    node = load_yaml(resolve(pose, poses_dir(), "pose"))
    placements = {k: (s["location"].vector("length", 3), angle_deg(s["angle"])) for k, s in node["segments"].items()}
    return placements, find_anthropometry(node["body"])


def closest_chain_pose(pose):
    """(ChainBody, placements, ChainPose, rms, max) of the chain pose closest to placement pose
    ``pose`` (m).  The chain's shoulders take the pose's upper-arm y (Aerobars and Aero Tuck
    bring the arms in), so that only the joining differs."""
    placements, path = pose_placements(pose)
    body = load_chain_body(path)
    shoulder = np.array([body.shoulder[0], placements["upper_arm"][0][1], body.shoulder[2]])
    body = replace(body, shoulder=shoulder)
    chain, rms, worst = fit_to_placements(body, placements)
    return body, placements, chain, rms, worst


def _rider_of(chain, body_name, source):
    body = load_body(Node(body_name, source, "body")).anthropometry
    return Rider("chain", "closest chain pose", pose_parts(chain, body, (), source))


def _speeds(bike, rider, combine, method):
    """Weave and capsize speeds (m/s) of ``bike`` carrying ``rider`` placed as written (both riders
    are compared where they sit, not re-seated)."""
    placed = SeatedRider(rider, bike, "as written", {}, None, ())
    result = analyse(Scenario(bike, placed, combine=combine, method=method).build().model)
    return result.weave_speeds, result.capsize_speeds


def compare_with_chain(pose, bike="jamis-thesis", combine="exact", method="exact"):
    """Dict: fit (rms, max, m), joint gaps (m) of the pose and of its chain pose, both riders'
    MassProperties, and weave/capsize speeds (m/s) of ``bike`` carrying each."""
    body, placements, chain, rms, worst = closest_chain_pose(pose)
    thesis = load_rider(pose)
    fitted = _rider_of(chain, body.name, body.source)
    bicycle = load_bicycle(bike)
    right, _ = chain.placements()
    return {"pose": pose, "chain": chain, "rms": rms, "max": worst,
            "gaps": joint_gaps(placements, body), "plane_gaps": joint_gaps(placements, body, plane=True),
            "chain_gaps": joint_gaps(right, body),
            "thesis": thesis.properties(method), "fitted": fitted.properties(method),
            "speeds": {"thesis": _speeds(bicycle, thesis, combine, method),
                       "chain": _speeds(bicycle, fitted, combine, method)},
            "warnings": chain.warnings()}


def first(speeds):
    """The first critical speed (m/s) or NaN."""
    return speeds[0] if speeds else np.nan
