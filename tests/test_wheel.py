"""What users install: the wheel, built from this checkout and installed into a clean virtual
environment, works from an unrelated folder and gives the checkout's numbers.

The wheel is built from a copy of the checkout in a temporary folder (nothing is written into the
checkout), without build isolation or an index (no network).  The virtual environment has no
packages of its own but the wheel; a ``.pth`` file puts this environment's site-packages on its
path for numpy & co.  Python processes the ``.pth`` files of site directories only, not of
folders a ``.pth`` adds, so an editable install of bikemass here stays out of the venv (checked).
Numbers of the installed wheel and of the checkout agree to 1e-12 (the same code and data on the
same machine; any difference means the wheel ships something else).
"""

import contextlib
import io
import json
import os
import re
import shutil
import site
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

import bikemass
from bikemass.cli.main import main

pytestmark = pytest.mark.slow     # builds and installs the wheel in a scratch environment (~45 s): pytest -m 'not slow' leaves it out

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ("pyproject.toml", "README.md", "src", "bodies", "frames", "reference")
"""What building the wheel reads."""
DATA = ("bodies", "frames", "reference")
TOL = 1e-12


def run(argv, **kwargs):
    out = subprocess.run([str(a) for a in argv], capture_output=True, text=True, timeout=300, **kwargs)
    assert out.returncode == 0, f"{argv}: exit {out.returncode}\n{out.stderr[-3000:]}"
    return out.stdout


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("wheel")
    source = tmp / "source"
    source.mkdir()
    for name in SOURCES:
        path = ROOT / name
        if path.is_dir():
            shutil.copytree(path, source / name, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
        else:
            shutil.copy2(path, source / name)
    run([sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "--no-build-isolation", "--no-index",
         "-w", tmp / "dist", source])
    [built] = (tmp / "dist").glob("bikemass-*.whl")
    return built


@pytest.fixture(scope="module")
def venv(wheel, tmp_path_factory):
    """``(bin folder, unrelated working folder, environment)`` of a venv holding only the wheel."""
    tmp = tmp_path_factory.mktemp("venv")
    run([sys.executable, "-m", "venv", "--without-pip", tmp / "venv"])
    bin_dir = tmp / "venv" / ("Scripts" if os.name == "nt" else "bin")
    python = bin_dir / "python"
    run([sys.executable, "-m", "pip", "-q", "--python", python, "install", "--no-deps", "--no-index", wheel])
    purelib = Path(run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]).strip())
    parents = [*site.getsitepackages(), site.getusersitepackages()]
    (purelib / "parent_environment.pth").write_text("\n".join(p for p in parents if Path(p).is_dir()) + "\n")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "BIKEMASS_DATA")}
    env["PYTHONNOUSERSITE"] = "1"
    elsewhere = tmp / "elsewhere"
    elsewhere.mkdir()
    return bin_dir, elsewhere, env


def bikemass_cli(venv, *argv):
    bin_dir, elsewhere, env = venv
    return run([bin_dir / "bikemass", *argv], cwd=elsewhere, env=env)


def checkout_cli(*argv):
    stdout = io.StringIO()
    with contextlib.redirect_stdout(stdout):
        assert main(list(argv)) == 0
    return stdout.getvalue()


def assert_close(ours, theirs, where="$"):
    """Same structure, same strings, numbers within TOL."""
    if isinstance(theirs, dict):
        assert set(ours) == set(theirs), where
        for key in theirs:
            assert_close(ours[key], theirs[key], f"{where}.{key}")
    elif isinstance(theirs, list):
        assert len(ours) == len(theirs), where
        for i, (a, b) in enumerate(zip(ours, theirs)):
            assert_close(a, b, f"{where}[{i}]")
    elif isinstance(theirs, (int, float)) and not isinstance(theirs, bool):
        assert ours == pytest.approx(theirs, rel=TOL, abs=TOL), where
    else:
        assert ours == theirs, where


def test_wheel_holds_every_module_and_every_shipped_file(wheel):
    names = set(zipfile.ZipFile(wheel).namelist())
    modules = {"bikemass/" + p.relative_to(ROOT / "src" / "bikemass").as_posix()
               for p in (ROOT / "src" / "bikemass").rglob("*.py")}
    data = {f"bikemass/shipped/{p.relative_to(ROOT).as_posix()}"
            for folder in DATA for p in (ROOT / folder).rglob("*.yaml")}
    assert len(data) > 20
    assert "bikemass/py.typed" in names                  # PEP 561 marker: type checkers read the annotations
    assert modules - names == set()
    assert data - names == set()


def test_installed_package_is_the_wheel_not_the_checkout(venv):
    bin_dir, elsewhere, env = venv
    where = run([bin_dir / "python", "-c", "import bikemass, bikemass.core.paths as p; "
                 "print(bikemass.__file__); print(p.data_root())"], cwd=elsewhere, env=env).split("\n")
    venv_root = bin_dir.parent.resolve()
    for path in where[:2]:
        assert Path(path).resolve().is_relative_to(venv_root), path
        assert not Path(path).resolve().is_relative_to(ROOT), path


def test_version_is_the_package_metadata_version(venv):
    bin_dir, elsewhere, env = venv
    metadata = run([bin_dir / "python", "-c", "import importlib.metadata as m; print(m.version('bikemass'))"],
                   cwd=elsewhere, env=env).strip()
    assert metadata == bikemass.__version__
    assert bikemass_cli(venv, "--version").strip() == f"bikemass {metadata}"


def test_riders_lists_every_shipped_pose_with_the_checkouts_numbers(venv):
    installed = json.loads(bikemass_cli(venv, "riders", "--format", "json"))
    poses = {p.stem.replace("_", "-") for p in (ROOT / "bodies" / "poses").glob("*.yaml")}
    assert set(installed["riders"]) == {p for p in poses if not p.endswith("-thesis")}
    assert_close(installed, json.loads(checkout_cli("riders", "--format", "json")))


def test_params_are_the_checkouts(venv):
    argv = ("params", "jamis", "--rider", "relaxed", "--format", "json")
    installed = json.loads(bikemass_cli(venv, *argv))
    assert len([v for v in installed.values() if isinstance(v, (int, float))]) >= 26
    assert_close(installed, json.loads(checkout_cli(*argv)))


def matched(report):
    """``(matched, total)`` of the summary line of a study's report.md."""
    found = re.search(r"\*\*(\d+) of (\d+)\*\* entries within", report.read_text())
    assert found, report
    return int(found[1]), int(found[2])


def test_study_matches_what_the_checkout_matches(venv, study):
    out = venv[1] / "study out"
    bikemass_cli(venv, "study", "--out", out, "--no-figures", "--quiet")
    assert matched(out / "report.md") == matched(study[0] / "report.md")
    assert_close(json.loads((out / "stability_ranges.json").read_text()),
                 json.loads((study[0] / "stability_ranges.json").read_text()))
