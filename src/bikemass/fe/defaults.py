"""Defaults of the beam model that the command line shows in its help (no numpy here)."""

DEFAULT_ELEMENT_SIZE = 0.02
"""Default element length for modal analysis (m); see docs/fe.md for the convergence study."""

MAX_ELEMENTS = 5000
"""Most beam elements in a frame-mode model (``bm.frame_modes(max_elements=...)``; ``--max-elements``
raises it)."""
