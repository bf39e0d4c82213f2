"""The members of the model family, one package each (:mod:`bikemass.models.members.spec` says what a
package holds).

To add a member: write its package and register it here, in :data:`PACKAGES`.
"""

import importlib

PACKAGES = (
    "rider_lean",
    "tyre",
    "flexible",
    "arms",
)
"""The registration: every member's package, one per line, in the canonical order of a combination's
name (``rider-lean+tyre``)."""

MEMBERS = tuple(importlib.import_module(f"{__name__}.{package}").MEMBER for package in PACKAGES)
"""Every member's :class:`~bikemass.models.members.spec.Member`, in the canonical order."""
