"""The stability engine names the flexible model's wobble (bikemass.analysis.engine), checked against
the eigenvalues followed by hand from standstill (plain numpy, not the engine's tracking), the member
undamped (no steering damper, no structural damping: ``Compliances.undamped``):

* the Jamis with the Relaxed rider and a steel frame and fork: the slowest oscillation of the
  compliances' family, followed from standstill to 8 m/s, is steer-dominated and lies in the 6-9 Hz
  of Ploechl et al. (2012), below the 8-12 Hz of Klinger et al. (2014, hands on); the engine's
  column with that root carries a label of the ``wobble`` family and the pair is named ``wobble``;
  the root grows at every speed above standstill, so the engine reports no crossing of it in
  (0, 30] m/s (and none a round-off from standstill, where every undamped oscillation sits on the
  axis) and an empty stable range;
* the Cargo with the same rider and frame material: its wobble is stable up to where its followed
  root's real part changes sign (Brent's method on that root), and there the engine's crossing is
  named ``wobble``, is destabilising, has the root's frequency and is among ``wobble_speeds``, not
  ``weave_speeds``.
"""

import numpy as np
import pytest
from scipy.optimize import brentq

import bikemass as bm
from bikemass.analysis.engine.crossings import DESTABILISING, OSCILLATORY
from bikemass.analysis.engine.naming import family
from bikemass.analysis.engine.stability import WOBBLE, analyse
from bikemass.fe.flexible import compliances
from bikemass.models.family import build

GRID = np.round(np.arange(0.0, 30.0 + 1e-9, 0.05), 12)


def flexible_model(bike):
    bicycle = bm.load_bicycle(bike)
    params = bm.parameters(bicycle, bm.load_rider("relaxed"))
    return build("flexible", params, compliances=compliances(bicycle, "steel").undamped())


def slowest_compliance_root(model):
    """The slowest oscillation at standstill whose largest participation is in the compliances' states."""
    values, X = np.linalg.eig(model.dynamic_matrix(0.0))
    share = np.abs(X * np.linalg.inv(X).T)
    states = list(dict(model.families)["wobble"])
    mine = [k for k in range(len(values)) if share[states, k].sum() > 0.5 and values[k].imag > 0]
    return values[min(mine, key=lambda k: values[k].imag)]


