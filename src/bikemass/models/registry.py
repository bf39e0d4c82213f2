"""The model family's names: ``--model`` strings to member combinations and back."""

from dataclasses import dataclass

from ..core.errors import InputError, short

BASE = "whipple"
"""The Whipple bicycle of Meijaard et al. (2007): every member extends it."""


@dataclass(frozen=True)
class MemberSpec:
    """What the shells say about a member: its ``name`` (as ``--model`` writes it), ``summary`` (what it
    adds, a phrase), ``needs`` (what a scenario must give it, a phrase; empty when nothing) and
    ``option`` (the command-line option of its parameter file, ``None`` without one, with ``option_key``
    the scenario's keyword it fills)."""

    name: str
    summary: str
    needs: str = ""
    option: str | None = None
    option_key: str | None = None


SPECS = (
    MemberSpec("rider-lean", "the rider's upper body leans at the hips against a spring and damper",
               "--rider, or a MooreRiderLean2012 parameter file as BIKE"),
    MemberSpec("tyre", "tyres that slip", "", "--tyres", "tyres"),
    MemberSpec("flexible", "the rear frame twists and the fork bends, stiffness and inertia from the beam models "
               "of the tubes in the --stiffness material (infinite: rigid)"),
    MemberSpec("arms", "the hands on the grips: a spring and damper about the steer axis between the bars and the "
               "upper body", "", "--arms", "arms"),
)
"""Every member of the family, in the canonical order of a combination's name: the one place the
command line's help, its option checks and the web page's note take the members from."""
MEMBERS = tuple(spec.name for spec in SPECS)
"""Every member's name, in the canonical order of a combination's name."""


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
