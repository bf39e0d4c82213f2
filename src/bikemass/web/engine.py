"""What the web page computes, cached: one :class:`Engine` per server.

Loading a bicycle or a rider builds meshes and costs tenths of a second; the
beam model of a frame costs as much again.  They change only when the bicycle,
rider or material changes, so they are cached; a typed-over benchmark parameter
then costs one stability analysis (milliseconds).  Uploaded files live in the
engine's own temporary folder, each in a folder of its own, named by a random secret: an
upload's name (``upload-<secret>``) is known only to whoever uploaded it (and whoever they
give its link), and cannot be guessed from its content.

Every computation runs :func:`bikemass.core.paths.confined` to the shipped data (and, while an
upload is read, to that upload's own folder: an upload can reach no other file, another upload
included), one at a time (the warnings module is process-wide), and records the
:class:`~bikemass.core.errors.BikemassWarning` s it issues: a cached result warns again whenever
it is used, so every answer carries its warnings (:meth:`Engine.answer`).  A finished answer is
kept with its warnings and served again without the lock, so a cached answer never waits for
another client's computation.  Errors about an upload name the file as uploaded, never the
server's folder; errors about a shipped file name it from the data folder, never the install path.
"""

import contextlib
import dataclasses
import functools
import os
import re
import secrets
import tempfile
import threading
import warnings
from collections import OrderedDict
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from ..core.errors import BikemassWarning, InputError, one_line
from ..models.parameters import BenchmarkParameters
from ..core.paths import confined
from ..core import data_folder
from .state import BODY_RIDER, SOURCE, PageState
from ..bicycle.loader import bicycle_sizes
from ..bicycle.loader import _is_parameter_text
from ..core.config import load_yaml
from ..core.paths import frames_dir, resolve
from ..mass.materials import frame_label, load_materials
from ..core.gate import read_text
from ..core.plain import file_form
from ..core.units import Quantity
from ..scenario.catalog import load_bicycle
from ..scenario.catalog import load_rider
from ..scenario.catalog import seated_rider
from ..core.choices import Combine, check
from ..models.registry import BASE
from ..rider.seating import SeatedRider
from ..scenario.scenario import Scenario
from ..models.plausibility import check_parameter_file, warn_parameters
from ..analysis.results import stability
from ..bicycle.chart import CHECKED_KEYS
from ..bicycle.sizes import select_size, size_names
from .state import CHART_ANGLES, CHART_PREFIX
from ..analysis.handling.survey import handling
import copy
import yaml

UPLOAD_LIMIT = 1_000_000
"""Largest accepted upload (bytes)."""
UPLOAD_SUFFIXES = (".yaml", ".yml", ".json", ".txt")
"""Uploads: bicycle YAML/JSON (keypoints, chart or parameters) or a BicycleParameters text file."""
UPLOAD_PREFIX = "upload-"
"""Bicycle names that refer to an uploaded file: ``upload-<digest>``."""
MAX_UPLOADS = 16
"""Uploads kept on the server (the oldest is deleted when another arrives)."""
MAX_UPLOAD_NAME = 100
"""Longest uploaded file name kept (characters); the file is stored under a name of its own."""
MAX_ANSWERS = 256
"""Finished answers kept for lock-free reuse (:meth:`Engine.answer`)."""
HANDLING_SPEEDS = (3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0)
"""Speeds (m/s) of the page's rider in the loop (a tuning costs about 0.2 s per speed)."""
RIGID_CHOICE = "infinite"


@dataclass(frozen=True)
class Evaluation:
    """One configuration's results: parameter set, stiffness S (None = rigid, or a model other than the
    Whipple bicycle's quasi-static frame) and stability."""

    parameters: BenchmarkParameters
    stiffness: object
    stability: object
    frame: str = "rigid frame"
    """What the frame is, as ``bikemass stability``'s title and JSON say (:func:`~bikemass.mass.materials.frame_label`)."""


def _recorded(function, maxsize):
    """``function`` cached (``maxsize`` results), its BikemassWarnings recorded with each result and
    issued again on every call, cached or not."""
    @lru_cache(maxsize=maxsize)
    def compute(*args):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", BikemassWarning)
            value = function(*args)
        return value, tuple((w.message, w.category) for w in caught if issubclass(w.category, BikemassWarning))

    @functools.wraps(function)
    def cached(*args):
        value, caught = compute(*args)
        for message, category in caught:
            warnings.warn(message, category, stacklevel=2)
        return value
    return cached


