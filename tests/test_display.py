"""Notebook manners: results show a compact HTML table (``_repr_html_``, IPython's rich display) and
a one-line ``repr``; figures show themselves (``_repr_png_``, tests/test_figures.py).

The table holds the result's values with their units; the numbers checked are published ones
(Meijaard et al. 2007: the benchmark's parameters, weave and capsize speeds)."""

from html.parser import HTMLParser

import numpy as np
import pytest

import bikemass as bm
from bikemass.core.display import LONGEST, brief, html_table


class Table(HTMLParser):
    """The rows of an HTML table as lists of cell texts, and its caption."""

    def __init__(self, text):
        super().__init__()
        self.rows, self.caption, self._cell, self._in_caption = [], "", None, False
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "caption":
            self._in_caption = True

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.rows[-1].append(self._cell)
            self._cell = None
        elif tag == "caption":
            self._in_caption = False

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data
        elif self._in_caption:
            self.caption += data


@pytest.fixture(scope="module")
def meijaard():
    return bm.parameters("benchmark")


def rows(result):
    table = Table(result._repr_html_())
    assert table.rows[0] == ["field", "value", "unit"]
    return {r[0]: (r[1], r[2]) for r in table.rows[1:]}


def test_stability_result_table_holds_the_critical_speeds_with_units(meijaard):
    shown = rows(bm.stability(meijaard))
    assert shown["weave speeds"] == ("4.2924", "m/s") and shown["capsize speeds"] == ("6.0243", "m/s")
    assert shown["stable (strict)"] == ("4.2924..6.0243", "m/s")
    assert shown["frame stiffness S"][0] == "rigid"


def test_parameters_table_holds_the_26_values_with_their_units(meijaard):
    table = Table(meijaard._repr_html_())
    body = {r[0].split(":")[0]: (r[1], r[2]) for r in table.rows[1:]}
    assert list(body) == list(bm.PARAMETER_NAMES)
    assert body["mB"] == ("85", "kg") and body["IBxz"] == ("2.4", "kg m^2") and body["lam"][1] == "rad"
    assert float(body["lam"][0]) == pytest.approx(np.pi / 10, abs=5e-7)


@pytest.mark.parametrize("make", [
    lambda p: p,
    lambda p: bm.stability(p),
    lambda p: bm.eigenvalues(p),
    lambda p: bm.matrices(p),
    lambda p: bm.sensitivity(p),
    lambda p: bm.uncertainty("benchmark", {"c": 0.001}),
    lambda p: bm.frame_modes("jamis", count=4),
    lambda p: bm.transfer_function(p, 5.0, "steer-torque", "roll-angle"),
    lambda p: bm.frequency_response(p, 5.0, "steer-torque", "roll-angle"),
    lambda p: bm.simulate(p, 4.6, initial={"roll-rate": 0.5}),
    lambda p: bm.mode_shapes(p, 5.0),
], ids=["parameters", "stability", "eigenvalues", "matrices", "sensitivity", "uncertainty", "frame_modes",
        "transfer_function", "frequency_response", "simulate", "mode_shapes"])
def test_results_have_a_short_repr_and_an_html_table(make, meijaard):
    result = make(meijaard)
    text = repr(result)
    assert "\n" not in text and len(text) <= 300, text
    table = Table(result._repr_html_())
    assert table.caption.startswith(type(result).__name__) and len(table.rows) >= 2


def test_brief_shortens_what_would_run_to_screens():
    assert brief(np.zeros((601, 4), complex)) == "array (601, 4) complex"
    assert brief(np.array([1.0, 2.5])) == "[1, 2.5]"
    assert brief(np.eye(2)) == "[[1, 0], [0, 1]]"
    assert brief(4.2923825363411040) == "4.29238"
    assert brief(tuple(range(100))) == "(100 int)"
    assert brief({f"k{i}": i for i in range(40)}) == "{40 keys}"
    assert len(brief("x" * 500)) <= LONGEST


def test_the_html_is_escaped():
    text = html_table("<i>", [("a<b", "&", "kg m^2")])
    assert "<i>" not in text and "<b>&lt;i&gt;</b>" in text and "a&lt;b" in text and "&amp;" in text
