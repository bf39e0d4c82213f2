"""A body from a yeadon measurement file (``body: {yeadon: PATH}``): yeadon's solids with
yeadon's mass properties, grouped into the chain's segment kinds and posed by the chain.

The 95-measurement file (Yeadon 1990; the format of yeadon's ``misc/samplemeasurements``
and of BicycleParameters' ``data/riders/*/RawData/*YeadonMeas.txt``) is read by the
``yeadon`` package (optional extra ``bikemass[yeadon]``) in its standing configuration
(every joint angle 0: arms hanging, legs straight, feet in line with the shanks) with
left and right limbs averaged, and ``totalmass`` honoured when the file gives one (every solid's mass and
inertia scaled by the same factor, as yeadon's own density scaling does).

Kinds (yeadon's segments and solids):

* torso: pelvis P, thorax T and the chest-head's solids up to the acromion (s3, s4);
  its top is the acromion level (Ls5), its length Ls5 to the hip-joint level (Ls0);
* head: the chest-head's solids above the acromion (s5 to s7, neck and head);
* upper arm: B1 (shoulder to elbow); lower arm: B2 (forearm and hand), its chain length
  from the elbow to the middle of the palm (halfway between base of thumb and knuckles);
* thigh: K1 (hip to knee); lower leg: K2 (shank and foot), its chain length from the knee
  to the ball of the foot (the pedal contact; yeadon's foot is in line with the shank);
  with ``feet: bicycleparameters`` from the knee to the heel's level on the shank's line
  (BicycleParameters' ``rider_on_bike``: Lj5L - Lj3L + Lj6L), the foot beyond it.

Joints: shoulders and hips where yeadon puts them (half the Ls4 width, half the hip width);
the seat (sit point below the hip joints) is the thigh radius at the crotch (Lk1p / 2 pi).
"""

import contextlib
import importlib.util
import io
import warnings
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..core.errors import BikemassWarning, shown
from ..core.gate import load_data, note_read
from ..mass.inertia import MassProperties, combine
from ..mass.solids import Lumped
from ..core.paths import named_file
from .anthropometry import Anthropometry, BodySegment
from .chain import BICYCLEPARAMETERS, ChainBody