class Answers:
    """A bounded map of finished answers (least recently used dropped first), read and written
    under a lock of its own that is held only for the lookup, never for a computation."""

    def __init__(self, size=MAX_ANSWERS):
        self._items, self._size, self._lock = OrderedDict(), size, threading.Lock()

    def get(self, key):
        """The answer kept for ``key``, or None."""
        with self._lock:
            value = self._items.get(key)
            if value is not None:
                self._items.move_to_end(key)
            return value

    def put(self, key, value):
        """Keep ``value`` (not None) for ``key``."""
        with self._lock:
            self._items[key] = value
            self._items.move_to_end(key)
            while len(self._items) > self._size:
                self._items.popitem(last=False)

    def drop(self, test):
        """Forget every answer whose key passes ``test``."""
        with self._lock:
            for key in [k for k in self._items if test(k)]:
                del self._items[key]


def _mentions(key, bike):
    """Whether the answer key ``key`` (tuples of states, names, ...) involves the bicycle ``bike``."""
    if isinstance(key, PageState):
        return key.bike == bike
    if isinstance(key, tuple):
        return any(_mentions(k, bike) for k in key)
    return key == bike


class Engine:
    """Cached bicycles, riders, parameters and stiffnesses for the page and its JSON API."""

    def __init__(self):
        self._folder = tempfile.TemporaryDirectory(prefix="bikemass-web-")
        self._uploads, self._labels = {}, {}
        self._lock = threading.RLock()
        self._answers = Answers()
        self.bicycle = self._guarded(_recorded(self._bicycle, 32))
        self.rider = self._guarded(_recorded(self._rider, 32))
        self.seated = self._guarded(_recorded(self._seated, 64))
        self.scenario = self._guarded(_recorded(self._scenario, 64))
        self.base_parameters = self._guarded(_recorded(self._base_parameters, 64))
        self.built = self._guarded(_recorded(self._built, 64))
        self.handling = self._guarded(_recorded(self._handling, 16))
        self.own_rider_label = self._guarded(_recorded(self._own_rider_label, 32))

    # -- the one way in ---------------------------------------------------------
    def _guarded(self, function):
        """``function`` run one at a time, confined to the shipped data (an upload's own folder is
        added only while that upload is read, :meth:`_reaching`), with its errors naming an upload
        as uploaded and a shipped file from the data folder."""
        @functools.wraps(function)
        def run(*args, **kwargs):
            with self._lock, confined():
                try:
                    return function(*args, **kwargs)
                except InputError as exc:
                    raise self._as_uploaded(exc) from None
        return run

    def _reaching(self, bike):
        """Confinement to the shipped data and the upload ``bike``'s own folder (a shipped bicycle:
        the shipped data only); InputError for an upload this server does not have."""
        if not bike.startswith(UPLOAD_PREFIX):
            return contextlib.nullcontext()
        return confined(Path(self.source(bike)).parent)

    def answer(self, compute, *args, key=None, render=None):
        """``(compute(*args), warnings)``: the value and the distinct messages of the
        BikemassWarnings its computation issued (cached parts warn again), in order; with
        ``render``, ``render(value, warnings)`` instead.

        The answer is kept under ``key`` (default ``(compute, args)``, hashable) and served again
        without waiting for the engine's lock, so a cached answer never waits for another
        client's computation; an upload the server no longer has is refused even then.
        """
        for arg in args:
            if isinstance(arg, PageState):
                self.source(arg.bike)                       # a forgotten upload answers no more
        key = (compute, args, render) if key is None else key
        found = self._answers.get(key)
        if found is not None:
            return found
        with self._lock:
            found = self._answers.get(key)                  # computed while this one waited
            if found is not None:
                return found
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", BikemassWarning)
                value = self._guarded(compute)(*args)
            lines = (self._scrubbed(str(w.message)) for w in caught if issubclass(w.category, BikemassWarning))
            lines = list(dict.fromkeys(lines))
            found = (value, lines) if render is None else render(value, lines)
            self._answers.put(key, found)
        return found

    def _scrubbed(self, text):
        """``text`` with every uploaded file's stored path replaced by the name it was uploaded as,
        and the shipped data's folder dropped (``frames/jamis.yaml``, never the install path)."""
        for name, path in list(self._uploads.items()):
            for shown in {str(path), os.path.realpath(path)}:
                text = text.replace(shown, self.upload_label(name))
        folder = re.escape(self._folder.name)
        text = re.sub(rf"{folder}[^\s:]*", "(upload)", text)
        root = data_folder.found_root()
        for top in {str(root), os.path.realpath(root)} if root is not None else ():
            text = text.replace(top.rstrip(os.sep) + os.sep, "")
        return text

    def _as_uploaded(self, exc):
        scrubbed = InputError(self._scrubbed(str(exc.source)), self._scrubbed(str(exc.key)),
                              self._scrubbed(str(exc.expected)))
        return exc if str(scrubbed) == str(exc) else scrubbed

    # -- inputs ---------------------------------------------------------------
    def add_upload(self, filename, content):
        """Store an uploaded bicycle file; return its name (``upload-<digest>``) once it loads (a
        size run: its first size).

        Raises InputError (one line, naming the file as uploaded) for a file that is too large,
        of another kind, not a bicycle, or that refers to any file but the shipped data.
        """
        shown = one_line(Path(str(filename)).name or "upload", MAX_UPLOAD_NAME)
        suffix = Path(shown).suffix.lower()
        if suffix not in UPLOAD_SUFFIXES:
            raise InputError(shown, "(file)", f"a bicycle file ending in {', '.join(UPLOAD_SUFFIXES)}")
        if len(content) > UPLOAD_LIMIT:
            raise InputError(shown, "(file)", f"at most {UPLOAD_LIMIT // 1000} kB")
        secret = secrets.token_hex(16)        # the name is the key: unguessable, not the content's digest
        name = UPLOAD_PREFIX + secret
        with self._lock:
            path = Path(self._folder.name) / secret / f"upload{suffix}"
            path.parent.mkdir()
            path.write_bytes(content)
            self._uploads[name] = path
            self._labels[name] = shown
            try:
                sizes = self.sizes(name)
                self.bicycle((name, sizes[0] if sizes else "", ()))
            except InputError:
                self._forget(name)
                raise
            while len(self._uploads) > MAX_UPLOADS:
                self._forget(next(iter(self._uploads)))
        return name

    def _forget(self, name):
        """Delete the upload ``name``, its file and the answers about it."""
        path = self._uploads.pop(name, None)
        self._labels.pop(name, None)
        self._answers.drop(lambda key: _mentions(key, name))
        if path is not None:
            path.unlink(missing_ok=True)
            with contextlib.suppress(OSError):
                path.parent.rmdir()

    def upload_label(self, name):
        """The file name an uploaded bicycle came from."""
        return self._labels.get(name, "upload")

    def source(self, bike):
        """The argument the loaders take for ``bike``: a shipped name or an uploaded file's path."""
        if bike.startswith(UPLOAD_PREFIX):
            if bike not in self._uploads:
                raise InputError("URL", "bike", "a shipped bicycle or a file uploaded to this server")
            return str(self._uploads[bike])
        if "/" in bike or "\\" in bike or bike.startswith("."):
            raise InputError("URL", "bike", "a shipped bicycle name (paths are not accepted)")
        return bike

    def bike_name(self, state):
        """The name figures give the bicycle of ``state``: its file's ``name:`` (an upload's too,
        never ``upload-<digest>``), else the uploaded file's name or the shipped name."""
        upload = state.bike.startswith(UPLOAD_PREFIX)
        try:
            name = self.bicycle(state.bicycle_key).name
        except InputError:
            name = None
        if upload and (not name or name == Path(self._uploads.get(state.bike, "upload")).stem):
            return self.upload_label(state.bike)            # no name: of its own (the stored file's stem)
        return name or state.bike

    def rider_label(self, state):
        """Who rides ``state``'s bicycle, in words for a figure title, as the command line's titles say it:
        the body's sex, height and mass, ``rider <pose>``, or with no rider added ``rider in the parameter
        set`` for a parameter file whose set holds its rider (the benchmark) and ``no rider`` otherwise
        (:meth:`~bikemass.scenario.scenario.Scenario.rider_label`)."""
        if state.rider == BODY_RIDER:
            return f"a {state.sex} rider of {state.height:g} m and {state.mass:g} kg"
        if state.rider != "none":
            return f"rider {state.rider}"
        return self.own_rider_label(state.bike)

    def _own_rider_label(self, bike):
        with self._reaching(bike):
            return Scenario(self.source(bike)).rider_label()

    def sizes(self, bike):
        """The size names of ``bike``'s size run, ``()`` if it has none."""
        def sizes():
            with self._reaching(bike):
                return bicycle_sizes(self.source(bike))
        return self._guarded(sizes)()

    def is_chart(self, bike):
        """True if ``bike`` is written as a geometry chart (so the page can edit its chart)."""

        def chart():
            with self._reaching(bike):
                path = resolve(self.source(bike), frames_dir(), "bicycle")
                return not _is_parameter_text(path) and load_yaml(path).has("chart")
        return self._guarded(chart)()

    def materials(self, bike, size=""):
        """The stiffness choices for ``bike``: ``infinite``, the frame's own tube materials, then
        every shipped material (its command-line name)."""
        names = {}                                   # material key -> [key, aliases...], as the file lists them
        for name, material in self._guarded(load_materials)().items():
            names.setdefault(material.key, []).append(name)
        shipped = {key: listed[1] if len(listed) > 1 else key for key, listed in names.items()}
        own = [t.material.key for t in self.bicycle((bike, size, ())).tubes]
        names = list(dict.fromkeys([shipped.get(k, k) for k in own] + list(shipped.values())))
        return [RIGID_CHOICE] + names

    def download_source(self, state):
        """The text of the bicycle file of ``state``: the file itself, or for a size run or a
        chart typed over, the mapping of that one size with the edits (YAML)."""

        def text():
            if state.chart or self.sizes(state.bike):
                with self._reaching(state.bike):
                    mapping = edited_chart(self.source(state.bike), dict(state.chart), state.size or None)
                return yaml.safe_dump(file_form(mapping), sort_keys=False)
            source = self.bicycle(state.bicycle_key).source
            with self._reaching(state.bike):
                return read_text(source)
        return self._guarded(text)()

    def _bicycle(self, key):
        """The bicycle of a :attr:`PageState.bicycle_key`: ``(bike, size, chart edits)``."""

        bike, size, chart = key
        size = size or None
        with self._reaching(bike):
            if not chart:
                return load_bicycle(self.source(bike), size=size)
            try:
                return load_bicycle(edited_chart(self.source(bike), dict(chart), size))
            except InputError as exc:
                if str(exc.source) == "<mapping>" and str(exc.key).startswith(CHART_PREFIX):
                    # a chart value typed over: named as the query names it (URL: chart.stack)
                    raise InputError(SOURCE, exc.key, exc.expected) from None
                raise

    def _rider(self, key):
        """The rider of a :attr:`PageState.rider_key` as loaded (a body rider: its pose mapping,
        which only a bicycle can solve)."""
        if isinstance(key, tuple):
            return body_pose(key)
        if "/" in key or "\\" in key or key.startswith("."):
            raise InputError("URL", "rider", "a shipped pose name (paths are not accepted)")
        return load_rider(key)

    def _seated(self, bicycle_key, rider_key):
        """The rider seated on the bicycle (None for no rider); InputError if it cannot sit."""
        return seated_rider(self.bicycle(bicycle_key), self.rider(rider_key))

    def _scenario(self, key, rider, combine, model):
        """The :class:`~bikemass.scenario.scenario.Scenario` of the bicycle, the rider as the page
        seated it (:meth:`seated`, cached) and the model; its parameter set is built here, so that
        its warnings are recorded with it."""
        bicycle = self.bicycle(key)
        seated = self.seated(key, rider)
        placed = None if seated is None else SeatedRider(seated, bicycle, "seated", {}, None, ())
        scenario = Scenario(bicycle, placed, combine=check(Combine, combine).value, method="mesh", model=model,
                            origin=SOURCE)
        scenario.parameters()
        return scenario

    def _base_parameters(self, key, rider, combine):
        """Parameters of the bicycle with its rider seated once (:meth:`seated`, cached)."""
        return self.scenario(key, rider, combine, BASE).parameters()

    def stiffness_choice(self, key, material):
        """The stiffness choice of the page's ``material`` on bicycle ``key``: ``infinite``, a tube
        material of the frame's own (a Material) or a shipped material's name; InputError otherwise."""
        own = {t.material.key: t.material for t in self.bicycle(key).tubes}
        if material != RIGID_CHOICE and material not in own and material not in load_materials():
            raise InputError(SOURCE, "stiffness", f"one of {', '.join(self.materials(key[0], key[1]))}")
        return own.get(material, material)

    def _built(self, key, rider, combine, model, material, overrides):
        """The scenario of ``key``, ``rider``, ``combine`` and ``model`` built with the stiffness
        ``material`` and the typed-over parameters ``overrides``."""
        choice = self.stiffness_choice(key, material)
        return self.scenario(key, rider, combine, model).build({**dict(overrides), "stiffness": choice})

    def warm(self, states=(PageState(),)):
        """Compute ``states`` (and so import what they need) ahead of the first request."""
        for state in states:
            try:
                self.answer(self.evaluate, state)
            except InputError:
                pass

    # -- results --------------------------------------------------------------
    def parameters(self, state: PageState):
        """The benchmark parameter set of ``state``, typed-over values applied (InputError for a set
        the model is not defined for: negative mass, lam outside (-pi/2, pi/2), ...)."""
        base = self.base_parameters(state.bicycle_key, state.rider_key, state.combine)
        if not state.overrides:
            return base
        params = dataclasses.replace(base, **dict(state.overrides))
        check_parameter_file(params, SOURCE)
        warn_parameters(params, SOURCE)
        return params

    def state_built(self, state: PageState):
        """The :class:`~bikemass.scenario.scenario.Built` of ``state`` (cached)."""
        self.parameters(state)                     # the typed-over values checked as the page shows them
        return self.built(state.bicycle_key, state.rider_key, state.combine, state.model, state.stiffness,
                          state.overrides)

    def model(self, state: PageState):
        """The linear model of ``state`` (the scenario builder's, :meth:`state_built`)."""
        return self.state_built(state).model

    def _handling(self, state):
        """``bm.handling`` of ``state`` at :data:`HANDLING_SPEEDS` (cached per state), with the
        warnings the command line gives (speeds where the procedure finds no gains are ``nan``)."""
        return handling(self.model(state), HANDLING_SPEEDS)

    def evaluate(self, state: PageState, speeds=None):
        """:class:`Evaluation` of ``state`` over ``speeds`` (default grid)."""

        built = self.state_built(state)
        frame = frame_label(self.stiffness_choice(state.bicycle_key, state.stiffness))
        return Evaluation(self.parameters(state), built.stiffness, stability(built, speeds=speeds), frame)


