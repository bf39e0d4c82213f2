"""A scenario and its one builder: a bicycle, a rider, a frame stiffness and a model choice -> the
linear model.

A :class:`Scenario` is a value: what to build.  :meth:`Scenario.build` makes it a :class:`Built`:
the benchmark parameter set, the rear frame's stiffness S, the
:class:`~bikemass.models.linear.LinearModel` of the chosen member of the family and what that
member took (the rider split at the hips, the frame's and fork's compliances, the tyres).  Every
entry point builds through it: ``bm.parameters``, ``bm.stability`` given a scenario, the commands
(``params``, ``stability``, ``eig``, ``sensitivity``, ``uncertainty``, ``sweep``, the handling
commands), the study, the web page.

``build(changes)`` rebuilds with any input changed (a benchmark parameter, a dotted path into the
bicycle or pose YAML, ``stiffness``: :mod:`bikemass.scenario.inputs`); each piece is cached by the
changes it depends on, and each built scenario by its changes, so that a sweep or a web page pays
only for what changed.

The model choice (``model=``, ``--model``; :mod:`bikemass.models.registry`):

* ``whipple`` (default): the Meijaard et al. (2007) bicycle; a stiffness choice other than
  ``infinite`` adds the thesis's quasi-static flexible rear frame (Williams 2015, Eq. 3.27-3.30);
* ``rider-lean``: the rider's upper body leans at the hips (:mod:`bikemass.rider.lean_split`);
  the bicycle may instead be BicycleParameters' ``MooreRiderLean2012`` parameter set, or a
  :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` (whose default model this is);
* ``tyre``: tyres that slip (``tyres``: a :class:`~bikemass.models.members.tyre.parameters.Tyres`, a tyre file or a
  mapping; default :data:`~bikemass.models.members.tyre.parameters.DEFAULT_TYRES`);
* ``flexible``: the rear frame's twist and the fork's bending with their inertia, from the beam
  models in the stiffness choice's material (``infinite``: both rigid, the rigid model back);
* members joined by ``+`` (``rider-lean+tyre+flexible``).

A benchmark parameter changed by name (``build({"c": 0.09})``) changes the set the model takes:
for ``rider-lean`` the bicycle with the rider's legs but without the upper body.
"""

import dataclasses
import os
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field, fields

import numpy as np

from ..core.choices import RIGID, Combine, Method, check
from ..core.units import ARTICLES, DIMENSIONS, Quantity, UnitError, convert, dimension_of, factor
from ..mass.materials import frame_label
from ..core.errors import BikemassWarning, InputError, short, wrong_type
from ..core.frozen import FrozenMap, readonly, short_repr
from ..models.family import build as build_member, dynamic_derivatives, generated, held_coordinates, linear_model, \
    input_owner, member_code_names, member_inputs, values as member_values
from ..models.linear import LinearModel
from ..models.members.spec import Source, with_inputs
from ..models.parameters import NAMES, BenchmarkParameters, dimension
from ..models.plausibility import check_parameters
from ..models.registry import BY_KEYWORD, BY_NAME, SPECS, ModelChoice, by_keyword, model_of, parse_model
from ..models import whipple
from ..rider.hands import hand_gaps
from .loading import BicycleLike, RiderLike
from .inputs import STIFFNESS_KEY, Inputs, _lru, file_unit, get_path, split_changes