YEADON_TO_BENCHMARK = np.array([[0.0, -1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
"""Rotation from yeadon's frame (x to the left, y backwards, z up) to the benchmark frame."""

PAIRS = ("upper_arm", "lower_arm", "thigh", "lower_leg")


def _bench(point):
    return YEADON_TO_BENCHMARK @ np.asarray(point, dtype=float).ravel()


def _props(solids, scale=1.0):
    """Combined MassProperties (benchmark axes) of yeadon solids, masses times ``scale``."""
    return combine(MassProperties(scale * s.mass, _bench(s.center_of_mass),
                                  scale * YEADON_TO_BENCHMARK @ np.asarray(s.inertia) @ YEADON_TO_BENCHMARK.T)
                   for s in solids)


def read_measurements(path):
    """(``{name: m}`` of the 95 measurements, total mass in kg or None) of a yeadon measurement
    file; ValueError naming the first bad or missing entry."""
    try:
        # lazy: yeadon is optional (the yeadon extra); only yeadon bodies need it
        import yeadon
    except ImportError:
        raise ImportError("the yeadon package: pip install 'bikemass[yeadon]'") from None
    content = load_data(path)            # the input gate: size, type, encoding, YAML limits
    if not isinstance(content, dict):
        raise ValueError("no 'name: value' lines")
    factor = content.pop("measurementconversionfactor", None)
    if not _positive(factor):
        raise ValueError("measurementconversionfactor: a positive factor to metres (0.01 for cm)")
    mass = content.pop("totalmass", None)
    if mass is not None and not (_positive(mass) or mass == -1):
        raise ValueError(f"totalmass: a mass in kg (or -1 for yeadon's densities), got {mass!r}")
    unknown = sorted(set(content) - set(yeadon.Human.measnames))
    if unknown:
        raise ValueError(f"{unknown[0]}: not one of yeadon's 95 measurement names")
    missing = [n for n in yeadon.Human.measnames if n not in content]
    if missing:
        raise ValueError(f"{missing[0]}: missing ({len(missing)} of the 95 measurements are)")
    bad = [n for n, v in content.items() if not _positive(v)]
    if bad:
        raise ValueError(f"{bad[0]}: a positive length, got {content[bad[0]]!r}")
    return {n: float(v) * factor for n, v in content.items()}, (float(mass) if mass not in (None, -1) else None)


def _positive(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and np.isfinite(v) and v > 0


@lru_cache(maxsize=1)
def _human_class():
    """A private copy of ``yeadon.human.Human``: yeadon keeps its segment densities in a class
    attribute that ``totalmass`` scaling overwrites in place, so every later Human of the
    process (ours included) would inherit the last file's scaling; a private copy of the
    module keeps yeadon's own densities."""
    spec = importlib.util.find_spec("yeadon.human")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.Human


def human(path):
    """(``yeadon.Human`` of measurement file ``path``, standing, limbs averaged; the factor that
    scales its masses to the file's ``totalmass`` (1 without one)).  Cached per file content
    (a pose is read up to three times when it is seated); the Human is not to be changed."""
    p = Path(path).resolve()
    note_read(p)
    return _human_of(str(p), p.stat().st_mtime_ns, p.stat().st_size)


@lru_cache(maxsize=16)
def _human_of(path, mtime_ns, size):
    measurements, mass = read_measurements(path)
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            h = _human_class()(measurements, symmetric=True)
        except Exception as exc:            # yeadon raises plain exceptions for impossible shapes
            raise ValueError(f"{type(exc).__name__}: {exc}") from None
    for w in caught:        # yeadon's own notes (a stadium it had to reshape): one line naming the file
        warnings.warn(f"{shown(path)}: yeadon: {' '.join(str(w.message).split())}", BikemassWarning, stacklevel=2)
    return h, (mass / h.mass if mass is not None else 1.0)


def segments_of(h, scale=1.0):
    """``{kind: (MassProperties in benchmark axes, top point, chain length)}`` of a yeadon Human
    (top points and lengths in m, benchmark frame, standing; masses times ``scale``)."""
    chest = h.C.solids
    grip = (_bench(h.B2.solids[-2].pos) + _bench(h.B2.solids[-2].end_pos)) / 2
    ball = _bench(h.K2.solids[-1].end_pos)
    top = {"head": _bench(chest[-1].end_pos), "torso": _bench(chest[2].pos),
           "upper_arm": _bench(h.B1.pos), "lower_arm": _bench(h.B2.pos),
           "thigh": _bench(h.K1.pos), "lower_leg": _bench(h.K2.pos)}
    far = {"head": top["torso"], "torso": _bench(h.P.pos), "upper_arm": top["lower_arm"], "lower_arm": grip,
           "thigh": top["lower_leg"], "lower_leg": ball}
    solids = {"head": chest[2:], "torso": [*h.P.solids, *h.T.solids, *chest[:2]],
              "upper_arm": h.B1.solids, "lower_arm": h.B2.solids, "thigh": h.K1.solids, "lower_leg": h.K2.solids}
    return {k: (_props(solids[k], scale), top[k], float(far[k][2] - top[k][2])) for k in solids}


def yeadon_body(node):
    """(:class:`~bikemass.rider.anthropometry.Anthropometry`, :class:`~bikemass.rider.chain.ChainBody`)
    of ``{yeadon: PATH}`` (PATH relative to ``node``'s file)."""
    node.check_keys(required=("yeadon",), optional=("name", "source", "note"))
    path = named_file(node["yeadon"])
    if not path.is_file():
        node.fail(f"a yeadon measurement file, {path} does not exist", "yeadon")
    try:
        h, scale = human(path)
    except ImportError as exc:
        node.fail(str(exc), "yeadon")
    except ValueError as exc:
        node.fail(f"a yeadon measurement file (95 measurements, docs/riders.md): {exc}", "yeadon")
    kinds = segments_of(h, scale)
    segments, lengths = {}, {}
    for kind, (props, top, length) in kinds.items():
        local = MassProperties(props.mass, props.com - top, props.inertia)
        segments[kind] = BodySegment(kind, Lumped(local), props.mass, kind in PAIRS)
        lengths[kind] = length
    torso_top = kinds["torso"][1]
    shoulder = kinds["upper_arm"][1] - torso_top
    hip = kinds["thigh"][1] - torso_top
    seat = (h.meas["Lj1p"] + h.meas["Lk1p"]) / 2 / (2 * np.pi)
    name = node.get("name", path.stem).string()
    anthropometry = Anthropometry(name, path, segments)
    # BicycleParameters seats the shank's line at the heel's level on the crank axis: the knee
    # to the ankle (Lj5L - Lj3L, both from the hip joint) and on by the heel's length (Lj6L, from the ankle)
    heel = float(h.meas["Lj5L"] - h.meas["Lj3L"] + h.meas["Lj6L"])
    chain = ChainBody(name, path, lengths, np.zeros(3), shoulder, hip, float(seat), ((BICYCLEPARAMETERS, heel),))
    return anthropometry, chain
