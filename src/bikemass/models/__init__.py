"""Linear bicycle models: the benchmark parameter set, its canonical matrices (rigid and with the
quasi-static flexible rear frame), the :class:`~bikemass.models.linear.LinearModel` seam and its
members, plausibility checks of parameter sets and stiffness, parameter sets as text."""
