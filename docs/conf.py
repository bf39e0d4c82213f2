"""Sphinx configuration of the bikemass site: narrative chapters (MyST reads docs/*.md as they are),
an API reference generated from ``bikemass.__all__`` (docs/_ext/api_reference.py) and a gallery of
executed examples (sphinx-gallery, docs/examples/).

Build (README.md, "Documentation"): ``sphinx-build -W docs docs/_build/html``. The build needs no
network: no intersphinx, no CDN (the theme's assets are shipped with it, math is rendered as text).
"""

import sys
from pathlib import Path

import bikemass
from sphinx_gallery.sorting import FileNameSortKey

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

project = "bikemass"
author = "the bikemass authors"
copyright = "the bikemass authors, MIT licence"
release = version = bikemass.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "api_reference",
    "plain_math",
    "outside_pages",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
# sg_execution_times: sphinx-gallery's timing pages load jQuery and DataTables from CDNs (the site opens offline)
exclude_patterns = ["_build", "screenshots", "examples", "sg_execution_times.rst", "auto_examples/sg_execution_times.rst"]

# The chapters link to each other by GitHub's heading anchors (stability.md#commands): MyST makes the same ones.
myst_heading_anchors = 6
myst_enable_extensions = ["colon_fence"]    # ::: fences: docs/readme.md includes README.md

# autodoc + numpydoc: signatures with their annotations, members in source order, numpydoc sections.
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
autodoc_preserve_defaults = True
# Annotations name numpy's ArrayLike rather than print the union it stands for.
autodoc_type_aliases = {"ArrayLike": "ArrayLike"}
autodoc_default_options = {"members": True, "show-inheritance": False}
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# sphinx-gallery: every example runs (no plot_ prefix needed), figures captured from the Figures the
# examples return (the scraper in docs/_ext/figure_scraper.py: bikemass never uses pyplot).
# The sort key is given as its class, which every sphinx-gallery since 0.15 (the docs extra's floor)
# takes; Sphinx then cannot cache this dict between builds (config.cache, its only consequence: a full
# re-read, which run_stale_examples asks for anyway), so that one warning is not an error.
suppress_warnings = ["config.cache"]
sphinx_gallery_conf = {
    "examples_dirs": "examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r".*\.py$",
    "within_subsection_order": FileNameSortKey,
    "image_scrapers": ("figure_scraper",),
    "reset_modules": (),
    "download_all_examples": False,
    "show_memory": False,
    "show_signature": False,
    "min_reported_time": 1e9,
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "capture_repr": ("_repr_html_", "__repr__"),
    "matplotlib_animations": False,
    "plot_gallery": "True",
    "image_srcset": [],
    # every build runs every example (an unchanged example can still break when bikemass changes)
    "run_stale_examples": True,
}

html_math_renderer = "plain"    # docs/_ext/plain_math.py: no MathJax from a CDN
html_theme = "pydata_sphinx_theme"
html_title = f"bikemass {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "navbar_end": ["theme-switcher"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
html_show_sourcelink = False
html_copy_source = False
