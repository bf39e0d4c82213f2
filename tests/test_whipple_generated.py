"""The Whipple bicycle through the generated model family (models.whipple_generated) against its
oracles: the matrices Meijaard et al. (2007) print (Sec. 4, 14-15 significant digits), the
hand-written closed form of their Appendix A (models.canonical, kept as the test oracle), and
BicycleParameters' model.

Tolerances: the generated code (sympy's Kane method, common subexpressions) and the hand-written
formulas round differently, and one entry of the generated K0 (the steer-steer one) is a difference
of two terms about 11 times its size on the benchmark (they cancel exactly in exact arithmetic), so
entries agree to a few units of rounding of the largest entry of their matrix: 1e-14 relative
(measured worst 5e-16 on 200 random sets).  Complex-step derivatives agree to 1e-13 relative
(the same rounding, differentiated).
"""

from types import SimpleNamespace

import numpy as np
import pytest

import bikemass as bm
from bikemass.models.canonical import canonical_entries, canonical_matrices
from bikemass.models.parameters import NAMES
from bikemass.models.whipple import whipple_model
from bikemass.models.whipple_generated import second_order_entries, whipple_matrices
from meijaard import C1, K0, K2, M

RELATIVE = 1e-14
BENCHMARK = bm.parameters("benchmark")


def _array(rows, count=None):
    """Nested 2x2 rows of numbers or (B,) arrays -> (2, 2) or (B, 2, 2) complex array."""
    if count is None:
        return np.array(rows, dtype=complex)
    return np.moveaxis(np.array([[np.broadcast_to(x, (count,)) for x in row] for row in rows], dtype=complex), -1, 0)


def _assert_close(ours, oracle, relative=RELATIVE):
    for name, a, b in zip(("M", "C1", "K0", "K2"), ours, oracle):
        scale = np.max(np.abs(b), axis=(-2, -1), keepdims=True)
        assert np.all(np.abs(a - b) <= relative * scale), (name, a, b)


def _random_sets(count, seed):
    """``count`` variants of the benchmark: every parameter but g times 0.6-1.4 (seeded)."""
    rng = np.random.default_rng(seed)
    base = BENCHMARK.to_dict()
    return [{k: v * rng.uniform(0.6, 1.4) if k != "g" else v for k, v in base.items()} for _ in range(count)]


def test_the_benchmark_matrices_are_the_papers():
    """Sec. 4 of Meijaard et al. (2007) prints M, C1, K0, K2 to 14-15 significant digits: the generated
    path gives them to the printed digits (5e-14 of the largest entry)."""
    ours = [np.array(m, dtype=float) for m in second_order_entries(BENCHMARK)]
    for a, b in zip(ours, (M, C1, K0, K2)):
        assert np.max(np.abs(a - b)) <= 5e-14 * np.max(np.abs(b))


def test_the_benchmark_matches_the_hand_written_closed_form():
    _assert_close([_array(m) for m in second_order_entries(BENCHMARK)],
                  [_array(m) for m in canonical_entries(BENCHMARK)])


def test_random_sets_match_the_closed_form_in_floats_and_as_arrays():
    """200 random variants (seeded) one by one (Python floats) and as one chunk of arrays (a sweep's path)."""
    sets = _random_sets(200, seed=3)
    for values in sets:
        p = SimpleNamespace(**values)
        _assert_close([_array(m) for m in second_order_entries(p)], [_array(m) for m in canonical_entries(p)])
    columns = SimpleNamespace(**{k: np.array([s[k] for s in sets]) for k in NAMES})
    _assert_close([_array(m, 200) for m in second_order_entries(columns)],
                  [_array(m, 200) for m in canonical_entries(columns)])


def test_floats_and_arrays_agree_contract():
    """Contract test (the code against itself): the float path (math's sin, cos) and the array path
    (numpy's) of the same generated arithmetic agree to rounding (1e-15 relative)."""
    sets = _random_sets(20, seed=4)
    columns = SimpleNamespace(**{k: np.array([s[k] for s in sets]) for k in NAMES})
    arrays = [_array(m, 20) for m in second_order_entries(columns)]
    for i, values in enumerate(sets):
        floats = [_array(m) for m in second_order_entries(SimpleNamespace(**values))]
        _assert_close(floats, [a[i] for a in arrays], 1e-15)