@dataclass(frozen=True, eq=False)
class Built:
    """A scenario built: what its linear model was made from, and the model.

    Attributes
    ----------
    parameters : BenchmarkParameters
        The Meijaard et al. (2007) set of the bicycle with its rider held rigid (what
        ``bikemass params`` prints; SI).
    stiffness : numpy.ndarray (2, 2) or None
        The rear frame's quasi-static stiffness S (N m/rad, read-only) of the ``whipple`` model;
        ``None`` for a rigid frame and for every other member (a member that takes the stiffness
        choice, the flexible frame, holds its own parameters instead).
    model : LinearModel
        The chosen model.
    choice : ModelChoice
        Which member of the family it is.
    members : FrozenMap
        ``{member name: its typed parameters}`` for each member of :attr:`choice`
        (:mod:`bikemass.models.members`).  Each is also an attribute by the name its member declares:
        ``lean`` (the rider split at the hips), ``compliances`` (the frame's twist and the fork's
        bending), ``tyres``, ``arms``; ``None`` for a member the model does not have.

    Examples
    --------
    >>> import bikemass as bm
    >>> built = bm.Scenario("benchmark").build()
    >>> print(built.model.name, built.stiffness, f"w = {built.parameters.w} m")
    whipple None w = 1.02 m
    >>> print(bm.Scenario("benchmark", model="tyre").build().tyres.front.relaxation_length, "m")
    0.175 m
    """

    parameters: BenchmarkParameters
    stiffness: np.ndarray | None
    model: LinearModel
    choice: ModelChoice = ModelChoice()
    members: FrozenMap = FrozenMap({})

    def __getattr__(self, name):
        spec = BY_KEYWORD.get(name)
        if spec is None or name != spec.attribute:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        return self.members.get(spec.name)

    def values(self):
        """``{name: float}`` of the parameters the model was generated from (the 26 benchmark names
        of the set the model takes, and its members'): what :func:`bikemass.models.family.linear_model`
        takes."""
        return member_values(self.choice, self.parameters, members=dict(self.members))

    def with_values(self, values):
        """The model of the same member at other parameter ``values`` (``{name: float}``, as
        :meth:`values`), the same coordinates held."""
        return linear_model(self.choice, values, held_coordinates(self.choice, self.members))

    def derivatives(self, speed, names, step):
        """``{name: dA/dp}``: the dynamic block of the model's ``A(speed)`` differentiated with respect to
        each parameter of ``names`` (as :meth:`values` names them) by the complex step ``i * step``."""
        return dynamic_derivatives(self.choice, self.values(), tuple(names), speed, step,
                                   held_coordinates(self.choice, self.members))

    def __repr__(self):
        return short_repr(self, ("model", repr(self.model.name)), ("stiffness", self.stiffness is not None))


def _rigid(choice):
    return choice is None or (isinstance(choice, str) and choice in (RIGID, "rigid"))


