"""bikemass: bicycle and rider geometry in YAML -> benchmark parameters, stiffness, stability.

All quantities are SI inside (m, kg, s, rad, N) in the Meijaard et al. (2007)
benchmark frame; see :mod:`bikemass.convention`.
"""

__version__ = "0.1.0"
