"""Bicycles described in YAML (``frames/``) -> parts by body -> benchmark parameters.

``load_bicycle(name_or_path)`` reads a shipped bicycle, a bicycle YAML file or a
benchmark parameter file; ``bicycle_parameters(bicycle, rider, combine, method)``
gives the Meijaard et al. (2007) parameter set.  Format: docs/bicycles.md.
"""

from .benchmark import COMBINE_CHOICES, bicycle_parameters, combined_bodies
from .components import BODIES
from .geometry import Geometry
from .loader import load_bicycle
from .model import Bicycle

__all__ = ["BODIES", "COMBINE_CHOICES", "Bicycle", "Geometry", "bicycle_parameters", "combined_bodies",
           "load_bicycle"]
