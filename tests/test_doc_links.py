"""Citations cannot rot: every link to a doc page and every ``PAGE.md#anchor`` resolves.

Checked in README.md, docs/, src/, frames/, bodies/, reference/, tests/, benchmarks/ and
examples/ (not in what the documentation build writes: docs/_build, docs/auto_examples,
docs/api-reference):

* every markdown link ``[text](target)`` of a ``.md`` page whose target is a local file
  names a file that exists (relative to the page), and every ``docs/NAME.md`` named
  anywhere is a page of docs/ (a help text pointing to a page that does not exist is
  caught too);
* every ``NAME.md#anchor`` written anywhere (markdown link, comment, docstring) names a
  page of the repository (relative to the citing file, else to the repository root) and
  a heading of that page; ``(#anchor)`` links point to a heading of their own page.

Anchors are the heading slugs GitHub makes: lower case, punctuation other than ``-`` and
``_`` dropped, spaces to ``-``, a repeated slug numbered ``-1``, ``-2``; headings inside
fenced code blocks do not count.
"""

import re
import sys
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
FOLDERS = ("docs", "src", "frames", "bodies", "reference", "tests", "benchmarks", "examples")
SUFFIXES = {".md", ".py", ".yaml", ".yml", ".txt", ".toml"}
CITATION = re.compile(r"((?:\.{1,2}/)?(?:[\w.-]+/)*[\w.-]+\.md)#([\w-]+)")
DOC_PAGE = re.compile(r"(?<![\w.-])docs/([\w.-]+\.md)")
LINK = re.compile(r"\]\(([^)\s]+)\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(page):
    """Every heading anchor of a markdown ``page`` (a Path)."""
    found, seen, fenced = set(), Counter(), False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
            continue
        m = None if fenced else HEADING.match(line)
        if m:
            base = slug(m.group(2))
            found.add(base if not seen[base] else f"{base}-{seen[base]}")
            seen[base] += 1
    return found


GENERATED = {"__pycache__", "_build", "auto_examples", "api-reference"}
"""Folders a build writes (git ignores them): the site's copies of the pages are not citations."""


def citing_files():
    files = [ROOT / "README.md"]
    for folder in FOLDERS:
        files += [p for p in sorted((ROOT / folder).rglob("*"))
                  if p.suffix in SUFFIXES and p.is_file() and not GENERATED & set(p.relative_to(ROOT).parts)]
    return [p for p in files if p != Path(__file__)]     # this file's examples are not citations


def resolve(source, target):
    """The repository file ``target`` names, seen from ``source`` (None if there is none)."""
    for base in (source.parent, ROOT):
        path = (base / target).resolve()
        if path.is_file() and ROOT.resolve() in path.parents:
            return path
    return None


def broken_references(source):
    text = source.read_text(encoding="utf-8", errors="replace")
    broken = [f"docs/{name}: no such page" for name in sorted(set(DOC_PAGE.findall(text)))
              if not (ROOT / "docs" / name).is_file()]
    for m in CITATION.finditer(text):
        page = resolve(source, m.group(1))
        if page is None:
            broken.append(f"{m.group(0)}: no page {m.group(1)}")
        elif m.group(2) not in anchors(page):
            broken.append(f"{m.group(0)}: no heading #{m.group(2)} in {page.relative_to(ROOT.resolve())}")
    if source.suffix == ".md":
        for m in LINK.finditer(text):
            target = m.group(1)
            if re.match(r"[a-z]+:", target):                       # http:, https:, mailto:
                continue
            path, _, anchor = target.partition("#")
            if not path:
                if anchor not in anchors(source):
                    broken.append(f"({target}): no heading #{anchor} on this page")
            elif resolve(source, path) is None:
                broken.append(f"({target}): no file {path}")
    return broken


@pytest.mark.parametrize("source", citing_files(), ids=lambda p: str(p.relative_to(ROOT)))
def test_references_resolve(source):
    assert not broken_references(source), f"{source.relative_to(ROOT)}: {broken_references(source)}"


def test_the_slugs_are_githubs():
    assert slug("Equivalent stiffness S: `condensed` (default) and `thesis`") == \
        "equivalent-stiffness-s-condensed-default-and-thesis"
    assert slug("Jamis (`frames/jamis.yaml`)") == "jamis-framesjamisyaml"
    assert slug("Table 3-3 errata") == "table-3-3-errata"


def test_a_broken_citation_is_found(tmp_path, monkeypatch):
    monkeypatch.setattr(sys.modules[__name__], "ROOT", tmp_path)
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "a.md").write_text("# A page\n\n```yaml\n# not a heading\n```\n[ok](#a-page) [bad](#gone)\n")
    source = tmp_path / "src.py"
    source.write_text("# see docs/a.md#a-page, docs/a.md#not-a-heading and docs/b.md#x\n")
    assert broken_references(source) == ["docs/b.md: no such page",
                                         "docs/a.md#not-a-heading: no heading #not-a-heading in docs/a.md",
                                         "docs/b.md#x: no page docs/b.md"]
    assert broken_references(tmp_path / "docs" / "a.md") == ["(#gone): no heading #gone on this page"]
