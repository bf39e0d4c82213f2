"""Outputs: an overwritten file keeps its permissions and its symbolic link, an output folder is
replaced whole or not at all, and frame modes come out the same on every call."""

import os
import stat

import numpy as np
import pytest

from bikemass.cli.main import main
from bikemass.fe import frame_modes
from bikemass.fe.modes import DENSE_LIMIT
from bikemass.fe.model import build_mesh
from bikemass.core.output import new_folder
from bikemass.scenario.frame import frame_structure


def test_overwrite_keeps_permissions_and_symlink(tmp_path, capsys):
    target = tmp_path / "real.yaml"
    target.write_text("old\n")
    os.chmod(target, 0o600)
    link = tmp_path / "link.yaml"
    link.symlink_to(target)
    assert main(["params", "benchmark", "-o", str(link)]) == 0
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o600
    assert target.read_text().startswith("w: 1.02\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.yaml", "real.yaml"]   # no temporary left


def test_a_folder_is_replaced_whole(tmp_path):
    out = tmp_path / "study"
    out.mkdir()
    (out / "report.md").write_text("old report\n")
    (out / "stale.png").write_text("from an older run\n")
    with new_folder(out) as folder:
        (folder / "report.md").write_text("new report\n")
        assert (out / "stale.png").exists()          # the old run stays complete until the end
    assert sorted(p.name for p in out.iterdir()) == ["report.md"]
    assert (out / "report.md").read_text() == "new report\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["study"]


def test_an_interrupted_folder_leaves_the_old_one(tmp_path):
    out = tmp_path / "study"
    out.mkdir()
    (out / "report.md").write_text("old report\n")
    with pytest.raises(KeyboardInterrupt):
        with new_folder(out) as folder:
            (folder / "report.md").write_text("half\n")
            raise KeyboardInterrupt
    assert (out / "report.md").read_text() == "old report\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["study"]


def test_sparse_frame_modes_are_the_same_every_call():
    structure = frame_structure("jamis")
    assert build_mesh(structure, None, 0.01).n_dof > DENSE_LIMIT    # the sparse (eigsh) path
    first, second = (frame_modes(structure, "free", 6, None, 0.01) for _ in range(2))
    assert np.array_equal(first.frequencies_hz, second.frequencies_hz)
    assert np.array_equal(first.shapes, second.shapes)


def test_a_full_disk_is_one_line_naming_the_file_and_leaves_the_old_one(tmp_path, monkeypatch, capsys):
    """A write that fails half-way (ENOSPC) names the path, removes its temporary file and leaves
    the file that was there."""
    import errno

    from bikemass.core import output
    out = tmp_path / "params.yaml"
    out.write_text("old\n")
    real = output.os.fdopen

    class Full:
        def __init__(self, fd, mode):
            self.fh = real(fd, mode)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.fh.close()

        def write(self, data):
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(output.os, "fdopen", lambda fd, mode="r", *a, **k: Full(fd, mode) if "w" in mode
                        else real(fd, mode, *a, **k))
    assert main(["params", "benchmark", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err == (f"bikemass: error: {out}: (output): room to write the file in its folder (No space left on "
                   "device; nothing was written)\n")
    assert out.read_text() == "old\n" and sorted(p.name for p in tmp_path.iterdir()) == ["params.yaml"]
