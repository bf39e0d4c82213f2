"""The layout shows the layers, and holds: the import graph of ``src/bikemass``, read from the
source, has no cycle, no import of a higher layer and none between two packages of one layer;
nothing but the facade sits at the package's root; every import inside a function says why it is
there.

Every import counts, those inside functions too (a lazy import hides a cycle, it does not remove
it).  Importing ``a.b.c`` also runs the package ``a.b``'s ``__init__``, so that is an edge too
(except for the importer's own packages, which are running already).  A module may import from its
own package and from packages of a lower rank (README.md, "Layout").  Imports by name through
``importlib`` are not seen; the three that exist say in a table what they load: the facade's
``_API``, ``fe/__init__``'s ``_LAZY`` and the command line's ``COMMAND_MODULES``.
"""

import ast
import sys
from functools import lru_cache
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"

RANKS = {
    "core": 0,        # plumbing: units, convention, errors, config, gate, output, paths, choices, ...
    "mass": 1,        # solids, parts, inertia, placement, sections, materials, tubes
    "models": 2,      # the benchmark parameters, canonical matrices, linear models, plausibility
    "fe": 3,          # beam finite elements of the rear frame
    "bicycle": 3,     # bicycles from YAML -> parts and parameters
    "rider": 4,       # riders: bodies, poses, chains, seating on a bicycle
    "plots": 5,       # figures of loaded objects and results
    "scenario": 6,    # names, files and mappings -> loaded bicycles, riders, parameters, stiffness
    "analysis": 7,    # stability, sensitivity, uncertainty
    "study": 8,       # the thesis study
    "sweep": 8,       # design sweeps
    "design": 8,      # design by optimisation
    "web": 9,         # the web page (a shell)
    "cli": 10,        # the command line (a shell; bikemass serve starts the web page)
}
"""Package (under ``bikemass``) -> layer: a module imports only from its own package and from lower ranks."""

ROOT_MODULES = {"__init__", "__main__"}
"""The only modules allowed at ``src/bikemass/``: the facade (``bm.*``) and ``python -m bikemass``."""

FROM_THE_FACADE = {"__version__"}
"""The only names a module may import from the facade (``bikemass/__init__.py``) itself."""

LAZY_MARK = "# lazy:"
"""What the comment on (or just above) an import inside a function starts with."""


def module_name(path, src):
    parts = list(path.relative_to(src).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules(src):
    """``{dotted name: path}`` of every module under ``src/bikemass``."""
    return {module_name(p, src): p for p in sorted((src / "bikemass").rglob("*.py"))}


@lru_cache(maxsize=None)
def parsed(path):
    """(source lines, syntax tree) of a module."""
    text = path.read_text(encoding="utf-8")
    return text.splitlines(), ast.parse(text, str(path))


def imports(name, path, known):
    """``[(target module, imported names or None, line, inside a function)]`` of one module: every
    ``import``/``from ... import`` of a bikemass module, at any depth."""
    tree = parsed(path)[1]
    package = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
    inside = {id(n) for f in ast.walk(tree) if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))
              for n in ast.walk(f) if n is not f}
    found = []
    for node in ast.walk(tree):
        lazy = id(node) in inside
        if isinstance(node, ast.Import):
            found += [(a.name, None, node.lineno, lazy) for a in node.names if a.name.split(".")[0] == "bikemass"]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package[:len(package) - node.level + 1] + ([node.module] if node.module else []))
            if base.split(".")[0] != "bikemass":
                continue
            names = [a.name for a in node.names if f"{base}.{a.name}" not in known]
            found += [(f"{base}.{a.name}", None, node.lineno, lazy) for a in node.names if f"{base}.{a.name}" in known]
            if names:
                found.append((base, names, node.lineno, lazy))
    return found


def graph(src):
    """``{module: {imported module: first line}}``, package ``__init__`` modules that run included."""
    known = modules(src)
    edges = {m: {} for m in known}
    for name, path in known.items():
        for target, _, line, _ in imports(name, path, known):
            parts = target.split(".")
            for i in range(2, len(parts) + 1):
                step = ".".join(parts[:i])
                own = name == step or name.startswith(step + ".")
                if step in known and step != name and (i == len(parts) or not own):
                    edges[name].setdefault(step, line)
    return edges


def package_of(name):
    """The top-level package (under ``bikemass``) of a module; ``""`` for the facade and root modules."""
    parts = name.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] not in ROOT_MODULES) else ""


def root_modules(src):
    return sorted(p.stem for p in (src / "bikemass").glob("*.py") if p.stem not in ROOT_MODULES)


