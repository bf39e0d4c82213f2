"""The input gate's YAML limits answer in bikemass's words, whatever parser (libyaml or pure Python,
any version, with or without its own nesting limit) reads the text."""

import pytest
import yaml
from yaml.error import Mark
from yaml.scanner import ScannerError

from bikemass import gate
from bikemass.errors import InputError


class _ParserWithItsOwnLimit(yaml.SafeLoader):
    """A parser that, like libyaml since 0.2.6, refuses flow nesting beyond 10 levels in its own
    words while looking ahead, before the events reach the gate."""

    def fetch_flow_collection_start(self, token_class):
        if self.flow_level >= 10:
            raise ScannerError(None, None, "some words of its own",
                               Mark("<text>", self.index, self.line, self.column, None, None))
        super().fetch_flow_collection_start(token_class)


LOADERS = {"libyaml": getattr(yaml, "CSafeLoader", yaml.SafeLoader), "pure-python": yaml.SafeLoader,
           "own-limit": _ParserWithItsOwnLimit}


@pytest.fixture(params=sorted(LOADERS))
def loader(request, monkeypatch):
    monkeypatch.setattr(gate, "_LOADER", LOADERS[request.param])
    return request.param


@pytest.mark.parametrize("text, line", [
    ("[" * 65 + "]" * 65, 1),
    ("[" * 100_000 + "]" * 100_000, 1),
    ("a: 1\nb:\n  c: " + "{x: " * 2000 + "1" + "}" * 2000, 3),
    ("a:\n- " + "[" * 5000, 2),                              # unclosed, too
])
def test_deep_flow_nesting_is_refused_by_the_depth_limit(loader, text, line):
    with pytest.raises(InputError) as err:
        gate.parse_yaml(text, "x.yaml")
    assert str(err.value) == f"x.yaml: line {line}: YAML nested at most {gate.MAX_DEPTH} levels deep"


def test_nesting_at_the_limit_is_read(loader):
    if loader == "own-limit":
        pytest.skip("that parser refuses 64 levels itself (its limit is 10)")
    data = gate.parse_yaml("[" * gate.MAX_DEPTH + "]" * gate.MAX_DEPTH, "x.yaml")
    for _ in range(gate.MAX_DEPTH - 1):
        (data,) = data
    assert data == []


@pytest.mark.parametrize("text", [
    'a: "' + "[" * 70 + '"\nb: [1\n',                       # brackets in a double-quoted scalar
    "a: '" + "{" * 70 + "'\nb: [1\n",                       # ... a single-quoted one
    "# " + "[" * 70 + "\nb: [1\n",                          # ... a comment
    "a: b" + "[" * 70 + "\nb: [1\n",                        # ... a plain scalar
])
def test_brackets_that_open_nothing_leave_a_syntax_error_its_own(loader, text):
    with pytest.raises(InputError) as err:
        gate.parse_yaml(text, "x.yaml")
    assert "valid YAML (" in str(err.value)


def test_flow_depth_counts_only_up_to_the_failing_line():
    text = "a: [1\n" + "[" * 70 + "\n"
    assert gate.flow_depth_line(text, 64) == 2
    assert gate.flow_depth_line(text, 64, last_line=1) is None
