"""Numbers read back from printed text, so that tests compare them with a tolerance (half a unit
in the last printed digit, or more) instead of as strings that a rounding tie could flip."""

import re

NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
"""A printed number: sign, digits, decimal point, exponent."""


def numbers(text):
    """Every number printed in ``text``, in order (floats)."""
    return [float(t) for t in NUMBER.findall(text)]


def number_after(text, prefix):
    """The number printed right after ``prefix`` in ``text`` (AssertionError if none)."""
    found = re.search(re.escape(prefix) + r"\s*(" + NUMBER.pattern + ")", text)
    assert found, f"no number after {prefix!r} in {text!r}"
    return float(found.group(1))
