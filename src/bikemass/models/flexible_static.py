"""Rear-frame flexibility (Williams 2015, Eq. 3.27-3.30).

A flexible rear frame is a 2x2 equivalent stiffness ``S`` (N m/rad, roll and steer
at the head tube) in series with the gravity stiffness ``g K0``::

    K_static = gK0 - gK0^T (gK0 + S)^-1 gK0

``M``, ``C1`` and ``K2`` are unchanged; ``S = None`` (infinitely stiff) is the rigid model.
"""

import numpy as np


def static_stiffness(gK0, S):
    """``gK0 - gK0^T (gK0 + S)^-1 gK0`` (N m/rad); ``S=None`` returns ``gK0``."""
    gK0 = np.asarray(gK0)
    if S is None:
        return gK0
    S = np.asarray(S)
    return gK0 - gK0.T @ np.linalg.solve(gK0 + S, gK0)


def with_frame_stiffness(matrices, S):
    """:class:`~bikemass.models.canonical.CanonicalMatrices` whose ``g K0`` is the flexible ``K_static``."""
    if S is None:
        return matrices
    return matrices.replace(K0=static_stiffness(matrices.gK0, S) / matrices.g)
