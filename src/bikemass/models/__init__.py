"""Linear bicycle models: the :class:`~bikemass.models.linear.LinearModel` seam and its members."""
