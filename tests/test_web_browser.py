"""The web page in a real browser: headless Chromium (Debian's ``chromium`` and
``chromium-driver``) driven through Selenium.

Without a browser these tests skip and say why; with ``BIKEMASS_REQUIRE_BROWSER=1``
(set by ``.ci/run``) that skip is a failure instead.
"""

import contextlib
import io
import json
import os
import shutil
import threading

import pytest

pytestmark = pytest.mark.slow     # drives the web page in a headless browser (~15 s): pytest -m 'not slow' leaves it out

pytest.importorskip("dash")

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMEDRIVER = shutil.which("chromedriver")
REQUIRED = os.environ.get("BIKEMASS_REQUIRE_BROWSER") == "1"


def _missing():
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "selenium is not installed (pip install 'bikemass[test]')"
    if not (CHROMIUM and CHROMEDRIVER):
        return "no chromium/chromedriver on PATH (Debian: apt-get install chromium chromium-driver)"
    return None


@pytest.fixture(scope="module")
def server():
    from bikemass.web import create_app
    from bikemass.web.serving import make_server

    httpd = make_server(create_app(), "127.0.0.1", 0, quiet=True)
    httpd.daemon_threads = False      # server_close() then waits for requests still being answered,
    httpd.block_on_close = True       # so no thread is inside numpy/trimesh when the interpreter exits
    thread = threading.Thread(target=httpd.serve_forever)
    thread.start()
    yield f"http://127.0.0.1:{httpd.port}"
    httpd.shutdown()
    httpd.server_close()
    thread.join()


@pytest.fixture(scope="module")
def browser():
    reason = _missing()
    if reason:
        if REQUIRED:
            pytest.fail(f"BIKEMASS_REQUIRE_BROWSER=1 but {reason}")
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--window-size=1400,1000"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    yield driver
    driver.quit()


def _cli_weave(*argv):
    from bikemass.cli.main import main
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        main(["stability", *argv, "--format", "json"])
    return json.loads(out.getvalue())["weave_speeds"][0]


def _number_in(browser, element_id, timeout=60, differs_from=None):
    """The number that the element's text starts with, once there (and changed, if asked)."""
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait

    def ready(driver):
        text = driver.find_element(By.ID, element_id).text.strip()
        try:
            value = float(text.split()[0])
        except (IndexError, ValueError):
            return False
        return value if differs_from is None or abs(value - differs_from) > 1e-3 else False
    return WebDriverWait(browser, timeout, poll_frequency=0.2).until(
        ready, message=f"#{element_id} shows no (new) number within {timeout} s")


def test_a_url_opens_its_configuration_and_a_change_updates_the_speeds(server, browser, tmp_path):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    browser.get(f"{server}/?bike=jamis&rider=relaxed&stiffness=steel")
    shown = _number_in(browser, "weave-speed")
    assert shown == pytest.approx(_cli_weave("jamis", "--rider", "relaxed", "--stiffness", "steel"), abs=1e-3)
    text = browser.find_element(By.ID, "weave-speed").text
    assert text.split()[1] == "m/s" and len(text.split()[0].split(".")[1]) >= 3

    trail = browser.find_element(By.XPATH, """//input[@id='{"key":"c","type":"param"}']""")
    trail.click()
    trail.send_keys("0.09", Keys.ENTER)
    changed = _number_in(browser, "weave-speed", differs_from=shown)
    assert "c=0.09" in browser.current_url
    import urllib.request
    query = browser.current_url.split("?", 1)[1]
    with urllib.request.urlopen(f"{server}/api/stability?{query}") as reply:
        api = json.load(reply)
    assert changed == pytest.approx(api["weave_speeds"][0], abs=1e-3)
    capsize = browser.find_element(By.ID, "capsize-speed").text
    if api["capsize_speeds"]:
        assert float(capsize.split()[0]) == pytest.approx(api["capsize_speeds"][0], abs=1e-3)
    else:
        assert capsize.startswith("none")
    screenshot = tmp_path / "page.png"
    assert browser.save_screenshot(str(screenshot))
    from PIL import Image
    with Image.open(screenshot) as image:
        assert image.size[0] >= 1000 and len(image.getcolors(1 << 20) or []) > 50


