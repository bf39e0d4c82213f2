"""The state space of a linear bicycle model at one speed, as data other tools read (``bm.state_space``).

``x' = A x + B u``, ``y = C x + D u`` with the names and units of the states ``x``, the inputs ``u``
and the outputs ``y``, and, where the model has mechanical coordinates ``q``, its second-order form
``M q'' + C(v) q' + K(v) q = F u`` with ``C(v)`` and ``K(v)`` as polynomials in the speed ``v``.
:class:`StateSpace` writes itself as MATLAB ``.mat`` (:func:`scipy.io.savemat`), numpy ``.npz``,
JSON or YAML (with the ``units`` block of docs/cli.md) and CSV (one row per matrix entry); the
layout is docs/handling.md, "State spaces out".
"""

import io
import json
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ..core.results import Result, declared_units, quantity
from ..core.frozen import readonly, short_repr
from ..models.linear import LinearModel
from ..models.parameters import BenchmarkParameters
from ..scenario.scenario import Scenario
from .handling.plant import check_speed, linear_model, output_row

CSV_HEADERS = ("matrix", "power", "row", "column", "value", "row unit", "column unit")
"""The CSV layout: one row per entry of A, B, C, D (power empty) and of the mechanics' matrices
(``power`` k: the coefficient of ``v**k`` of ``mechanics_C`` and ``mechanics_K``)."""


def rate_unit(unit):
    """The unit of a state's time derivative: ``rad`` -> ``rad/s``, ``rad/s`` -> ``rad/s^2``, ``N`` -> ``N/s``."""
    return f"{unit}^2" if unit.endswith("/s") else f"{unit}/s"


