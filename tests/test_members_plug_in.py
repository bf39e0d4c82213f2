"""Members of the model family plug in as packages (``bikemass/models/members/<name>/``).

- No module of ``src/bikemass`` outside the member packages (and the generated code) names a member:
  the source is read and every string that is a model name is looked for.
- A toy fourth member, a steering damper, added to a temporary copy of the package as one package plus
  one registration line: ``bikemass stability benchmark --model <it>`` then works, its option comes from
  its declaration, and its critical speeds equal an independent route (the Whipple bicycle's canonical
  matrices with the damper added to ``C``, eigenvalues by LAPACK and brentq on the largest real part).
"""

import ast
import json
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import bikemass
from bikemass.core.paths import data_root
from bikemass.models.canonical import canonical_matrices
from bikemass.models.members import MEMBERS, PACKAGES
from bikemass.models.registry import SPECS

SRC = Path(bikemass.__file__).resolve().parent
OUTSIDE = ("models/members/", "models/generated/")
"""Where members may be named: their own packages, and the code generated per combination."""


def _names_a_member(text, names):
    """Whether a string constant is a member's name or a combination with one (``tyre+flexible``); prose
    (anything with whitespace) is not a name."""
    if not text or any(c.isspace() for c in text):
        return False
    return any(part in names for part in text.split("+"))


def _hits(root, names):
    found = []
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        if rel.startswith(OUTSIDE):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and _names_a_member(node.value, names):
                found.append(f"{rel}:{node.lineno}: {node.value!r}")
    return found


def test_no_module_outside_the_member_packages_names_a_member():
    names = {spec.name for spec in SPECS}
    assert names == {"rider-lean", "tyre", "flexible", "arms"}        # the scan looks for the real names
    assert _hits(SRC, names) == []


def test_the_scan_finds_a_member_named_in_code(tmp_path):
    (tmp_path / "generic.py").write_text('def f(choice):\n    return choice.has("tyre") or x == "rider-lean+arms"\n')
    (tmp_path / "prose.py").write_text('"""The tyre member adds tyres."""\n')
    assert _hits(tmp_path, {"tyre", "rider-lean", "arms"}) == ["generic.py:2: 'tyre'", "generic.py:2: 'rider-lean+arms'"]


def test_the_registry_is_the_member_packages():
    assert tuple(spec.name for spec in SPECS) == tuple(m.name for m in MEMBERS)
    for package, spec in zip(PACKAGES, MEMBERS):
        assert spec.package == f"bikemass.models.members.{package}"
        runtime = spec.runtime()
        assert callable(runtime.coerce) and callable(runtime.values)
        if spec.derived:
            assert spec.derivation().__name__          # its derivation hook is found (imports sympy)


# -- a toy fourth member ---------------------------------------------------------------------------------
DAMPER_INIT = '''
"""A steering damper: a torque -c delta' between the front and rear frames about the steer axis."""

from ..spec import Member, Source

MEMBER = Member(
    name="steering-damper", package=__name__, source=Source.OPTION, keyword="damper", option="--damper",
    attribute="damper", derived=False, summary="a steering damper",
    option_help="damper file: damping (N m s/rad); default 1 N m s/rad")
'''
DAMPER_PARAMETERS = '''
"""The steering damper's parameter."""

from dataclasses import dataclass


@dataclass(frozen=True)
class Damper:
    damping: float = 1.0
'''
DAMPER_RUNTIME = '''
"""The steering damper's run-time protocol: it acts through the steer-torque input of any combination."""

import numpy as np
import yaml

from .parameters import Damper

PARAMETERS = (("c_damper", "N m s/rad", "steering damper"),)


def coerce(given, source="damper"):
    if given is None:
        return Damper()
    if isinstance(given, Damper):
        return given
    with open(given, encoding="utf-8") as f:
        return Damper(float(yaml.safe_load(f)["damping"]))


def values(typed, base):
    return {"c_damper": typed.damping}


def transform(values, code, E, A, B):
    rate = [n for n, _ in code.STATES].index("steer-rate")
    torque = [n for n, _ in code.INPUTS].index("steer-torque")
    A = np.array(A, dtype=np.result_type(A, values["c_damper"]))
    degrees = B.shape[-3]                      # B's powers of the speed (A has as many or more)
    A[..., :degrees, :, rate] -= np.asarray(values["c_damper"])[..., None, None] * B[..., :, :, torque]
    return E, A, B
'''


