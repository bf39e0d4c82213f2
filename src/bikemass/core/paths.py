"""Where the shipped data live and how names resolve to files.

The shipped data are three folders: ``bodies/`` (anthropometry, poses), ``frames/``
(bicycles, materials) and ``reference/`` (the thesis's printed tables).  They sit at
the top of the repository, and a wheel carries them as ``bikemass/shipped/``.  The
data folder is the first of:

1. ``BIKEMASS_DATA``, when set (it must hold the folders it is asked for);
2. the installed package's data (``bikemass/shipped/``, through :mod:`importlib.resources`);
3. the checkout (the repository two folders above ``src/bikemass``).

No data found is an error (:class:`~bikemass.core.errors.InputError`), never an empty list.
A name that is an existing file path is used as it is.

Files named inside other files (``base:``, ``materials:``, ``parameters:``, a chain pose's
``bike:``, an anthropometry, ``yeadon:``) are found by :func:`named_file` (next to the
naming file) and :func:`resolve` (a shipped name).  Under :func:`confined` (the web page
reading an upload) every such file, and every file the input gate reads, must lie in the
shipped data or in the folders given: anything else is refused before it is looked at, so
an upload cannot reach, nor echo, any other file on the server.
"""

import contextlib
import contextvars
import os
from pathlib import Path

from . import data_folder
from .choices import closest
from .errors import InputError, short

_REACH = contextvars.ContextVar("bikemass_reach", default=None)
"""While :func:`confined` is active: the resolved folders files may be read from."""


def data_root() -> Path:
    """Folder holding ``bodies/``, ``frames/`` and ``reference/`` (see the module's lookup order)."""
    root = data_folder.found_root()
    if root is None:
        places = [f"the installed package ({data_folder.installed_data()})"]
        places += [f"the checkout ({top})" for top in [data_folder.checkout()] if top is not None]
        raise InputError("bikemass", "shipped data", f"bodies/, frames/ and reference/ in {' or in '.join(places)}; "
                         "none found (reinstall bikemass)")
    return root


def shipped_dir(name) -> Path:
    """The shipped folder ``name`` (``"bodies"``, ``"frames"``, ``"reference"``), which must exist."""
    folder = data_root() / name
    if not folder.is_dir():
        missing_folder(folder)
    return folder


def missing_folder(folder, expected="a folder of shipped files"):
    """Raise the one-line error for a shipped folder that is not there (or holds nothing)."""
    env = os.environ.get("BIKEMASS_DATA")
    if env:
        raise InputError(f"BIKEMASS_DATA={env}", str(folder),
                         f"{expected} (BIKEMASS_DATA must name a folder holding bodies/, frames/ and reference/)")
    raise InputError("bikemass", str(folder), f"{expected} (reinstall bikemass)")


def bodies_dir() -> Path:
    return shipped_dir("bodies")


def frames_dir() -> Path:
    return shipped_dir("frames")


def reference_dir() -> Path:
    return shipped_dir("reference")


@contextlib.contextmanager
def confined(*folders):
    """While active, files may only be read from the shipped data folders (``bodies/``,
    ``frames/``, ``reference/``) and from ``folders``: :func:`check_reach` (called by the input
    gate for every file, and by :func:`named_file` and :func:`resolve` before they look for one)
    refuses anything else.  For input that must not reach the machine's other files (the web
    page's uploads)."""
    root = data_folder.found_root()
    shipped = [root / name for name in data_folder.SHIPPED] if root is not None else []
    token = _REACH.set(tuple(os.path.realpath(f) for f in (*shipped, *folders)))
    try:
        yield
    finally:
        _REACH.reset(token)


def within_reach(path):
    """Whether ``path`` may be read: always, unless :func:`confined` is active and it lies outside
    the folders allowed (links are followed before the check)."""
    allowed = _REACH.get()
    if allowed is None:
        return True
    try:
        real = os.path.realpath(path)
    except (OSError, ValueError):
        return False
    return any(real == folder or real.startswith(folder + os.sep) for folder in allowed)


def near_spec(spec_path, name):
    """A file named relative to a spec file (a sweep's, an optimisation's), if it exists there; else the
    name as given (a shipped name, or a path from the current folder)."""
    here = Path(spec_path).parent / name
    return str(here.resolve()) if within_reach(here) and here.is_file() else name


def near_spec_file(spec_path, name):
    """A stiffness choice as :func:`near_spec` reads a file name (one with a suffix or a folder:
    ``frame.yaml``, ``data/S.csv``) relative to the spec file; a material or ``infinite`` as given."""
    return near_spec(spec_path, name) if Path(name).suffix or "/" in name or "\\" in name else name


def check_reach(path, source, key, given=None):
    """``path`` if :func:`within_reach`, else InputError naming ``source`` and ``key`` (the file
    and key that named it) and the name as ``given`` there, never the file's content."""
    if not within_reach(path):
        raise InputError(source, key, "a shipped name or a file of the upload itself (an uploaded file cannot "
                                      f"reach other files), got {short(str(given if given is not None else path))}")
    return path


def named_file(node, name=None):
    """The path a file names at ``node`` (a :class:`~bikemass.config.Node`): ``name`` (default its
    string value) as an absolute path, or relative to the naming file's folder; checked by
    :func:`check_reach` before anyone looks whether it exists."""
    name = node.string() if name is None else name
    given = Path(name)
    path = given if given.is_absolute() else Path(node.source).parent / given
    return check_reach(path, node.source, node.key, name)


def resolve(name, folder: Path, what: str) -> Path:
    """Path for ``name``: an existing file, else ``folder/<name>.yaml`` (``-`` and ``_`` alike);
    InputError for a name the system refuses as a path (too long, ...), or out of reach
    (:func:`confined`)."""
    try:
        return _resolve(name, folder, what)
    except OSError as exc:
        raise InputError(name, "(file)", f"a {what} file name the system accepts "
                                         f"({exc.strerror or type(exc).__name__})") from None


def _resolve(name, folder, what):
    p = Path(name)
    if p.suffix in (".yaml", ".yml", ".json", ".txt") or (within_reach(p) and p.is_file()):
        check_reach(p, name, "(file)")
        if not os.path.lexists(p):
            raise InputError(p, "(file)", f"an existing {what} file")
        return p   # not necessarily a regular file: the input gate says what it is
    shipped_name = p.name == name and name not in (".", "..")      # a name, not a path into another folder
    for stem in (name, name.replace("-", "_"), name.replace("_", "-")) if shipped_name else ():
        candidate = folder / f"{stem}.yaml"
        if candidate.is_file():
            return candidate
    known = available(folder)
    raise InputError(name, "(name)", f"a {what} file or one of: {', '.join(known)}{closest_name(name, known)}")


def closest_name(name, names):
    """``" (did you mean 'x'?)"`` for the entry of ``names`` closest to a misspelt ``name``, else ``""``."""
    return closest(Path(str(name)).stem.replace("_", "-"), names)


SHARED_FILES = ("materials", "chart_defaults")
"""YAML files in ``frames/`` that are not bicycles."""


def available(folder: Path):
    """Names of the shipped YAML files in ``folder`` (``_`` shown as ``-``), shared files left out;
    a missing or empty folder is an error (missing data must not look like an empty list)."""
    if not folder.is_dir():
        missing_folder(folder)
    names = sorted(p.stem.replace("_", "-") for p in folder.glob("*.yaml") if p.stem not in SHARED_FILES)
    if not names:
        missing_folder(folder, "shipped files (*.yaml); this folder has none")
    return names
