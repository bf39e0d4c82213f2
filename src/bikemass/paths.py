"""Where the shipped data lives and how names resolve to files.

``bodies/`` (anthropometry, poses) and ``frames/`` (bicycles, materials) sit at
the repository root; set ``BIKEMASS_DATA`` to a folder holding both to use
another copy.  A name that is an existing file path is used as it is.
"""

import os
from pathlib import Path

from .errors import InputError


def data_root() -> Path:
    """Folder holding ``bodies/`` and ``frames/``."""
    env = os.environ.get("BIKEMASS_DATA")
    return Path(env) if env else Path(__file__).resolve().parents[2]


def bodies_dir() -> Path:
    return data_root() / "bodies"


def frames_dir() -> Path:
    return data_root() / "frames"


def resolve(name, folder: Path, what: str) -> Path:
    """Path for ``name``: an existing file, else ``folder/<name>.yaml`` (``-`` and ``_`` alike)."""
    p = Path(name)
    if p.suffix in (".yaml", ".yml", ".json", ".txt") or p.is_file():
        if not os.path.lexists(p):
            raise InputError(p, "(file)", f"an existing {what} file")
        return p   # not necessarily a regular file: the input gate says what it is
    for stem in (name, name.replace("-", "_"), name.replace("_", "-")):
        candidate = folder / f"{stem}.yaml"
        if candidate.is_file():
            return candidate
    known = available(folder)
    raise InputError(name, "(name)", f"a {what} file or one of: {', '.join(known)}{closest_name(name, known)}")


def closest_name(name, names):
    """``" (did you mean 'x'?)"`` for the entry of ``names`` closest to a misspelt ``name``, else ``""``."""
    from .choices import closest
    return closest(Path(str(name)).stem.replace("_", "-"), names)


SHARED_FILES = ("materials", "chart_defaults")
"""YAML files in ``frames/`` that are not bicycles."""


def available(folder: Path):
    """Names of the shipped YAML files in ``folder`` (``_`` shown as ``-``), shared files left out;
    a missing folder is an error (a wrong ``BIKEMASS_DATA`` must not look like an empty list)."""
    if not folder.is_dir():
        env = os.environ.get("BIKEMASS_DATA")
        raise InputError(f"BIKEMASS_DATA={env}" if env else "bikemass", str(folder),
                         "a folder of shipped files (BIKEMASS_DATA must name a folder holding bodies/ and frames/)")
    return sorted(p.stem.replace("_", "-") for p in folder.glob("*.yaml") if p.stem not in SHARED_FILES)
