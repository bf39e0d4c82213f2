"""Exact derivatives of the Whipple model's matrices by the complex step.

Complex parameter values give a complex :class:`~bikemass.models.linear.LinearModel` (the one
builder, :func:`~bikemass.models.whipple.whipple_model`, whose matrices come from the generated model
family's code, which takes complex values as they are), so ``f'(p) = Im f(p + i h) / h`` with
``h = 1e-30`` differentiates the matrices and the state matrix exactly to rounding: no
subtraction, no finite-difference step.
"""

from types import SimpleNamespace

import numpy as np

from ..models.whipple import whipple_model
from ..models.parameters import NAMES

STEP = 1e-30
"""Complex step (dimensionless multiple of i)."""
MATRICES = ("M", "C1", "K0", "K2")
STIFFNESS_ENTRIES = {"S_phiphi": ((0, 0),), "S_phidelta": ((0, 1), (1, 0)), "S_deltadelta": ((1, 1),)}
"""Entries of the symmetric rear-frame stiffness S (N m/rad); ``S_phidelta`` moves both off-diagonals."""


def values_of(params):
    """``{name: float}`` of a :class:`~bikemass.models.parameters.BenchmarkParameters`."""
    return {name: float(getattr(params, name)) for name in NAMES}


def model_of(values, S=None):
    """The Whipple model of a mapping ``{name: value}`` of the 26 names (values may be complex) with
    rear-frame stiffness ``S`` (2x2 N m/rad, may be complex, or ``None``)."""
    return whipple_model(SimpleNamespace(**values), S)


def _stepped(base, name):
    return {**base, name: base[name] + 1j * STEP}


def matrix_derivatives(params, S=None, names=NAMES):
    """``{name: {"M", "C1", "K0", "K2": 2x2 derivative}}`` (complex step) for each of ``names``;
    ``K0`` is the static stiffness over g (the rigid frame's ``K0``)."""
    base = values_of(params)
    out = {}
    for name in names:
        values = _stepped(base, name)
        mech = model_of(values, S).mechanics
        m = {"M": mech.M, "C1": mech.C[1], "K0": mech.K[0] / values["g"], "K2": mech.K[2]}
        out[name] = {k: np.imag(v) / STEP for k, v in m.items()}
    return out


def state_matrix_derivatives(params, v, S=None, names=NAMES):
    """``{name: dA/dp}`` (dynamic block, at speed ``v``) by the complex step."""
    base = values_of(params)
    return {name: model_of(_stepped(base, name), S).dynamic_matrix(v).imag / STEP for name in names}


def stiffness_state_derivatives(params, v, S):
    """``{entry: dA/dS_entry}`` (dynamic block, per N m/rad) at speed ``v``; empty for a rigid frame."""
    if S is None:
        return {}
    base = values_of(params)
    out = {}
    for name, cells in STIFFNESS_ENTRIES.items():
        Sc = np.array(S, dtype=complex)
        for cell in cells:
            Sc[cell] += 1j * STEP
        out[name] = model_of(base, Sc).dynamic_matrix(v).imag / STEP
    return out
