"""Work limits on speed grids, shared by the library and the command line (no numpy: the command
line reads them for ``--help``).  Each keeps an accidental argument from exhausting the machine;
the library's ``max_speeds=`` and the command line's ``--max-speeds`` raise the first."""

MAX_SPEEDS = 100_000
"""Most speeds in one grid (``max_speeds=`` / ``--max-speeds`` raises it)."""
MAX_SPEED = 1000.0
"""Highest speed of a grid (m/s)."""
MIN_SPEED_STEP = 1e-6
"""Finest speed step (m/s): finer steps print as duplicate speeds."""
MAX_SAMPLES = 1_000_000
"""Most time samples of one response or run (its states, a few hundred bytes a sample)."""
