"""The flexible frame and fork: the rear frame twists and the fork bends (beam models of the tubes)."""

from ..spec import Member, Source

MEMBER = Member(
    name="flexible", package=__name__, source=Source.BEAM_MODELS, attribute="compliances", takes_stiffness=True,
    summary="the rear frame twists and the fork bends, stiffness and inertia from the beam models of the tubes "
            "in the --stiffness material (infinite: rigid)")
"""The member's declaration (:class:`~bikemass.models.members.spec.Member`)."""
