"""What the web page computes, cached: one :class:`Engine` per server.

Loading a bicycle or a rider builds meshes and costs tenths of a second; the
beam model of a frame costs as much again.  They change only when the bicycle,
rider or material changes, so they are cached; a typed-over benchmark parameter
then costs one stability analysis (milliseconds).  Uploaded files live in the
engine's own temporary folder under a name made from their content.
"""

import hashlib
import tempfile
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from ..errors import InputError
from ..parameters import BenchmarkParameters
from .state import PageState

UPLOAD_LIMIT = 1_000_000
"""Largest accepted upload (bytes)."""
UPLOAD_SUFFIXES = (".yaml", ".yml", ".json", ".txt")
"""Uploads: bicycle YAML/JSON (keypoints, chart or parameters) or a BicycleParameters text file."""
UPLOAD_PREFIX = "upload-"
"""Bicycle names that refer to an uploaded file: ``upload-<digest>``."""


@dataclass(frozen=True)
class Evaluation:
    """One configuration's results: parameter set, stiffness S (None = rigid) and stability."""

    parameters: BenchmarkParameters
    stiffness: object
    stability: object


class Engine:
    """Cached bicycles, riders, parameters and stiffnesses for the page and its JSON API."""

    def __init__(self):
        self._folder = tempfile.TemporaryDirectory(prefix="bikemass-web-")
        self._uploads = {}
        self.bicycle = lru_cache(maxsize=32)(self._bicycle)
        self.rider = lru_cache(maxsize=32)(self._rider)
        self.seated = lru_cache(maxsize=64)(self._seated)
        self.base_parameters = lru_cache(maxsize=64)(self._base_parameters)
        self.stiffness = lru_cache(maxsize=64)(self._stiffness)

    # -- inputs ---------------------------------------------------------------
    def add_upload(self, filename, content):
        """Store an uploaded bicycle file; return its name (``upload-<digest>``) once it loads.

        Raises InputError (one line) for a file that is too large, of another kind,
        not a bicycle, or that refers to any file but a shipped bicycle.
        """
        shown = Path(filename).name or "upload"
        suffix = Path(shown).suffix.lower()
        if suffix not in UPLOAD_SUFFIXES:
            raise InputError(shown, "(file)", f"a bicycle file ending in {', '.join(UPLOAD_SUFFIXES)}")
        if len(content) > UPLOAD_LIMIT:
            raise InputError(shown, "(file)", f"at most {UPLOAD_LIMIT // 1000} kB")
        digest = hashlib.sha256(content).hexdigest()[:16]
        name = UPLOAD_PREFIX + digest
        path = Path(self._folder.name) / digest / shown
        path.parent.mkdir(exist_ok=True)
        path.write_bytes(content)
        _check_references(path)
        self._uploads[name] = path
        try:
            self.bicycle((name, "", ()))
        except InputError:
            del self._uploads[name]
            raise
        return name

    def upload_label(self, name):
        """The file name an uploaded bicycle came from."""
        return self._uploads[name].name

    def source(self, bike):
        """The argument the loaders take for ``bike``: a shipped name or an uploaded file's path."""
        if bike.startswith(UPLOAD_PREFIX):
            if bike not in self._uploads:
                raise InputError("URL", "bike", "a shipped bicycle or a file uploaded to this server")
            return str(self._uploads[bike])
        if "/" in bike or "\\" in bike or bike.startswith("."):
            raise InputError("URL", "bike", "a shipped bicycle name (paths are not accepted)")
        return bike

    def sizes(self, bike):
        """The size names of ``bike``'s size run, ``()`` if it has none."""
        from ..bicycle.loader import bicycle_sizes
        return bicycle_sizes(self.source(bike))

    def is_chart(self, bike):
        """True if ``bike`` is written as a geometry chart (so the page can edit its chart)."""
        from ..config import load_yaml
        from ..paths import frames_dir, resolve

        path = resolve(self.source(bike), frames_dir(), "bicycle")
        return path.suffix != ".txt" and load_yaml(path).has("chart")

    def _bicycle(self, key):
        """The bicycle of a :attr:`PageState.bicycle_key`: ``(bike, size, chart edits)``."""
        from ..catalog import load_bicycle

        bike, size, chart = key
        size = size or None
        if not chart:
            return load_bicycle(self.source(bike), size=size)
        return load_bicycle(edited_chart(self.source(bike), dict(chart)), size=size)

    def _rider(self, key):
        """The rider of a :attr:`PageState.rider_key` as loaded (a body rider: its pose mapping,
        which only a bicycle can solve)."""
        from ..catalog import load_rider
        if isinstance(key, tuple):
            return body_pose(key)
        if "/" in key or "\\" in key or key.startswith("."):
            raise InputError("URL", "rider", "a shipped pose name (paths are not accepted)")
        return load_rider(key)

    def _seated(self, bicycle_key, rider_key):
        """The rider seated on the bicycle (None for no rider); InputError if it cannot sit."""
        from ..catalog import seated_rider
        return seated_rider(self.bicycle(bicycle_key), self.rider(rider_key))

    def _base_parameters(self, key, rider, combine):
        """Parameters of the bicycle with its rider seated once (:meth:`seated`, cached)."""
        from ..bicycle import bicycle_parameters
        from ..choices import Combine, check
        return bicycle_parameters(self.bicycle(key), self.seated(key, rider), check(Combine, combine).value, "mesh")

    def _stiffness(self, key, material):
        from ..catalog import stiffness
        return stiffness(self.bicycle(key), material)

    def warm(self, states=(PageState(),)):
        """Compute ``states`` (and so import what they need) ahead of the first request."""
        for state in states:
            try:
                self.evaluate(state)
            except InputError:
                pass

    # -- results --------------------------------------------------------------
    def parameters(self, state: PageState):
        """The benchmark parameter set of ``state``, typed-over values applied (InputError for a set
        the model is not defined for: negative mass, lam outside (-pi/2, pi/2), ...)."""
        base = self.base_parameters(state.bicycle_key, state.rider_key, state.combine)
        if not state.overrides:
            return base
        from ..plausibility import check_parameters
        from .state import SOURCE
        return check_parameters(base.replace(**dict(state.overrides)), SOURCE)

    def evaluate(self, state: PageState, speeds=None):
        """:class:`Evaluation` of ``state`` over ``speeds`` (default grid)."""
        from ..dynamics import stability

        params = self.parameters(state)
        S = self.stiffness(state.bicycle_key, state.stiffness)
        return Evaluation(params, S, stability(params, S, speeds))


