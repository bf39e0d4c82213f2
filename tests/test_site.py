"""The documentation site builds with warnings as errors, documents every public name, runs its
gallery, and opens offline.

The site is built once for this module, as README.md says (``sphinx-build -W``), from a copy of
``docs/`` (with README.md and reference/README.md, which it includes) into a scratch folder: every
build runs every gallery example afresh, and the checkout is left as it was. A broken reference, a
docstring numpydoc cannot read or an example that raises fails the build, so the test. Sphinx and
its extensions come with the ``test`` extra (pyproject.toml); nothing here is skipped.
"""

import os
import re
import shutil
import subprocess
import sys
import html
from html.parser import HTMLParser
from pathlib import Path

import pytest

import bikemass as bm

pytestmark = pytest.mark.slow     # builds the documentation site with Sphinx (~80 s): pytest -m 'not slow' leaves it out

ROOT = Path(__file__).parents[1]
GENERATED = ("_build", "auto_examples", "api-reference")
"""What a build writes into docs/ (git ignores them): not copied, so the build starts clean."""
MIN_EXAMPLES = 6


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The built site's folder (a failed build fails every test here, with Sphinx's last lines)."""
    scratch = tmp_path_factory.mktemp("site")
    shutil.copytree(ROOT / "docs", scratch / "docs", ignore=shutil.ignore_patterns(*GENERATED, "__pycache__"))
    shutil.copy(ROOT / "README.md", scratch / "README.md")
    shutil.copy(ROOT / "CHANGELOG.md", scratch / "CHANGELOG.md")          # docs/changelog.md includes it
    (scratch / "reference").mkdir()
    shutil.copy(ROOT / "reference" / "README.md", scratch / "reference" / "README.md")
    out = scratch / "html"
    done = subprocess.run([sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", str(scratch / "docs"), str(out)],
                          capture_output=True, text=True, timeout=900, env=_environment())
    assert done.returncode == 0, f"sphinx-build -W failed:\n{done.stdout[-3000:]}\n{done.stderr[-5000:]}"
    return out


def _environment():
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)         # the examples' figures need no backend: bikemass sets none
    return env


class Resources(HTMLParser):
    """Every resource a page loads: ``<script src>``, ``<link href>``, ``<img src>``, ``<iframe src>``."""

    def __init__(self):
        super().__init__()
        self.found = []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        key = {"script": "src", "img": "src", "iframe": "src", "link": "href"}.get(tag)
        if key and attrs.get(key) and (tag != "link" or "stylesheet" in (attrs.get("rel") or "")
                                       or attrs.get("rel") in ("preload", "icon")):
            self.found.append(attrs[key])


def test_every_public_name_has_a_reference_entry(site):
    index = (site / "api-reference" / "index.html").read_text(encoding="utf-8")
    missing = []
    for name in bm.__all__:
        page = site / "api-reference" / f"{name}.html"
        text = page.read_text(encoding="utf-8") if page.is_file() else ""
        if f'id="bikemass.{name}"' not in text or f"{name}.html#bikemass.{name}" not in index:
            missing.append(name)
    assert not missing, f"no reference entry for {missing}"
    print(f"{len(bm.__all__)} names of bikemass.__all__ with a reference entry")


def test_reference_pages_show_typed_signatures_and_numpydoc_sections(site):
    page = re.sub(r"<[^>]+>", "", (site / "api-reference" / "stability.html").read_text(encoding="utf-8"))
    assert "stiffness: ArrayLike | None = None" in page and "StabilityResult" in page
    for section in ("Parameters", "Returns", "Raises", "See also", "Examples"):
        assert section in page, section
    assert "4.292382536" in page            # the example's weave speed (Meijaard et al. 2007)


def test_the_gallery_runs_its_examples_with_figures(site):
    pages = sorted(p for p in (site / "auto_examples").glob("*.html") if p.name != "index.html")
    assert len(pages) >= MIN_EXAMPLES, [p.name for p in pages]
    for page in pages:
        parser = Resources()
        parser.feed(page.read_text(encoding="utf-8"))
        images = [site / "auto_examples" / src for src in parser.found if "sphx_glr_" in src and src.endswith(".png")]
        assert images, f"{page.name}: no figure"
        for image in images:
            assert image.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", image
    tour = (site / "auto_examples" / "plot_01_tour.html").read_text(encoding="utf-8")
    assert "bikemass-result" in tour               # a result's _repr_html_ table, captured
    print(f"{len(pages)} gallery examples")


def test_the_site_needs_no_network(site):
    remote = re.compile(r"^(https?:)?//", re.I)
    loads = {}
    for page in site.rglob("*.html"):
        parser = Resources()
        parser.feed(page.read_text(encoding="utf-8"))
        outside = [src for src in parser.found if remote.match(src)]
        if outside:
            loads[str(page.relative_to(site))] = outside
    assert not loads, loads
    css = [p for p in site.rglob("*.css") if re.search(r"url\(\s*['\"]?(https?:)?//", p.read_text(errors="replace"))]
    assert not css, css


def test_the_chapters_and_the_readme_are_pages(site):
    for chapter in sorted((ROOT / "docs").glob("*.md")):
        title = chapter.read_text(encoding="utf-8").splitlines()[0].lstrip("# ").replace("`", "")
        page = (site / f"{chapter.stem}.html").read_text(encoding="utf-8")
        shown = re.search(r"<title>(.*?)</title>", page, re.S).group(1)
        assert title.split(":")[0] in html.unescape(shown), (chapter.name, title, shown)
    thesis = (site / "thesis.html").read_text(encoding="utf-8")
    assert 'href="thesis-tables.html"' in thesis       # ../reference/README.md, as a page of the site
