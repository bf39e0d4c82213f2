"""Tyres that slip: a lateral force with a relaxation length, and the tyre's moments, per wheel."""

from ..spec import Member, Source

MEMBER = Member(
    name="tyre", package=__name__, source=Source.OPTION, keyword="tyres", option="--tyres", attribute="tyres",
    summary="tyres that slip",
    option_help="tyre file for the tyre member: front: and rear: each with cornering_coefficient and "
                "camber_coefficient (1/rad or 1/deg) and relaxation_length (m); default: measured bicycle "
                "tyres (Dressel 2013; docs/models.md)")
"""The member's declaration (:class:`~bikemass.models.members.spec.Member`)."""
