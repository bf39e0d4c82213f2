"""The public annotations are types: ``typing.get_type_hints`` resolves every annotation of every
function and class of the facade (``bikemass.__all__``, the package ships ``py.typed``), and every
module a public name comes from is on the type checker's list (``pyproject.toml``, ``[tool.mypy]``
``files``; ``.ci/run`` runs ``mypy`` and ``ruff check src`` before the tests)."""

import inspect
import typing
from pathlib import Path

import pytest

import bikemass as bm

ROOT = Path(__file__).resolve().parents[1]
NAMES = [n for n in bm.__all__ if n not in ("__version__", "PARAMETER_NAMES")]


def _annotated(value):
    """``value`` and, for a class, its own public methods and properties (what a user calls)."""
    yield value
    if inspect.isclass(value):
        for name, member in vars(value).items():
            if name.startswith("_") and name != "__init__":
                continue
            if isinstance(member, property):
                member = member.fget
            elif isinstance(member, (staticmethod, classmethod)):
                member = member.__func__
            if inspect.isfunction(member):
                yield member


@pytest.mark.parametrize("name", NAMES)
def test_every_public_annotation_resolves(name):
    value = getattr(bm, name)
    assert inspect.isfunction(value) or inspect.isclass(value), name
    for target in _annotated(value):
        hints = typing.get_type_hints(inspect.unwrap(target))
        if inspect.isfunction(value) and target is value:
            parameters = inspect.signature(value).parameters
            assert set(parameters) - {"self"} <= set(hints), f"bm.{name}: unannotated {set(parameters) - set(hints)}"
            assert "return" in hints, f"bm.{name} has no return annotation"


def test_the_type_checker_reads_every_module_of_the_facade():
    tomllib = pytest.importorskip("tomllib")          # Python >= 3.11; 3.10 checks the same file anyway
    checked = set(tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["mypy"]["files"])
    for name, module in bm._API.items():
        path = ROOT / "src" / "bikemass" / Path(*module.split("."))
        file = path / "__init__.py" if path.is_dir() else path.with_suffix(".py")
        assert str(file.relative_to(ROOT)) in checked, f"bm.{name}: {file.relative_to(ROOT)} not in [tool.mypy] files"
    assert "src/bikemass/__init__.py" in checked
