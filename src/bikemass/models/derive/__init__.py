"""Derivation of the linear bicycle models with sympy.physics.mechanics (run by hand, needs sympy).

``python -m bikemass.models.derive`` derives every member combination of the model family and writes
the numeric code to :mod:`bikemass.models.generated`; nothing here runs when bikemass is used.
"""