def test_a_bad_url_shows_the_one_line_error(server, browser):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(f"{server}/?bike=jamis&rider=relaxed&stiffness=rubber")
    WebDriverWait(browser, 60).until(lambda d: d.find_element(By.ID, "error").text.strip())
    message = browser.find_element(By.ID, "error").text
    assert "stiffness" in message and "steel" in message


def _settled(browser, timeout=120):
    """Wait until no Dash callback is loading (every figure and number the address asked for is in)."""
    from selenium.webdriver.support.ui import WebDriverWait
    WebDriverWait(browser, timeout, poll_frequency=0.2).until(
        lambda d: d.execute_script("return document.querySelectorAll('[data-dash-is-loading=\"true\"]').length === 0"
                                   " && !!document.getElementById('side-view')"
                                   " && !!document.getElementById('side-view').getAttribute('src')"),
        message=f"the page did not settle within {timeout} s")


def _policy_violations(browser):
    """Console lines about the content security policy (the page must work under it)."""
    try:
        return [e["message"] for e in browser.get_log("browser") if "Content Security Policy" in e["message"]]
    except Exception:                     # a driver without the log: nothing to check there
        return []


def test_a_link_with_a_model_joined_by_plus_opens_that_model(server, browser):
    """docs/web.md writes ``model=rider-lean+tyre``; in an address '+' arrives as a space.  The page
    must show that model's speeds (the command line's, to 1e-3 m/s as printed), keep the model in
    its address and show no error."""
    from selenium.webdriver.common.by import By

    browser.get(f"{server}/?bike=jamis&rider=relaxed&stiffness=infinite&model=rider-lean+tyre")
    shown = _number_in(browser, "weave-speed")
    _settled(browser)
    cli = _cli_weave("jamis", "--rider", "relaxed", "--model", "rider-lean+tyre")
    whipple = _cli_weave("jamis", "--rider", "relaxed")
    assert shown == pytest.approx(cli, abs=1e-3) and abs(cli - whipple) > 0.05
    assert browser.find_element(By.ID, "error").text.strip() == ""
    assert "model=rider-lean%2Btyre" in browser.current_url or "model=rider-lean+tyre" in browser.current_url
    assert float(browser.find_element(By.ID, "weave-speed").text.split()[0]) == pytest.approx(cli, abs=1e-3)
    assert not _policy_violations(browser)


def test_a_bad_link_keeps_its_error_and_its_address(server, browser):
    """A link the page cannot open: its error stays once every callback has run, the address is not
    rewritten to another configuration, and the results are marked as not being the link's."""
    from selenium.webdriver.common.by import By

    link = f"{server}/?bike=jamis&rider=relaxed&stiffness=infinite&model=rider-lean+bogus"
    browser.get(link)
    _settled(browser)
    message = browser.find_element(By.ID, "error").text
    assert "model" in message and "bogus" not in browser.find_element(By.ID, "weave-speed").text
    assert "bogus" in browser.current_url
    assert "stale" in browser.find_element(By.ID, "results").get_attribute("class")
    assert browser.find_element(By.ID, "stale-note").is_displayed()


def test_results_kept_after_an_error_are_marked_stale(server, browser):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(f"{server}/?bike=benchmark&rider=none&stiffness=infinite")
    shown = _number_in(browser, "weave-speed")
    assert not browser.find_element(By.ID, "stale-note").is_displayed()
    mass = browser.find_element(By.XPATH, """//input[@id='{"key":"mB","type":"param"}']""")
    mass.click()
    mass.send_keys("-5", Keys.ENTER)
    WebDriverWait(browser, 60).until(lambda d: d.find_element(By.ID, "error").text.strip())
    assert browser.find_element(By.ID, "error").text.startswith("Benchmark parameter mB: ")
    assert "stale" in browser.find_element(By.ID, "results").get_attribute("class")
    assert browser.find_element(By.ID, "stale-note").is_displayed()
    assert float(browser.find_element(By.ID, "weave-speed").text.split()[0]) == shown      # kept, marked
    mass.send_keys(Keys.BACKSPACE, Keys.BACKSPACE, "80", Keys.ENTER)      # the published 85 kg: no change
    _number_in(browser, "weave-speed", differs_from=shown)
    WebDriverWait(browser, 60).until(lambda d: "stale" not in d.find_element(By.ID, "results").get_attribute("class"))
    assert not browser.find_element(By.ID, "stale-note").is_displayed()