@pytest.fixture(scope="module")
def with_damper(tmp_path_factory):
    """A copy of the package with the toy member: its package and one registration line."""
    root = tmp_path_factory.mktemp("plugin")
    copy = root / "bikemass"
    shutil.copytree(SRC, copy, ignore=shutil.ignore_patterns("__pycache__"))
    package = copy / "models" / "members" / "steering_damper"
    package.mkdir()
    for name, text in (("__init__", DAMPER_INIT), ("parameters", DAMPER_PARAMETERS), ("runtime", DAMPER_RUNTIME)):
        (package / f"{name}.py").write_text(textwrap.dedent(text).lstrip(), encoding="utf-8")
    registry = copy / "models" / "members" / "__init__.py"
    text = registry.read_text(encoding="utf-8")
    assert text.count('    "arms",\n') == 1
    registry.write_text(text.replace('    "arms",\n', '    "arms",\n    "steering_damper",\n'), encoding="utf-8")
    return root


def _run(root, *args):
    env = {**os.environ, "PYTHONPATH": str(root), "BIKEMASS_DATA": str(data_root())}   # the data stay where they are
    command = "import sys; from bikemass.cli.main import main; sys.exit(main(sys.argv[1:]))"
    return subprocess.run([sys.executable, "-c", command, *args], capture_output=True, text=True, env=env,
                          cwd=root, timeout=300)


def _reference_crossings(damping):
    """Speeds (m/s) where the benchmark with ``damping`` (N m s/rad) added to C's steer entry changes
    stability: LAPACK eigenvalues of the 4x4 state matrix, the largest real part's sign changes on a
    0.01 m/s grid, each polished by brentq."""
    m = canonical_matrices(bikemass.parameters("benchmark"))
    Minv = np.linalg.inv(m.M)

    def growth(v):
        C = v * m.C1 + np.diag([0.0, damping])
        K = m.g * m.K0 + v ** 2 * m.K2
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ K, -Minv @ C]])
        return np.linalg.eigvals(A).real.max()

    grid = np.arange(0.01, 15.0, 0.01)
    signs = np.sign([growth(v) for v in grid])
    return [brentq(growth, grid[i], grid[i + 1], xtol=1e-14) for i in np.flatnonzero(signs[:-1] != signs[1:])]


@pytest.mark.slow
@pytest.mark.parametrize("damping", [None, 2.5])
def test_a_toy_fourth_member_plugs_in_with_one_package_and_one_line(with_damper, tmp_path, damping):
    args = ["stability", "benchmark", "--model", "steering-damper", "--format", "json"]
    if damping is not None:
        path = tmp_path / "damper.yaml"
        path.write_text(f"damping: {damping}\n", encoding="utf-8")
        args += ["--damper", str(path)]
    done = _run(with_damper, *args)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    crossings = _reference_crossings(1.0 if damping is None else damping)
    assert result["model"] == "steering-damper"
    assert len(crossings) == 2                       # stable between the weave and the capsize speed
    assert result["weave_speeds"] == pytest.approx([crossings[0]], abs=1e-9)
    assert result["capsize_speeds"] == pytest.approx([crossings[1]], abs=1e-9)


@pytest.mark.slow
def test_the_toy_members_option_and_name_reach_the_help_and_the_checks(with_damper):
    done = _run(with_damper, "stability", "--help")
    assert done.returncode == 0 and "--damper" in done.stdout and "steering-damper" in done.stdout
    done = _run(with_damper, "stability", "benchmark", "--model", "tyre+steering-damper", "--format", "json")
    assert done.returncode == 0, done.stderr
    done = _run(with_damper, "stability", "benchmark", "--damper", "x.yaml")
    assert done.returncode == 2 and "steering-damper member" in done.stderr and "Traceback" not in done.stderr
