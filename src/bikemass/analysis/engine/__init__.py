"""The one stability engine for every linear model: eigenvalues over speed, modes followed and
named, exact critical speeds (crossings of ``Re = 0``) and stable speed ranges.

:func:`~bikemass.analysis.engine.stability.analyse` takes a
:class:`~bikemass.models.linear.LinearModel` of any size; a two-coordinate model takes the
closed-form fast path (:mod:`~bikemass.analysis.engine.closed_form`,
:mod:`~bikemass.analysis.engine.quartic`), which the tests hold equal to the general one.
"""
