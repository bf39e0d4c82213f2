"""Benchmark parameters from measurements: BicycleParameters' raw measured-data files.

BicycleParameters (Moore et al.) keeps what was measured on a bicycle in
``bicycles/<Name>/RawData/<Name>Measured.txt``: ``name = value`` or ``name = value+/-std`` lines (as
its ``<Name>Benchmark.txt``; comma-separated values averaged).  This module reads such a file (or
a YAML mapping of the same names, values as numbers or ``"value+/-std"`` strings) into a
:class:`MeasuredData` and computes the 26 benchmark parameters of Meijaard et al. (2007) from it,
each with its standard deviation, by the method the measurements were made for (Moore 2012, PhD
thesis, Ch. 2; Kooijman et al. 2008):

* wheel radii from the distance ``dR``/``dF`` (m) rolled in ``nR``/``nF`` revolutions:
  ``r = d / (2 pi n)``;
* the frame geometry either as wheelbase ``w`` (m), head-tube angle ``gamma`` (deg; ``lam = 90 deg -
  gamma``) and fork offset ``f`` (m), or as the heights ``h1..h5`` and diameters ``d1..d4``, ``d``
  (m) of the bicycle on a table: the offsets ``a = h1 + h2 - h3 + (d1 - d2)/2`` (rear wheel),
  ``b = h4 - h5 + (d4 - d3)/2`` (front wheel) and ``c = sqrt((d + (d2 + d3)/2)^2 - (a - b)^2)``,
  then ``lam`` from ``(a + b) sin lam - c cos lam = rF - rR`` (closed form: ``lam = atan(c/(a+b))
  + asin((rF - rR)/sqrt((a+b)^2 + c^2))``), ``w = (a + b) cos lam + c sin lam`` and the fork offset
  ``b``; the trail ``c = (rF sin lam - offset) / cos lam``;
* each frame's mass centre from the lines through it when hung in orientations ``i``: the
  pendulum axis at angle ``alpha{P}{i}`` (deg) from the horizontal, ``a{P}{i}`` (m) from a reference
  point (the rear axle for the rear frame ``B``, the front axle for the front frame ``H`` or the
  fork ``S``, the handlebar reference point for the handlebar ``G``); ``beta = lam - alpha`` and the
  line ``z = -tan(beta) x + b`` in the benchmark frame; the mass centre is the mean of the lines'
  pairwise intersections;
* the moments of inertia about the y axis of the wheels and frames from compound-pendulum periods
  ``Tc{P}1`` (s): ``I = m l (g T^2 / (4 pi^2) - l)`` with ``l`` the distance from the pivot (wheel:
  ``lR``/``lF``; frame: its reference axle, the handlebar reference point) to the mass centre;
* every other moment from torsional-pendulum periods ``Tt{P}{i}`` (s), the pendulum's stiffness
  calibrated by a rod (mass ``mP``, length ``lP``, diameter ``dP``, period ``TtP1``):
  ``I = I_rod (T / TtP1)^2``, ``I_rod = mP (3 (dP/2)^2 + lP^2) / 12``; a wheel's ``Ixx`` from
  ``Tt{R|F}1``, a frame's ``Ixx``, ``Ixz``, ``Izz`` from its orientations ``i`` (at least three; least
  squares beyond three): ``J_i = Ixx cos^2 beta_i - 2 Ixz sin beta_i cos beta_i + Izz sin^2 beta_i``;
* a front frame measured as handlebar ``G`` and fork ``S`` apart (``mG``, ``mS``, the handlebar
  reference point from ``h6``, ``h7``, ``d5``, ``d6``, ``l``) combined into ``H`` by the
  parallel-axis theorem; a flywheel ``D`` (``mD``, ``TcD1``, ``TtD1``, measured inside the front
  wheel: the wheel subtracted) and a lateral-force point ``xcl``, ``zcl`` are computed and kept
  in :attr:`~bikemass.bicycle.parameter_text.MeasuredParameters.extra` (the Whipple model has no
  place for them).

Standard deviations are first-order (linear) propagation of the independent measurements'
standard deviations, ``std(y)^2 = sum_j (dy/dx_j std_j)^2``, as the ``uncertainties`` package
BicycleParameters uses computes them; the derivatives ``dy/dx_j`` are exact (complex step: every
formula above is analytic).  The full covariance of the 26 parameters (they share
measurements: ``rF`` enters the trail, the front frame's mass centre and its inertia) is kept
too (:attr:`~bikemass.bicycle.parameter_text.MeasuredParameters.covariance`).

One choice differs from BicycleParameters (1.5.2), by default: where ``lam`` follows from the
offsets (``h1..h5``), BicycleParameters gives it the standard deviation of its initial guess
``atan(c / (a + b))`` and makes it a new measurement independent of all the others (its own
comment says the standard deviation is wrong); here ``lam``'s derivatives follow from its
equation (implicit function theorem), so ``lam``, ``w`` and the trail keep their correlation with
the offsets and the wheel radii.  ``lam_std="bicycleparameters"`` reproduces BicycleParameters.
"""

