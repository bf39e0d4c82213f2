"""BicycleParameters' parameter text files, read as that package ships them.

A file ``<Name>Benchmark.txt`` (BicycleParameters' ``bicycles/<Name>/Parameters/``)
holds one ``name = value`` line per parameter; a value may carry a standard
deviation (``0.08+/-0.01`` or ``0.08 ± 0.01``), several comma-separated values
are averaged (their standard deviations combined as for a mean of independent
measurements), ``#`` starts a comment.  Besides the 26 Meijaard names a file may hold:

* a front frame split into handlebar ``G`` and fork ``S`` (``mG xG zG IGxx IGyy IGzz
  IGxz`` and the same with ``S``): combined into ``H`` (parallel-axis theorem); where
  the file also gives ``H``, the given ``H`` is used (as BicycleParameters does) and
  checked against the combination;
* ``IRzz``/``IFzz`` (checked equal to ``IRxx``/``IFxx``: the model's wheels are
  axisymmetric) and lateral positions ``yB yH yG yS`` (checked zero: the model is
  laterally symmetric);
* anything else (a flywheel ``D``, ...), which the Whipple model has no place for:
  reported and not used.

Every such decision is kept in :attr:`MeasuredParameters.notes`; a check that fails
is also issued as a :class:`ParameterFileWarning`.  Nominal values build the
:class:`~bikemass.models.parameters.BenchmarkParameters`; the standard deviations are kept
(:attr:`MeasuredParameters.std`, with ``H``'s propagated linearly from ``G`` and
``S`` when combined) for uncertainty propagation.
"""

import os
import re
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType

import numpy as np

from ..core.config import Node, MAX_MAGNITUDE
from ..core.errors import BikemassWarning, InputError, wrong_type, short
from ..core.gate import read_text
from ..mass.inertia import MassProperties, combine
from ..models.parameters import NAMES, from_node
from ..models.plausibility import check_parameter_file

BODY_KEYS = ("m", "x", "z", "Ixx", "Iyy", "Izz", "Ixz")
"""A rigid body's seven planar mass properties: ``m{P} x{P} z{P} I{P}xx ...`` for body letter ``P``."""
SPLIT_BODIES = {"G": "handlebar", "S": "fork"}
"""The front frame's parts when BicycleParameters measured them apart."""
AXISYMMETRIC = {"IRzz": "IRxx", "IFzz": "IFxx"}
LATERAL = ("yB", "yH", "yG", "yS")
CHECK_SIGMAS = 3.0
"""A check passes when values differ by at most this many (combined) standard deviations
plus what the printed digits can hide."""

_NAME = re.compile(r"[A-Za-z_]\w*$")
_NUMBER = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,4})?"
"""A decimal number as Python's float() reads it (no ``1.2.3``, no bare ``.``; exponents of at
most four digits)."""
_VALUE = re.compile(rf"^\s*([-+]?{_NUMBER})\s*(?:(?:\+/-|±)\s*({_NUMBER}))?\s*$")


class ParameterFileWarning(BikemassWarning):
    """A BicycleParameters file is read, but something in it does not add up.

    See Also
    --------
    bikemass.load_parameter_text : Issues it.

    Examples
    --------
    >>> import os, tempfile, warnings
    >>> import bikemass as bm
    >>> path = os.path.join(tempfile.mkdtemp(), "TandemBenchmark.txt")
    >>> lines = [f"{k} = {v}" for k, v in bm.parameters("benchmark").to_dict().items()]
    >>> _ = open(path, "w").write(chr(10).join(lines + ["mStoker = 70.0"]))
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always", bm.ParameterFileWarning)
    ...     measured = bm.load_parameter_text(path)
    >>> print(caught[0].category.__name__, str(caught[0].message).split(": ", 1)[1])
    ParameterFileWarning not used by the Whipple model: mStoker
    >>> issubclass(bm.ParameterFileWarning, bm.BikemassWarning)
    True
    """


def _key(part, k):
    return f"{k}{part}" if k in "mxz" else f"I{part}{k[1:]}"


def body_names(part):
    """The seven parameter names of body letter ``part`` (``mH xH zH IHxx IHyy IHzz IHxz``)."""
    return tuple(_key(part, k) for k in BODY_KEYS)


