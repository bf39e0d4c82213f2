"""The stability study run three ways, each configuration evaluated once per run.

* ``thesis``: what the thesis computed: the published Table 3-9 bodies
  (``<bike>-thesis``), the published Table 3-4 riders (``<pose>-thesis``) added with
  Eq. 3.6 (``combine="thesis"``: no parallel-axis terms), the published Table 3-12 S,
  ranges read off the 0..30 m/s grid (step 0.05) with the 2 rad/s marginal modulus.
* ``corrected``: the same published bodies and riders, so that the difference isolates
  the physical corrections: rider and frame combined with the parallel-axis theorem,
  S condensed onto roll and steer (``procedure="condensed"``) from the beam model of the
  geometry bicycle's rear frame (:data:`~bikemass.study.configurations.FE_FRAME`), and
  critical speeds and range ends as exact roots.
* ``geometry``: everything from geometry: the geometry bicycles and the Table 3-3 riders
  (closed-form solids), combined and stiffened as ``corrected``; ranges on the grid.

The benchmark bicycle is the same parameter file in every run.
"""

from dataclasses import dataclass

from ..analysis.engine.modes import follow_modes
from ..analysis.engine.naming import BICYCLE_LABELS as LABELS
from ..analysis.engine.ranges import MARGINAL_THRESHOLD, grid_ranges, is_stable
from ..analysis.engine.stability import analyse
from ..analysis.engine.speeds import speed_grid
from ..fe import equivalent_stiffness
from ..mass.materials import load_materials
from ..models.whipple import whipple_model
from ..scenario import catalog
from ..scenario.scenario import Scenario
from .configurations import BENCHMARK, BENCHMARK_RIDER, FE_FRAME
from ..rider.seating import seat_rider

CRITERIA = ("strict", "marginal")
METHOD = "exact"
"""Mass properties of geometry parts from closed-form solids (the meshes agree to ~1e-5)."""


@dataclass(frozen=True)
class RunSpec:
    """How one run builds its parameter sets and stiffnesses and reads its ranges."""

    name: str
    title: str
    published_bodies: bool
    combine: str
    stiffness_source: str
    procedure: str
    exact: bool

    def bike_name(self, bike):
        return bike if bike == BENCHMARK or not self.published_bodies else f"{bike}-thesis"

    def rider_name(self, rider):
        if rider in ("none", BENCHMARK_RIDER):
            return None
        return f"{rider}-thesis" if self.published_bodies else rider


THESIS = RunSpec("thesis", "thesis mode (published bodies and riders, Eq. 3.6, published S, 0.05 m/s grid)",
                 published_bodies=True, combine="thesis", stiffness_source="published",
                 procedure="thesis", exact=False)
CORRECTED = RunSpec("corrected", "corrected (published bodies and riders, parallel axis, condensed S "
                    "from the beam model, exact critical speeds)",
                    published_bodies=True, combine="exact", stiffness_source="computed",
                    procedure="condensed", exact=True)
GEOMETRY = RunSpec("geometry", "from geometry (geometry bicycles and Table 3-3 riders, parallel axis, condensed "
                   "S from the beam model; ranges on the 0.05 m/s grid)",
                   published_bodies=False, combine="exact", stiffness_source="computed",
                   procedure="condensed", exact=False)
RUNS = (THESIS, CORRECTED, GEOMETRY)


@dataclass(frozen=True)
class Outcome:
    """Result of one configuration in one run.

    ``ranges[kind][criterion][mode]`` = ``[[start, stop], ...]`` (m/s) with ``kind``
    ``grid`` (always) or ``exact`` (exact runs), ``criterion`` in :data:`CRITERIA`,
    ``mode`` ``overall`` (all modes together) or a mode label; ``weave_speeds`` / ``capsize_speeds`` (m/s) are the
    exact crossings (``None`` in grid-only runs).
    """

    configuration: object
    parameters: object
    S: object
    modes: object
    ranges: dict
    weave_speeds: list = None
    capsize_speeds: list = None


def grid_outcome_ranges(modes, marginal=MARGINAL_THRESHOLD):
    """``{criterion: {mode: [[first, last], ...]}}``: runs of stable grid speeds of tracked ``modes``."""
    out = {}
    for criterion, threshold in zip(CRITERIA, (None, marginal)):
        stable = is_stable(modes.eigenvalues, threshold)
        out[criterion] = {"overall": grid_ranges(modes.speeds, stable.all(axis=1))}
        out[criterion].update({label: grid_ranges(modes.speeds, stable[:, modes.labels.index(label)])
                               for label in LABELS})
    return out


def _exact_ranges(st):
    return {kind: {criterion: {"overall": st.ranges[criterion][kind],
                               **{label: st.mode_ranges[label][criterion][kind] for label in LABELS}}
                   for criterion in CRITERIA} for kind in ("grid", "exact")}


