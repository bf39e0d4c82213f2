"""Fixtures and settings shared by several test files.  Hypothesis runs derandomized (the same
examples on every run and every machine, so a failure reproduces) and keeps no example
database between runs."""

import contextlib
import io
from unittest import mock

import pytest
from hypothesis import settings

settings.register_profile("bikemass", derandomize=True, database=None)
settings.load_profile("bikemass")


class CountingProgress:
    """Stands in for the progress bar: records its total and every step."""

    def __init__(self, total, title, **options):
        self.total, self.labels = total, []
        CountingProgress.last = self

    def __enter__(self):
        return self

    def step(self, label=""):
        self.labels.append(label)

    def __exit__(self, *exc):
        return False


@pytest.fixture(scope="session")
def study(tmp_path_factory):
    """One ``bikemass study --no-figures`` of the checkout (tests/test_study.py checks it, and
    tests/test_wheel.py compares the installed wheel's run with it): ``(folder, stdout, results,
    progress bar)``."""
    from bikemass.cli.main import main
    from bikemass.study import pipeline
    out = tmp_path_factory.mktemp("study")
    stdout = io.StringIO()
    kept = {}

    def keep(results, folder, paths=()):           # the results object, for the report.html test
        kept["results"] = results
        return write_html(results, folder, paths)

    write_html = pipeline.write_html
    with contextlib.redirect_stdout(stdout), mock.patch("bikemass.cli.study.Progress", CountingProgress), \
            mock.patch.object(pipeline, "write_html", keep):
        code = main(["study", "--out", str(out), "--no-figures"])
    assert code == 0
    return out, stdout.getvalue(), kept["results"], CountingProgress.last