import os
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from ..core.config import load_yaml
from ..core.errors import InputError, short, wrong_type
from ..core.frozen import readonly
from ..core.gate import read_text
from ..core.paths import frames_dir, resolve
from ..models.parameters import NAMES, BenchmarkParameters
from ..models.plausibility import check_parameter_file, check_parameters
from .parameter_text import MeasuredParameters, _parse_value, looks_like_parameter_text, parse_parameter_text

LAM_STD = ("implicit", "bicycleparameters")
"""How ``lam``'s uncertainty follows from the offsets: from its equation (default), or as
BicycleParameters 1.5.2 gives it (the guess's std, independent of every other measurement)."""

COMMON = ("dR", "nR", "dF", "nF", "mR", "mF", "mB", "g", "lR", "lF", "TcR1", "TcF1", "TcB1",
          "mP", "lP", "dP", "TtP1", "TtR1", "TtF1")
"""Names every measured-data file needs."""
WHEELBASE_GEOMETRY = ("w", "gamma", "f")
OFFSET_GEOMETRY = ("h1", "h2", "h3", "h4", "h5", "d1", "d2", "d3", "d4", "d")
SPLIT_REFERENCE = ("h6", "h7", "d5", "d6", "l")
"""The handlebar reference point of a split front frame: table heights of the front axle and the
reference circle, their diameters, and the outer distance between them (m)."""
MARKERS = ("TtP1", "TcB1")
"""Names only a measured-data file holds (a parameter file has none of them)."""
STEP = 1e-30
"""Complex step: exact first derivatives (no subtraction, so no cancellation)."""


@dataclass(frozen=True)
class MeasuredData:
    """What was measured on a bicycle, as BicycleParameters' ``<Name>Measured.txt`` holds it.

    ``nominal[name]`` and ``std[name]`` in the file's units (lengths m, masses kg, periods s,
    the angles ``gamma`` and ``alpha{P}{i}`` degrees, ``g`` m/s^2; std 0 where the file gives
    none); ``front`` is ``"H"`` (front frame measured whole) or ``"GS"`` (handlebar and fork apart);
    ``orientations[P]`` the suffixes ``i`` of body ``P``'s pendulum orientations.

    See Also
    --------
    read_measured_data : Reads one.
    benchmark_from_measured : The benchmark parameters it gives.

    Examples
    --------
    >>> import bikemass as bm
    >>> data = bm.read_measured_data("browser-measured")
    >>> print(data.front, dict(data.orientations), data.nominal["TtP1"], data.std["mB"])
    H {'B': ('1', '2', '3'), 'H': ('1', '2', '3')} 1.89399317145 0.02
    """

    source: str
    nominal: MappingProxyType
    std: MappingProxyType
    front: str
    orientations: MappingProxyType

    def __repr__(self):
        return f"MeasuredData({self.source!r}, {len(self.nominal)} values, front {self.front})"


def looks_measured(names):
    """True if the names (of a file's lines or a mapping's keys) are those of a measured-data file."""
    return all(m in names for m in MARKERS) and "IBxx" not in names


