"""Where the shipped data are found: BIKEMASS_DATA, then the installed package's data, then the
checkout; none found is one line and exit status 2 (never an empty table), while ``--version``
and ``--help`` never need the data.  tests/test_wheel.py checks the same from an installed wheel."""

import json
import shutil
from pathlib import Path

import pytest

from bikemass.core import data_folder, paths
from bikemass.cli.main import main

ROOT = Path(__file__).resolve().parents[1]


def copy_of_the_data(folder, wheelbase):
    """The shipped folders copied into ``folder``, the benchmark's wheelbase set to ``wheelbase`` (m)."""
    for name in data_folder.SHIPPED:
        shutil.copytree(ROOT / name, folder / name)
    benchmark = folder / "frames" / "benchmark.yaml"
    text = benchmark.read_text()
    assert "\nw: 1.02\n" in text
    benchmark.write_text(text.replace("\nw: 1.02\n", f"\nw: {wheelbase}\n"))
    return folder


def wheelbase(capsys):
    assert main(["params", "benchmark", "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)["w"]


@pytest.fixture
def no_package_data(monkeypatch, tmp_path):
    """A checkout as it is: no ``bikemass/shipped`` beside the code, BIKEMASS_DATA unset."""
    monkeypatch.delenv("BIKEMASS_DATA", raising=False)
    monkeypatch.setattr(data_folder, "installed_data", lambda: tmp_path / "no-package-data")


def test_the_checkout_is_used_without_package_data(no_package_data, capsys):
    assert paths.data_root() == ROOT
    assert wheelbase(capsys) == 1.02


def test_package_data_come_before_the_checkout(no_package_data, monkeypatch, tmp_path, capsys):
    installed = copy_of_the_data(tmp_path / "shipped", 1.5)
    monkeypatch.setattr(data_folder, "installed_data", lambda: installed)
    assert paths.data_root() == installed
    assert wheelbase(capsys) == 1.5


def test_bikemass_data_comes_first(no_package_data, monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(data_folder, "installed_data", lambda: copy_of_the_data(tmp_path / "shipped", 1.5))
    monkeypatch.setenv("BIKEMASS_DATA", str(copy_of_the_data(tmp_path / "mine", 1.25)))
    assert wheelbase(capsys) == 1.25


@pytest.mark.parametrize("from_checkout", [True, False], ids=["checkout", "installed"])
@pytest.mark.parametrize("argv", [["riders"], ["params", "jamis"], ["rider", "relaxed"],
                                  ["study", "--out", "OUT", "--no-figures"]])
def test_no_data_anywhere_is_one_line_and_status_2(argv, from_checkout, monkeypatch, tmp_path, capsys):
    monkeypatch.delenv("BIKEMASS_DATA", raising=False)
    monkeypatch.setattr(data_folder, "installed_data", lambda: tmp_path / "site-packages" / "bikemass" / "shipped")
    monkeypatch.setattr(data_folder, "checkout", lambda: tmp_path / "top" if from_checkout else None)
    out = tmp_path / "study"
    assert main([str(out) if a == "OUT" else a for a in argv]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    [line] = captured.err.splitlines()
    assert line.startswith("bikemass: error: ") and "none found (reinstall bikemass)" in line
    assert str(tmp_path / "site-packages" / "bikemass" / "shipped") in line
    assert "BIKEMASS_DATA" not in line
    assert (f"or in the checkout ({tmp_path / 'top'})" in line) == from_checkout
    assert not out.exists()


def test_an_empty_folder_is_no_empty_table(monkeypatch, tmp_path, capsys):
    data = copy_of_the_data(tmp_path / "mine", 1.02)
    for pose in (data / "bodies" / "poses").glob("*.yaml"):
        pose.unlink()
    monkeypatch.setenv("BIKEMASS_DATA", str(data))
    assert main(["riders"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err == (f"bikemass: error: BIKEMASS_DATA={data}: {data / 'bodies' / 'poses'}: shipped files "
                            "(*.yaml); this folder has none (BIKEMASS_DATA must name a folder holding bodies/, "
                            "frames/ and reference/)\n")


def test_version_and_help_need_no_data(monkeypatch, tmp_path, capsys):
    monkeypatch.setenv("BIKEMASS_DATA", str(tmp_path / "nothing here"))
    with pytest.raises(SystemExit) as exit_:
        main(["--version"])
    assert exit_.value.code in (0, None)
    assert capsys.readouterr().out.startswith("bikemass ")
    with pytest.raises(SystemExit) as exit_:
        main(["params", "--help"])
    assert exit_.value.code in (0, None)
    text = " ".join(capsys.readouterr().out.split())
    assert "a shipped bicycle (none found: BIKEMASS_DATA=" in text


def test_help_lists_the_shipped_bicycles(monkeypatch, capsys):
    monkeypatch.delenv("BIKEMASS_DATA", raising=False)
    with pytest.raises(SystemExit):
        main(["params", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    names = sorted(p.stem.replace("_", "-") for p in (ROOT / "frames").glob("*.yaml")
                   if p.stem not in paths.SHARED_FILES)
    assert f"a shipped bicycle ({', '.join(names)})" in text
