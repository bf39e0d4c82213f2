"""Linear stability of the Whipple bicycle: matrices, eigenvalues over speed, modes,
critical speeds, stable ranges, rear-frame flexibility (Meijaard et al. 2007; Williams 2015)."""

from .analysis import DEFAULT_SPEEDS, Stability, critical_speeds, speed_grid, stability
from .critical import Crossing, SpeedEigenvalues, speeds_of_kind
from .eigen import EigenSweep, eigen_sweep, state_matrices
from .flexible import static_stiffness, with_frame_stiffness
from .labels import LABELS
from .matrices import CanonicalMatrices, canonical_matrices
from .modes import Modes, follow_modes

__all__ = ["CanonicalMatrices", "canonical_matrices", "state_matrices", "EigenSweep", "eigen_sweep",
           "Modes", "follow_modes", "LABELS", "Stability", "stability", "speed_grid",
           "DEFAULT_SPEEDS", "static_stiffness", "with_frame_stiffness", "Crossing", "SpeedEigenvalues",
           "critical_speeds", "speeds_of_kind"]