def followed(model, speeds):
    """The root continuing :func:`slowest_compliance_root` at each speed (nearest root, small steps),
    with the coordinates' part of its eigenvector at the last speed."""
    root, roots = slowest_compliance_root(model), []
    for v in speeds:
        values, vectors = np.linalg.eig(model.dynamic_matrix(v))
        k = int(np.argmin(np.abs(values - root)))
        root = values[k]
        roots.append(root)
    return np.array(roots), vectors[:model.n_dynamic // 2, k]


@pytest.fixture(scope="module")
def jamis():
    model = flexible_model("jamis")
    return model, analyse(model, GRID)


def test_jamis_wobble_is_named_wobble_in_the_published_band(jamis):
    model, result = jamis
    k = int(np.flatnonzero(GRID == 8.0)[0])
    roots, shape = followed(model, GRID[:k + 1])
    frequency = roots[-1].imag / (2 * np.pi)
    assert 6.0 <= frequency <= 9.0 and frequency < 8.0        # Ploechl's band, below Klinger's
    coordinates = [s.name for s in model.dynamic_states[:model.n_dynamic // 2]]
    assert coordinates[int(np.argmax(np.abs(shape)))] == "steer-angle"
    column = int(np.argmin(np.abs(result.eigenvalues[k] - roots[-1])))
    assert abs(result.eigenvalues[k, column] - roots[-1]) < 1e-8 * abs(roots[-1])
    assert family(result.labels[column]) == WOBBLE
    assert result.modes.names()[k, column] == WOBBLE


def test_jamis_wobble_grows_from_standstill_without_a_crossing(jamis):
    model, result = jamis
    roots, _ = followed(model, GRID)
    assert np.all(roots[1:].real > 0)
    column = int(np.argmin(np.abs(result.eigenvalues[-1] - roots[-1])))
    assert result.mode_ranges[result.labels[column]]["strict"]["exact"] == ()
    assert result.wobble_speeds == ()
    assert all(c.speed > 1e-6 for c in result.crossings)     # none a round-off from standstill
    assert result.stable_speeds == ()


def test_cargo_wobble_crossing_is_named_wobble():
    model = flexible_model("cargo")
    result = analyse(model, GRID)
    roots, _ = followed(model, GRID)
    signs = np.sign(roots.real[1:])
    assert signs[0] < 0 and np.count_nonzero(np.diff(signs)) == 1    # stable, then unstable once
    i = int(np.flatnonzero(np.diff(signs))[0]) + 1

    def real_part(v):
        values = np.linalg.eigvals(model.dynamic_matrix(v))
        return values[np.argmin(np.abs(values - roots[i]))].real
    speed = brentq(real_part, GRID[i], GRID[i + 1], xtol=1e-12)
    crossing, = [c for c in result.crossings if family(c.mode) == WOBBLE]
    assert crossing.kind == OSCILLATORY and crossing.direction == DESTABILISING
    assert crossing.speed == pytest.approx(speed, abs=1e-8)
    values = np.linalg.eigvals(model.dynamic_matrix(speed))
    assert crossing.frequency == pytest.approx(abs(values[np.argmin(np.abs(values - roots[i]))].imag), rel=1e-6)
    assert result.wobble_speeds == (crossing.speed,) and crossing.speed not in result.weave_speeds


# ---------------------------------------------------------------- modes named by what moves
def _dominant_coordinate(model, root, speed):
    """The coordinate with the largest summed participation in ``root`` (plain numpy)."""
    values, X = np.linalg.eig(model.dynamic_matrix(speed))
    k = int(np.argmin(np.abs(values - root)))
    share = np.abs(X[:, k] * np.linalg.inv(X)[k, :])
    by = {}
    for state, x in zip(model.dynamic_states, share):
        name = state.name.removesuffix("-rate").removesuffix("-angle")
        by[name] = by.get(name, 0.0) + x
    return max(by, key=by.get)


@pytest.mark.parametrize("model_name", ["flexible", "tyre+flexible"])
def test_no_mode_above_15_hz_is_named_wobble(model_name):
    """Wobble is the steer-dominated oscillation of the published band (about 4-12 Hz, 15 Hz at most);
    the compliances' modes far above it are named by the coordinate that moves most in them, found here
    by plain numpy at 8 m/s (the issue: the 64 Hz fork mode was "wobble 1/2")."""
    model = bm.Scenario("jamis", "relaxed", stiffness="steel", model=model_name).build().model
    result = analyse(model, GRID)
    k = int(np.flatnonzero(GRID == 8.0)[0])
    names = result.modes.names()[k]
    for c, root in enumerate(result.eigenvalues[k]):
        hz = abs(root.imag) / (2 * np.pi)
        if hz > 15.0:
            assert family(result.labels[c]) != WOBBLE and names[c] != WOBBLE
            if family(result.labels[c]) in ("fork-bending", "frame-twist"):
                assert family(result.labels[c]) == _dominant_coordinate(model, root, 8.0)
    assert any(family(label) == "fork-bending" for label in result.labels)


def test_where_no_stable_range_exists_the_output_names_the_modes_that_prevent_it(jamis):
    """The Jamis on steel, flexible: never stable; ``prevented_by`` is the grid speed with the fewest
    unstable roots (counted here with numpy's eigenvalues at every grid speed) and names those roots'
    modes; the text and JSON of ``bikemass stability`` carry it."""
    model, result = jamis
    counts = [int(np.sum(np.linalg.eigvals(model.dynamic_matrix(v)).real > 0)) for v in GRID]
    p = result.prevented_by
    assert result.stable_speeds == () and p.speed == GRID[int(np.argmin(counts))]
    values = np.linalg.eigvals(model.dynamic_matrix(p.speed))
    unstable = values[values.real > 0]
    assert sum(2 if r.imag else 1 for r in p.roots) == min(counts)
    for r in p.roots:
        assert np.min(np.abs(unstable - r)) < 1e-9 * abs(r)
    assert "wobble" in p.modes
    assert result.to_dict()["no_stable_range"]["unstable_modes"] == list(p.modes)


def _steer_dominated_in_band(model, speed):
    """The roots (Im > 0) at ``speed`` of 3-15 Hz whose largest participation, summed by coordinate, is on
    steer (plain numpy), with their steer participation."""
    values, X = np.linalg.eig(model.dynamic_matrix(speed))
    share = np.abs(X * np.linalg.inv(X).T)
    out = []
    for k, root in enumerate(values):
        if root.imag <= 0 or not 3.0 <= root.imag / (2 * np.pi) <= 15.0:
            continue
        by = {}
        for state, x in zip(model.dynamic_states, share[:, k] / share[:, k].sum()):
            name = state.name.removesuffix("-rate").removesuffix("-angle")
            by[name] = by.get(name, 0.0) + x
        if max(by, key=by.get) == "steer":
            out.append((root, by["steer"]))
    return out


@pytest.mark.parametrize("grid", [GRID, np.arange(1.0, 9.5, 1.0), np.arange(0.0, 5.01, 0.5), np.arange(10.0, 20.01, 2.0)],
                         ids=["0-30", "1-9", "0-5", "10-20"])
def test_tyre_and_flexible_wobble_is_labelled_by_what_moves(grid):
    """Jamis + Relaxed, tyre+flexible, steel: the steer-dominated oscillation of the wobble band at 8 m/s
    (found by plain numpy: one root, 6.5 Hz) is the column labelled ``wobble 1`` / ``wobble 2`` (its
    conjugate) on any grid (the labels are fixed following the modes up to 8 m/s whatever the grid; the
    grid's own roots are compared at a grid speed), which was labelled ``tyre 3`` / ``tyre 4`` by its family at
    standstill; no other label is of the wobble family and none above 15 Hz."""
    model = bm.Scenario("jamis", "relaxed", stiffness="steel", model="tyre+flexible").build().model
    (root, steer), = _steer_dominated_in_band(model, 8.0)
    assert 6.0 <= root.imag / (2 * np.pi) <= 7.0 and steer > 0.3
    result = analyse(model, grid)
    assert sorted(label for label in result.labels if family(label) == WOBBLE) == ["wobble 1", "wobble 2"]
    reference = analyse(model, GRID)
    k = int(np.flatnonzero(GRID == 8.0)[0])
    column = int(np.argmin(np.abs(reference.eigenvalues[k] - root)))
    assert abs(reference.eigenvalues[k, column] - root) < 1e-8 * abs(root)
    assert reference.labels[column] == "wobble 1" and reference.modes.names()[k, column] == WOBBLE
    for c, label in enumerate(result.labels):       # the same mode on every grid: compare at its first speed
        same = int(np.argmin(np.abs(reference.eigenvalues[int(np.argmin(np.abs(GRID - grid[0])))] -
                                    result.eigenvalues[0, c])))
        if np.isclose(GRID, grid[0], atol=1e-9).any():
            assert reference.labels[same] == label
    hz = np.abs(result.eigenvalues.imag) / (2 * np.pi)
    assert not any(family(label) == WOBBLE and np.any(hz[:, c] > 15.0) for c, label in enumerate(result.labels))


def test_flexible_jamis_without_tyres_keeps_its_wobble_by_family():
    """The flexible Jamis (no tyres) has no steer-dominated oscillation in the band at 8 m/s (plain numpy:
    its 7.4 Hz mode is frame-twist-dominated by participation), so its labels by family stand: the 7.4 Hz
    pair is ``wobble 1`` / ``wobble 2``."""
    model = flexible_model("jamis")
    assert _steer_dominated_in_band(model, 8.0) == []
    result = analyse(model, GRID)
    k = int(np.flatnonzero(GRID == 8.0)[0])
    column = result.labels.index("wobble 1")
    assert 7.0 <= abs(result.eigenvalues[k, column].imag) / (2 * np.pi) <= 8.0