@dataclass(frozen=True)
class ParameterText:
    """Everything in one parameter text file: ``nominal[name]`` and ``std[name]``
    (SI, radians; std 0 where the file gives none), ``resolution[name]`` (half a unit in
    the last printed digit), ``lines[name]`` (1-based line number)."""

    source: str
    nominal: MappingProxyType
    std: MappingProxyType
    resolution: MappingProxyType
    lines: MappingProxyType

    def __repr__(self):
        return f"ParameterText({self.source!r}, {len(self.nominal)} names)"


def printed_resolution(text):
    """Half a unit in the last printed digit of a number written as ``text``."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def _parse_value(text, source, where):
    """(nominal, std, resolution) of one right-hand side; several values are averaged."""
    values = []
    for item in text.split(","):
        m = _VALUE.match(item)
        if not m:
            raise InputError(source, where, f"a number or number+/-std (comma-separated to average), "
                                            f"got {text.strip()!r}")
        nominal, std = float(m.group(1)), float(m.group(2) or 0.0)
        if not (abs(nominal) <= MAX_MAGNITUDE and std <= MAX_MAGNITUDE):
            raise InputError(source, where, f"finite numbers of magnitude at most {MAX_MAGNITUDE:g}, "
                                            f"got {short(text.strip())}")
        values.append((nominal, std, printed_resolution(m.group(1))))
    n = len(values)
    return (sum(v[0] for v in values) / n, float(np.sqrt(sum(v[1] ** 2 for v in values))) / n,
            max(v[2] for v in values))


def parse_parameter_text(text, source="(text)"):
    """:class:`ParameterText` of the text of a parameter file; :class:`InputError` on a bad line."""
    nominal, std, lines, res = {}, {}, {}, {}
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        where = f"line {number}"
        name, eq, value = line.partition("=")
        name = name.strip()
        if not eq or not _NAME.match(name):
            raise InputError(source, where, f"'name = value' or 'name = value+/-std', got {raw.strip()!r}")
        if name in nominal:
            raise InputError(source, where, f"{name} given once (also on line {lines[name]})")
        nominal[name], std[name], res[name] = _parse_value(value, source, f"{where} ({name})")
        lines[name] = number
    if not nominal:
        raise InputError(source, "(file)", "'name = value' lines (a BicycleParameters parameter file)")
    return ParameterText(str(source), *(MappingProxyType(d) for d in (nominal, std, res, lines)))


def read_parameter_text(path):
    """:class:`ParameterText` of the file at ``path``."""
    path = Path(path)
    return parse_parameter_text(read_text(path), str(path))


def looks_like_parameter_text(text):
    """True if every non-comment line of ``text`` is ``name = ...`` (a BicycleParameters file)."""
    lines = [ln.split("#", 1)[0].strip() for ln in text.splitlines()]
    lines = [ln for ln in lines if ln]
    return bool(lines) and all(_NAME.match(ln.partition("=")[0].strip()) and "=" in ln for ln in lines)


@dataclass(frozen=True)
class MeasuredParameters:
    """A measured bicycle: nominal :class:`~bikemass.models.parameters.BenchmarkParameters`,
    ``std[name]`` for the 26 names (SI), and ``notes``: how every key beyond the 26 was used.

    Computed from raw measurements (:func:`bikemass.load_measured`) it also holds ``extra``
    and ``extra_std``: values the Whipple model has no place for (a split front frame's handlebar
    ``G`` and fork ``S``, a flywheel ``D``), and ``covariance``: the 26 x 26 covariance (SI, in
    the order of ``bikemass.PARAMETER_NAMES``; the parameters share measurements), else ``None``
    (a parameter file gives standard deviations only); ``data``: the
    :class:`~bikemass.bicycle.measured.MeasuredData` it was computed from, else ``None``.

    See Also
    --------
    bikemass.load_parameter_text : Reads one.

    Examples
    --------
    >>> import os, tempfile
    >>> import bikemass as bm
    >>> path = os.path.join(tempfile.mkdtemp(), "BenchmarkBenchmark.txt")
    >>> values = bm.parameters("benchmark").to_dict()
    >>> lines = [f"{k} = {v}+/-0.001" for k, v in values.items()]
    >>> _ = open(path, "w").write(chr(10).join(lines))      # BicycleParameters' name = value+/-std
    >>> measured = bm.load_parameter_text(path)
    >>> print(measured.parameters.w, measured.std["w"])
    1.02 0.001
    """

    parameters: object
    std: MappingProxyType
    notes: tuple
    source: str
    extra: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))
    extra_std: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))
    covariance: object = None
    data: object = None

    def __repr__(self):
        return f"MeasuredParameters({self.source!r}, {len(self.notes)} notes)"


def _body(values, part):
    m, x, z, xx, yy, zz, xz = (values[n] for n in body_names(part))
    return MassProperties(m, [x, 0.0, z], [[xx, 0.0, xz], [0.0, yy, 0.0], [xz, 0.0, zz]])


def combined_front_frame(values):
    """The seven ``H`` values (dict) of handlebar ``G`` + fork ``S`` in ``values`` (parallel-axis theorem)."""
    H = combine([_body(values, "G"), _body(values, "S")])
    return dict(zip(body_names("H"), (H.mass, H.com[0], H.com[2], H.inertia[0, 0], H.inertia[1, 1],
                                      H.inertia[2, 2], H.inertia[0, 2])))


def _linear_spread(f, values, spreads, inputs):
    """Linear propagation of ``spreads`` of ``inputs`` through ``f`` (dict -> dict):
    ``(root-sum-square, sum of absolute contributions)`` per output."""
    rss, total = {}, {}
    for name in inputs:
        h = 1e-7 * max(abs(values[name]), 1e-3)
        up, down = f({**values, name: values[name] + h}), f({**values, name: values[name] - h})
        for out in up:
            d = (up[out] - down[out]) / (2 * h) * spreads[name]
            rss[out] = rss.get(out, 0.0) + d * d
            total[out] = total.get(out, 0.0) + abs(d)
    return {k: float(np.sqrt(v)) for k, v in rss.items()}, total


def _front_frame(pt, values, std, notes):
    """Combine or check the split front frame in place; returns nothing."""
    split = [n for part in SPLIT_BODIES for n in body_names(part)]
    present = [n for n in split if n in pt.nominal]
    if not present:
        return
    missing = [n for n in split if n not in pt.nominal]
    if missing:
        raise InputError(pt.source, missing[0], "every handlebar G and fork S name when either is given "
                                                f"({', '.join(split)})")
    inputs = {n: pt.nominal[n] for n in split}
    combined = combined_front_frame(inputs)
    spread, rounding = _linear_spread(combined_front_frame, inputs, pt.std, split)
    _, digits = _linear_spread(combined_front_frame, inputs, pt.resolution, split)
    given = [n for n in body_names("H") if n in pt.nominal]
    if len(given) < 7:
        for n in body_names("H"):
            values[n], std[n] = combined[n], spread[n]
        notes.append("front frame H = handlebar G + fork S (parallel-axis theorem)"
                     + (f"; the file's {', '.join(given)} not used: H is incomplete" if given else ""))
        return
    off = []
    for n in given:
        tol = CHECK_SIGMAS * np.hypot(pt.std[n], spread[n]) + pt.resolution[n] + digits[n]
        if abs(pt.nominal[n] - combined[n]) > tol:
            off.append(f"{n} {pt.nominal[n]:.6g} vs {combined[n]:.6g}")
    if off:
        message = (f"{pt.source}: the front frame H given differs from handlebar G + fork S combined "
                   f"({'; '.join(off)}); the given H is used, as BicycleParameters does")
        warnings.warn(message, ParameterFileWarning, stacklevel=3)
        notes.append("front frame H given, checked against handlebar G + fork S: differs (" + "; ".join(off) + ")")
    else:
        notes.append("front frame H given, checked against handlebar G + fork S: agrees "
                     f"(within {CHECK_SIGMAS:g} std and the printed digits)")


def _checked_extra(pt, name, expected, what, notes):
    tol = CHECK_SIGMAS * np.hypot(pt.std[name], pt.std.get(what, 0.0)) + pt.resolution[name]
    if abs(pt.nominal[name] - expected) > tol:
        message = (f"{pt.source}: {name} = {pt.nominal[name]:.6g} but the model needs {expected:.6g} "
                   f"({'= ' + what if what else 'lateral symmetry'}); not used")
        warnings.warn(message, ParameterFileWarning, stacklevel=4)
        notes.append(f"{name} differs from {expected:.6g}: not used")
    else:
        notes.append(f"{name} checked: equals {what or '0'} as the model assumes")


def measured_parameters(pt, key=""):
    """:class:`MeasuredParameters` of a :class:`ParameterText` (see the module docstring); errors
    name the keys below ``key`` (a YAML file's ``values``, say).  A file of the rider's body alone
    (BicycleParameters' ``riders/<Name>/Parameters/``: only ``mB xB yB zB IB..``) is refused as such."""
    if set(pt.nominal) <= set(body_names("B")) | {"yB"}:
        raise InputError(pt.source, "(file)", "a bicycle's parameters (w, c, lam, rR, ...); this holds a rider's "
                                              "body B alone (a BicycleParameters rider file), which is no bicycle")
    values = {n: pt.nominal[n] for n in NAMES if n in pt.nominal}
    std = {n: pt.std[n] for n in NAMES if n in pt.nominal}
    notes = []
    _front_frame(pt, values, std, notes)
    for name, partner in AXISYMMETRIC.items():
        if name in pt.nominal and partner in pt.nominal:
            _checked_extra(pt, name, pt.nominal[partner], partner, notes)
    for name in LATERAL:
        if name in pt.nominal:
            _checked_extra(pt, name, 0.0, "", notes)
    known = set(NAMES) | set(AXISYMMETRIC) | set(LATERAL) | {n for p in SPLIT_BODIES for n in body_names(p)}
    unknown = [n for n in pt.nominal if n not in known]
    if unknown:
        message = f"{pt.source}: not used by the Whipple model: {', '.join(unknown)}"
        warnings.warn(message, ParameterFileWarning, stacklevel=3)
        notes.append(f"not used (no place in the Whipple model): {', '.join(unknown)}")
    params = from_node(Node(values, pt.source, key))
    check_parameter_file(params, pt.source, f"{key}." if key else "")
    return MeasuredParameters(params, MappingProxyType({n: std[n] for n in NAMES}), tuple(notes), pt.source)


def load_parameter_text(path: "str | os.PathLike") -> MeasuredParameters:
    """A measured bicycle from a BicycleParameters parameter file (``<Name>Benchmark.txt``).

    Lines ``name = value`` or ``name = value+/-std`` (comma-separated values are averaged); the
    26 benchmark names are read in SI, and every further key a BicycleParameters file may hold is
    either used (noted in ``notes``) or warned about.

    Parameters
    ----------
    path : str or os.PathLike
        The parameter text file.

    Returns
    -------
    MeasuredParameters
        ``.parameters`` (the nominal :class:`~bikemass.BenchmarkParameters`), ``.std`` (SI; 0
        where the file gives none), ``.notes``.

    Raises
    ------
    InputError
        A file that cannot be read, a line that is not ``name = value``, a name given twice, or
        a parameter missing.

    Warns
    -----
    ParameterFileWarning
        Something in the file that does not add up (an unused key, an inconsistent value).

    See Also
    --------
    load_bicycle : Also reads these files (``bm.load_bicycle("BenchmarkBenchmark.txt")``).

    Examples
    --------
    >>> import os, tempfile
    >>> import bikemass as bm
    >>> path = os.path.join(tempfile.mkdtemp(), "BenchmarkBenchmark.txt")
    >>> lines = [f"{k} = {v}" for k, v in bm.parameters("benchmark").to_dict().items()]
    >>> _ = open(path, "w").write(chr(10).join(lines))
    >>> bm.load_parameter_text(path).parameters == bm.parameters("benchmark")
    True
    """
    if not isinstance(path, (str, os.PathLike)):
        raise wrong_type("path", path, "a BicycleParameters file path")
    return measured_parameters(read_parameter_text(path))
