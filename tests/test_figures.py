"""Figures as library values: matplotlib Figures from the object API (the caller's backend and
pyplot state untouched), the shared figure options, vector text kept as text."""

import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from bikemass.cli import main

SRC = Path(__file__).parents[1] / "src"

EVERY_FIGURE = """
import sys
import matplotlib
matplotlib.use("svg")                      # the caller's choice, not the default
from matplotlib.figure import Figure
from bikemass import catalog
from bikemass.bicycle.drawing import plot_side_view
from bikemass.fe import frame_modes
from bikemass.fe.plot import plot_frame_modes
from bikemass.frame import frame_structure
from bikemass.plots.stability import plot_comparison, plot_eigenvalues
from bikemass.stability import canonical_matrices, speed_grid, stability

result = stability(canonical_matrices(catalog.parameters("benchmark", "none", "exact")), speed_grid(0, 8, 0.5))
figures = [plot_eigenvalues(result, "benchmark"), plot_eigenvalues(result.modes),
           plot_comparison({"benchmark": result.modes}),
           plot_side_view(catalog.load_bicycle("benchmark")),
           plot_frame_modes(frame_modes(frame_structure("jamis"), "fix-rear", 2))]
assert all(type(f) is Figure for f in figures), [type(f) for f in figures]
assert matplotlib.get_backend() == "svg", matplotlib.get_backend()
assert "matplotlib.pyplot" not in sys.modules, "pyplot imported"
print("ok")
"""


def test_plotting_leaves_the_callers_backend_and_pyplot_alone():
    """Every plotting function returns a Figure; the backend chosen by the caller is unchanged
    and pyplot (global figure state) is never imported.  A fresh interpreter, so that no other
    test's imports hide a use of pyplot."""
    done = subprocess.run([sys.executable, "-c", EVERY_FIGURE], capture_output=True, text=True,
                          env={"PYTHONPATH": str(SRC), "PATH": "/usr/bin:/bin"}, timeout=120)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr[-2000:]


def _png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def test_size_and_dpi_set_the_pixels(tmp_path, capsys):
    png = tmp_path / "side.png"
    assert main(["draw", "benchmark", "-o", str(png), "--size", "4,3", "--dpi", "50"]) == 0
    assert _png_size(png.read_bytes()) == (200, 150)


def test_svg_keeps_its_text_as_text(tmp_path, capsys):
    svg = tmp_path / "side.svg"
    assert main(["draw", "benchmark", "-o", str(svg)]) == 0
    texts = [t for e in ET.parse(svg).iter() if e.tag.endswith("text") for t in e.itertext()]
    assert any("height" in t for t in texts)            # the axis label, as editable text


def test_axis_limits_reach_the_axes(tmp_path, capsys):
    svg = tmp_path / "side.svg"
    from bikemass import catalog
    from bikemass.bicycle.drawing import plot_side_view
    ax = plot_side_view(catalog.load_bicycle("benchmark"), xlim=(-0.5, 1.5), ylim=(0, 1.4)).axes[0]
    assert ax.get_xlim() == pytest.approx((-0.5, 1.5)) and ax.get_ylim() == pytest.approx((0, 1.4))
    assert main(["draw", "benchmark", "-o", str(svg), "--xlim=-0.5:1.5"]) == 0


@pytest.mark.parametrize("argv,needle", [
    (["eig", "benchmark", "--plot", "eig.xyz"], ".svg"),
    (["modes", "jamis", "--plot", "m.docx"], ".png"),
    (["draw", "benchmark", "-o", "d.txt"], ".pdf"),
    (["compare", "benchmark", "-o", "c.csv"], ".png"),
    (["draw", "benchmark", "-o", "d.png", "--size", "4"], "--size"),
    (["draw", "benchmark", "-o", "d.png", "--size", "0.1,3"], "--size"),
    (["draw", "benchmark", "-o", "d.png", "--dpi", "many"], "--dpi"),
    (["stability", "benchmark", "--plot", "s.png", "--xlim", "5:1"], "--xlim"),
    (["eig", "benchmark", "--plot", "s.png", "--ylim", "a:b"], "--ylim"),
])
def test_bad_figure_options_exit_2_before_any_work(tmp_path, capsys, monkeypatch, argv, needle):
    monkeypatch.chdir(tmp_path)
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and needle in err
    assert list(tmp_path.iterdir()) == []              # nothing written


def test_eig_with_only_a_figure_prints_no_table(tmp_path, capsys):
    svg = tmp_path / "eig.svg"
    assert main(["eig", "benchmark", "--plot", str(svg)]) == 0
    assert capsys.readouterr().out == "" and svg.stat().st_size > 0
    assert main(["eig", "benchmark", "--speeds", "0:1:1", "--plot", str(svg), "--format", "csv"]) == 0
    assert capsys.readouterr().out.startswith("speed,weave_1_re")      # a table asked for: printed
