"""The API reference, generated from ``bikemass.__all__`` when the build starts.

Every public name gets a page ``api-reference/<name>.rst`` (autodoc with numpydoc: the typed signature,
Parameters, Returns, Raises, See Also, Examples) and a row in ``api-reference/index.rst``, grouped in the
sections of :data:`SECTIONS`; a name that no section lists lands in "Other names", so a name added
to ``__all__`` is documented without touching this file. The pages are written into the source
folder (git ignores ``docs/api-reference/``) and only when their text changes, so that an unchanged
build reads nothing again.
"""

import enum
import inspect
import re
from pathlib import Path

from sphinx.pycode import ModuleAnalyzer

import bikemass

FOLDER = "api-reference"
"""Where the pages go, relative to the source folder (not ``reference/``: that name is the repository's
folder of the thesis's tables)."""

SECTIONS = {
    "Bicycles, riders and their parameters": [
        "load_bicycle", "load_rider", "parameters", "stiffness", "seated_rider", "pose_rider", "geometry_chart",
        "load_parameter_text", "load_parameter_set", "Bicycle", "Rider", "PosedRider", "BenchmarkParameters",
        "MeasuredParameters", "ParameterSetFile", "RiderLeanParameters", "PARAMETER_NAMES"],
    "Stability": ["stability", "eigenvalues", "matrices", "speeds", "linear_model", "StabilityResult", "LinearModel"],
    "The frame's beam finite elements": ["frame_stiffness", "frame_modes", "frame_structure"],
    "Sensitivity, uncertainty and sweeps": ["sensitivity", "geometry_sensitivity", "uncertainty", "sweep"],
    "Handling": ["transfer_function", "frequency_response", "simulate", "mode_shapes", "handling", "lane_change",
                 "Gains"],
    "Figures": ["plot_eigenvalues", "plot_critical_speeds", "plot_side_view", "plot_pose", "plot_chart",
                "plot_frame_modes", "plot_bode", "plot_time_response", "plot_mode_shapes", "plot_handling",
                "plot_lane_change", "save_figure"],
    "Choices": ["Combine", "Method", "Overlap", "Procedure", "Beam", "Source", "Support", "MaterialName", "Grip",
                "EigenPart", "Format"],
    "Errors and warnings": ["InputError", "BikemassWarning", "ParameterFileWarning"],
    "The package": ["__version__"],
}
"""Section title -> the names it lists, in reading order."""

OTHER = "Other names"


def sections(names):
    """``[(title, [name, ...])]``: :data:`SECTIONS` restricted to ``names``, then the names no section lists."""
    listed = {n for members in SECTIONS.values() for n in members}
    out = [(title, [n for n in members if n in names]) for title, members in SECTIONS.items()]
    rest = [n for n in names if n not in listed]
    return [(t, m) for t, m in out + [(OTHER, rest)] if m]


def attribute_doc(name):
    """The docstring written under a module-level assignment (``NAME = ...`` then a string) of the
    module that defines public ``name``, or ``""``."""
    module = "bikemass" if name == "__version__" else f"bikemass.{bikemass._API[name]}"
    attribute = bikemass._RENAMED.get(name, name)
    docs = ModuleAnalyzer.for_module(module).find_attr_docs()
    return "\n".join(docs.get(("", attribute), [])).strip()


def kind(value):
    """How autodoc documents a public value: ``function``, ``exception``, ``enum``, ``class`` or ``data``."""
    if inspect.isclass(value):
        if issubclass(value, BaseException):
            return "exception"
        return "enum" if issubclass(value, enum.Enum) else "class"
    return "function" if callable(value) else "data"


def summary(name, value):
    """The first paragraph of ``value``'s docstring on one line (its numpydoc short summary)."""
    doc = attribute_doc(name) if kind(value) == "data" else inspect.getdoc(value) or ""
    return " ".join(doc.split("\n\n")[0].split())


