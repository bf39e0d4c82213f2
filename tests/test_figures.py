"""Figures as library values: matplotlib Figures from the object API (the caller's backend and
pyplot state untouched), the shared figure options, vector text kept as text."""

import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from bikemass.cli.main import main
from bikemass.plots.critical_speeds import plot_critical_speeds
from bikemass.plots.stability import plot_eigenvalues

SRC = Path(__file__).parents[1] / "src"

EVERY_FIGURE = """
import sys
import matplotlib
matplotlib.use("svg")                      # the caller's choice, not the default
from matplotlib.figure import Figure
from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.plots.side_view import plot_side_view
from bikemass.fe import frame_modes
from bikemass.plots.frame_modes import plot_frame_modes
from bikemass.scenario.frame import frame_structure
from bikemass.plots.critical_speeds import plot_critical_speeds
from bikemass.plots.stability import plot_eigenvalues
from bikemass.analysis.engine.stability import analyse
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.whipple import whipple_model

result = analyse(whipple_model(scenario_parameters("benchmark", "none", "exact")), speed_grid(0, 8, 0.5))
figures = [plot_eigenvalues(result, "benchmark"), plot_eigenvalues(result.modes),
           plot_critical_speeds({"no rider": {"rigid": result}}),
           plot_side_view(catalog.load_bicycle("benchmark")),
           plot_frame_modes(frame_modes(frame_structure("jamis"), "fix-rear", 2))]
assert all(isinstance(f, Figure) for f in figures), [type(f) for f in figures]
# Jupyter shows them without %matplotlib inline: IPython's rich display asks for _repr_png_
assert all(f._repr_png_().startswith(b"\\x89PNG") for f in figures)
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
    assert main(["draw", "benchmark", "--plot", str(png), "--size", "4,3", "--dpi", "50"]) == 0
    assert _png_size(png.read_bytes()) == (200, 150)


def test_svg_keeps_its_text_as_text(tmp_path, capsys):
    svg = tmp_path / "side.svg"
    assert main(["draw", "benchmark", "--plot", str(svg)]) == 0
    texts = [t for e in ET.parse(svg).iter() if e.tag.endswith("text") for t in e.itertext()]
    assert any("height" in t for t in texts)            # the axis label, as editable text


def test_axis_limits_reach_the_axes(tmp_path, capsys):
    svg = tmp_path / "side.svg"
    from bikemass.scenario import catalog
    from bikemass.plots.side_view import plot_side_view
    ax = plot_side_view(catalog.load_bicycle("benchmark"), xlim=(-0.5, 1.5), ylim=(0, 1.4)).axes[0]
    assert ax.get_xlim() == pytest.approx((-0.5, 1.5)) and ax.get_ylim() == pytest.approx((0, 1.4))
    assert main(["draw", "benchmark", "--plot", str(svg), "--xlim=-0.5:1.5"]) == 0


@pytest.mark.parametrize("argv,needle", [
    (["eig", "benchmark", "--plot", "eig.xyz"], ".svg"),
    (["modes", "jamis", "--plot", "m.docx"], ".png"),
    (["draw", "benchmark", "--plot", "d.txt"], ".pdf"),
    (["compare", "benchmark", "--plot", "c.csv"], ".png"),
    (["draw", "benchmark", "--plot", "d.png", "--size", "4"], "--size"),
    (["draw", "benchmark", "--plot", "d.png", "--size", "0.1,3"], "--size"),
    (["draw", "benchmark", "--plot", "d.png", "--dpi", "many"], "--dpi"),
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


def _svg_texts(path):
    """The characters of every <text> element, whitespace between glyph spans removed."""
    return ["".join(part.strip() for part in e.itertext()) for e in ET.parse(path).iter() if e.tag.endswith("}text")]


def test_eig_figure_names_the_weave_and_capsize_speeds(tmp_path, capsys):
    svg = tmp_path / "eig.svg"
    assert main(["eig", "benchmark", "--plot", str(svg)]) == 0
    texts = _svg_texts(svg)
    # Meijaard et al. (2007): v_w = 4.292 m/s, v_c = 6.024 m/s; the symbol (mathtext) is drawn
    # just before its value (one plain string, editable as text)
    for symbol, value in (("vw", "= 4.29 m/s"), ("vc", "= 6.02 m/s")):
        assert texts[texts.index(value) + 1] == symbol


@pytest.fixture(scope="module")
def benchmark_stability():
    """The benchmark's stability on the thesis's grid (exact mass properties)."""
    from bikemass.scenario.scenario import parameters as scenario_parameters
    from bikemass.analysis.engine.stability import analyse
    from bikemass.analysis.engine.speeds import speed_grid
    from bikemass.models.whipple import whipple_model
    return analyse(whipple_model(scenario_parameters("benchmark", "none", "exact")), speed_grid(0, 30, 0.05))


def _lines(ax, label):
    return [line for line in ax.lines if line.get_label() == label]


def test_eig_figure_is_zoomed_to_the_crossings_with_one_weave(benchmark_stability):
    import numpy as np
    ax = plot_eigenvalues(benchmark_stability).axes[0]
    assert ax.get_xlim() == (0.0, 10.0)                  # about 1.6 x the capsize speed, as Meijaard's Fig. 3
    low, high = ax.get_ylim()
    assert -15 < low < -10 and 10 < high < 15            # the caster (-25 1/s at 10 m/s) is clipped ...
    assert any("caster mode below the axis" in t.get_text() for t in ax.texts)     # ... and says so
    spans = [p for p in ax.patches if p.get_label().startswith("stable")]
    corners = spans[0].get_path().transformed(spans[0].get_patch_transform()).vertices[:, 0]
    start, stop = corners.min(), corners.max()      # a Rectangle (matplotlib >= 3.9) or a Polygon (earlier)
    assert (start, stop) == pytest.approx((4.2924, 6.0243), abs=1e-4)     # Meijaard et al. (2007)
    weave, = _lines(ax, "weave")                         # one curve for the pair, not weave 1 and weave 2
    speeds, real = weave.get_data()
    drawn = speeds[np.isfinite(real)]
    assert 0.6 < drawn.min() < 0.75 and drawn.max() == pytest.approx(30)   # the pair forms at ~0.68 m/s
    split, = _lines(ax, "weave as real roots")
    assert np.nanmax(np.where(np.isfinite(split.get_ydata()), split.get_xdata(), np.nan)) < 0.75
    assert {"capsize", "caster", "real part", "imaginary part"} <= {line.get_label() for line in ax.lines}


def test_eig_figure_limits_can_be_set(benchmark_stability):
    ax = plot_eigenvalues(benchmark_stability, xlim=(2, 8), ylim=(-5, 5)).axes[0]
    assert ax.get_xlim() == (2, 8) and ax.get_ylim() == (-5, 5)
    assert [t.get_text().strip() for t in ax.texts if t.get_text().startswith(("=", " $v"))] == [
        "= 4.29 m/s", "$v_\\mathrm{w}$", "= 6.02 m/s", "$v_\\mathrm{c}$"]


def test_compare_figure_shows_each_configurations_speeds(tmp_path, capsys):
    """Jamis + relaxed rider as the thesis (Eq. 3.6, published S): the capsize speed moves from
    10.38 m/s (rigid) to 8.35 m/s (steel frame), the stable speeds shrink with it."""
    import numpy as np
    import bikemass as bm
    bike = bm.load_bicycle("jamis-thesis")
    p = bm.parameters(bike, "relaxed-thesis", combine="thesis")
    results = {"relaxed": {s: bm.stability(p, stiffness=bm.stiffness(bike, s)) for s in ("rigid", "steel")}}
    ax = plot_critical_speeds(results).axes[0]
    squares = [line for line in ax.lines if line.get_marker() == "s" and len(line.get_xdata())]
    assert sorted(float(x) for line in squares for x in line.get_xdata()) == pytest.approx([8.3514, 10.3803], abs=1e-3)
    bars = [line for line in ax.lines if line.get_linewidth() > 4 and len(line.get_xdata())]
    assert [tuple(np.round(line.get_xdata(), 2)) for line in bars] == [(5.68, 10.38), (5.83, 8.35)]
    assert [t.get_text() for t in ax.get_yticklabels()] == ["relaxed"]
    assert {"10.38", "8.35"} <= {t.get_text() for t in ax.texts}


def test_frame_modes_figure_shows_supports_views_and_mode_types():
    from bikemass.fe import frame_modes
    from bikemass.plots.frame_modes import classify, clamped_nodes, plot_frame_modes
    from bikemass.scenario.frame import frame_structure
    structure = frame_structure("jamis")
    modes = frame_modes(structure, "fix-rear", 3)
    dropouts = sorted(modes.mesh.keypoint_nodes[k] for k in structure.dropouts)
    assert list(clamped_nodes(modes)) == dropouts
    fig = plot_frame_modes(modes)
    assert len(fig.axes) == 6                                   # side and top view per mode
    assert [ax.get_title(loc="left").split(", ")[-1] for ax in fig.axes[::2]] == [
        classify(modes.shapes[:, i].reshape(-1, 6)) for i in range(3)]
    assert "in-plane bending" in fig.axes[0].get_title(loc="left")      # the Jamis's first fix-rear mode
    assert "lateral" in fig.axes[2].get_title(loc="left")
    assert all(ax.get_xlabel() or i < 4 for i, ax in enumerate(fig.axes))
    markers = [line for line in fig.axes[0].lines if line.get_marker() == "^"]
    assert len(markers[0].get_xdata()) == 2                     # both dropouts drawn as supports
    assert "mm" in fig._suptitle.get_text()                      # the deformation scale is stated
    assert not len(clamped_nodes(frame_modes(structure, "free", 2)))


def test_classify_on_made_up_shapes():
    import numpy as np
    shape = np.zeros((4, 6))
    shape[:, 0] = [0, 1, 2, 1]                                   # x and z translations only
    shape[:, 2] = 0.5
    assert classify_(shape) == "in-plane bending"
    twist = np.zeros((4, 6))
    twist[:, 1], twist[:, 3] = 1.0, 2.0                          # lateral, rotation about x
    assert classify_(twist) == "out-of-plane torsion"
    twist[:, 5] = 3.0                                            # rotation about z dominates
    assert classify_(twist) == "out-of-plane lateral bending"


def classify_(shape):
    from bikemass.plots.frame_modes import classify
    return classify(shape)


def test_side_view_draws_wheels_for_a_parameter_file_and_colours_by_body():
    from matplotlib.colors import to_rgba
    from bikemass.scenario import catalog
    from bikemass.plots.side_view import COLOURS, plot_side_view
    ax = plot_side_view(catalog.load_bicycle("jamis-thesis")).axes[0]
    g = catalog.load_bicycle("jamis-thesis").geometry
    for body, axle, radius in (("rear_wheel", g.rear_axle, g.rear_wheel_radius),
                               ("front_wheel", g.front_axle, g.front_wheel_radius)):
        tyres = [line for line in ax.lines if line.get_color() == COLOURS[body] and line.get_linewidth() == 1.6]
        x, h = tyres[0].get_data()
        assert max(x) - min(x) == pytest.approx(2 * radius, rel=1e-3) and min(h) == pytest.approx(0, abs=1e-3)
    import yaml
    pose = yaml.safe_load((SRC.parent / "bodies" / "poses" / "relaxed.yaml").read_text())
    pose["segments"]["lower_arm"]["frame"] = "front"             # forearms moving with the handlebar
    rider = catalog.load_rider(pose)
    ax = plot_side_view(catalog.load_bicycle("jamis"), rider).axes[0]
    assert any(t.get_text().startswith("rear frame + rider") for t in ax.texts)
    labels = [t.get_text() for t in ax.figure.legends[0].get_texts()]
    assert any("ellipse of gyration" in t for t in labels)
    assert any(t.get_text().startswith("front frame + rider") for t in ax.texts)
    forearms = [p for p in ax.patches if p.get_facecolor() == pytest.approx(to_rgba(COLOURS["front_frame"], 0.3))]
    assert len(forearms) == 2 and all(p.get_edgecolor()[:3] == pytest.approx(to_rgba(COLOURS["front_frame"])[:3])
                                      for p in forearms)                 # in the front frame's colour


def _decoded(png):
    from io import BytesIO

    import numpy as np
    from PIL import Image
    image = Image.open(BytesIO(png))
    return image.mode, np.asarray(image.convert("RGBA"))


@pytest.mark.parametrize("size, dpi", [((6.4, 4.2), 150), ((7.0, 4.6), 100), ((5.0, 3.3), 97.3)])
def test_png_pixels_are_matplotlibs_own_and_opaque_figures_carry_no_alpha(size, dpi):
    """figure_bytes writes the pixels matplotlib's own PNG writer writes (decoded, every channel
    equal), as RGB when the figure is opaque; a see-through figure keeps its alpha channel."""
    from io import BytesIO

    from matplotlib.figure import Figure

    from bikemass.plots.figure import figure_bytes
    for alpha, mode in ((1.0, "RGB"), (0.0, "RGBA")):
        fig = Figure(figsize=size)
        fig.patch.set_alpha(alpha)
        fig.subplots().plot([0, 1, 2], [1, 0, 2], label="$v_w$")
        theirs = BytesIO()
        fig.savefig(theirs, format="png", dpi=dpi)
        ours_mode, ours = _decoded(figure_bytes(fig, "png", dpi))
        assert ours_mode == mode and (ours == _decoded(theirs.getvalue())[1]).all()