def measured_data(nominal, std, source):
    """:class:`MeasuredData` of ``{name: value}`` and ``{name: std}``; InputError naming the first
    missing name, or an orientation without its distance or period."""
    names = set(nominal)
    split = "mG" in names or "mS" in names
    geometry = WHEELBASE_GEOMETRY if "w" in names else OFFSET_GEOMETRY
    parts = ("B", "G", "S") if split else ("B", "H")
    needed = [*COMMON, *geometry, *([f"m{p}" for p in "GS"] + [f"Tc{p}1" for p in "GS"] + list(SPLIT_REFERENCE)
                                    if split else ["mH", "TcH1"])]
    for name in needed:
        if name not in names:
            raise InputError(source, name, "a value: a measured-data file needs " + ", ".join(needed)
                             + " and each body's pendulum orientations alpha{P}{i}, a{P}{i}, Tt{P}{i}")
    orientations = {}
    for part in parts:
        found = sorted((k[6:] for k in names if k.startswith(f"alpha{part}") and k[6:].isdigit()), key=int)
        for i in found:
            for name in (f"a{part}{i}", f"Tt{part}{i}"):
                if name not in names:
                    raise InputError(source, name, f"a value: orientation {i} of body {part} has alpha{part}{i}")
        if len(found) < 3:
            raise InputError(source, f"alpha{part}{len(found) + 1}", f"at least three pendulum orientations of body "
                             f"{part} (alpha{part}i, a{part}i, Tt{part}i), got {len(found)}")
        orientations[part] = tuple(found)
    for name, value in nominal.items():
        if not np.isfinite(value):
            raise InputError(source, name, f"a finite number, got {short(value)}")
    periods = [f"Tt{part}{i}" for part, found in orientations.items() for i in found]
    for name in (*needed, *periods):
        if name not in ("f", *OFFSET_GEOMETRY, *SPLIT_REFERENCE) and not nominal[name] > 0:
            raise InputError(source, name, f"a positive number (a length, mass, count or period), got {nominal[name]!r}")
    for part, found in orientations.items():
        axes = {}                                                   # alpha and alpha + 180 deg: one axis
        for i in found:
            axes.setdefault(round(nominal[f"alpha{part}{i}"] % 180.0, 9), f"alpha{part}{i}")
        if len(axes) < 3:
            repeated = next(f"alpha{part}{i}" for i in found if f"alpha{part}{i}" not in axes.values())
            raise InputError(source, repeated, f"pendulum orientations of body {part} about at least "
                             f"three different axes (angles apart by other than a multiple of 180 deg), got "
                             + ", ".join(f"{nominal[f'alpha{part}{i}']:g}" for i in found) + " deg")
    if split and not nominal["l"] > (nominal["d5"] + nominal["d6"]) / 2:
        raise InputError(source, "l", "the outer distance from the front axle to the handlebar reference circle: "
                         f"more than their radii together ({(nominal['d5'] + nominal['d6']) / 2!r} m)")
    return MeasuredData(str(source), MappingProxyType(dict(nominal)), MappingProxyType(dict(std)),
                        "GS" if split else "H", MappingProxyType(orientations))


def read_measured_data(path: "str | os.PathLike") -> MeasuredData:
    """The measurements in a BicycleParameters measured-data file.

    Parameters
    ----------
    path : str or os.PathLike
        ``<Name>Measured.txt`` (``name = value`` or ``name = value+/-std`` lines, ``#`` comments,
        comma-separated values averaged), or a YAML file mapping the same names to numbers or
        ``"value+/-std"`` strings (the same units: lengths m, angles deg, periods s), or the name
        of a shipped one (``"browser-measured"``).

    Returns
    -------
    MeasuredData
        The nominal values and standard deviations.

    Raises
    ------
    InputError
        An unreadable file, a bad line or value, a name missing for the computation.

    See Also
    --------
    benchmark_from_measured : The benchmark parameters of the measurements.

    Examples
    --------
    >>> import bikemass as bm
    >>> data = bm.read_measured_data("browser-measured")
    >>> print(data.nominal["gamma"], data.std["gamma"])
    67.1 0.2
    """
    if not isinstance(path, (str, os.PathLike)):
        raise wrong_type("path", path, "a measured-data file path")
    path = resolve(os.fspath(path), frames_dir(), "measured-data")
    text = read_text(path)
    if not looks_like_parameter_text(text):
        return measured_data_of_node(load_yaml(path))
    parsed = parse_parameter_text(text, str(path))
    return measured_data(parsed.nominal, parsed.std, str(path))