def unranked_packages(src):
    return sorted(p.name for p in (src / "bikemass").iterdir()
                  if (p / "__init__.py").is_file() and p.name not in RANKS)


def wrong_way(src):
    """Every import of a higher or same-rank other package, or of the facade (``module:line -> target``)."""
    known = modules(src)
    bad = []
    for name, path in known.items():
        home = package_of(name)
        for target, names, line, _ in imports(name, path, known):
            there = package_of(target)
            if target == "bikemass":
                if names is None or set(names) - FROM_THE_FACADE:
                    bad.append(f"{name}:{line} -> the facade bikemass ({', '.join(names or ['*'])})")
            elif there != home and home in RANKS and there in RANKS and RANKS[there] >= RANKS[home]:
                side = "has the rank of" if RANKS[there] == RANKS[home] else "ranks above"
                bad.append(f"{name}:{line} -> {target} ({there}/ {side} {home}/)")
    return bad


def cycles(src):
    """Every strongly connected set of more than one module (Tarjan), each sorted, with its edges."""
    edges = graph(src)
    index, low, stack, on, found = {}, {}, [], set(), []
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10 * len(edges)))

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                members = set(group)
                found.append(sorted(f"{a}:{edges[a][b]} -> {b}" for a in members for b in edges[a] if b in members))
    for v in edges:
        if v not in index:
            visit(v)
    return sorted(found)


def unexplained_lazy_imports(src):
    """Imports of any module inside a function without a ``# lazy:`` comment on their line or on the
    line above them (one comment may head a run of consecutive imports)."""
    bad = []
    for name, path in modules(src).items():
        lines, tree = parsed(path)
        for f in ast.walk(tree):
            if not isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)):
                continue
            for node in ast.walk(f):
                if node is f or not isinstance(node, (ast.Import, ast.ImportFrom)):
                    continue
                row = node.lineno - 1
                while row > 0 and lines[row - 1].lstrip().startswith(("import ", "from ")):
                    row -= 1                      # the first of a run of imports
                above = lines[row - 1].lstrip() if row > 0 else ""
                marked = LAZY_MARK in lines[node.lineno - 1] or above.startswith(LAZY_MARK)
                if not marked:
                    bad.append(f"{name}:{node.lineno}: {lines[node.lineno - 1].strip()}")
    return sorted(set(bad))


def test_nothing_but_the_facade_sits_at_the_root():
    assert root_modules(SRC) == []


def test_every_package_has_a_layer():
    assert unranked_packages(SRC) == []


def test_no_import_goes_up_or_sideways():
    assert wrong_way(SRC) == []


def test_no_import_cycles():
    assert cycles(SRC) == []


def test_every_lazy_import_says_why():
    assert unexplained_lazy_imports(SRC) == []


def _tree(root, files):
    for name, text in files.items():
        path = root / "bikemass" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


@pytest.fixture
def broken(tmp_path):
    """A package with every fault the checks look for."""
    return _tree(tmp_path, {
        "__init__.py": "",
        "loose.py": "",
        "misc/__init__.py": "",
        "core/__init__.py": "",
        "core/a.py": "def f():\n    from . import b\n",                      # a cycle hidden in a function,
        "core/b.py": "from .a import f\n",                                    # and no comment on the lazy import
        "mass/__init__.py": "",
        "mass/solid.py": "from ..scenario.catalog import load\n",             # upwards
        "fe/__init__.py": "from ..bicycle import model\n",                    # sideways (same rank)
        "bicycle/__init__.py": "",
        "bicycle/model.py": "from .. import __version__\n",                   # allowed
        "scenario/__init__.py": "",
        "scenario/catalog.py": "import bikemass\nload = None\n",               # the facade
        "rider/__init__.py": "from . import seat\n",                          # a cycle below an __init__
        "rider/seat.py": "from ..rider.pose import p\n",
        "rider/pose.py": "from . import seat\np = 1\n",
    })


def test_the_checks_find_each_fault(broken):
    src = broken
    assert root_modules(src) == ["loose"]
    assert unranked_packages(src) == ["misc"]
    assert wrong_way(src) == ["bikemass.fe:1 -> bikemass.bicycle.model (bicycle/ has the rank of fe/)",
                              "bikemass.mass.solid:1 -> bikemass.scenario.catalog (scenario/ ranks above mass/)",
                              "bikemass.scenario.catalog:1 -> the facade bikemass (*)"]
    assert cycles(src) == [["bikemass.core.a:2 -> bikemass.core.b", "bikemass.core.b:1 -> bikemass.core.a"],
                           ["bikemass.rider.pose:1 -> bikemass.rider.seat",
                            "bikemass.rider.seat:1 -> bikemass.rider.pose"]]
    assert unexplained_lazy_imports(src) == ["bikemass.core.a:2: from . import b"]


