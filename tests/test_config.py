"""YAML reading: clear one-line errors naming file, key, expectation."""

import pytest

from bikemass.core.config import load_yaml
from bikemass.core.errors import InputError


def write(tmp_path, text):
    p = tmp_path / "f.yaml"
    p.write_text(text)
    return p


def test_errors_name_file_key_and_expectation(tmp_path):
    p = write(tmp_path, "a: {b: -1, c: [1, 2]}\n")
    root = load_yaml(p)
    with pytest.raises(InputError, match=r"f\.yaml: a\.b: a positive number"):
        root["a"]["b"].number("length", positive=True)
    with pytest.raises(InputError, match=r"a\.c: a list of 3 numbers"):
        root["a"]["c"].vector("length", 3)
    with pytest.raises(InputError, match=r"a\.d: a required key"):
        root["a"]["d"]
    with pytest.raises(InputError, match=r"a\.c: no such key \(allowed: b\)"):
        root["a"].check_keys(required=("b",))


def test_bad_yaml_and_missing_file(tmp_path):
    with pytest.raises(InputError, match="line 2: valid YAML"):
        load_yaml(write(tmp_path, "a: [1, 2\n"))
    with pytest.raises(InputError, match="an existing file"):
        load_yaml(tmp_path / "missing.yaml")
    with pytest.raises(InputError, match="mapping at the top"):
        load_yaml(write(tmp_path, "- 1\n"))


def test_only_safe_yaml(tmp_path):
    with pytest.raises(InputError):
        load_yaml(write(tmp_path, "a: !!python/object/apply:os.system ['true']\n"))
