"""Linear stability of the Whipple bicycle: eigenvalues over speed, modes, critical speeds, stable
ranges (Meijaard et al. 2007; Williams 2015).  The matrices are :mod:`bikemass.models.canonical` and
:mod:`bikemass.models.flexible_static`."""

from .analysis import DEFAULT_SPEEDS, Stability, critical_speeds, speed_grid, stability
from .critical import Crossing, SpeedEigenvalues, speeds_of_kind
from .eigen import EigenSweep, eigen_sweep, state_matrices
from .labels import LABELS
from .modes import Modes, follow_modes

__all__ = ["state_matrices", "EigenSweep", "eigen_sweep", "Modes", "follow_modes", "LABELS", "Stability",
           "stability", "speed_grid", "DEFAULT_SPEEDS", "Crossing", "SpeedEigenvalues", "critical_speeds",
           "speeds_of_kind"]
