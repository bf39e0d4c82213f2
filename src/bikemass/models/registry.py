"""The model family's names: ``--model`` strings to member combinations and back."""

import os
from dataclasses import dataclass

from ..core.errors import InputError, short
from .members import MEMBERS as MEMBERS_DECLARED

BASE = "whipple"
"""The Whipple bicycle of Meijaard et al. (2007): every member extends it."""


SPECS = MEMBERS_DECLARED
"""Every member's :class:`~bikemass.models.members.spec.Member`, in the canonical order of a combination's
name (:data:`bikemass.models.members.PACKAGES`): the one place the command line's options and help, the
scenario, the sweeps, the exports and the web page take the members from."""
MEMBERS = tuple(spec.name for spec in SPECS)
"""Every member's name, in the canonical order of a combination's name."""
BY_NAME = {spec.name: spec for spec in SPECS}
"""Member name -> its :class:`~bikemass.models.members.spec.Member`."""
KEYWORDS = tuple(spec.keyword for spec in SPECS if spec.keyword)
"""The members' keywords (``tyres``, ``arms``): a scenario's, an analysis's, a spec's top-level keys."""
BY_KEYWORD = {key: spec for spec in SPECS for key in (spec.keyword, spec.attribute) if key}
"""A member's keyword or built attribute (``tyres``, ``compliances``) -> its
:class:`~bikemass.models.members.spec.Member`."""


def by_keyword(given, source="members"):
    """``{member name: value}`` of ``{keyword: value}`` (each key a member's name, its keyword or its
    attribute: ``tyres``, ``compliances``); ``None`` values left out; InputError for an unknown key."""
    out = {}
    for key, value in given.items():
        spec = BY_NAME.get(key) or BY_KEYWORD.get(key)
        if spec is None:
            known = sorted({k for s in SPECS for k in (s.name, s.keyword, s.attribute) if k})
            raise InputError(source, key, f"a member's parameters by its name or keyword: {', '.join(known)}")
        if value is not None:
            out[spec.name] = value
    return out


def model_help():
    """One paragraph naming the Whipple bicycle and every member, with what each adds and needs."""
    parts = [f"{s.name} ({s.summary}" + (f"; needs {s.needs}" if s.needs else "")
             + (f"; {s.option} FILE" if s.option else "") + ")" for s in SPECS]
    return (f"{BASE} (default: Meijaard et al. 2007; with --stiffness other than infinite, the thesis's "
            f"quasi-static flexible rear frame), {', '.join(parts)}, or members joined by + "
            f"(e.g. {SPECS[0].name}+{SPECS[1].name})")


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

    @property
    def specs(self):
        """The :class:`~bikemass.models.members.spec.Member` of each member on, in canonical order."""
        return tuple(BY_NAME[m] for m in self.members)

    def with_member(self, member):
        """The combination with ``member`` added (its canonical name: what an error suggests)."""
        return parse_model("+".join((*self.members, member)))


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
    :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters`), else the Whipple bicycle."""
    if model is not None:
        return parse_model(model, source)
    return parse_model(getattr(type(params), "MODEL", BASE), source)


def module_name(members):
    """The generated module of a combination: ``whipple``, ``rider_lean``, ``tyre``, ``rider_lean_tyre`` (the
    derived members only: one without a derivation changes the equations of the combination it joins)."""
    return "_".join(m.replace("-", "_") for m in members if BY_NAME[m].derived) or BASE


def spec_members(node, near, model=None):
    """``((keyword, path), ...)``: the members' files a spec's top-level config
    :class:`~bikemass.core.config.Node` names under their keywords (``tyres: tyres.yaml``), each path made
    relative to the spec by ``near(text)``, read once here (a bad file is its own error, naming its key)
    and, where ``model`` (the spec's, a name) is given, refused under a model without the member (the
    spec's key named, before any configuration is built)."""
    out = []
    for key in KEYWORDS:
        if not node.has(key):
            continue
        spec, path = BY_KEYWORD[key], near(node[key].string())
        if model is not None and not parse_model(model).has(spec.name):
            node[key].fail(f"a model with the {spec.name} member (model: "
                           f"{parse_model(model).with_member(spec.name).name}); model: {model} has none")
        if not os.path.isfile(path):
            node[key].fail(f"the path of an existing {spec.name} file (no file {path})")
        spec.runtime().coerce(path, key)              # a bad file: its own error, naming its key
        out.append((key, path))
    return tuple(out)


def spec_model(node):
    """The ``model:`` of a spec's top-level config :class:`~bikemass.core.config.Node` (a sweep's, an
    optimisation's) as its canonical name, ``whipple`` without one; InputError naming the key."""
    if not node.has("model"):
        return BASE
    try:
        return parse_model(node["model"].string()).name
    except InputError as exc:
        node["model"].fail(exc.expected)