@dataclass(frozen=True, init=False)
class Scenario:
    """What to build: a bicycle, a rider, a frame stiffness and a model (see the module docstring).

    Parameters
    ----------
    bicycle
        Anything :func:`bikemass.load_bicycle` takes (a name, ``"NAME@SIZE"``, a YAML or parameter
        file, a mapping, a parameter set, a Bicycle), or for a model with the ``rider-lean`` member
        a ``MooreRiderLean2012`` parameter set (BicycleParameters' YAML, a file or a mapping).
    rider
        Anything :func:`bikemass.load_rider` takes; ``None`` (default) for no rider.  Seated on the
        bicycle (:func:`bikemass.seated_rider`); a person (a chain pose without ``bike:``) is
        re-seated on every changed bicycle.  A :class:`~bikemass.rider.seating.SeatedRider` (what
        ``seat_rider`` gives, its contacts measured) is taken as seated.
    stiffness
        The frame: ``"infinite"`` (rigid, default), a material name or file, a 2x2 matrix or a
        stiffness file (N m/rad) as for :func:`bikemass.stiffness`; with ``flexible`` a material.
    combine : {"exact", "thesis"}
        Rider + rear frame: parallel-axis theorem or the thesis's Eq. 3.6.
    method : {"mesh", "exact"}
        Mass properties from meshes or closed-form solids.
    model : str or ModelChoice, optional
        ``"whipple"``, ``"rider-lean"``, ``"tyre"``, ``"flexible"`` or members joined by ``+``.
        Default: ``"whipple"``, or ``"rider-lean"`` for a bicycle given as
        :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` (the parameter set's own member).
    member_inputs : Mapping, optional
        ``{member name: its parameters}`` for members that take parameters from the scenario's user
        (:mod:`bikemass.models.members`); the same as the keywords below.
    allow_off_contact : bool
        Use a rider pose as written even off the bicycle's contacts (the thesis's riders).
    origin : str
        What errors about changes name as their source (a sweep's spec file, ``--inputs``, ...).
    **keywords
        A member's parameters by the keyword it declares (``Member.keyword``), refused without the member:

        ``tyres`` (the ``tyre`` member): a :class:`~bikemass.models.members.tyre.parameters.Tyres`, a
        tyre YAML file or a mapping in its form; ``None``: a parameter file's ``tyre:`` block, else the
        defaults.

        ``arms`` (the ``arms`` member): a :class:`~bikemass.models.members.arms.parameters.Arms`, an arms
        YAML file or a mapping in its form (``stiffness`` N m/rad, ``damping`` N m s/rad about the steer
        axis; ``forearms: handlebars`` puts the seated rider's forearms on the front frame); ``None``: a
        parameter file's ``arms:`` block, else zero (no published default; warned).

    Raises
    ------
    InputError
        An unknown model, combine or method; tyres without the tyre member; a stiffness the model
        cannot take.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.stability(bm.Scenario("benchmark"))          # Meijaard et al. (2007), exact digits
    >>> print(f"{r.weave_speeds[0]:.12f} {r.capsize_speeds[0]:.12f}")
    4.292382536341 6.024262015388
    >>> lean = bm.Scenario("jamis", "relaxed", model="rider-lean").build()
    >>> print(lean.model.state_names[:3])
    ('roll-angle', 'steer-angle', 'lean-angle')
    """

    bicycle: object
    rider: object = None
    stiffness: object = None
    combine: str = Combine.EXACT.value
    method: str = Method.MESH.value
    model: "ModelChoice | str | None" = None
    member_inputs: FrozenMap = FrozenMap({})
    allow_off_contact: bool = False
    origin: str = field(default="changes", compare=False)

    def __init__(self, bicycle: object, rider: object = None, stiffness: object = None,
                 combine: str = Combine.EXACT.value, method: str = Method.MESH.value,
                 model: "ModelChoice | str | None" = None, member_inputs: "Mapping | None" = None,
                 allow_off_contact: bool = False, origin: str = "changes", **keywords: object):
        set_ = object.__setattr__
        for name, value in (("bicycle", bicycle), ("rider", rider), ("stiffness", stiffness), ("combine", combine),
                            ("method", method), ("allow_off_contact", allow_off_contact), ("origin", origin)):
            set_(self, name, value)
        choice = model_of(bicycle, model) if model is not None else own_model(bicycle, self)   # None: the bicycle's own
        set_(self, "model", choice)
        if member_inputs is not None and not isinstance(member_inputs, Mapping):
            raise wrong_type("member_inputs", member_inputs, "a mapping of a member's name or keyword to its "
                             "parameters (e.g. {'tyres': 'tyres.yaml'})")
        set_(self, "member_inputs", FrozenMap(by_keyword({**(member_inputs or {}), **keywords}, "Scenario")))
        set_(self, "combine", check(Combine, self.combine).value)
        set_(self, "method", check(Method, self.method).value)
        if not isinstance(self.allow_off_contact, bool):
            raise InputError("allow_off_contact", short(self.allow_off_contact), "True or False")
        for name, given in self.member_inputs.items():         # a member's parameters only with the member
            if not choice.has(name):
                key = BY_NAME[name].keyword or name
                raise InputError(key, short(given), f"a model with the {name} member (e.g. "
                                 f"{choice.with_member(name).name}) for {key}; the model {choice.name} has none")
            spec = BY_NAME[name]
            if spec.source is not Source.OPTION:
                raise InputError(spec.keyword or name, short(given), f"nothing: the {name} member takes its "
                                 "parameters from the scenario's bicycle and rider")
            if not isinstance(given, (str, os.PathLike, Mapping)):
                spec.runtime().coerce(given, spec.keyword or name)      # a typed value, or names what it takes
        self._refuse_stiffness(self.stiffness)

    def __getattr__(self, name):
        spec = BY_KEYWORD.get(name)
        if spec is None or name != spec.keyword:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        return self.member_inputs.get(spec.name)

    def _refuse_stiffness(self, choice):
        """A frame stiffness other than rigid needs the Whipple model (its quasi-static spring) or
        the flexible member (whose beam models take a material)."""
        if self.model.members and _stiffness_member(self.model) is None and not _rigid(choice):
            member = next(spec.name for spec in SPECS if spec.takes_stiffness)
            raise InputError("stiffness", short(choice), f"infinite (rigid) with the model {self.model.name}, whose "
                             f"frame is rigid; a flexible frame is the {member} member's "
                             f"(--model {self.model.with_member(member).name}: beam models of a material), or "
                             "the Whipple model's quasi-static spring (--model whipple)")

    def check_stiffness(self, choice):
        """InputError unless this scenario's model takes stiffness choice ``choice`` on its bicycle
        (the Whipple model's S, or the flexible member's compliances, is made and cached)."""
        self._refuse_stiffness(choice)
        if _stiffness_member(self.model) is not None:
            self.inputs.compliances(choice)
        elif not self.model.members:
            self.inputs.frame_stiffness(choice)

    def rider_label(self):
        """Who rides, in words for a title: ``rider <name>`` for a rider given, else ``"rider in the parameter
        set"`` for a parameter file whose set holds its rider (``rider_included: true``, the benchmark, what
        ``params`` writes with a rider; a ``MooreRiderLean2012`` set), else ``"no rider"``.  Only a
        parameter file is read for it.

        Examples
        --------
        >>> import bikemass as bm
        >>> bm.Scenario("benchmark").rider_label(), bm.Scenario("jamis").rider_label()
        ('rider in the parameter set', 'no rider')
        """
        if self.rider not in (None, "none"):
            return f"rider {self.rider}" if isinstance(self.rider, (str, os.PathLike)) else "rider"
        return "rider in the parameter set" if self.rider_in_set() else "no rider"

    def rider_in_set(self):
        """Whether the bicycle is a parameter file whose set holds its rider (``rider_included: true``, the
        benchmark, what ``params`` writes with a rider; a ``MooreRiderLean2012`` set); only a parameter file is
        read for it."""
        try:
            node = self.inputs.parameter_node
            return node is not None and (self.inputs.lean_set is not None or
                                         node.get("rider_included", False).value is True)
        except InputError:
            return False

    def frame_label(self):
        """What this scenario's frame is, in words for a title: as
        :func:`~bikemass.mass.materials.frame_label` names its stiffness choice, or, with none given, the
        frame stiffness its parameter file carries (taken then: ``params --stiffness`` wrote it), else
        ``rigid frame``.

        Examples
        --------
        >>> import bikemass as bm
        >>> bm.Scenario("benchmark").frame_label()
        'rigid frame'
        """
        if self.stiffness is None:
            try:
                own = self.inputs.file_members
            except InputError:
                own = {}
            if "frame_stiffness" in own and not self.model.members or \
                    any(spec.takes_stiffness and spec.name in own for spec in self.model.specs):
                return "the frame stiffness the parameter file carries"
        return frame_label(self.stiffness)

    def __getstate__(self):
        """The scenario's fields only: its caches stay in the process that made them."""
        return {f.name: getattr(self, f.name) for f in fields(self)}

    def __setstate__(self, state):
        for name, value in state.items():
            object.__setattr__(self, name, value)

    @property
    def inputs(self):
        """The :class:`~bikemass.scenario.inputs.Inputs` behind this scenario (read once, cached)."""
        found = self.__dict__.get("_inputs")
        if found is None:
            found = Inputs(self.bicycle, self.rider, self.combine, self.method, self.origin, self.allow_off_contact)
            object.__setattr__(self, "_inputs", found)
        return found

    # -- inputs by key ----------------------------------------------------------------------
    def value(self, key):
        """The current value of input ``key`` (SI; :func:`~bikemass.scenario.inputs.get_path`); a
        benchmark name's in the set the model takes (for ``rider-lean``, without the upper body)."""
        if key in NAMES and _split_member(self.model) is not None:
            return float(getattr(self.inputs.lean(forearms_held=self._held()).bicycle, key))
        if self.model.members and key in member_inputs(self.model):
            return float(self.build().values()[key])
        self._refuse_code_name(key)
        return get_path(self.inputs, key)

    def _refuse_code_name(self, key):
        """InputError for ``key`` where it is a member's parameter that is no input here: a parameter of this
        model's code that follows from the member's data (naming the inputs), or a member input of a member
        this model does not have (naming the model that has it)."""
        if self.model.members and key in member_code_names(self.model):
            inputs = member_inputs(self.model)
            raise InputError(self.origin, key, f"one of the {self.model.name} model's inputs ("
                             f"{', '.join(inputs) or 'none'}): {key} follows from the member's own data")
        owner = input_owner(key)
        if owner is not None:
            raise InputError(self.origin, key, f"an input of the bicycle, the rider or the model: {key} is the "
                             f"{owner.name} member's (model: {owner.name}, --model {owner.name})")

    def file_unit(self, key):
        """The unit a bare value of ``key`` is read in (the file's unit there), or None for SI (a member's
        input, a parameter of the model's code, is read in its code's SI unit)."""
        if self.model.members and key in member_inputs(self.model):
            return None
        return file_unit(self.inputs, key)

    def input_dimension(self, key):
        """The physical dimension (:mod:`bikemass.core.units`: ``"length"``, ``"angle"``, ...) of input ``key``:
        a benchmark name's, a member input's (its code's unit), or that of the unit its file writes it in;
        ``None`` where the file gives it as a bare number or the key is no input (nothing to check against)."""
        if key in NAMES:
            return dimension(key)
        if self.model.members and key in member_inputs(self.model):
            return dimension_of(member_inputs(self.model)[key][1])
        try:
            unit = self.file_unit(key)
        except InputError:
            return None
        return dimension_of(unit) if unit else None

    def unit_problem(self, key, unit):
        """What input ``key`` is (``"a length"``) where a value of it cannot carry ``unit``, else ``None``: its
        known dimension (:meth:`input_dimension`) compared, or where the file writes it bare, the nominal
        value written in ``unit`` built (the bicycle's reader names what it takes there).  ``None`` also for a
        key that is no input (its own error comes where it is used)."""
        given = dimension_of(unit)
        known = self.input_dimension(key)
        if known is not None:
            return None if given == known else f"{ARTICLES.get(known, 'a')} {known}"
        try:
            x = self.value(key)
        except InputError:
            return None
        if given is None or isinstance(x, bool) or not isinstance(x, (int, float)):
            return None
        try:
            self.build({key: Quantity(x / factor(unit, DIMENSIONS[given][0]), unit)})
        except InputError as exc:
            return exc.expected.split(",")[0].split(" (")[0]
        return None

    @property
    def file_std(self):
        """``{name: std}`` (SI) of a measured bicycle's 26 parameters (a BicycleParameters text file's
        ``+/-`` values, a parameter file's ``uncertainty:`` block, or computed from measurements);
        ``{}`` otherwise."""
        return self.inputs.file_std

    @property
    def measurement_std(self):
        """``{"measured.<name>": std}`` of a bicycle computed from measurements (BicycleParameters'
        ``<Name>Measured.txt``; std in the file's units), ``{}`` otherwise: the independent inputs
        whose spread ``bikemass uncertainty`` propagates (the 26 parameters share them)."""
        return self.inputs.measurement_std

    # -- the builder ------------------------------------------------------------------------
    def parameters(self, changes=None):
        """The benchmark parameter set (:attr:`Built.parameters`) with ``changes``, without building
        the model."""
        bike, rider, params, _ = split_changes(changes or {})
        if self.inputs.lean_set is not None and _split_member(self.model) is None:
            member = next(spec.name for spec in SPECS if spec.source is Source.RIDER_SPLIT)
            raise InputError(self.inputs._lean_source, "parameterization", "a Whipple parameter set (benchmark or "
                             f"principal) for the model {self.model.name}; a MooreRiderLean2012 set is for the "
                             f"{member} model (--model {member}, bm.Scenario(FILE, model={member!r}))")
        p = self.inputs.parameters(bike, rider, self._held())
        if params:
            if _split_member(self.model) is not None:
                return self._lean(bike, rider, params).rigid()
            p = check_parameters(dataclasses.replace(p, **dict(params)), self.origin)
        return p

    def frame_stiffness(self, which=None, changes=None):
        """S (N m/rad) or ``None`` of stiffness choice ``which`` (default the scenario's) on the bicycle
        with ``changes``: what :attr:`Built.stiffness` holds for the Whipple model."""
        bike, _, _, _ = split_changes(changes or {})
        return self.inputs.frame_stiffness(self.stiffness if which is None else which, bike)

    def _lean(self, bike, rider, params):
        lean = self.inputs.lean(bike, rider, self._held())
        if params:
            lean = lean.replace(bicycle=check_parameters(dataclasses.replace(lean.bicycle, **dict(params)), self.origin))
        return lean

    def _option(self, spec, quiet=False):
        """The typed parameters of member ``spec`` whose source is its keyword: the scenario's, else a
        parameter file's block, else its default (``quiet``: without the default's own warning, where the
        member's inputs are set by name)."""
        given = self.member_inputs.get(spec.name)
        if given is None and spec.name in self.inputs.file_members:
            return self.inputs.file_members[spec.name]        # a parameter file's block (params --model)
        if given is None and quiet:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", BikemassWarning)
                return spec.runtime().coerce(given, spec.keyword or spec.name)
        return spec.runtime().coerce(given, spec.keyword or spec.name)

    def _held(self):
        """Whether a member holds the rider's forearms on the handlebars (the arms' ``forearms: handlebars``)."""
        if self.rider in (None, "none"):
            return False          # no seated rider to move (a parameter file's set has its forearms where they were)
        found = self.__dict__.get("_forearms")
        if found is None:
            found = False
            for spec in self.model.specs:
                hook, given = spec.hook("forearms_held"), self.member_inputs.get(spec.name)
                if hook is not None and given is not None:
                    found = found or hook(spec.runtime().coerce(given, spec.keyword or spec.name))
            object.__setattr__(self, "_forearms", found)
        return found

    def build(self, changes=None):
        """:class:`Built` of the scenario with ``changes`` (``{key: value}``, keys as in
        :mod:`bikemass.scenario.inputs`; cached by their values)."""
        changes, own = self._own_changes(_checked_changes(changes))
        key = split_changes(changes)
        key = (key[0], key[1], key[2], _hashable(key[3]), own)
        return _lru(self.inputs._cache("built"), key, lambda: self._build(changes, dict(own)))

    def _own_changes(self, changes):
        """``(changes, own)``: ``changes`` without those of the model's member inputs (its code's own parameters,
        :func:`~bikemass.models.family.member_inputs`), and those as sorted ``(name, SI value)`` pairs; a
        value with a unit is converted to the code's unit, a bare number is taken in it.  A parameter of the
        model's code that is no input is refused in one line naming the inputs."""
        code = member_code_names(self.model) if self.model.members else frozenset()
        if not any(key in code or input_owner(key) is not None for key in changes):
            return changes, ()
        inputs = member_inputs(self.model)
        rest, own = {}, []
        for key, value in changes.items():
            if key in inputs:
                own.append((key, _in_unit(value, inputs[key][1], self.origin, key)))
            else:
                self._refuse_code_name(key)
                rest[key] = value
        return rest, tuple(sorted(own))

    def _build(self, changes, named=None):
        bike, rider, params, stiffness = split_changes(changes)
        choice = self.stiffness if stiffness is None else stiffness
        self._refuse_stiffness(choice)
        p = self.parameters(changes)
        if not self.model.members:
            S = self.inputs.frame_stiffness(choice, bike)
            return Built(p, None if S is None else readonly(S), whipple.whipple_model(p, S), self.model)
        typed = {}
        for spec in self.model.specs:
            if spec.source is Source.RIDER_SPLIT:
                typed[spec.name] = self._lean(bike, rider, params)
            elif spec.source is Source.BEAM_MODELS:
                typed[spec.name] = self.inputs.compliances(choice, bike)
            inputs = spec.hook("INPUTS") or {}
            mine = {k: v for k, v in (named or {}).items() if k in inputs}
            if spec.source not in (Source.RIDER_SPLIT, Source.BEAM_MODELS):
                typed[spec.name] = self._option(spec, quiet=bool(mine))
            if mine:                             # the member's own parameters changed by name (its checks run)
                typed[spec.name] = with_inputs(typed[spec.name], mine, inputs, self.origin)
                if spec.source is Source.RIDER_SPLIT:     # the set with the rider held rigid holds the change too
                    p = typed[spec.name].rigid()
        hands = None
        for spec in self.model.specs:            # a member that acts through the rider's hands checks them
            check_hands = spec.hook("check_hands")
            if check_hands is not None:
                hands = self._hands(bike, rider) if hands is None else hands
                # a parameter file's own block over its own rider (params wrote both): nothing to check
                own = self.member_inputs.get(spec.name) is None and spec.name in self.inputs.file_members
                if not (hands is _IN_THE_SET and own):
                    check_hands(typed[spec.name], None if hands is _IN_THE_SET else hands[0],
                                rider_in_set=hands is _IN_THE_SET)
        return Built(p, None, build_member(self.model, p, members=typed), self.model, FrozenMap(typed))

    def _hands(self, bike, rider):
        """``(gap,)``: how far the seated rider's hand furthest from a grip is from one (m; ``inf`` where not
        known), or ``(None,)`` without a seated rider (a member's ``check_hands`` protocol); ``_IN_THE_SET``
        where the rider is in the parameter set (a ``MooreRiderLean2012`` set, a file with
        ``rider_included: true``, as ``params`` writes it): no pose to check; a member block of that file
        (``params --model M`` wrote it with the rider) is taken as it is."""
        if self.inputs.lean_set is not None:
            return _IN_THE_SET
        seated = self.inputs.seated(bike, rider)
        if seated is None:
            return _IN_THE_SET if self.inputs.bicycle(bike).rider_included else (None,)
        contacts = self.inputs.bicycle(bike).contacts
        if contacts is None:                      # a parameter set seated by its placement: no grips to reach
            return (float("inf"),)
        gaps = hand_gaps(seated, dict(contacts.grips))
        return (max((gap for gap, _ in gaps.values()), default=float("inf")),)

    def replace(self, **changes):
        """A copy with some fields changed (a new scenario: its own caches); a member's keyword (``tyres=``)
        replaces that member's parameters."""
        keywords = by_keyword({k: v for k, v in changes.items() if k in BY_KEYWORD}, "replace")
        rest = {k: v for k, v in changes.items() if k not in BY_KEYWORD}
        inputs = {**self.member_inputs, **keywords}
        for key, value in changes.items():                 # tyres=None removes the tyres given
            if key in BY_KEYWORD and value is None:
                inputs.pop(BY_KEYWORD[key].name, None)
        return Scenario(**{**{f.name: getattr(self, f.name) for f in fields(self)}, "member_inputs": inputs, **rest})