def body_pose(key):
    """The chain-form pose mapping of a body rider key ``("body", height m, mass kg, sex, hands)``:
    the body from height, mass and sex, hands on the grip, solved on whichever bicycle it meets."""
    _, height, mass, sex, hands = key
    return {"name": f"{sex}, {height:g} m, {mass:g} kg, hands on the {hands}",
            "body": {"height": Quantity(height, "m"), "mass": Quantity(mass, "kg"), "sex": sex},
            "chain": {"hands": hands}}


def edited_chart(source, edits, size=None):
    """The mapping of chart bicycle ``source`` (one ``size`` of a size run) with ``edits``
    (``{key: mm or deg}``) typed over its chart (as :class:`~bikemass.core.units.Quantity` values: a
    file writer writes them as text, :func:`~bikemass.core.plain.file_form`); the published redundant values (wheelbase,
    trail, ...) are dropped, since they describe the unedited frame."""

    path = resolve(source, frames_dir(), "bicycle")
    node = load_yaml(path)
    if size_names(node):
        node = select_size(node, size if size is not None else size_names(node)[0])
    elif size is not None:
        select_size(node, size)                    # names the size this file does not have
    if not node.has("chart"):
        if not edits:
            return copy.deepcopy(node.mapping())
        node.fail("a geometry chart (chart:) to edit; this bicycle is given by keypoints or parameters",
                  "chart")
    mapping = copy.deepcopy(node.mapping())
    chart = {k: v for k, v in mapping["chart"].items() if k not in CHECKED_KEYS or not edits}
    for key, value in edits.items():
        chart[key] = Quantity(value, "deg" if key in CHART_ANGLES else "mm")
    mapping["chart"] = chart
    mapping.setdefault("name", path.stem)
    return mapping