def measured_data_of_node(node):
    """:class:`MeasuredData` of a YAML mapping :class:`~bikemass.core.config.Node` of measurements."""
    nominal, std = {}, {}
    for key, item in node.items():
        key = str(key)
        if key in ("name", "description", "source"):
            continue
        value = item.value
        if isinstance(value, bool) or not isinstance(value, (int, float, str)):
            item.fail(f"a number or 'number+/-std', got {short(value)}")
        nominal[key], std[key], _ = _parse_value(str(value), str(node.source), item.key)
    return measured_data(nominal, std, str(node.source))


def _compound(m, g, length, period):
    """Moment of inertia (kg m^2) about the mass centre of a compound pendulum of mass ``m`` whose
    mass centre hangs ``length`` below its pivot, swinging with ``period``."""
    return m * length * (g * period ** 2 / (4 * np.pi ** 2) - length)


def _lines_meet(slopes, intercepts):
    """Mean of the pairwise intersections of the lines ``z = slope x + intercept``."""
    xs, zs = [], []
    n = len(slopes)
    for i in range(n):
        for j in range(i + 1, n):
            x = (intercepts[i] - intercepts[j]) / (slopes[j] - slopes[i])
            xs.append(x)
            zs.append(intercepts[i] + slopes[i] * x)
    return sum(xs) / len(xs), sum(zs) / len(zs)


def _planar_inertia(moments, betas):
    """``(Ixx, Ixz, Izz)`` from moments about axes at angles ``betas`` (least squares beyond
    three; plain transposes, so complex steps pass through)."""
    c, s = np.cos(betas), np.sin(betas)
    A = np.stack([c * c, -2 * s * c, s * s], axis=1)
    J = np.asarray(moments)
    if len(J) > 3:
        A, J = A.T @ A, A.T @ J
    return np.linalg.solve(A, J)


def _steer_tilt(rF, rR, a, b, c):
    """``lam`` solving ``(a + b) sin lam - c cos lam = rF - rR``: the root nearest
    ``atan(c/(a+b))``, the steer axis of equal wheels."""
    return np.arctan(c / (a + b)) + np.arcsin((rF - rR) / np.sqrt((a + b) ** 2 + c ** 2))


