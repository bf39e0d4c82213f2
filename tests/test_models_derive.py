"""The shipped generated code (bikemass.models.generated) against a fresh derivation.

SLOW BY DESIGN (about 90 s of CPU): every member combination is derived again with sympy
(``python -m bikemass.models.derive`` does the same before writing the code) and its matrices,
evaluated with 30 digits at seeded random parameter points, are compared with what the shipped
numpy code computes there.  A derivation changed without regenerating, or generated code edited
by hand, fails here.  The flexible member's combinations with other members (about 50 s of CPU each)
are not derived here (:data:`CHECKED`): tests/test_models_flexible.py holds them to the models they
combine (the compliances held rigid; the tyres, or the hip joint, made stiff).
"""

import random

import mpmath
import numpy as np
import pytest

sm = pytest.importorskip("sympy")

from bikemass.models.derive.build import derive  # noqa: E402  (needs sympy)
from bikemass.models.derive.members import COMBINATIONS, members  # noqa: E402
from bikemass.models.family import generated  # noqa: E402
from bikemass.models.registry import ModelChoice  # noqa: E402

pytestmark = pytest.mark.slow     # derives the model family again with sympy (~80 s): pytest -m 'not slow' leaves it out


def _point(rng, parameters):
    """Random values near a real bicycle: every parameter within a factor 0.7..1.3 of a typical size."""
    typical = {"lam": 0.3, "g": 9.81, "c": 0.08, "xB": 0.3, "zB": -0.9, "xH": 0.9, "zH": -0.7, "IBxz": 2.4,
               "IHxz": -0.0076, "xU": 0.3, "zU": -1.3, "zhip": -1.0, "IUxz": 0.4}
    return {name: typical.get(name, 1.0) * rng.uniform(0.7, 1.3) for name, _, _ in parameters}


CHECKED = tuple(c for c in COMBINATIONS if "flexible" not in c or c == ("flexible",))
"""The combinations derived again here: all but the flexible member's with other members."""


@pytest.fixture(scope="module", params=CHECKED, ids=lambda names: ModelChoice(names).name)
def fresh(request):
    return derive(members(request.param)), generated(ModelChoice(request.param))


def test_generated_code_matches_a_fresh_derivation(fresh):
    derived, code = fresh
    assert code.PARAMETERS == derived.parameters and code.STATES == derived.states
    assert code.INPUTS == derived.inputs and code.FAMILIES == derived.families
    assert (code.N_DYNAMIC, code.COORDINATES, code.SECOND_ORDER) == (derived.n_dynamic, derived.coordinates,
                                                                     derived.second_order)
    symbols = [sm.Symbol(name) for name, _, _ in derived.parameters]
    matrices = [derived.E, *derived.A, *derived.B]
    exact = sm.lambdify(symbols, [list(m) for m in matrices], "mpmath")
    rng = random.Random(25)
    for _ in range(3):
        point = _point(rng, derived.parameters)
        with mpmath.workdps(30):
            reference = [np.array([float(x) for x in m], dtype=float) for m in exact(*point.values())]
        E, A, B = code.coefficients(**point)
        pad = lambda terms, n: [*terms, *np.zeros((n - len(terms), *terms.shape[1:]))]
        shipped = [E, *pad(A, len(derived.A)), *pad(B, len(derived.B))]
        for k, (ref, got) in enumerate(zip(reference, shipped)):
            got = got.ravel()
            scale = np.max(np.abs(ref)) or 1.0
            assert np.all((ref == 0) == (got == 0)), f"{code.NAME}: matrix {k}: zero pattern"
            np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-13 * scale, err_msg=f"{code.NAME} {k}")
