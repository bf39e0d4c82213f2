"""Where the data folder is: ``BIKEMASS_DATA``, else the installed package's data, else the
checkout (the lookup order of :mod:`bikemass.core.paths`, which raises when there is none).
Nothing here raises: error messages (:func:`bikemass.core.errors.shown`) name a shipped file
relative to this folder.
"""

import os
from pathlib import Path

SHIPPED = ("bodies", "frames", "reference")
"""The shipped data folders."""


def found_root():
    """The data folder by the lookup order of :mod:`bikemass.core.paths`, or None when neither the
    package nor a checkout has one."""
    env = os.environ.get("BIKEMASS_DATA")
    if env:
        return Path(env)
    for root in (installed_data(), checkout()):
        if root is not None and all((root / name).is_dir() for name in SHIPPED):
            return root
    return None


def checkout():
    """The repository's top folder when bikemass runs from a checkout (``<top>/src/bikemass``), else None."""
    package = Path(__file__).resolve().parents[1]     # this file is <top>/src/bikemass/core/data_folder.py
    return package.parents[1] if package.parent.name == "src" else None


def installed_data() -> Path:
    """``bikemass/shipped/`` of the installed package (absent in a checkout: the data sit at its top)."""
    # lazy: importlib.resources (and tempfile, random, typing behind it) stays out of bikemass --help
    from importlib.resources import files
    return Path(str(files("bikemass") / "shipped"))
