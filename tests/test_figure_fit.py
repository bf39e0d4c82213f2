"""Figures a new user meets (issue 35): titles inside the figure (wrapped to its width), the
bicycle's own name in titles, one colour per legend entry, an eigenvalue axis set by the bicycle
modes with the off-scale modes named, negative axis limits written as ``--ylim -15:60``, the HQM
curves' frequency axis over their peaks, and sweep heat maps with units on their axes.

Each figure is decoded (Pillow / matplotlib's imread) and its content checked: a title's
bounding box, measured by a renderer, inside the figure; no ink on the image's outermost pixels
(where clipped text would be cut)."""

from pathlib import Path

import matplotlib.colors
import matplotlib.image
import numpy as np
import pytest
from matplotlib.backends.backend_agg import RendererAgg

import bikemass as bm
from bikemass.cli import dialect
from bikemass.cli.main import main
from bikemass.plots.figure import figure_bytes, fit_titles

LONG_NAME = "Jamis Satellite 2015 steel road bicycle, 56 cm, as measured in the lab by a student"


def _captured(monkeypatch):
    """The Figures the command line saves, in order (the file is still written)."""
    figures = []
    write = dialect.write_figure

    def keep(fig, path, options):
        figures.append(fig)
        write(fig, path, options)
    monkeypatch.setattr(dialect, "write_figure", keep)
    return figures


def _titles_inside(fig):
    """Every title's box (renderer-measured, after layout) lies inside the figure's box."""
    fig.draw_without_rendering()
    renderer = RendererAgg(int(fig.bbox.width), int(fig.bbox.height), fig.dpi)
    texts = [fig._suptitle] if fig._suptitle is not None else []
    texts += [ax.title for ax in fig.axes]
    boxes = [t.get_window_extent(renderer) for t in texts if t.get_text()]
    assert boxes, "no title drawn"
    w, h = fig.bbox.width, fig.bbox.height
    return all(b.x0 >= -0.5 and b.y0 >= -0.5 and b.x1 <= w + 0.5 and b.y1 <= h + 0.5 for b in boxes)


def _edges_blank(path, border=2):
    """No ink in the ``border`` outermost rows and columns of the PNG (a cut title or legend leaves
    ink on the edge): every pixel there within 2 % of white."""
    pixels = matplotlib.image.imread(str(path))[..., :3]
    edges = np.concatenate([pixels[:border].reshape(-1, 3), pixels[-border:].reshape(-1, 3),
                            pixels[:, :border].reshape(-1, 3), pixels[:, -border:].reshape(-1, 3)])
    return float(edges.min()) >= 0.98


@pytest.fixture
def long_named(tmp_path):
    path = tmp_path / "upload-0123abcd.yaml"
    path.write_text(f'base: jamis\nname: "{LONG_NAME}"\n')
    return path


def test_a_long_title_is_wrapped_to_the_figure(long_named):
    """A title three figure-widths long is wrapped at spaces into lines that fit, every word kept."""
    fig = bm.plot_eigenvalues(bm.eigenvalues(bm.parameters("benchmark")), title=" ".join([LONG_NAME] * 3))
    changed = fit_titles(fig)
    assert changed and changed[0].get_text().count("\n") >= 2
    assert changed[0].get_text().split() == " ".join([LONG_NAME] * 3).split()
    assert _titles_inside(fig)
    assert fit_titles(fig) == []                      # fitted once: nothing left to change


def test_bode_of_a_long_named_bicycle_keeps_its_title_inside(tmp_path, monkeypatch, long_named):
    """The Bode title (the bicycle's name: from its YAML, not the upload-<digest> file name) fits
    the figure: wrapped, inside the figure's box, no ink on the PNG's edges."""
    figures = _captured(monkeypatch)
    png = tmp_path / "bode.png"
    assert main(["bode", str(long_named), "--speed", "5", "--input", "steer-torque", "--output", "roll-angle",
                 "--plot", str(png)]) == 0
    title = figures[0].axes[0].get_title()
    assert " ".join(title.split()).startswith(LONG_NAME) and "upload-" not in title
    assert _titles_inside(figures[0]) and _edges_blank(png)


