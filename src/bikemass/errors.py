"""The one exception type for bad user input.

Every loader raises :class:`InputError`; the command line prints its message as
one line and exits with status 2.
"""


from pathlib import Path


def _shown(source):
    """A shipped file as ``frames/jamis.yaml`` rather than its absolute path."""
    from .paths import data_root
    try:
        return str(Path(source).resolve().relative_to(data_root().resolve()))
    except (ValueError, OSError):
        return str(source)


class InputError(ValueError):
    """Bad input: names the file, the key and what was expected (a ValueError)."""

    def __init__(self, source, key, expected):
        self.source, self.key, self.expected = _shown(source), str(key), str(expected)
        super().__init__(f"{self.source}: {self.key}: {self.expected}")

    def __reduce__(self):
        """Picklable (raised in worker processes of the study)."""
        return (_rebuilt, (self.source, self.key, self.expected))


def _rebuilt(source, key, expected):
    error = InputError.__new__(InputError)
    error.source, error.key, error.expected = source, key, expected
    ValueError.__init__(error, f"{source}: {key}: {expected}")
    return error


class BikemassWarning(UserWarning):
    """A result that is computed but worth a second look (e.g. a joint angle outside the
    typical human range); the command line shows each as one ``bikemass: warning:`` line."""