def _stiffness_member(choice):
    """The member of ``choice`` that takes the stiffness choice (a material), or None."""
    return next((spec for spec in choice.specs if spec.takes_stiffness), None)


_IN_THE_SET = ("in the set",)
""":meth:`Scenario._hands` of a rider that is in the parameter set: no hands to check."""


def own_model(bicycle, scenario=None):
    """The :class:`~bikemass.models.registry.ModelChoice` a bicycle input selects by its own type when no
    model is named: the member its parameter set declares (``rider-lean`` for
    :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters`, and for a file or mapping
    holding BicycleParameters' ``MooreRiderLean2012`` set), the ``model:`` a parameter file written by
    ``bikemass params --model M`` declares, else the Whipple bicycle.  A bicycle input that
    cannot be read selects the Whipple bicycle here; building the scenario reports what is wrong with it.
    ``scenario``: the :class:`Scenario` whose inputs read the file (read once, kept), else a fresh one's.

    Examples
    --------
    >>> from bikemass.scenario.scenario import own_model
    >>> own_model("benchmark").name
    'whipple'
    """
    choice = model_of(bicycle, None)
    if choice.members or not isinstance(bicycle, (str, os.PathLike, Mapping)):
        return choice
    inputs = scenario.inputs if scenario is not None else Inputs(bicycle, None, Combine.EXACT.value,
                                                                 Method.MESH.value, "changes", False)
    try:
        node = inputs.parameter_node
    except InputError:
        return choice                        # what is wrong with the file: reported where it is built
    if node is not None and node.has("model"):
        # a parameter file written by ``params --model M``: its model, named by its own key alone (a bad
        # member block is reported where the model reads it); a model that is not one is refused here
        try:
            return parse_model(node["model"].string(), "model")
        except InputError as exc:
            node["model"].fail(exc.expected)
    try:
        lean = inputs.lean_set
    except InputError:
        return choice
    return choice if lean is None else model_of(lean, None)