ASSEMBLY = "state_form"
"""The one function that assembles a state matrix: ``bikemass.models.linear.state_form`` solves a
descriptor form ``E x' = A(v) x + B(v) u`` on E's mass rows (``models.family._state_form`` only
names those rows for the generated code)."""
INVERSES = {
    "bikemass.models.linear": "state_form: the mass matrix, on the descriptor's mass rows",
    "bikemass.models.flexible_static": "the thesis's static stiffness (gK0 + S)^-1: a 2x2 stiffness, no state matrix",
    "bikemass.sweep.vectorised": "the same static stiffness for a sweep chunk's stacked 2x2 (gK0 + S): no state matrix",
    "bikemass.analysis.engine.naming": "left eigenvectors (participation factors)",
    "bikemass.analysis.engine.polynomial": "a speed polynomial made monic after a Moebius shift: no state matrix",
    "bikemass.analysis.engine.crossings": "the quasi-steady fast states of a state matrix whose roots are 1e8 apart "
                                          "(separated_eigenvalues), to verify its crossings",
    "bikemass.analysis.engine.batch": "Newton's method on det A(v) and det(i w I - A(v)) (log-derivatives: "
                                      "traces of their inverses) and participation factors: no state matrix",
    "bikemass.analysis.sensitivity": "left eigenvectors (eigenvalue derivatives)",
    "bikemass.analysis.uncertainty": "left eigenvectors (eigenvalue derivatives)",
    "bikemass.analysis.handling.mode_shapes": "the kinematic states of an eigenvector",
    "bikemass.analysis.handling.tuning": "a loop's transfer function as a modal sum (left eigenvectors)",
    "bikemass.fe.stiffness": "beam stiffness condensation",
    "bikemass.fe.fork": "the fork's beam deflection",
    "bikemass.fe.twist": "the rear frame's beam deflection",
    "bikemass.scenario.frame": "calls the beam model's modal solver, imported as solve",
    "bikemass.fe.elements": "a beam element's shape functions",
    "bikemass.bicycle.measured": "a frame's Ixx, Ixz, Izz from its torsional-pendulum moments (3x3 least squares)",
    "bikemass.models.nonlinear": "the nonlinear bicycle's dependent speeds (the constraints) and its "
                                 "constrained accelerations: no linear state matrix",
}
"""Every module that inverts or solves with a matrix, and what for: a new one must say here why it
is not a second assembly of a state matrix."""


def _calls(node):
    """Names of every function called inside ``node`` (``f(...)`` and ``x.f(...)``)."""
    return {c.func.id if isinstance(c.func, ast.Name) else c.func.attr for c in ast.walk(node)
            if isinstance(c, ast.Call) and isinstance(c.func, (ast.Name, ast.Attribute))}


def state_matrix_builders(src):
    """``(functions that build a LinearModel without state_form, modules inverting a matrix)``."""
    bad, inverting = [], set()
    for name, path in modules(src).items():
        tree = parsed(path)[1]
        if {"inv", "solve", "lstsq", "pinv"} & _calls(tree):
            inverting.add(name)
        for f in ast.walk(tree):
            if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef)) and "LinearModel" in _calls(f):
                if not {ASSEMBLY, f"_{ASSEMBLY}"} & _calls(f):
                    bad.append(f"{name}.{f.name}")
    return sorted(bad), sorted(inverting)


def test_the_state_matrix_is_assembled_in_one_place():
    """Every :class:`~bikemass.models.linear.LinearModel` gets its ``A(v)``, ``B(v)`` from
    :func:`~bikemass.models.linear.state_form`: the Whipple bicycle (``second_order_model``: M, C, K
    as a descriptor form) and every generated member (``models.family.linear_model``) alike; no
    other module inverts a matrix except for the reasons :data:`INVERSES` gives."""
    bad, inverting = state_matrix_builders(SRC)
    assert bad == []
    assert inverting == sorted(INVERSES)


def test_the_state_matrix_check_finds_a_second_assembly(tmp_path):
    src = _tree(tmp_path, {
        "__init__.py": "",
        "models/__init__.py": "",
        "models/other.py": "import numpy as np\ndef make(M, K):\n    A = -np.linalg.inv(M) @ K\n"
                           "    return LinearModel('x', (), 2, (), A, None)\n",
    })
    assert state_matrix_builders(src) == (["bikemass.models.other.make"], ["bikemass.models.other"])
