"""What a member of the model family declares: :class:`Member`, and the run-time protocol of its package.

A member is one package under ``bikemass/models/members/<name>/``:

- ``__init__.py`` holds ``MEMBER``, a :class:`Member`: its ``--model`` name, what it adds and needs,
  where a scenario finds its parameters, and the keyword and option that give them.  It imports
  nothing heavy: the command line's help reads it.
- ``parameters.py`` holds its typed parameter value; ``runtime.py`` the run-time protocol (module-level
  functions, each optional unless said):

  ``coerce(given, source)``
      The typed value of ``given`` (the value itself, a file path, a mapping in the file's form, or
      ``None`` for the default; :class:`~bikemass.core.errors.InputError` naming ``source`` when there
      is no default).  Required.
  ``values(typed, base)``
      ``{name: float}`` of the generated code's parameters the member sets, given the values so far
      (``base``: the 26 benchmark names and earlier members').  Required.
  ``held(typed)``
      The coordinates the member holds at zero (removed from the model); default none.
  ``read_block(node)`` / ``write_block(typed)``
      Its block in a parameter file (the key is the member's name): read from a config
      :class:`~bikemass.core.config.Node`, written as plain data.
  ``forearms_held(typed)``
      Whether the rider's forearms move with the front frame (the seated rider is posed again).
  ``check_hands(typed, gap, rider_in_set=False)``
      Warnings for a member that acts through the rider's hands: ``gap`` is how far (m) the seated
      rider's hand furthest from a grip is (``inf`` where not known), ``None`` without a seated rider;
      ``rider_in_set`` whether the parameter set holds the rider (the benchmark's).
  ``INPUTS``
      ``{name: dotted path}``: the generated code's parameters that are inputs of a scenario (changed by
      ``Scenario.build({name: value})``, and so swept, drawn, differentiated through the builder and
      optimised), each the path of the field of the typed value that holds it (``"front.cornering_coefficient"``
      for ``CaF``); the typed value checks a changed one as it checks its own (:func:`with_inputs`).
      Default none.
  ``PARAMETERS`` and ``transform(values, code, E, A, B)``
      Only for a member without a derivation (``derived=False``): the parameters it adds
      ((name, unit, description)) and how it changes the descriptor form ``E x' = sum_k v**k A[k] x + B u``
      of the combination it joins (``code`` the generated module: its ``STATES``, ``INPUTS``).

- ``derivation.py`` (``derived=True``) holds its :class:`~bikemass.models.derive.bicycle.Member`
  subclass for the derivation (needs sympy; only ``python -m bikemass.models.derive`` imports it).

The members are registered, in their canonical order, in :data:`bikemass.models.members.PACKAGES`.
"""

import dataclasses
import importlib
from dataclasses import dataclass
from enum import Enum

from ...core.errors import InputError


class Source(str, Enum):
    """Where a scenario finds a member's parameters."""

    OPTION = "option"
    """Its keyword (``Scenario(..., <keyword>=...)``, the command line's option, a spec's key) or its
    block in a parameter file; the member's default without either."""
    RIDER_SPLIT = "rider-split"
    """The seated rider split at the hips (or the bicycle's own parameter set of the member's type)."""
    BEAM_MODELS = "beam-models"
    """The bicycle's beam models in the scenario's stiffness choice (a material)."""


@dataclass(frozen=True)
class Member:
    """One member of the model family (module docstring).

    Attributes
    ----------
    name : str
        As ``--model`` writes it (``"tyre"``); also the key of its block in a parameter file.
    summary : str
        What it adds, a phrase (the command line's help, the web page's note).
    package : str
        Its package's dotted name (``__name__`` in its ``__init__.py``).
    needs : str
        What a scenario must give it, a phrase; empty when nothing.
    source : Source
        Where a scenario finds its parameters.
    keyword : str or None
        The scenario's and the analyses' keyword of its parameters (``tyres=``), also a sweep's and an
        optimisation's spec key; ``None`` when it takes none.
    option : str or None
        The command line's option of its parameter file (``--tyres``), with ``option_help``.
    attribute : str or None
        The attribute of a built scenario that holds its typed parameters (``built.tyres``).
    takes_stiffness : bool
        Whether the scenario's stiffness choice is its input (a material; then the Whipple model's
        quasi-static spring is not used).
    derived : bool
        Whether it has a derivation (new coordinates or forces: generated code for every combination
        with it) or changes the equations of the combination it joins (``transform``).
    """

    name: str
    summary: str
    package: str
    needs: str = ""
    source: Source = Source.OPTION
    keyword: str | None = None
    option: str | None = None
    option_help: str = ""
    attribute: str | None = None
    takes_stiffness: bool = False
    derived: bool = True

    def runtime(self):
        """Its ``runtime`` module: the run-time protocol (module docstring)."""
        return importlib.import_module(f"{self.package}.runtime")

    def hook(self, name, default=None):
        """The protocol function ``name`` of :meth:`runtime`, or ``default`` where the member has none."""
        return getattr(self.runtime(), name, default)

    def derivation(self):
        """Its derivation's :class:`~bikemass.models.derive.bicycle.Member` class (imports sympy)."""
        module = importlib.import_module(f"{self.package}.derivation")
        return module.DERIVATION


def with_inputs(typed, changes, inputs, source="changes"):
    """``typed`` (a member's frozen typed value) with each of ``changes`` (``{name: float}``, SI) put in the field
    ``inputs[name]`` names (a dotted path through nested frozen dataclasses), all the changes of one part at once
    (so that its checks see the part as asked for, not a half-changed one); the typed value's own checks run
    on the result; :class:`~bikemass.core.errors.InputError` naming ``source`` and a change's name for a value
    the member refuses or a field it does not have (a held compliance)."""
    tree = {}
    for name, value in changes.items():
        *parents, leaf = inputs[name].split(".")
        node = tree
        for part in parents:
            node = node.setdefault(part, {})
        node[leaf] = (name, value)
    try:
        return _replaced(typed, tree)
    except InputError as exc:
        named = [n for n in changes if inputs[n].rsplit(".", 1)[-1] == exc.key]
        raise InputError(source, named[0] if named else ", ".join(changes), exc.expected) from None


def _replaced(obj, tree):
    """``obj`` with the fields of ``tree`` (``{field: (name, value)}`` or ``{field: subtree}``) replaced at once."""
    if obj is None:
        raise InputError("member", next(iter(tree)), "a part the model has (this one is held: infinitely stiff)")
    return dataclasses.replace(obj, **{field: _replaced(getattr(obj, field), sub) if isinstance(sub, dict) else sub[1]
                                       for field, sub in tree.items()})