def test_the_complex_step_through_both_agrees():
    """d(entry)/d(parameter) by the complex step (h = 1e-30) through the generated code and through
    the closed form, for every parameter of the benchmark: the same to 1e-13 of each matrix's
    largest derivative (exact derivatives of two roundings of one function)."""
    base = BENCHMARK.to_dict()
    for name in NAMES:
        stepped = SimpleNamespace(**{**base, name: base[name] + 1e-30j})
        ours = [_array(m).imag / 1e-30 for m in second_order_entries(stepped)]
        oracle = [_array(m).imag / 1e-30 for m in canonical_entries(stepped)]
        for a, b in zip(ours, oracle):
            assert np.all(np.abs(a - b) <= 1e-13 * max(np.max(np.abs(b)), 1e-300)), (name, a, b)


@pytest.mark.parametrize("massive", [False, True])
def test_point_wheels(massive):
    """Radius-0 wheels (the two-mass skate: the generated code divides by the radii): without mass they
    drop out, with mass they are point masses at the contacts; both as the closed form, in floats and
    in a chunk mixing point and real wheels."""
    wheels = {"rR": 0.0, "rF": 0.0, "IRyy": 0.0, "IFyy": 0.0}
    if not massive:
        wheels.update(mR=0.0, mF=0.0, IRxx=0.0, IFxx=0.0)
    values = {**BENCHMARK.to_dict(), **wheels}
    p = SimpleNamespace(**values)
    _assert_close([_array(m) for m in second_order_entries(p)], [_array(m) for m in canonical_entries(p)])
    mixed = {k: np.array([v, BENCHMARK.to_dict()[k], v]) for k, v in values.items()}
    mixed = SimpleNamespace(**mixed)
    _assert_close([_array(m, 3) for m in second_order_entries(mixed)], [_array(m, 3) for m in canonical_entries(mixed)])


def test_the_matrices_and_the_model_come_from_the_generated_path():
    """whipple_matrices (bm.matrices, the sweep's arrays) and whipple_model's mechanics: the closed form's
    matrices, rigid and with a frame stiffness in series with gravity (1e-14 relative)."""
    ours, oracle = whipple_matrices(BENCHMARK), canonical_matrices(BENCHMARK)
    _assert_close([ours.M, ours.C1, ours.K0, ours.K2], [oracle.M, oracle.C1, oracle.K0, oracle.K2])
    assert not ours.M.flags.writeable
    S = np.array([[8000.0, 1500.0], [1500.0, 3000.0]])
    from bikemass.models.flexible_static import static_stiffness
    for stiffness in (None, S):
        mech = whipple_model(BENCHMARK, stiffness).mechanics
        gK0 = static_stiffness(BENCHMARK.g * oracle.K0, stiffness)
        _assert_close([mech.M, mech.C[1], mech.K[0], mech.K[2]], [oracle.M, oracle.C1, gK0, oracle.K2])


def test_the_generated_path_matches_bicycleparameters():
    """BicycleParameters' Meijaard2007Model (its own formulas) at 601 speeds: the same eigenvalues to 1e-10 1/s."""
    pytest.importorskip("bicycleparameters")
    from bicycleparameters.models import Meijaard2007Model
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet
    speeds = np.linspace(0.0, 30.0, 601)
    theirs = Meijaard2007Model(Meijaard2007ParameterSet({**BENCHMARK.to_dict(), "v": 0.0}, True)).calc_eigen(v=speeds)[0]
    ours = np.linalg.eigvals(whipple_model(BENCHMARK).dynamic_matrix(speeds))
    assert np.max(np.abs(np.sort_complex(ours) - np.sort_complex(theirs))) < 1e-10


def test_the_hand_written_formulas_are_only_an_oracle():
    """No module of the package but the oracle itself calls the hand-written formulas (the run-time path is
    the generated family's code); the tests compare the two."""
    import ast
    from pathlib import Path
    src = Path(bm.__file__).resolve().parent
    callers = []
    for path in src.rglob("*.py"):
        if path.name == "canonical.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Name) and node.id in ("canonical_matrices", "canonical_entries"):
                callers.append(f"{path.relative_to(src)}:{node.lineno}")
    assert callers == []