def _benchmark(v, data, lam_shift=0.0, fixed_lam=None):
    """``{name: value}`` of the 26 parameters and the extras from measurements ``v`` (real or
    complex-stepped); ``fixed_lam``: use this ``lam`` (BicycleParameters' way) plus ``lam_shift``.
    Also returns ``lam``'s initial guess under ``"guess"`` (offset geometry only)."""
    pi = np.pi
    out = {"rF": v["dF"] / (2 * pi * v["nF"]), "rR": v["dR"] / (2 * pi * v["nR"]), "g": v["g"]}
    rF, rR = out["rF"], out["rR"]
    if "w" in data.nominal:
        lam, w, offset = pi / 180 * (90 - v["gamma"]), v["w"], v["f"]
    else:
        a = v["h1"] + v["h2"] - v["h3"] + 0.5 * v["d1"] - 0.5 * v["d2"]
        b = v["h4"] - 0.5 * v["d3"] - v["h5"] + 0.5 * v["d4"]
        c = np.sqrt((v["d"] + 0.5 * (v["d2"] + v["d3"])) ** 2 - (a - b) ** 2)
        out["guess"] = np.arctan(c / (a + b))
        lam = (_steer_tilt(rF, rR, a, b, c) if fixed_lam is None else fixed_lam) + lam_shift
        w, offset = (a + b) * np.cos(lam) + c * np.sin(lam), b
    out.update(lam=lam, w=w, c=(rF * np.sin(lam) - offset) / np.cos(lam))
    u1 = u2 = 0.0
    if data.front == "GS":                        # the handlebar reference point from the front axle
        r5, r6 = v["d5"] / 2, v["d6"] / 2
        l1, l0 = v["h7"] - v["h6"] + r5 - r6, v["l"] - r5 - r6
        l2 = np.sqrt(l0 ** 2 - l1 ** 2)
        u1 = l2 * np.sin(lam) - l1 * np.cos(lam)
        u2 = u1 / np.tan(lam) + l1 / np.sin(lam)
    rod = v["mP"] * (3 * (v["dP"] / 2) ** 2 + v["lP"] ** 2) / 12

    def torsional(period):
        return rod * (period / v["TtP1"]) ** 2

    for wheel in "RF":
        out[f"m{wheel}"] = v[f"m{wheel}"]
        out[f"I{wheel}yy"] = _compound(v[f"m{wheel}"], v["g"], v[f"l{wheel}"], v[f"Tc{wheel}1"])
        out[f"I{wheel}xx"] = torsional(v[f"Tt{wheel}1"])
    for part, suffixes in data.orientations.items():
        slopes, intercepts, betas = [], [], []
        for i in suffixes:
            beta = lam - v[f"alpha{part}{i}"] * pi / 180
            along = -v[f"a{part}{i}"] / np.cos(beta)
            if part == "B":
                intercept = along - rR
            elif part == "G":
                intercept = along - (rF + u2) + (w - u1) * np.tan(beta)
            else:
                intercept = along - rF + w * np.tan(beta)
            slopes.append(-np.tan(beta))
            intercepts.append(intercept)
            betas.append(beta)
        x, z = _lines_meet(slopes, intercepts)
        pivot = {"B": (0.0, -rR), "G": (w - u1, -rF - u2)}.get(part, (w, -rF))
        m = v[f"m{part}"]
        Ixx, Ixz, Izz = _planar_inertia([torsional(v[f"Tt{part}{i}"]) for i in suffixes], np.array(betas))
        length = np.sqrt((x - pivot[0]) ** 2 + (z - pivot[1]) ** 2)
        out.update({f"m{part}": m, f"x{part}": x, f"z{part}": z, f"I{part}xx": Ixx, f"I{part}xz": Ixz,
                    f"I{part}zz": Izz, f"I{part}yy": _compound(m, v["g"], length, v[f"Tc{part}1"])})
    if data.front == "GS":
        _join_front(out)
    if "mD" in data.nominal and "TcD1" in data.nominal and "TtD1" in data.nominal:
        out["mD"] = v["mD"] - v["mF"]             # weighed with the front wheel it sits in
        out["IDyy"] = _compound(v["mD"], v["g"], v["lF"], v["TcD1"]) - out["IFyy"]
        out["IDxx"] = torsional(v["TtD1"]) - out["IFxx"]
    for name in ("xcl", "zcl"):
        if name in data.nominal:
            out[name] = v[name]
    return out


def _join_front(out):
    """The front frame ``H`` of handlebar ``G`` and fork ``S`` (parallel-axis theorem), in ``out``."""
    mG, mS = out["mG"], out["mS"]
    m = mG + mS
    x, z = (mG * out["xG"] + mS * out["xS"]) / m, (mG * out["zG"] + mS * out["zS"]) / m
    H = {"mH": m, "xH": x, "zH": z, "IHxx": 0.0, "IHyy": 0.0, "IHzz": 0.0, "IHxz": 0.0}
    for p, mp in (("G", mG), ("S", mS)):
        dx, dz = out[f"x{p}"] - x, out[f"z{p}"] - z
        H["IHxx"] = H["IHxx"] + out[f"I{p}xx"] + mp * dz * dz
        H["IHyy"] = H["IHyy"] + out[f"I{p}yy"] + mp * (dx * dx + dz * dz)
        H["IHzz"] = H["IHzz"] + out[f"I{p}zz"] + mp * dx * dx
        H["IHxz"] = H["IHxz"] - mp * dx * dz + out[f"I{p}xz"]
    out.update(H)


