"""One version: ``bikemass.__version__`` is what the package metadata and ``--version`` say."""

import importlib.metadata
import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

import bikemass


def test_version_has_one_source():
    assert re.fullmatch(r"\d+\.\d+\.\d+", bikemass.__version__)
    assert importlib.metadata.version("bikemass") == bikemass.__version__


def test_command_line_prints_the_version():
    out = subprocess.run([sys.executable, "-m", "bikemass.cli.main", "--version"], capture_output=True, text=True)
    assert out.returncode == 0
    assert out.stdout.strip() == f"bikemass {bikemass.__version__}"


# The release's version in every place a reader or a packager looks (docs/releases.md): the changelog's
# newest release, CITATION.cff (valid CFF 1.2.0) and the documentation say what ``bikemass --version`` does.

ROOT = Path(__file__).resolve().parents[1]
RELEASE = re.compile(r"^## \[(\d+\.\d+\.\d+)\] - (\d{4}-\d{2}-\d{2})$", re.M)
CFF_REQUIRED = ("cff-version", "message", "title", "authors")
"""The keys the CFF 1.2.0 schema requires at the top level."""


def _releases():
    return RELEASE.findall((ROOT / "CHANGELOG.md").read_text())


def test_changelog_names_the_version_first():
    text = (ROOT / "CHANGELOG.md").read_text()
    assert "keepachangelog.com" in text and "## [Unreleased]" in text
    releases = _releases()
    assert releases[0][0] == bikemass.__version__
    assert [v for v, _ in releases] == sorted((v for v, _ in releases), key=lambda v: tuple(map(int, v.split("."))),
                                              reverse=True)
    assert [d for _, d in releases] == sorted((d for _, d in releases), reverse=True)
    for version, _ in releases:                          # every release says what changed
        section = text.split(f"## [{version}]")[1].split("\n## ")[0]
        assert re.search(r"^### (Added|Changed|Deprecated|Removed|Fixed|Security)$", section, re.M), version


def _citation():
    return yaml.safe_load((ROOT / "CITATION.cff").read_text())


def test_citation_carries_the_version_and_date():
    cff = _citation()
    assert cff["version"] == bikemass.__version__
    assert str(cff["date-released"]) == dict(_releases())[bikemass.__version__]
    assert cff["cff-version"] == "1.2.0"
    for key in CFF_REQUIRED:
        assert cff.get(key), key
    assert all(isinstance(a, dict) and a for a in cff["authors"])


def test_citation_validates_against_the_cff_schema():
    """The CFF 1.2.0 JSON schema cffconvert ships (``cffconvert --validate`` reads the same one). cffconvert
    is not in the test extra (it pins jsonschema < 4, which other test dependencies outgrew); without it
    :func:`test_citation_carries_the_version_and_date` checks the schema's required keys."""
    cffconvert = pytest.importorskip("cffconvert")
    jsonschema = pytest.importorskip("jsonschema")
    import json
    schema = json.loads((Path(cffconvert.__file__).parent / "schemas" / "1.2.0" / "schema.json").read_text())
    # the schema's date format and the YAML loader: dates as the strings the file holds
    data = json.loads(json.dumps(_citation(), default=str))
    jsonschema.Draft7Validator(schema).validate(data)


def test_docs_show_the_version():
    """docs/releases.md shows ``bikemass --version``'s line (tests/test_docs.py runs it) and says the version."""
    text = (ROOT / "docs" / "releases.md").read_text()
    assert f"$ bikemass --version\nbikemass {bikemass.__version__}\n" in text
    assert f"This is bikemass **{bikemass.__version__}**" in text
