"""Property tests: random YAML values fed into every loader give exit status 0 or 2 (one line),
never a traceback.  Hypothesis runs derandomized, so every run tries the same examples."""

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bikemass.core.errors import InputError
from bikemass.core.gate import parse_yaml
from hostile.corpus import run
from hostile.generators import dump, shipped

SETTINGS = settings(max_examples=12, derandomize=True, deadline=None,
                    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])

scalars = (st.none() | st.booleans() | st.integers(min_value=-10**40, max_value=10**40)
           | st.floats(allow_nan=True, allow_infinity=True) | st.text(max_size=12)
           | st.sampled_from(["1 in", "3 furlongs", "1e300 m", "-0 deg", "nan kg", "steel", "all", ""]))
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=4)
                      | st.dictionaries(st.text(max_size=6), inner, max_size=3), max_leaves=8)


def _leaf_paths(document, prefix=()):
    """Every dotted path into ``document`` (mappings and lists), leaves and branches."""
    items = document.items() if isinstance(document, dict) else enumerate(document) if isinstance(document, list) else ()
    paths = []
    for key, value in items:
        paths.append(prefix + (key,))
        paths += _leaf_paths(value, prefix + (key,))
    return paths


def _replace(document, path, value):
    node = document
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return document


def _check(tmp_path, document, argv):
    path = tmp_path / "in.yaml"
    path.write_text(dump(document))
    outcome = run([a.replace("{in}", str(path)) for a in argv])
    assert not outcome.crash and not outcome.hung, outcome.crash
    assert outcome.status in (0, 2) and "Traceback" not in outcome.stderr, outcome.stderr
    assert "internal error" not in outcome.stderr, outcome.stderr
    if outcome.status == 2:
        assert len(outcome.stderr.splitlines()) == 1, outcome.stderr


LOADERS = {
    # loader: (shipped document or literal, command)
    "parameter file": ("frames/benchmark.yaml", ["params", "{in}"]),
    "bicycle file": ("frames/jamis.yaml", ["params", "{in}", "--method", "exact"]),
    "placement pose": ("bodies/poses/relaxed.yaml", ["rider", "{in}", "--method", "exact"]),
    "lumped pose": ("bodies/poses/relaxed_thesis.yaml", ["rider", "{in}"]),
    "chain pose": ({"body": "thesis_rider", "bike": "jamis", "chain": {"torso_lean": 30, "hands": "hoods"}},
                   ["rider", "{in}", "--method", "exact"]),
    "stiffness file": ({"S": [[6538.4, 1234.9], [1234.9, 3622.1]]},
                       ["stability", "benchmark", "--stiffness", "{in}", "--speeds", "0:2:1"]),
    "material file": ({"bronze": {"E": "110 GPa", "nu": 0.34, "density": "8.8 g/cm^3"}},
                      ["stiffness", "jamis", "--material", "{in}"]),
}


def _document(source):
    return shipped(source) if isinstance(source, str) else __import__("copy").deepcopy(source)


@pytest.mark.parametrize("loader", LOADERS)
def test_random_values_into_every_loader(loader, tmp_path):
    source, argv = LOADERS[loader]
    paths = _leaf_paths(_document(source))

    @SETTINGS
    @given(st.sampled_from(paths), values)
    def replaced(path, value):
        _check(tmp_path, _replace(_document(source), path, value), argv)

    replaced()


@pytest.mark.parametrize("loader", ["parameter file", "placement pose", "stiffness file"])
def test_random_top_level_documents(loader, tmp_path):
    _, argv = LOADERS[loader]

    @SETTINGS
    @given(values)
    def whole(value):
        _check(tmp_path, value, argv)

    whole()


@settings(max_examples=300, derandomize=True, deadline=None)
@given(st.binary(max_size=300) | st.text(max_size=300).map(str.encode))
def test_the_gate_parses_or_refuses_any_bytes(data):
    """Arbitrary bytes through the gate: data or one InputError, nothing else."""
    from bikemass.core.gate import decode
    try:
        parse_yaml(decode(data, Path("x.yaml")), Path("x.yaml"))
    except InputError as exc:
        assert "\n" not in str(exc)
