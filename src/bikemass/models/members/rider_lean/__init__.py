"""The leaning rider: the upper body turns about a hip joint against a spring and damper (Moore 2012).

Its parameters are the rider split at the hips (:class:`.parameters.RiderLeanParameters`); a
parameter set of that type (BicycleParameters' ``MooreRiderLean2012``) selects this member.
"""

from ..spec import Member, Source

MEMBER = Member(
    name="rider-lean", package=__name__, source=Source.RIDER_SPLIT, attribute="lean",
    summary="the rider's upper body leans at the hips against a spring and damper",
    needs="--rider, or a MooreRiderLean2012 parameter file as BIKE")
"""The member's declaration (:class:`~bikemass.models.members.spec.Member`)."""
