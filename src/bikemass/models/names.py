"""The 26 benchmark parameter names and their sign classes, apart from the parameter set itself:
:mod:`~bikemass.models.plausibility` checks them and :class:`~bikemass.models.parameters.BenchmarkParameters`
calls those checks (``replace``), so neither imports the other for them."""

NAMES = ("w", "c", "lam", "g", "rR", "mR", "IRxx", "IRyy", "xB", "zB", "mB", "IBxx", "IByy", "IBzz", "IBxz",
         "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "rF", "mF", "IFxx", "IFyy")
"""The 26 parameter names in the Meijaard order (the fields of ``BenchmarkParameters``)."""
SIGNED = ("lam", "xB", "zB", "xH", "zH", "IBxz", "IHxz", "c")
"""Parameters that may be zero or negative (``lam``'s range is checked apart)."""
POSITIVE = ("w", "g", "mB", "mH")
"""Parameters that must be positive: the model divides by the wheelbase and by the masses of the
whole bicycle and of the front assembly."""
NONNEGATIVE = tuple(k for k in NAMES if k not in SIGNED + POSITIVE)
"""Wheel radii, wheel masses and moments of inertia: zero is a legitimate limit (the two-mass-skate
bicycle of Kooijman et al. 2011 has point wheels without mass and point masses without inertia)."""