def own_members(cls):
    """``None`` (every documented member) for a class whose public attributes are all bikemass's; for one
    that carries a library's generated members (a matplotlib Figure's ``set``), the names of bikemass's own
    public methods and properties only (the library documents its own)."""
    def ours(member):
        target = member.fget if isinstance(member, property) else member
        return getattr(target, "__module__", "bikemass").startswith("bikemass")
    public = {n: m for n, m in vars(cls).items() if not n.startswith("_") and callable(getattr(m, "fget", m))}
    if all(ours(m) for m in public.values()):
        return None
    return sorted(n for n, m in public.items() if ours(m))


def page(name, value):
    """The reST of the reference page of public ``name``."""
    target = f"bikemass.{name}"
    title = f"``{target}``"
    head = f"{title}\n{'=' * len(title)}\n\n"
    what = kind(value)
    if what == "function":
        return head + f".. autofunction:: {target}\n"
    if what == "exception":
        return head + f".. autoexception:: {target}\n   :members:\n"
    if what == "enum":
        return head + f".. autoclass:: {target}\n   :members:\n   :undoc-members:\n   :member-order: bysource\n"
    if what == "class":
        own = own_members(value)
        if own is None:
            return head + f".. autoclass:: {target}\n   :members:\n"
        return head + f".. autoclass:: {target}\n" + (f"   :members: {', '.join(own)}\n" if own else "   :no-members:\n")
    body = "\n".join("   " + line if line else "" for line in attribute_doc(name).splitlines())
    return head + f".. py:data:: {target}\n   :type: {type(value).__name__}\n   :value: {value!r}\n\n{body}\n"


def index(groups, values):
    """The reST of the reference's front page: one table per section, a hidden toctree of every page."""
    lines = ["API reference", "=============", "",
             "Every name of ``import bikemass as bm`` (``bikemass.__all__``), one page each. All quantities",
             "are SI (m, kg, s, rad, N) in the benchmark frame of Meijaard et al. (2007); see",
             "``bikemass.core.convention``.", ""]
    for title, names in groups:
        lines += [title, "-" * len(title), "", ".. list-table::", "   :widths: 30 70", ""]
        for name in names:
            role = "py:data" if kind(values[name]) == "data" else "py:obj"
            lines += [f"   * - :{role}:`bm.{name} <bikemass.{name}>`", f"     - {summary(name, values[name]) or ' '}"]
        lines.append("")
    lines += [".. toctree::", "   :hidden:", ""] + [f"   {name}" for _, names in groups for name in names]
    return "\n".join(lines) + "\n"


def _write(path, text):
    """Write ``text`` to ``path`` unless the file holds it already (no needless re-reads)."""
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def generate(app):
    """Write the reference pages (Sphinx's ``builder-inited`` event)."""
    names = list(bikemass.__all__)
    values = {name: getattr(bikemass, name) for name in names}
    folder = Path(app.srcdir) / FOLDER
    folder.mkdir(exist_ok=True)
    wanted = {f"{name}.rst": page(name, values[name]) for name in names}
    wanted["index.rst"] = index(sections(names), values)
    for stale in folder.glob("*.rst"):
        if stale.name not in wanted:
            stale.unlink()
    for filename, text in wanted.items():
        _write(folder / filename, text)


ALIAS = re.compile(r"TypeAliasForwardRef\('([\w.]+)'\)")
"""How Sphinx 9 prints a name of ``autodoc_type_aliases`` inside a union (``TypeAliasForwardRef('ArrayLike')``)."""


def aliases_by_name(app, what, name, obj, options, signature, return_annotation):
    """A signature with each type alias shown by its name (``ArrayLike | None``), the union it
    stands for left out (Sphinx's ``autodoc-process-signature`` event)."""
    def shown(text):
        return ALIAS.sub(r"\1", text) if text else text
    return shown(signature), shown(return_annotation)


def setup(app):
    app.connect("builder-inited", generate)
    app.connect("autodoc-process-signature", aliases_by_name)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