def evaluate(configuration, parameters, S, exact, model=None):
    """:class:`Outcome` of a parameter set with rear-frame stiffness ``S`` (N m/rad, ``None``: rigid) on
    the thesis's grid; ``model`` the Whipple model they build (:attr:`Inputs.built`), made here if
    not given."""
    model = whipple_model(parameters, S) if model is None else model
    speeds = speed_grid()
    if exact:
        st = analyse(model, speeds, stiffness=S)
        return Outcome(configuration, parameters, S, st.modes, _exact_ranges(st),
                       list(st.weave_speeds), list(st.capsize_speeds))
    modes = follow_modes(model, speeds)
    return Outcome(configuration, parameters, S, modes, {"grid": grid_outcome_ranges(modes)})


class Inputs:
    """Loads bicycles, riders, parameter sets and stiffnesses once and hands them to every run; each
    configuration's model is its :class:`~bikemass.scenario.scenario.Scenario`'s."""

    def __init__(self):
        self._bicycles, self._riders, self._scenarios, self._stiffness = {}, {}, {}, {}
        self.contacts = {}
        """``{(rider, bike): {contact: (gap m, bicycle key)}}`` of every rider seated so far."""
        self._materials = None

    def bicycle(self, name):
        if name not in self._bicycles:
            self._bicycles[name] = catalog.load_bicycle(name)
        return self._bicycles[name]

    def rider(self, name, bike=None):
        """The rider ``name`` (None: no rider); with ``bike``, on it as the thesis placed it: its
        contacts are measured (:attr:`contacts`, for the report) and the pose kept as written."""
        seated = self._seat(name, bike)
        return seated.rider if bike is not None and seated is not None else seated

    def _seat(self, name, bike):
        """The rider ``name`` loaded (no ``bike``) or seated on ``bike`` (a SeatedRider), cached."""
        key = (name, bike)
        if name is not None and key not in self._riders:
            if bike is None:
                self._riders[key] = catalog.load_rider(name)
            else:
                seated = seat_rider(name, self.bicycle(bike), allow_off_contact=True)
                self._riders[key], self.contacts[key] = seated, seated.contacts
        return self._riders.get(key)

    def scenario(self, spec, configuration):
        """The :class:`~bikemass.scenario.scenario.Scenario` of ``configuration`` as ``spec`` builds it
        (cached: its parameter set is built once)."""
        key = (spec.bike_name(configuration.bike), spec.rider_name(configuration.rider), spec.combine)
        if key not in self._scenarios:
            bike, rider, combine = key
            self._scenarios[key] = Scenario(self.bicycle(bike), self._seat(rider, bike), combine=combine,
                                            method=METHOD)
        return self._scenarios[key]

    def parameters(self, spec, configuration):
        """Benchmark parameter set of ``configuration`` as ``spec`` builds it (cached)."""
        return self.scenario(spec, configuration).parameters()

    def built(self, spec, configuration):
        """The :class:`~bikemass.scenario.scenario.Built` Whipple model of ``configuration``: its
        parameter set with the stiffness :meth:`stiffness` gives."""
        S = self.stiffness(spec, configuration)
        return self.scenario(spec, configuration).build(None if S is None else {"stiffness": S})

    def stiffness(self, spec, configuration):
        """2x2 S (N m/rad) of ``configuration`` in ``spec``, ``None`` if rigid."""
        if configuration.stiffness == "infinite":
            return None
        if spec.stiffness_source == "computed":
            return self.frame_stiffness(FE_FRAME[configuration.bike], configuration.stiffness, spec.procedure)
        bicycle = self.bicycle(spec.bike_name(configuration.bike))
        S = bicycle.published_stiffness(self.material(configuration.stiffness))
        if S is None:
            raise ValueError(f"{bicycle.name} has no published {configuration.stiffness} stiffness")
        return S

    def material(self, name):
        if self._materials is None:
            self._materials = load_materials()
        return self._materials[name]

    def frame_stiffness(self, frame, material, procedure):
        """S (N m/rad) of the rear-frame beam model of bicycle ``frame`` in ``material`` (cached)."""
        key = (frame, material, procedure)
        if key not in self._stiffness:
            self._stiffness[key] = equivalent_stiffness(self.bicycle(frame).structure, self.material(material),
                                                        procedure)
        return self._stiffness[key]


def run(spec, configurations, inputs, step=None):
    """``{configuration: Outcome}`` of one run; ``step(label)`` is called after each configuration."""
    out = {}
    for c in configurations:
        built = inputs.built(spec, c)
        out[c] = evaluate(c, built.parameters, built.stiffness, spec.exact, built.model)
        if step is not None:
            step(f"{spec.name}: {c.label}")
    return out
