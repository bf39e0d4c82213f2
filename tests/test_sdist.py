"""What a packager gets: the source distribution holds the tests and their data, the shipped data,
the documentation, the benchmarks and the examples (MANIFEST.in), so the test suite runs from it
alone (docs/releases.md); a wheel built from the unpacked sdist installs into a clean virtual
environment and finds its shipped data from an unrelated folder.

The sdist is built from a copy of the checkout in a temporary folder (nothing is written into the
checkout) by setuptools' PEP 517 backend in this environment (no build isolation, no network).
"""

import json
import os
import shutil
import site
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

import bikemass

ROOT = Path(__file__).resolve().parents[1]
CARRIED = ("tests", "bodies", "frames", "reference", "docs", "benchmarks", "examples")
"""Folders the sdist carries whole (less what builds and runs write)."""
TOP = ("pyproject.toml", "README.md", "CHANGELOG.md", "CITATION.cff", "MANIFEST.in")
WRITTEN = {"__pycache__", ".pytest_cache", ".hypothesis", "_build", "api-reference", "auto_examples",
           "bikemass.egg-info", "build", "dist", ".git"}
"""Folders that builds, test runs and the documentation build write: never part of the source."""

pytestmark = pytest.mark.slow


def _source_files():
    """Repository-relative paths of the files the sdist must carry (the source folders' files and the
    top-level files of :data:`TOP`)."""
    files = set(TOP)
    for folder in (*CARRIED, "src"):
        for path in (ROOT / folder).rglob("*"):
            rel = path.relative_to(ROOT)
            if path.is_file() and not WRITTEN & set(rel.parts) and path.suffix not in (".pyc", ".pyo") \
                    and rel.as_posix() != "docs/sg_execution_times.rst":
                files.add(rel.as_posix())
    return files


def run(argv, **kwargs):
    out = subprocess.run([str(a) for a in argv], capture_output=True, text=True, timeout=600, **kwargs)
    assert out.returncode == 0, f"{argv}: exit {out.returncode}\n{out.stderr[-3000:]}"
    return out.stdout


@pytest.fixture(scope="module")
def sdist(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("sdist")
    source = tmp / "source"
    source.mkdir()
    for name in (*TOP, *CARRIED, "src", ".ci"):
        path = ROOT / name
        if path.is_dir():
            shutil.copytree(path, source / name, ignore=shutil.ignore_patterns(*WRITTEN, "*.pyc"))
        else:
            shutil.copy2(path, source / name)
    name = run([sys.executable, "-c", "from setuptools import build_meta; print(build_meta.build_sdist('dist'))"],
               cwd=source).strip().splitlines()[-1]
    return source / "dist" / name


def test_sdist_holds_the_tests_data_docs_benchmarks_and_examples(sdist):
    prefix = f"bikemass-{bikemass.__version__}/"
    assert sdist.name == f"bikemass-{bikemass.__version__}.tar.gz"
    with tarfile.open(sdist) as tar:
        held = {m.name[len(prefix):] for m in tar.getmembers() if m.isfile()}
    missing = _source_files() - held
    assert not missing, f"the sdist lacks {sorted(missing)[:20]}"
    for folder in ("tests/data", "bodies", "frames", "reference"):      # data, not only code
        assert any(f.startswith(folder + "/") and f.endswith((".yaml", ".json", ".txt", ".csv")) for f in held), folder
    leftovers = WRITTEN - {"bikemass.egg-info"}            # setuptools's own metadata belongs in an sdist
    assert not [f for f in held if leftovers & set(f.split("/")[:-1]) or f.endswith(".pyc")], "build leftovers"


def test_wheel_from_the_sdist_installs_and_runs(sdist, tmp_path):
    """Unpacked, the sdist builds a wheel holding every shipped file, which installs into a clean
    virtual environment and answers from an unrelated folder."""
    with tarfile.open(sdist) as tar:
        tar.extractall(tmp_path, filter="data")
    unpacked = tmp_path / f"bikemass-{bikemass.__version__}"
    run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "--no-index",
         "-w", tmp_path / "dist", unpacked])
    [wheel] = (tmp_path / "dist").glob("bikemass-*.whl")
    with zipfile.ZipFile(wheel) as z:
        names = set(z.namelist())
    for folder in ("bodies", "frames", "reference"):
        shipped = {p.relative_to(ROOT / folder).as_posix() for p in (ROOT / folder).rglob("*")
                   if p.is_file() and p.suffix in (".yaml", ".md")}
        assert shipped and {f"bikemass/shipped/{folder}/{s}" for s in shipped} <= names, folder
    run([sys.executable, "-m", "venv", "--without-pip", tmp_path / "venv"])
    bin_dir = tmp_path / "venv" / ("Scripts" if os.name == "nt" else "bin")
    run([sys.executable, "-m", "pip", "-q", "--python", bin_dir / "python", "install", "--no-deps", "--no-index",
         wheel])
    purelib = Path(run([bin_dir / "python", "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]).strip())
    parents = [*site.getsitepackages(), site.getusersitepackages()]
    (purelib / "parent_environment.pth").write_text("\n".join(p for p in parents if Path(p).is_dir()) + "\n")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BIKEMASS_DATA")}
    env["PYTHONNOUSERSITE"] = "1"
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    assert run([bin_dir / "bikemass", "--version"], cwd=elsewhere, env=env).strip() == \
        f"bikemass {bikemass.__version__}"
    where = run([bin_dir / "python", "-c", "import bikemass.core.paths as p; print(p.frames_dir())"],
                cwd=elsewhere, env=env).strip()
    assert Path(where).is_relative_to(purelib)
    params = json.loads(run([bin_dir / "bikemass", "params", "benchmark", "--format", "json"], cwd=elsewhere,
                            env=env))
    assert params["w"] == 1.02                          # Meijaard et al. (2007), Table 1: wheelbase 1.02 m