def test_draw_of_a_chart_bicycle_with_a_rider_keeps_title_and_legend_inside(tmp_path, monkeypatch):
    """The side view of a chart bicycle with a seated rider is taller than the default proportions
    foresaw: its title (the YAML's name:) and legend stay inside the image."""
    figures = _captured(monkeypatch)
    png = tmp_path / "draw.png"
    assert main(["draw", "bmc-roadmachine@56", "--rider", "relaxed", "--plot", str(png)]) == 0
    assert figures[0].axes[0].get_title().startswith("BMC Roadmachine (2017)")
    assert _titles_inside(figures[0]) and _edges_blank(png)
    fig = figures[0]
    renderer = RendererAgg(int(fig.bbox.width), int(fig.bbox.height), fig.dpi)
    legend = fig.legends[0].get_window_extent(renderer)
    assert legend.y0 >= 0 and legend.x0 >= 0 and legend.x1 <= fig.bbox.width


def test_eig_titles_name_the_bicycle_from_its_yaml(tmp_path, monkeypatch, long_named):
    figures = _captured(monkeypatch)
    assert main(["eig", str(long_named), "--speeds", "0:8:0.5", "--plot", str(tmp_path / "e.png"), "--quiet"]) == 0
    assert " ".join(figures[0].axes[0].get_title().split()).startswith(LONG_NAME)


def _legend_colours(ax):
    """``{label: rgb}`` of the legend's mode entries (the real/imaginary part keys excluded)."""
    legend = ax.get_legend()
    return {t.get_text(): matplotlib.colors.to_rgb(h.get_color())
            for t, h in zip(legend.get_texts(), legend.legend_handles)
            if t.get_text() not in ("real part", "imaginary part") and hasattr(h, "get_color")}


def test_every_legend_entry_has_its_own_colour():
    """rider-lean+tyre has nine modes on the legend (weave, capsize, caster, tyre, the lean's
    branches, ...): nine different colours."""
    fig = bm.plot_eigenvalues(bm.stability(_lean_tyre_model()))
    colours = _legend_colours(fig.axes[0])
    assert len(colours) >= 6
    assert len(set(colours.values())) == len(colours), colours


def _lean_tyre_model():
    from bikemass.scenario.scenario import Scenario
    return Scenario("jamis", "relaxed", model="rider-lean+tyre").build().model


@pytest.fixture(scope="module")
def flexible_stability():
    from bikemass.scenario.scenario import Scenario
    built = Scenario("jamis", "relaxed", "steel", model="flexible").build()
    return bm.stability(built.model, speeds=np.arange(0, 18.01, 0.25))


def test_flexible_eigenvalues_keep_weave_and_capsize_readable(flexible_stability):
    """The flexible model's fork mode (Im lambda about 400 1/s, 64 Hz) does not set the axis: the
    axis reaches no further than the bicycle modes' roots (weave, capsize) need, with the
    3x allowance (docs: OFF_SCALE_FACTOR); the mode off the axis is named with its reach."""
    modes = flexible_stability.modes
    names, z = modes.names(), modes.eigenvalues
    fast = np.abs(z.imag).max()
    assert fast > 2 * np.pi * 50                       # the fork mode is there (about 64 Hz)
    fig = bm.plot_eigenvalues(flexible_stability)
    ax = fig.axes[0]
    bicycle = np.isin(names, ["weave", "weave 1", "weave 2", "capsize"]) | np.char.startswith(
        names.astype(str), "weave")
    core = max(np.abs(z[bicycle].real).max(), np.abs(z[bicycle].imag).max())
    low, high = ax.get_ylim()
    assert high <= 3.0 * 1.08 * core + 1e-9 and high < fast / 10
    notes = [t.get_text() for t in ax.texts if t.get_text().startswith("off the axis")]
    assert len(notes) == 1 and "wobble" in notes[0]
    assert f"{fast:.3g}" in notes[0]


