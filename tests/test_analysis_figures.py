"""What the sensitivity, uncertainty and sweep figures draw, read back from their artists and held
against independent references: Meijaard et al. (2007) Table 2 eigenvalues, central differences of
the critical speeds, and the general engine's crossings at each grid point."""

import numpy as np
import pytest
import yaml
from matplotlib.collections import PolyCollection, QuadMesh
from matplotlib.patches import Rectangle

import bikemass as bm
from bikemass.analysis.engine import crossings
from bikemass.analysis.sensitivity import sensitivity_figure
from bikemass.analysis.uncertainty import uncertainty_figure
from bikemass.models.whipple import whipple_model
from bikemass.sweep.figures import heatmap_figure
from bikemass.sweep.spec import read_spec
from test_stability import TABLE_4_1

BENCHMARK = bm.parameters("benchmark")
WEAVE, CAPSIZE = 4.2923825363411040, 6.0242620153883589     # Meijaard et al. 2007, exact (docs/stability.md)


def weave_capsize(p):
    found = crossings.axis_crossings(whipple_model(p), 0.0, 30.0)       # [(speed, kind, frequency)]
    weave = next(speed for speed, kind, _ in found if kind == "oscillatory")
    capsize = next(speed for speed, kind, _ in found if kind == "real")
    return weave, capsize


def test_sensitivity_bars_are_the_elasticities_of_a_central_difference():
    fig = sensitivity_figure(bm.sensitivity(BENCHMARK))
    names = [t.get_text() for t in fig.axes[0].get_yticklabels()]
    bars = [{names[i]: r.get_width() for i, r in enumerate(p for p in ax.patches if isinstance(p, Rectangle))}
            for ax in fig.axes[:2]]
    assert "4.2924" in fig.axes[0].get_title() and "6.0243" in fig.axes[1].get_title()
    for name in ("c", "w", "lam", "mB", "IFyy"):
        x = getattr(BENCHMARK, name)
        h = 1e-6 * abs(x)
        up, down = weave_capsize(BENCHMARK.replace(**{name: x + h})), weave_capsize(BENCHMARK.replace(**{name: x - h}))
        for k, v in enumerate((WEAVE, CAPSIZE)):
            elasticity = x / v * (up[k] - down[k]) / (2 * h)
            assert bars[k][name] == pytest.approx(elasticity, rel=1e-6, abs=1e-9), (name, k)


def test_uncertainty_lines_are_meijaards_eigenvalues_and_the_critical_speeds_are_marked():
    result = bm.uncertainty("benchmark", {"c": 0.002, "lam": 0.01}, speeds=np.arange(1.0, 6.0))
    fig = uncertainty_figure(result)
    left, right = fig.axes[:2]
    lines = {line.get_label(): line.get_ydata() for line in left.get_lines() if not line.get_label().startswith("_")}
    table = np.array(TABLE_4_1)[:5]                      # v = 1..5 m/s
    np.testing.assert_allclose(lines["weave 1"], table[:, 1], rtol=0, atol=1e-10)
    np.testing.assert_allclose(lines["capsize"], table[:, 3], rtol=0, atol=1e-10)
    np.testing.assert_allclose(lines["caster"], table[:, 4], rtol=0, atol=1e-10)
    bands = [c for c in left.collections if isinstance(c, PolyCollection)]
    assert len(bands) == len(lines)                       # one +-2 std band per mode
    marked = sorted(line.get_xdata()[0] for line in right.get_lines())
    np.testing.assert_allclose(marked, [WEAVE, CAPSIZE], rtol=0, atol=1e-9)


def test_sweep_heatmap_cells_are_the_general_engines_critical_speeds(tmp_path):
    spec_path = tmp_path / "grid.yaml"
    spec_path.write_text(yaml.safe_dump({"name": "grid", "bike": "benchmark",
                                          "vary": {"c": [0.06, 0.08, 0.1], "lam": [0.25, 0.3141592653589793]}}))
    spec = read_spec(str(spec_path))
    rows = []
    for c in (0.06, 0.08, 0.1):
        for lam in (0.25, 0.3141592653589793):
            weave, capsize = weave_capsize(BENCHMARK.replace(c=c, lam=lam))
            rows.append({"c": c, "lam": lam, "weave_speed": weave, "capsize_speed": capsize})
    fig = heatmap_figure(rows, spec)
    for ax, column in zip(fig.axes[:2], ("weave_speed", "capsize_speed")):
        mesh = next(c for c in ax.collections if isinstance(c, QuadMesh))
        drawn = np.asarray(mesh.get_array()).reshape(2, 3)      # rows: lam, columns: c
        expected = np.array([[r[column] for r in rows if r["lam"] == lam] for lam in (0.25, 0.3141592653589793)])
        np.testing.assert_allclose(drawn, expected, rtol=0, atol=1e-12)
    assert drawn[1, 1] != pytest.approx(0) and rows[3]["weave_speed"] == pytest.approx(WEAVE, abs=1e-9)
