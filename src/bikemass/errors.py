"""The one exception type for bad user input.

Every loader raises :class:`InputError`; the command line prints its message as
one line and exits with status 2.
"""


class InputError(Exception):
    """Bad input: names the file, the key and what was expected."""

    def __init__(self, source, key, expected):
        self.source, self.key, self.expected = str(source), str(key), str(expected)
        super().__init__(f"{self.source}: {self.key}: {self.expected}")
