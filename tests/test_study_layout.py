"""The study's figures share one layout per kind (issue 37): the second figure of a kind takes the
axes positions matplotlib's constrained layout gave the first, without running the solver; a figure
whose artists would then reach past its edge is laid out by the solver itself."""

import io

import numpy as np
import pytest
from PIL import Image

import bikemass as bm
from bikemass.plots.figure import figure_bytes
from bikemass.plots.stability import CriticalSpeeds, eigenvalue_figure
from bikemass.study import figures


@pytest.fixture(scope="module")
def results():
    jamis = bm.load_bicycle("jamis")
    return [bm.stability(bm.parameters("benchmark")), bm.stability(bm.parameters(jamis, "relaxed"))]


def _figure(result, title):
    return eigenvalue_figure(result.modes, CriticalSpeeds.of(result), title)


def _pixels(fig):
    return np.asarray(Image.open(io.BytesIO(figure_bytes(fig, "png", 60))).convert("L"))


def test_a_kinds_second_figure_takes_the_firsts_layout(results, monkeypatch):
    monkeypatch.setattr(figures, "_LAYOUTS", {})
    first = figures.laid_out(_figure(results[1], "Jamis, relaxed"), "eig")
    second = figures.laid_out(_figure(results[1], "Jamis, relaxed (2)"), "eig")
    assert type(second.get_layout_engine()).__name__ == "PlaceHolderLayoutEngine"      # no solver ran
    assert np.allclose(first.axes[0].get_position().bounds, second.axes[0].get_position().bounds)
    # the same as the solver would give it, to 3 % of the figure; nothing reaches past the edges, and
    # the image's outermost rows and columns are as light as the solver's own figure's
    alone = _figure(results[1], "Jamis, relaxed")
    alone.get_layout_engine().execute(alone)
    assert np.allclose(alone.axes[0].get_position().bounds, second.axes[0].get_position().bounds, atol=0.03)
    assert figures._inside(second)
    image, reference = _pixels(second), _pixels(alone)
    assert image.shape == reference.shape and image.min() < 100               # something drawn
    for edge in (np.s_[:, :1], np.s_[:, -1:], np.s_[:1, :], np.s_[-1:, :]):
        assert image[edge].min() >= min(reference[edge].min(), 200)


def test_a_figure_reaching_past_its_edge_gets_the_solver(results, monkeypatch):
    monkeypatch.setattr(figures, "_LAYOUTS", {})
    figures.laid_out(_figure(results[0], "Benchmark"), "eig")
    wide = figures.laid_out(_figure(results[1], "J" * 150), "eig")
    assert type(wide.get_layout_engine()).__name__ == "ConstrainedLayoutEngine"
    assert not figures._inside(_figure(results[1], "J" * 150))