def test_a_negative_axis_limit_may_follow_its_option(tmp_path, monkeypatch):
    """``--ylim -15:60`` is the axis range, as ``--ylim=-15:60``; the same for any one-value option
    (``--speeds -1:5:0.1`` reaches the speed check, not argparse's 'expected one argument')."""
    figures = _captured(monkeypatch)
    png = tmp_path / "e.png"
    assert main(["eig", "benchmark", "--speeds", "0:8:0.5", "--ylim", "-15:60", "--xlim", "-1:8",
                 "--plot", str(png), "--quiet"]) == 0
    assert figures[0].axes[0].get_ylim() == (-15.0, 60.0) and figures[0].axes[0].get_xlim() == (-1.0, 8.0)
    assert matplotlib.image.imread(str(png)).shape[2] in (3, 4)


def test_a_negative_value_reaches_the_options_own_check(capsys):
    assert main(["eig", "benchmark", "--speeds", "-1:5:0.1"]) == 2
    err = capsys.readouterr().err
    assert "--speeds: -1:5:0.1: START:STOP:STEP" in err and "expected one argument" not in err


def test_the_hqm_frequency_axis_shows_every_peak():
    """Jamis with the relaxed rider at 10 m/s peaks above 20 rad/s: the axis reaches past it."""
    p = bm.parameters("jamis", "relaxed")
    result = bm.handling(p, [4.0, 10.0])
    w = np.asarray(result.hqm_frequencies)
    peaks = [w[int(np.nanargmax(c))] for c in result.hqm]
    assert max(peaks) > 20.0                           # the case the fixed 0..20 axis cut
    fig = bm.plot_handling(result)
    assert fig.axes[0].get_xlim()[1] >= 1.2 * max(peaks)


def test_sweep_heat_maps_label_axes_with_units(tmp_path, monkeypatch):
    """A 3 x 3 sweep over trail and steer tilt (given in degrees: a benchmark parameter is read
    into SI, so its column is in rad): the heat map's and the lines' axes name their units."""
    from bikemass.cli import analysis
    figures = {}
    write = analysis.write_figure

    def keep(fig, path, options):
        figures[Path(path).stem] = fig
        write(fig, path, options)
    monkeypatch.setattr(analysis, "write_figure", keep)
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: benchmark\nvary:\n  c: {from: 0.05, to: 0.1, num: 3}\n"
                    "  lam: [15 deg, 18 deg, 21 deg]\n")
    out = tmp_path / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--workers", "1", "--quiet"]) == 0
    heat = figures["heatmap"]
    assert {(ax.get_xlabel(), ax.get_ylabel()) for ax in heat.axes if ax.get_xlabel()} == {("c (m)", "lam (rad)")}
    assert {ax.get_xlabel() for ax in figures["lines"].axes} == {"c (m)"}
    assert matplotlib.image.imread(str(out / "heatmap.png")).ndim == 3


def test_sweep_keys_in_a_files_unit_say_it(tmp_path):
    """A dotted key of a chart given in mm keeps mm on the axis."""
    from bikemass.sweep.figures import key_label
    from bikemass.sweep.spec import read_spec
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: bmc-roadmachine@56\nvary:\n  chart.stack: [580 mm, 590 mm]\n"
                    "  chart.reach: [0.38, 0.39]\n")
    parsed = read_spec(spec)
    assert key_label(parsed, "chart.stack") == "chart.stack (mm)"
    assert key_label(parsed, "chart.reach").startswith("chart.reach (")


def test_figure_bytes_fits_titles_of_any_figure():
    """Saving fits the titles of a figure bikemass did not make (a caller's own suptitle)."""
    from bikemass.plots.figure import new_figure
    fig = new_figure((4, 3))
    fig.subplots().plot([0, 1], [0, 1])
    fig.suptitle("a suptitle much too long for a four inch wide figure, which would be cut at both sides")
    data = figure_bytes(fig, "png", 100)
    assert data.startswith(b"\x89PNG") and "\n" in fig._suptitle.get_text()
    assert _titles_inside(fig)