def _checked(compute, values, data):
    """``compute(values, data)`` (real values), InputError naming the first result that is not a finite
    number (measurements that give no bicycle: parallel mass-centre lines, offsets longer than the
    distance they span, ...)."""
    with np.errstate(all="ignore"):
        found = compute(_Tracked({k: np.float64(v) for k, v in values.items()}), data)
    for name, value in found.items():
        if not np.isfinite(value):
            name = "lam" if name == "guess" else name
            raise InputError(data.source, name, "measurements that give a bicycle: they give "
                             f"{name} = {value} (parallel mass-centre lines, an offset longer than the distance "
                             "it spans, a zero period, ...)")
    return found


class _Tracked(dict):
    """A dict that remembers which keys were read (:attr:`read`)."""

    def __init__(self, *args):
        super().__init__(*args)
        self.read = set()

    def __getitem__(self, key):
        self.read.add(key)
        return super().__getitem__(key)


def unused_names(data):
    """The names of ``data`` (:class:`MeasuredData`) the computation does not read (BicycleParameters'
    rider-placement lengths ``lcs``, ``hbb``, ..., a fourth distance without its angle, ...)."""
    values = _Tracked({k: float(x) for k, x in data.nominal.items()})
    with np.errstate(all="ignore"):
        _benchmark(values, data)
    return tuple(n for n in data.nominal if n not in values.read)


def _propagated(data, lam_std):
    """Nominal outputs, their names, the measured inputs with a std, and the Jacobian (outputs x
    inputs, plus BicycleParameters' independent ``lam`` as a last input when asked for)."""
    base = {k: float(x) for k, x in data.nominal.items()}
    nominal = _checked(_benchmark, base, data)
    fixed = nominal["lam"] if lam_std == "bicycleparameters" and "guess" in nominal else None
    names = [n for n in nominal if n != "guess"]
    inputs = [k for k, s in data.std.items() if s > 0]
    jac = np.zeros((len(names) + 1, len(inputs) + 1))
    for j, key in enumerate(inputs):
        with np.errstate(all="ignore"):
            stepped = _benchmark({**base, key: base[key] + 1j * STEP}, data, fixed_lam=fixed)
        jac[:, j] = [np.imag(stepped.get(n, 0.0)) / STEP for n in [*names, "guess"]]
    sigma = np.array([data.std[k] for k in inputs] + [0.0])
    if fixed is not None:                         # lam: a new measurement with the guess's std
        sigma[-1] = float(np.sqrt(np.sum((jac[-1, :-1] * sigma[:-1]) ** 2)))
        stepped = _benchmark(base, data, lam_shift=1j * STEP, fixed_lam=fixed)
        jac[:, -1] = [np.imag(stepped.get(n, 0.0)) / STEP for n in [*names, "guess"]]
    values = {n: float(np.real(nominal[n])) for n in names}
    return values, names, jac[:-1], sigma


