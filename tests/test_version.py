"""One version: ``bikemass.__version__`` is what the package metadata and ``--version`` say."""

import importlib.metadata
import re
import subprocess
import sys

import bikemass


def test_version_has_one_source():
    assert re.fullmatch(r"\d+\.\d+\.\d+", bikemass.__version__)
    assert importlib.metadata.version("bikemass") == bikemass.__version__


def test_command_line_prints_the_version():
    out = subprocess.run([sys.executable, "-m", "bikemass.cli.main", "--version"], capture_output=True, text=True)
    assert out.returncode == 0
    assert out.stdout.strip() == f"bikemass {bikemass.__version__}"