@dataclass(frozen=True, eq=False, repr=False)
class StateSpace(Result):
    """``x' = A x + B u``, ``y = C x + D u`` of a linear model at one speed, with names and units.

    Attributes
    ----------
    model : str
        The model's name (``"whipple"``, ``"tyre"``, ...).
    speed : float
        Forward speed (m/s).
    states, inputs, outputs : tuple of str
        The signals' names in the order of the rows and columns; ``state_units``, ``input_units``,
        ``output_units`` their SI units.
    A, B, C, D : numpy.ndarray
        (N, N), (N, m), (p, N), (p, m); read-only.
    coordinates : tuple of str
        The mechanical coordinates ``q`` of the second-order form (empty where the model has none,
        e.g. the tyre member, whose tyre forces lag).
    mechanics_M : numpy.ndarray (n, n) or None
        Mass matrix.
    mechanics_C, mechanics_K : numpy.ndarray (d + 1, n, n) or None
        Coefficients of ``v**k`` of the damping and stiffness matrices: for the Whipple bicycle
        ``mechanics_C[1]`` is Meijaard et al.'s ``C1``, ``mechanics_K[0]`` their ``g K0`` and
        ``mechanics_K[2]`` their ``K2``.
    mechanics_F : numpy.ndarray (n, m) or None
        How the inputs enter the equations of motion.

    Examples
    --------
    >>> import bikemass as bm
    >>> ss = bm.state_space(bm.parameters("benchmark"), 5.0)
    >>> ss.states[:4], ss.A.shape, ss.mechanics_K.shape
    (('roll-angle', 'steer-angle', 'roll-rate', 'steer-rate'), (6, 6), (3, 2, 2))
    """

    model: str
    speed: float = quantity("m/s", "forward speed")
    states: tuple = ()
    inputs: tuple = ()
    outputs: tuple = ()
    state_units: tuple = ()
    input_units: tuple = ()
    output_units: tuple = ()
    A: np.ndarray = quantity("(row state's unit)/s per (column state's unit)", "(N, N)", default=None)
    B: np.ndarray = quantity("(row state's unit)/s per (column input's unit)", "(N, m)", default=None)
    C: np.ndarray = quantity("(row output's unit) per (column state's unit)", "(p, N)", default=None)
    D: np.ndarray = quantity("(row output's unit) per (column input's unit)", "(p, m)", default=None)
    coordinates: tuple = ()
    mechanics_M: np.ndarray | None = quantity("SI (kg m^2 where the coordinates are angles)", "mass matrix",
                                              default=None)
    mechanics_C: np.ndarray | None = quantity(
        "SI per (m/s)^k (N m s/rad where the coordinates are angles and the inputs torques)",
        "(d + 1, n, n): the coefficients of v**k of the damping matrix", default=None)
    mechanics_K: np.ndarray | None = quantity(
        "SI per (m/s)^k (N m/rad where the coordinates are angles and the inputs torques)",
        "(d + 1, n, n): the coefficients of v**k of the stiffness matrix", default=None)
    mechanics_F: np.ndarray | None = quantity(
        "(row equation's generalised force) per (column input's unit): 1 for torques on angles",
        "(n, m): how the inputs enter the equations of motion", default=None)

    def __post_init__(self):
        for name in ("A", "B", "C", "D", "mechanics_M", "mechanics_C", "mechanics_K", "mechanics_F"):
            object.__setattr__(self, name, readonly(getattr(self, name), None if getattr(self, name) is None
                                                    else float))
        for name in ("states", "inputs", "outputs", "state_units", "input_units", "output_units", "coordinates"):
            object.__setattr__(self, name, tuple(getattr(self, name)))

    def arrays(self):
        """``{key: value}`` of every field (names as tuples of str, matrices as arrays); the mechanics'
        keys only where the model has them."""
        keys = ("model", "speed", "states", "inputs", "outputs", "state_units", "input_units", "output_units",
                "A", "B", "C", "D")
        if self.mechanics_M is not None:
            keys += ("coordinates", "mechanics_M", "mechanics_C", "mechanics_K", "mechanics_F")
        return {k: getattr(self, k) for k in keys}

    def to_dict(self):
        """Plain data (lists, floats, strings) of :meth:`arrays`."""
        return {k: v.tolist() if isinstance(v, np.ndarray) else list(v) if isinstance(v, tuple) else v
                for k, v in self.arrays().items()}

    def units(self):
        """The ``units`` block: the declared unit of each key of :meth:`to_dict` that holds a quantity
        (:data:`MATRIX_UNITS`' order: the matrices, then the speed)."""
        return {k: u for k, u in MATRIX_UNITS.items() if k in self.arrays()}

    def to_npz(self):
        """The bytes of a numpy ``.npz`` file: every key of :meth:`arrays` (names as string arrays) and
        ``units``, the JSON text of :meth:`units` (no pickled objects: ``numpy.load`` reads it as it is)."""
        data = {k: np.asarray(v) for k, v in self.arrays().items()}
        data["units"] = np.asarray(json.dumps(self.units()))
        buffer = io.BytesIO()
        np.savez(buffer, **data)
        return buffer.getvalue()

    def to_mat(self):
        """The bytes of a MATLAB ``.mat`` file (version 5, :func:`scipy.io.savemat`): the matrices as
        double arrays, the names as cell arrays of strings, ``units`` a struct."""
        # lazy: scipy.io is needed only for a .mat file
        import scipy.io
        data = {k: np.array(v, dtype=object) if isinstance(v, tuple) else v for k, v in self.arrays().items()}
        data["units"] = self.units()
        buffer = io.BytesIO()
        scipy.io.savemat(buffer, data, oned_as="column")
        return buffer.getvalue()

    def csv_rows(self):
        """The rows of the CSV layout (:data:`CSV_HEADERS`): matrix, power, row and column names, the
        value, the units of the row's and the column's signals."""
        d_states = tuple(rate_unit(u) for u in self.state_units)
        rows = []

        def add(name, matrix, row_names, row_units, column_names, column_units, power=None):
            for i, (r, ru) in enumerate(zip(row_names, row_units)):
                for j, (c, cu) in enumerate(zip(column_names, column_units)):
                    rows.append([name, power, r, c, float(matrix[i, j]), ru, cu])

        add("A", self.A, self.states, d_states, self.states, self.state_units)
        add("B", self.B, self.states, d_states, self.inputs, self.input_units)
        add("C", self.C, self.outputs, self.output_units, self.states, self.state_units)
        add("D", self.D, self.outputs, self.output_units, self.inputs, self.input_units)
        if self.mechanics_M is not None:
            q, units = self.coordinates, self.state_units[:len(self.coordinates)]
            add("mechanics_M", self.mechanics_M, q, units, q, units)
            for name in ("mechanics_C", "mechanics_K"):
                for k, matrix in enumerate(getattr(self, name)):
                    add(name, matrix, q, units, q, units, k)
            add("mechanics_F", self.mechanics_F, q, units, self.inputs, self.input_units)
        return rows

    def __repr__(self):
        return short_repr(self, ("model", self.model), ("speed", f"{self.speed:g} m/s"),
                          ("states", len(self.states)), ("inputs", len(self.inputs)), ("outputs", len(self.outputs)))