def body_pose(key):
    """The chain-form pose mapping of a body rider key ``("body", height m, mass kg, sex, hands)``:
    the body from height, mass and sex, hands on the grip, solved on whichever bicycle it meets."""
    _, height, mass, sex, hands = key
    return {"name": f"{sex}, {height:g} m, {mass:g} kg, hands on the {hands}",
            "body": {"height": f"{height!r} m", "mass": f"{mass!r} kg", "sex": sex},
            "chain": {"hands": hands}}


def edited_chart(source, edits):
    """The mapping of chart bicycle ``source`` with ``edits`` (``{key: mm or deg}``) typed over
    its chart; the published redundant values (wheelbase, trail, ...) are dropped, since they
    describe the unedited frame."""
    import copy

    from ..bicycle.chart import CHECKED_KEYS
    from ..config import load_yaml
    from ..paths import frames_dir, resolve
    from .state import CHART_ANGLES

    path = resolve(source, frames_dir(), "bicycle")
    node = load_yaml(path)
    if not node.has("chart"):
        node.fail("a geometry chart (chart:) to edit; this bicycle is given by keypoints or parameters",
                  "chart")
    mapping = copy.deepcopy(node.mapping())
    chart = {k: v for k, v in mapping["chart"].items() if k not in CHECKED_KEYS}
    for key, value in edits.items():
        chart[key] = f"{value!r} {'deg' if key in CHART_ANGLES else 'mm'}"
    mapping["chart"] = chart
    mapping.setdefault("name", path.stem)
    return mapping


def _check_references(path):
    """An uploaded bicycle may build on a shipped bicycle (``base: jamis``), never on a file."""
    from ..config import load_yaml
    from ..paths import available, frames_dir

    if path.suffix == ".txt":
        return
    node = load_yaml(path)
    if node.has("base"):
        base = node["base"].string()
        if base.replace("_", "-") not in available(frames_dir()):
            node.fail("the name of a shipped bicycle (an uploaded file cannot refer to other files)",
                      "base")