def refuse_riderless(node, model, bike):
    """A spec's (a sweep's, an optimisation's; its top-level config :class:`~bikemass.core.config.Node`)
    ``model`` (a name) that splits a rider at the hips, with no ``rider:`` (or ``rider: none``) on a
    ``bike`` that is no ``MooreRiderLean2012`` set: InputError naming the spec's ``rider`` key (before any
    configuration is built; each would be refused alike)."""
    member = _split_member(parse_model(model))
    riderless = not node.has("rider") or node["rider"].string() == "none"
    if member is not None and riderless and not own_model(bike).has(member.name):
        node.fail(f"a rider for the {member.name} model to split at the hips (rider: POSE), or a "
                  "MooreRiderLean2012 parameter set as the bike", "rider")


def _split_member(choice):
    """The member of ``choice`` whose parameters are the rider split at the hips, or None."""
    return next((spec for spec in choice.specs if spec.source is Source.RIDER_SPLIT), None)


def _checked_changes(changes):
    """``changes`` (a mapping of dotted keys to values, or ``None``) with every list, tuple and array
    value a tuple (a cache key; :func:`~bikemass.scenario.inputs.set_path` writes it as a list), the
    stiffness choice as given; :class:`~bikemass.core.errors.InputTypeError` for anything else than a
    mapping of string keys to numbers, strings, Quantities or sequences of them."""
    if changes is None:
        return {}
    if not isinstance(changes, Mapping):
        raise wrong_type("changes", changes, "changes are a mapping {dotted key: value}")
    out = {}
    for key, value in changes.items():
        if not isinstance(key, str):
            raise wrong_type("changes", key, "a change's key is a dotted path (str)")
        out[key] = value if key == STIFFNESS_KEY else _frozen_value(key, value)
    return out