MATRIX_UNITS = {k: declared_units(StateSpace)[k] for k in ("A", "B", "C", "D", "mechanics_M", "mechanics_C",
                                                          "mechanics_K", "mechanics_F", "speed")}
"""The ``units`` block of a written state space, as :class:`StateSpace`'s fields declare it: each
matrix's entries relate the units that its rows' and columns' signals name (``state_units``,
``input_units``, ``output_units``)."""


def state_space(system: LinearModel | Scenario | BenchmarkParameters, speed: float,
                outputs: "list[str] | None" = None, stiffness: "ArrayLike | None" = None) -> StateSpace:
    """The state space ``A, B, C, D`` of a linear bicycle model at one speed, named, with units.

    Parameters
    ----------
    system : LinearModel, Scenario or BenchmarkParameters
        A model of the family, a scenario (built with its ``model``), or the 26 Meijaard et al.
        (2007) parameters (the Whipple bicycle).
    speed : float
        Forward speed (m/s), 0 to 1000.
    outputs : sequence of str, optional
        The outputs ``y``, each a state or a further output of the model (the Whipple bicycle's
        ``front-lateral``); default every state and every further output.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set; ``None`` for a rigid frame.

    Returns
    -------
    StateSpace
        ``A`` (N, N), ``B`` (N, m), ``C`` (p, N), ``D`` (p, m) in SI with the names and units of the
        states, inputs and outputs, and the second-order form where the model has one.

    Raises
    ------
    InputError
        A speed that is not a finite number in 0..1000 m/s, an unknown output (the closest name is
        suggested), a bad S, or a system of another type.

    See Also
    --------
    linear_model : The model itself; its ``to_control`` and ``to_scipy`` give python-control's and
        scipy's state-space objects.

    Examples
    --------
    >>> import bikemass as bm
    >>> ss = bm.state_space(bm.parameters("benchmark"), 5.0, outputs=["roll-angle", "steer-angle"])
    >>> ss.C.shape, ss.inputs
    ((2, 6), ('roll-torque', 'steer-torque'))
    >>> print(f"{ss.A[2, 1]:.6f} 1/s^2")     # d(roll-rate)/dt per rad of steer
    -22.851467 1/s^2
    """
    model = linear_model(system, stiffness)
    v = check_speed(speed)
    names = model.output_names if outputs is None else tuple(outputs)
    C = np.array([output_row(model, name) for name in names]).reshape(len(names), len(model.states))
    A, B = model.state_matrix(v), model.input_matrix(v)
    mech = model.mechanics
    extra = {} if mech is None else {
        "coordinates": tuple(s.name for s in mech.coordinates), "mechanics_M": mech.M, "mechanics_C": mech.C,
        "mechanics_K": mech.K, "mechanics_F": mech.F}
    return StateSpace(model.name, v, model.state_names, model.input_names, names,
                      tuple(s.unit for s in model.states), tuple(s.unit for s in model.inputs),
                      tuple(model.output_signal(n).unit for n in names), A, B, C,
                      np.zeros((len(names), len(model.inputs))), **extra)
