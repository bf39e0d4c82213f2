"""Links to the Markdown pages that live outside ``docs/``: README.md, CHANGELOG.md and reference/README.md.

The chapters link to them as files (``README.md#units-in-yaml`` of the folder above), which is
right on GitHub and in a checkout; the site shows them as its pages ``readme`` and ``thesis-tables`` (each a MyST
``include`` of the file), and this post-transform points such links there before MyST resolves
them, so they are checked like every other link (a missing heading still fails the build).
"""

import os
from pathlib import Path

from sphinx import addnodes
from sphinx.transforms.post_transforms import SphinxPostTransform

PAGES = {"README": "readme", "CHANGELOG": "changelog", "reference/README": "thesis-tables"}
"""File outside docs/ (repository-relative, no suffix) -> the site page that includes it."""


class OutsidePages(SphinxPostTransform):
    """Retarget MyST document links to files of :data:`PAGES`."""

    default_priority = 8          # before MyST's own resolver (9)

    def run(self, **kwargs):
        root = Path(self.env.srcdir).parent
        targets = {os.path.normpath(root / name): page for name, page in PAGES.items()}
        for node in self.document.findall(addnodes.pending_xref):
            if node.get("reftype") != "myst":
                continue
            if node.get("refdomain") == "doc":
                # MyST names the file relative to the source folder (older releases) or absolutely
                target = os.path.normpath(os.path.join(self.env.srcdir, node["reftarget"]))
                node["reftarget"] = targets.get(target, node["reftarget"])
            elif node.get("reftarget") in ("reference/README.md", "CHANGELOG.md"):
                # README.md's own links to reference/README.md and CHANGELOG.md, read in the page that
                # includes README.md
                page = PAGES[node["reftarget"][:-len(".md")]]
                node["refdomain"], node["reftarget"], node["reftargetid"] = "doc", page, None


def setup(app):
    app.add_post_transform(OutsidePages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