def _frozen_value(key, value):
    """A change's value as a cache key: sequences (lists, tuples, arrays) as tuples, recursively."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return tuple(_frozen_value(key, v) for v in value)
    if isinstance(value, Mapping) or value is None:
        raise wrong_type(key, value, "a number (SI), a string with its unit, or a list of them")
    return value


def _in_unit(value, unit, source, key):
    """``value`` (a number in ``unit``, a Quantity or ``"<number> <unit>"``) of the dimension of ``unit`` as a
    float in ``unit``; InputError naming ``source`` and ``key`` otherwise."""
    dimension = dimension_of(unit)
    try:
        number = convert(value, dimension, unit, bare_unit=unit)
    except UnitError:
        raise InputError(source, key, f"a number in {unit} (the model's code's unit) or '<number> <unit>' in "
                                      f"another unit of {dimension}, got {short(value)}") from None
    if not np.isfinite(number):
        raise InputError(source, key, f"a finite number ({unit}), got {short(value)}")
    return number


def _hashable(choice):
    """A stiffness choice as a cache key (a matrix by its values)."""
    try:
        hash(choice)
        return choice
    except TypeError:
        return tuple(map(tuple, readonly(choice, float).tolist()))


def parameters(bicycle: BicycleLike, rider: RiderLike = None, combine: Combine | str = Combine.EXACT,
               method: Method | str = Method.MESH, allow_off_contact: bool = False) -> BenchmarkParameters:
    """The Meijaard et al. (2007) benchmark parameter set of a bicycle with a rider.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`load_bicycle` takes.
    rider : str, os.PathLike, Mapping, Rider or None
        Anything :func:`load_rider` takes; ``None`` (default) for no rider.  The rider is
        seated on the bicycle (:func:`seated_rider`): a contact off the bicycle is an error
        unless ``allow_off_contact``.
    combine : {"exact", "thesis"}
        Rider + frame body: parallel-axis theorem (``exact``, default) or the thesis's
        Eq. 3.6 (central inertias added), see :class:`~bikemass.Combine`.
    method : {"mesh", "exact"}
        Mass properties from trimesh meshes (default) or closed-form solids.
    allow_off_contact : bool
        Use a pose as written even where it misses the saddle, grips or pedals by more than
        1 mm (the gaps are warned about); by default such a pose is re-seated by its posture.

    Returns
    -------
    BenchmarkParameters
        Immutable; the 26 values as attributes (``p.w`` in m, ``p.lam`` in rad, ``p.IBxx``
        in kg m^2, ...) and ``p.to_dict()`` as plain floats.  A parameter file without a
        rider returns its own values exactly.

    Raises
    ------
    InputError
        Bad bicycle or rider (see :func:`load_bicycle`, :func:`load_rider`), a rider that
        cannot be seated, a bicycle that already holds a rider, or an unknown ``combine`` or
        ``method``.

    See Also
    --------
    stability : Critical speeds and stable ranges of the parameter set.
    stiffness : The rear frame's stiffness to analyse it with.
    BenchmarkParameters : The 26 values.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")                  # Meijaard et al. (2007), Table 1
    >>> print(p.w, p.c, round(p.lam, 6), p.mB)
    1.02 0.08 0.314159 85.0
    >>> p = bm.parameters("jamis", "relaxed")
    >>> thesis = bm.parameters("jamis", "relaxed", combine="thesis")
    >>> print(f"mB {p.mB:.3f} kg, IBxx {p.IBxx:.3f} kg m^2 (the thesis's Eq. 3.6: {thesis.IBxx:.3f})")
    mB 86.707 kg, IBxx 14.464 kg m^2 (the thesis's Eq. 3.6: 12.281)
    """
    return Scenario(bicycle, rider, combine=combine, method=method, allow_off_contact=allow_off_contact).parameters()


def model_signals(model):
    """``(inputs, outputs)``: the ``(name, unit)`` of every input and every output (the states, then
    any further outputs) of the linear model :meth:`Scenario.build` builds for ``model`` (a name or a
    :class:`~bikemass.models.registry.ModelChoice`), read from the code without parameters: the
    Whipple bicycle's from :mod:`bikemass.models.whipple` (front-lateral beyond its states), a
    member combination's from its generated module (every coordinate free)."""
    choice = parse_model(model)
    if not choice.members:
        states = (*whipple.COORDINATES, *whipple.RATES, *whipple.KINEMATIC, *whipple.FURTHER_OUTPUTS)
        return tuple((s.name, s.unit) for s in whipple.INPUTS), tuple((s.name, s.unit) for s in states)
    code = generated(choice)
    return tuple(code.INPUTS), tuple(code.STATES)
