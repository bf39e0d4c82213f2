"""The model family's names: ``--model`` strings to member combinations and back."""

from dataclasses import dataclass

from ..core.errors import InputError, short

BASE = "whipple"
"""The Whipple bicycle of Meijaard et al. (2007): every member extends it."""
MEMBERS = ("rider-lean", "tyre", "flexible", "arms")
"""Every member of the family, in the canonical order of a combination's name."""


@dataclass(frozen=True)
class ModelChoice:
    """A member combination: ``members`` in canonical order (empty for the Whipple bicycle)."""

    members: tuple = ()

    @property
    def name(self):
        """``"whipple"``, ``"rider-lean"``, ..., ``"rider-lean+tyre"``."""
        return "+".join(self.members) or BASE

    def has(self, member):
        """Whether ``member`` is on."""
        return member in self.members


def parse_model(text, source="model"):
    """The :class:`ModelChoice` of ``text`` (``"whipple"``, ``"tyre+rider-lean"``, ...; order does not
    matter, ``whipple`` may be named alongside); :class:`~bikemass.core.errors.InputError` naming the
    choices for anything else."""
    if isinstance(text, ModelChoice):
        return text
    choices = f"{BASE}, {', '.join(MEMBERS)}, or members joined by '+' (e.g. rider-lean+tyre)"
    if not isinstance(text, str) or not text.strip():
        raise InputError(source, short(text) or "(empty)", f"a model name: {choices}")
    names = [part.strip() for part in text.split("+")]
    for name in names:
        if name != BASE and name not in MEMBERS:
            raise InputError(source, short(text), f"unknown model {name!r}: one of {choices}")
        if names.count(name) > 1:
            raise InputError(source, short(text), f"{name!r} given twice in {text!r}")
    return ModelChoice(tuple(m for m in MEMBERS if m in names))


def model_of(params, model=None, source="model"):
    """The :class:`ModelChoice` to build from the parameter set ``params``: ``model`` when given, else
    the one its type declares (a class attribute ``MODEL``: ``"rider-lean"`` for
    :class:`~bikemass.models.lean.RiderLeanParameters`), else the Whipple bicycle."""
    if model is not None:
        return parse_model(model, source)
    return parse_model(getattr(type(params), "MODEL", BASE), source)


def module_name(members):
    """The generated module of a combination: ``whipple``, ``rider_lean``, ``tyre``, ``rider_lean_tyre``."""
    return "_".join(m.replace("-", "_") for m in members) or BASE


def spec_model(node):
    """The ``model:`` of a spec's top-level config :class:`~bikemass.core.config.Node` (a sweep's, an
    optimisation's) as its canonical name, ``whipple`` without one; InputError naming the key."""
    if not node.has("model"):
        return BASE
    try:
        return parse_model(node["model"].string()).name
    except InputError as exc:
        node["model"].fail(exc.expected)
