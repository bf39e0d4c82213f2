"""The rider's arms: a spring and damper about the steer axis between the handlebars and the upper body."""

from ..spec import Member, Source

MEMBER = Member(
    name="arms", package=__name__, source=Source.OPTION, keyword="arms", option="--arms", attribute="arms",
    summary="the hands on the grips: a spring and damper about the steer axis between the bars and the upper body",
    option_help="arms file for the arms member: stiffness (N m/rad) and damping (N m s/rad) about the steer axis, "
                "forearms: pose or handlebars (their mass with the front frame); default 0, 0, pose, warned: no "
                "published measurement was at hand (docs/models.md, The rider's arms)")
"""The member's declaration (:class:`~bikemass.models.members.spec.Member`)."""