def benchmark_from_measured(data: MeasuredData, lam_std: str = "implicit") -> MeasuredParameters:
    """The benchmark parameters of a bicycle's measurements, with standard deviations.

    Parameters
    ----------
    data : MeasuredData
        The measurements (:func:`read_measured_data`).
    lam_std : {"implicit", "bicycleparameters"}
        Where ``lam`` follows from the offsets ``h1..h5``: its derivatives from its equation
        (default), or BicycleParameters 1.5.2's standard deviation (that of its initial guess
        ``atan(c/(a+b))``, independent of every other measurement).  Without offsets (``gamma``
        given) both are the same.

    Returns
    -------
    MeasuredParameters
        ``.parameters`` the 26 nominal values (SI), ``.std`` their standard deviations (first-order
        propagation), ``.covariance`` (26 x 26, in the order of ``bikemass.PARAMETER_NAMES``),
        ``.extra``/``.extra_std`` what the Whipple model has no place for (a split front frame's
        ``G`` and ``S``, a flywheel ``D``, ``xcl``, ``zcl``), ``.notes``.

    Raises
    ------
    InputError
        Measurements that give no bicycle (an unknown ``lam_std``, a parameter out of range).

    See Also
    --------
    read_measured_data : Reads the measurements.
    load_bicycle : Takes a measured-data file as a bicycle.

    Examples
    --------
    >>> import bikemass as bm
    >>> data = bm.read_measured_data("browser-measured")
    >>> found = bm.benchmark_from_measured(data)
    >>> print(f"trail {found.parameters.c:.5f} +- {found.std['c']:.5f} m, IBxx {found.parameters.IBxx:.4f} kg m^2")
    trail 0.06858 +- 0.00169 m, IBxx 0.5296 kg m^2
    """
    if not isinstance(data, MeasuredData):
        raise wrong_type("data", data, "a MeasuredData (bm.read_measured_data)")
    if lam_std not in LAM_STD:
        raise InputError("lam_std", lam_std, f"one of {', '.join(LAM_STD)}")
    values, names, jac, sigma = _propagated(data, lam_std)
    scaled = jac * sigma
    std = dict(zip(names, np.sqrt(np.sum(scaled ** 2, axis=1))))
    rows = [names.index(n) for n in NAMES]
    covariance = readonly(scaled[rows] @ scaled[rows].T)
    params = BenchmarkParameters(**{n: values[n] for n in NAMES})
    check_parameter_file(params, data.source)
    notes = [f"benchmark parameters computed from measurements ({len([s for s in sigma if s > 0])} with a std); "
             f"lam std: {lam_std}"]
    if data.front == "GS":
        notes.append("front frame H = handlebar G + fork S (parallel-axis theorem)")
    extra = [n for n in names if n not in NAMES]
    unused = unused_names(data)
    if unused:
        notes.append("measurements not used: " + ", ".join(unused))
    if any(n in extra for n in ("mD", "xcl")):
        notes.append("not used (no place in the Whipple model): "
                     + ", ".join(n for n in extra if n[1:2] == "D" or n in ("xcl", "zcl")))
    return MeasuredParameters(params, MappingProxyType({n: float(std[n]) for n in NAMES}), tuple(notes), data.source,
                              extra=MappingProxyType({n: values[n] for n in extra}),
                              extra_std=MappingProxyType({n: float(std[n]) for n in extra}), covariance=covariance,
                              data=data)


def measured_values(data, changes=None):
    """The nominal :class:`~bikemass.models.parameters.BenchmarkParameters` of ``data`` with its
    measurements ``changes`` (``{name: value}``, the file's units) changed, checked as a parameter file
    is (errors; no warnings); no standard deviations (what a Monte Carlo draw or a difference step needs).  InputError
    naming a change that is no measurement of ``data``."""
    nominal = dict(data.nominal)
    for name, value in (changes or {}).items():
        if name not in nominal:
            raise InputError(data.source, name, f"a measurement of this file ({short(', '.join(nominal), 80)})")
        nominal[name] = float(value)
    found = _checked(_benchmark, nominal, data)
    params = BenchmarkParameters(**{n: float(np.real(found[n])) for n in NAMES})
    check_parameters(params, data.source)          # errors only: the file's own warnings came when it was read
    return params


def load_measured(path: "str | os.PathLike", lam_std: str = "implicit") -> MeasuredParameters:
    """:func:`benchmark_from_measured` of :func:`read_measured_data` ``(path)``.

    Parameters
    ----------
    path : str or os.PathLike
        A BicycleParameters measured-data file (``<Name>Measured.txt``), its YAML form, or the
        name of a shipped one (``"browser-measured"``).
    lam_std : {"implicit", "bicycleparameters"}
        See :func:`benchmark_from_measured`.

    Returns
    -------
    MeasuredParameters
        The 26 parameters with standard deviations and covariance.

    Raises
    ------
    InputError
        An unreadable file, a bad value, a measurement missing, or measurements that give no bicycle.

    See Also
    --------
    load_bicycle : Takes the same file as a bicycle.

    Examples
    --------
    >>> import bikemass as bm
    >>> found = bm.load_measured("browser-measured")
    >>> print(f"w = {found.parameters.w} +- {found.std['w']} m")
    w = 1.121 +- 0.002 m
    """
    return benchmark_from_measured(read_measured_data(path), lam_std)


def measured_of_node(node):
    """:class:`MeasuredParameters` of a YAML mapping of measurements (``node``)."""
    return benchmark_from_measured(measured_data_of_node(node))
