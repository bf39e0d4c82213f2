"""CI runs the README's test command (the newest releases) and then the build check, and .ci/oldest.txt pins the oldest
release pyproject.toml allows of every dependency the tests install."""

import re
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.version import Version

REPO = Path(__file__).resolve().parents[1]


def _readme_test_command():
    text = (REPO / "README.md").read_text()
    section = text[text.index("Install and run the tests"):]
    return re.search(r"```shell\n(.+?)\n```", section, re.S).group(1).strip()


def test_ci_runs_exactly_the_readme_test_command():
    command = _readme_test_command()
    assert "--upgrade-strategy eager" in command and command.endswith("python -m pytest")
    steps = [step.strip() for step in command.split("&&")]
    assert steps.index("ruff check src") < steps.index("mypy") < steps.index("python -m pytest")   # lint, types, tests
    lines = [line for line in (REPO / ".ci" / "run").read_text().splitlines() if line and not line.startswith("#")]
    assert command in lines
    after = lines[lines.index(command) + 1:]
    assert after == ["rm -rf dist && python -m build && twine check --strict dist/*"], \
        "after the tests, only the build check (docs/releases.md)"


def _requirements():
    tomllib = pytest.importorskip("tomllib")          # Python >= 3.11; 3.10 checks the same file anyway
    project = tomllib.loads((REPO / "pyproject.toml").read_text())["project"]
    return [Requirement(r) for r in project["dependencies"] + project["optional-dependencies"]["test"]]


def test_oldest_pins_each_minimum_of_the_pyproject():
    pins = {}
    for line in (REPO / ".ci" / "oldest.txt").read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            name, _, version = line.partition("==")
            pins[name.lower()] = Version(version)
    for requirement in _requirements():
        (minimum,) = [Version(s.version) for s in requirement.specifier if s.operator == ">="]
        pinned = pins.pop(requirement.name.lower())
        assert pinned >= minimum and pinned.release[:2] == (minimum.release + (0, 0))[:2], \
            f"{requirement.name}: pinned {pinned}, pyproject's minimum {minimum}"
    assert not pins, f"pinned but not required: {sorted(pins)}"
