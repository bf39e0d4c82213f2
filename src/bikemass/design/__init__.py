"""Design by optimisation: the inputs of a bicycle and rider chosen for an objective on its dynamics.

:func:`~bikemass.design.optimise.optimise` takes an :class:`~bikemass.design.spec.OptimiseSpec` (read
from YAML by :func:`~bikemass.design.spec.read_spec`): the design variables with their bounds (any
input a sweep can vary), an objective on one metric (:mod:`bikemass.design.metrics`) and constraints
on others.  Every metric comes with its gradient: the critical speeds' derivatives with respect to the
parameters are exact (eigenvalue derivatives and the implicit function theorem,
:mod:`bikemass.analysis.sensitivity`), chained with the derivatives of the parameters with respect to
the design variables (exact for benchmark parameters, central differences for geometry).
"""
