"""The one exception type for bad user input.

Every loader raises :class:`InputError`; the command line prints its message as
one line and exits with status 2.  The message is always one line: control
characters (a newline in a key, say) are escaped and long parts are cut, so a
hostile value can neither split the line nor flood the terminal.
"""

from pathlib import Path

from .data_folder import found_root

MAX_PART = 300
"""Longest file name, key or expectation shown in a message (characters)."""


def _plain(value):
    """``value`` with numpy arrays and numbers as Python lists and numbers (``1000000.0``, not
    ``array([1000000.])`` or ``np.float64(1000000.0)``); anything else as it is."""
    if type(value).__module__ == "numpy" and hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (list, tuple)) and any(type(v).__module__ == "numpy" for v in value):
        return type(value)(_plain(v) for v in value)
    return value


def short(value, limit=60):
    """``repr`` of ``value`` cut to about ``limit`` characters (never more than one line); numpy
    arrays and numbers written as plain Python lists and numbers."""
    text = repr(_plain(value))
    return one_line(text if len(text) <= limit else text[:limit - 5] + "...", limit)


def one_line(text, limit=MAX_PART):
    """``text`` with control characters escaped, cut to ``limit`` characters."""
    text = "".join(c if c.isprintable() else repr(c)[1:-1] for c in str(text))
    return text if len(text) <= limit else text[:limit - 3] + "..."


def shown(source):
    """A shipped file as ``frames/jamis.yaml`` rather than its absolute path."""
    root = found_root()
    try:
        return str(Path(source).resolve().relative_to(root.resolve())) if root else str(source)
    except (ValueError, OSError, RuntimeError):
        return str(source)


class InputError(ValueError):
    """Bad input: names the file, the key and what was expected (a ValueError).

    Parameters
    ----------
    source : str or os.PathLike
        The file (a shipped file shown relative to the data folder, e.g. ``frames/jamis.yaml``),
        ``<mapping>`` for a Python value, or the argument's name.
    key : str
        The key or option that is wrong (``(argument)`` for a whole argument).
    expected : str
        What was expected, in words.

    Attributes
    ----------
    source, key, expected : str
        The three parts, each on one line (control characters escaped, long parts cut).

    See Also
    --------
    BikemassWarning : Legal but unusual input.

    Examples
    --------
    >>> import bikemass as bm
    >>> try:
    ...     bm.stability(bm.parameters("benchmark"), stiffness=[[1.0, 2.0], [3.0, 4.0]])
    ... except bm.InputError as error:
    ...     print(error.source, "|", error.key, "|", error.expected[:43])
    stiffness | (matrix) | a symmetric positive definite 2x2 stiffness
    >>> isinstance(bm.InputError("f.yaml", "w", "a length"), ValueError)
    True
    """

    def __init__(self, source, key, expected):
        self.source, self.key = one_line(shown(source)), one_line(key)
        self.expected = one_line(expected, 2 * MAX_PART)
        super().__init__(f"{self.source}: {self.key}: {self.expected}")

    def __reduce__(self):
        """Picklable (raised in worker processes of the study)."""
        return (_rebuilt, (self.source, self.key, self.expected))


class InputTypeError(InputError, TypeError):
    """Bad input of the wrong Python type (``bm.load_bicycle(None)``): an :class:`InputError`
    that is also a ``TypeError``.

    Examples
    --------
    >>> import bikemass as bm
    >>> try:
    ...     bm.load_bicycle(None)
    ... except bm.InputTypeError as error:
    ...     print(error.key, "|", isinstance(error, TypeError), isinstance(error, bm.InputError))
    (argument) | True True
    """


def wrong_type(what, value, expected):
    """:class:`InputTypeError` for argument ``what`` holding ``value`` where ``expected`` was wanted."""
    return InputTypeError(what, "(argument)", f"{expected}, not {type(value).__name__}")


def _rebuilt(source, key, expected):
    error = InputError.__new__(InputError)
    error.source, error.key, error.expected = source, key, expected
    ValueError.__init__(error, f"{source}: {key}: {expected}")
    return error


class BikemassWarning(UserWarning):
    """A result that is computed but worth a second look (e.g. a joint angle outside the
    typical human range); the command line shows each as one ``bikemass: warning:`` line (``--strict`` makes it an
    error).  :mod:`bikemass.models.plausibility` issues them for legal but unusual input.

    See Also
    --------
    InputError : Input that is refused.

    Examples
    --------
    Warnings go through :mod:`warnings`, so the usual filters apply:

    >>> import warnings
    >>> import bikemass as bm
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always", bm.BikemassWarning)
    ...     posed = bm.pose_rider("jamis", hands="tops", fixed={"torso_lean": 100})
    >>> print(str(caught[0].message))
    torso lean 100.0 deg is outside the typical human range -20..90 deg
    """