def test_web_figures_name_an_upload_by_its_name():
    """An uploaded bicycle's figures carry its ``name:``, never ``upload-<digest>``."""
    pytest.importorskip("dash")
    from bikemass.web import create_app
    from bikemass.web.page import _bode_figure, _eigenvalue_figure
    from bikemass.web.state import PageState
    engine = create_app().engine
    upload = engine.add_upload("mine.yaml", f'base: jamis\nname: "{LONG_NAME}"\n'.encode())
    state = PageState(bike=upload, rider="none")
    assert upload.startswith("upload-") and engine.bike_name(state) == LONG_NAME
    result = engine.evaluate(state).stability
    fig = _eigenvalue_figure(result, state, engine.bike_name(state), engine.rider_label(state))
    fit_titles(fig)
    title = fig.axes[0].get_title()
    assert " ".join(title.split()).startswith(LONG_NAME) and "upload-" not in title and _titles_inside(fig)
    fr = bm.frequency_response(engine.model(state), 5.0, "steer-torque", "roll-angle")
    assert "upload-" not in _bode_figure(fr, engine.bike_name(state)).axes[0].get_title()


@pytest.mark.parametrize("argv", [
    ["eig", "{bike}", "--speeds", "0:10:0.5"],
    ["stability", "{bike}", "--speeds", "0:10:0.5"],
    ["bode", "{bike}", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle"],
    ["mode-shapes", "{bike}", "--speed", "5"],
    ["simulate", "{bike}", "--speed", "5", "--duration", "2"],
    ["handling", "{bike}", "--speeds", "4,6"],
    ["draw", "{bike}"],
    ["geometry", "{bike}"],
])
def test_every_figure_of_a_long_named_bicycle_keeps_its_text_inside(tmp_path, long_named, argv):
    """The figures a new user makes of a bicycle with a long name: the PNG's outermost pixels
    blank (no title, legend or label cut at the edge)."""
    png = tmp_path / "figure.png"
    assert main([a.format(bike=long_named) for a in argv] + ["--plot", str(png), "--quiet"]) == 0
    assert _edges_blank(png)


def _eigenvalue_figure():
    """The benchmark's eigenvalue figure as the study draws it (legend beside the axes)."""
    from bikemass.plots.stability import CriticalSpeeds, eigenvalue_figure
    p = bm.parameters("benchmark")
    return eigenvalue_figure(bm.eigenvalues(p), CriticalSpeeds(), "Benchmark bicycle")


def _left_spine_column(pixels):
    """The first column where most rows of the image's middle third are dark: the axes' left spine."""
    rows = pixels[pixels.shape[0] // 3: 2 * pixels.shape[0] // 3, :, :3].mean(axis=2)
    return int(np.argmax((rows < 0.3).mean(axis=0) > 0.9))


def test_fixed_margins_place_the_axes_where_asked(tmp_path):
    """png_bytes with margins that hold the labels: the axes' left spine at the left margin
    (0.9 in at 100 dpi: column 90, within 1 px), nothing cut at the edges."""
    from bikemass.plots.figure import png_bytes
    path = tmp_path / "fixed.png"
    path.write_bytes(png_bytes(_eigenvalue_figure(), 100, margins=(0.9, 0.6, 2.6, 0.4)))
    pixels = matplotlib.image.imread(str(path))
    assert abs(_left_spine_column(pixels) - 90) <= 1
    assert _edges_blank(path)


def _right_spine_column(pixels):
    """The last column where most rows of the image's middle third are dark: the axes' right spine."""
    rows = pixels[pixels.shape[0] // 3: 2 * pixels.shape[0] // 3, :, :3].mean(axis=2)
    dark = (rows < 0.3).mean(axis=0) > 0.9
    return int(len(dark) - 1 - np.argmax(dark[::-1]))


def test_margins_too_small_for_the_labels_widen_to_what_constrained_layout_gives(tmp_path):
    """png_bytes with margins the legend does not fit in (0.2 in on the right): that margin is
    widened to what the labels need, as matplotlib's constrained layout (figure_bytes) places the
    axes' right edge: the right spine no further right (1 px) and at most 3 px left of it (the
    legend sits 1 % of the axes' width beside them, measured on the wider axes of the first
    drawing: 2 px here), the other margins kept (left spine at 0.9 in: column 90 within 1 px), no
    ink cut at the edges."""
    from bikemass.plots.figure import png_bytes
    fixed, free = tmp_path / "fixed.png", tmp_path / "free.png"
    fixed.write_bytes(png_bytes(_eigenvalue_figure(), 100, margins=(0.9, 0.6, 0.2, 0.4)))
    free.write_bytes(figure_bytes(_eigenvalue_figure(), "png", 100))
    pixels = [matplotlib.image.imread(str(p)) for p in (fixed, free)]
    assert abs(_left_spine_column(pixels[0]) - 90) <= 1
    right = [_right_spine_column(p) for p in pixels]
    assert -3 <= right[0] - right[1] <= 1 and right[0] < pixels[0].shape[1] - 100
    assert _edges_blank(fixed)


def test_margins_no_figure_fits_fall_back_to_constrained_layout(tmp_path):
    """png_bytes with margins wider than the figure: constrained layout's figure (the same left
    spine column as figure_bytes, within 1 px), nothing cut at the edges."""
    from bikemass.plots.figure import png_bytes
    fixed, free = tmp_path / "fixed.png", tmp_path / "free.png"
    fixed.write_bytes(png_bytes(_eigenvalue_figure(), 100, margins=(4.0, 0.6, 4.0, 0.4)))
    free.write_bytes(figure_bytes(_eigenvalue_figure(), "png", 100))
    columns = [_left_spine_column(matplotlib.image.imread(str(p))) for p in (fixed, free)]
    assert abs(columns[0] - columns[1]) <= 1
    assert _edges_blank(fixed)


@pytest.mark.parametrize("face", ["white", "none"])
def test_png_bytes_decodes_to_matplotlibs_own_png(face):
    """png_bytes writes its PNG itself (rows unfiltered, zlib): decoded by Pillow, the pixels
    (RGB for an opaque figure, RGBA for a transparent one) equal those of matplotlib's own PNG
    writer (savefig) exactly, and the resolution is the dpi (100, within Pillow's rounding of
    pixels per metre: 0.01)."""
    from io import BytesIO

    from PIL import Image

    from bikemass.plots.figure import png_bytes

    def figure():
        fig = _eigenvalue_figure()
        fig.set_facecolor(face)
        return fig
    ours = Image.open(BytesIO(png_bytes(figure(), 100)))
    theirs = BytesIO()
    figure().savefig(theirs, format="png", dpi=100)
    reference = np.asarray(Image.open(theirs).convert("RGBA"))
    assert ours.mode == ("RGB" if face == "white" else "RGBA")
    assert np.array_equal(np.asarray(ours.convert("RGBA")), reference)
    assert ours.info["dpi"] == pytest.approx((100, 100), abs=0.01)
    if face == "none":
        assert np.asarray(ours)[0, 0, 3] == 0


def test_no_stable_speed_note_overlaps_no_value():
    """plot_critical_speeds writes "no stable speed" right of a row's marks and values, not over
    the value written left of a mark near the axis's start (the study's Cargo with the
    aluminium frame: "no stable speed6.00"): no two texts' boxes (renderer-measured) overlap."""
    from bikemass.plots.stability import CriticalSpeeds
    results = {"near the start": {"a": CriticalSpeeds(capsize=(1.2,)), "b": CriticalSpeeds(weave=(9.0,), capsize=(5.0,))},
               "stable": {"a": CriticalSpeeds(weave=(4.0,), capsize=(8.0,), stable=((4.0, 8.0),))},
               "nothing": {"a": CriticalSpeeds()}}
    fig = bm.plot_critical_speeds(results)
    fig.draw_without_rendering()
    renderer = RendererAgg(int(fig.bbox.width), int(fig.bbox.height), fig.dpi)
    texts = fig.axes[0].texts
    notes = [t for t in texts if t.get_text() == "no stable speed"]
    assert len(notes) == 3
    boxes = [t.get_window_extent(renderer) for t in texts]
    assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])
