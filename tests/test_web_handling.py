"""The web page's handling panel and ``/api/handling``: the command line's numbers for the
configuration on screen (Flask test client and the page's callbacks, no browser)."""

import contextlib
import io
import json

import numpy as np
import pytest

pytest.importorskip("dash")

from bikemass.cli.main import main  # noqa: E402
from bikemass.web import create_app  # noqa: E402
from bikemass.web.engine import HANDLING_SPEEDS  # noqa: E402
from bikemass.web.page import _layout  # noqa: E402
from dash import no_update  # noqa: E402


@pytest.fixture(scope="module")
def app():
    return create_app()


def cli_json(*argv):
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(list(argv)) == 0
    return json.loads(out.getvalue())


def test_api_handling_is_the_command_lines_json(app):
    reply = app.server.test_client().get("/api/handling?bike=jamis&rider=relaxed&stiffness=steel")
    assert reply.status_code == 200
    ours = reply.get_json()
    cli = cli_json("handling", "jamis", "--rider", "relaxed", "--stiffness", "steel",
                   "--speeds", ",".join(f"{v:g}" for v in HANDLING_SPEEDS), "--format", "json")
    # the web API adds the warnings the command line prints to stderr (a list, empty when none)
    assert ours.pop("warnings") == [] and ours.keys() == cli.keys() and ours["speeds"] == list(HANDLING_SPEEDS)
    np.testing.assert_allclose(ours["hqm_peak"], cli["hqm_peak"], rtol=1e-12)
    np.testing.assert_allclose(ours["gains"]["k_delta"], cli["gains"]["k_delta"], rtol=1e-12)
    assert ours["closed_loop_stable"] == cli["closed_loop_stable"]


def test_api_handling_refuses_a_bad_query_in_one_line(app):
    reply = app.server.test_client().get("/api/handling?bike=jamis&stiffness=granite")
    assert reply.status_code == 400 and "\n" not in reply.get_json()["error"]


def _callback(app, output):
    """The function behind the callback whose outputs include ``output``."""
    for key, spec in app.callback_map.items():
        if output in key:
            return spec["callback"].__wrapped__
    raise KeyError(output)


CONFIGURATION = ("jamis", None, "relaxed", "1.8", "75", "male", "hoods", "infinite", "exact",
                 [""] * 9, [""] * 26, "whipple")


def test_the_panel_draws_the_bode_plot_and_the_hqm_of_the_configuration(app):
    layout = str(_layout({}))
    for ident in ("bode-figure", "bode-speed", "bode-input", "bode-output", "hqm-figure", "hqm-summary"):
        assert ident in layout
    bode = _callback(app, "bode-figure.src")
    src, error, stale = bode(*CONFIGURATION, "5", "steer-torque", "roll-angle")
    assert src.startswith("data:image/svg+xml;base64,") and error == "" and stale == ""
    # a bad speed: the last good figure stays (no_update), dimmed, and the error names the field
    for speed, expected in (("fast", "a number"), ("-5", "a forward speed in m/s, a finite number in 0..1000")):
        src, error, stale = bode(*CONFIGURATION, speed, "steer-torque", "roll-angle")
        assert src is no_update and error == f"Bode plot speed (m/s): {expected}" and stale == "stale"
    hqm = _callback(app, "hqm-figure.src")
    src, summary, stale = hqm(*CONFIGURATION)
    assert src.startswith("data:image/svg+xml;base64,") and "5 m/s: HQM peak" in summary
