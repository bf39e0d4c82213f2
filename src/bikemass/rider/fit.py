"""Does the rider fit the bicycle?  The checks a bicycle fitter makes, as warning lines.

A rider seated on a bicycle (:func:`bikemass.rider.seating.seat_rider`) may reach every
contact and still be on the wrong size of frame.  Five checks, each a warning naming the
rider, the bicycle and the number (docs/riders.md, "Fit"):

* **seat post showing**: the saddle's height above the seat tube's top, less the saddle, is
  the seat post out of the frame.  A post is 300-400 mm long and must stay in the frame by
  at least 2.5 times its diameter (about 70 mm for a 27.2 mm post; the shop rule behind the
  minimum-insertion mark that ISO 4210-2 asks of every post): more than
  :data:`MAX_EXPOSED_POST` showing is more than a post holds, the frame too small;
* **saddle against the seat tube**: with the post fully in, the saddle is still above the
  rider's saddle height (LeMond: 0.883 x inseam) by more than :data:`SADDLE_TOO_HIGH`: the
  frame is too big (further, the pedals are out of reach: an error of the seating);
* **reach of the arms**: hands on a grip with the elbows locked straight (flexion below
  :data:`MIN_ELBOW_FLEXION`) means the bars are too far (a fitter wants them slightly bent;
  bars out of reach altogether are an error of the seating).  Bent elbows are not judged:
  a tuck or aerobars bend them by design;
* **toe overlap**: with the crank forward and level, the toe (the ball of the foot over the
  pedal spindle, the foot :data:`FOOT_PER_INSEAM` x inseam long, the toe
  :data:`TOE_AHEAD_OF_BALL` of it ahead of the ball, plus :data:`SHOE` of shoe) reaches into
  the front wheel's circle when the wheel is turned by more than :data:`TOE_OVERLAP` (a few
  millimetres are common on small road frames and meet only the give of a shoe's toe box).
* **standover**: the top of the top tube at its midpoint (the chart's ``standover``, as built:
  :func:`~bikemass.bicycle.derived_chart.derived_chart`) above the rider's crotch standing flat
  on the ground astride the frame: the inseam (floor to crotch: the chain body's legs less its
  seat depth; for a body from height, mass and sex the stature fractions' hip height, about
  0.47 of the stature, less the thigh's radius) plus :data:`SOLE` of shoe. Fitters ask 2-5 cm
  of clearance; bikemass warns where there is none (:data:`MIN_STANDOVER_CLEARANCE`): the
  rider cannot stand astride the frame.

Where a check needs what the bicycle or pose does not say (a saddle fixed without a seat
tube top, a pose used as written), it is left out.
"""

import numpy as np
from ..bicycle.contacts import SADDLE_RULES
from ..bicycle.derived_chart import derived_chart

MAX_EXPOSED_POST = 0.30
"""m of seat post above the seat tube: a 350 mm post less 2.5 x 27.2 mm in the frame leaves
280 mm, a 400 mm post 330 mm."""
SADDLE_TOO_HIGH = 0.02
"""m the lowest saddle may sit above the rider's LeMond height before the frame is too big."""
MIN_ELBOW_FLEXION = 5.0
"""deg: elbows straighter than this are locked (the reach too long)."""
FOOT_PER_INSEAM = 0.152 / 0.48
"""Foot length per inseam: foot 0.152 of stature (Drillis and Contini 1966), inseam (crotch
height) 0.48 of it (ANSUR II, men's means 843/1756 mm)."""
TOE_AHEAD_OF_BALL = 0.27
"""Fraction of the foot's length from the ball (first metatarsal head, about 73 % of the foot
from the heel) to the tip of the toes."""
SHOE = 0.01
"""m of shoe beyond the toes."""
TOE_OVERLAP = 0.02
"""m of toe overlap warned about beyond."""
SOLE = 0.01
"""m of shoe sole under the foot of a rider standing astride the frame."""
MIN_STANDOVER_CLEARANCE = 0.0
"""m between crotch and top tube below which the standover is warned about: none at all (the top
tube above the crotch of a rider standing flat-footed astride it)."""


def fit_warnings(bicycle, chain, solution, rider_name, hands=None):
    """The fit warnings (lines) of a rider with joints ``chain`` (:class:`~bikemass.rider.chain.ChainBody`)
    seated on ``bicycle``; ``solution`` is the solved chain (:class:`~bikemass.rider.solve.Solution`)
    or ``None`` for a pose used as written; ``hands`` the grip held (``"none"``: no hands)."""
    contacts = bicycle.contacts
    if contacts is None or chain is None:
        return []
    who = f"{bicycle.name} for rider {rider_name}"
    lines = []
    post, too_high = _saddle(bicycle, contacts, chain.inseam)
    if post is not None and post > MAX_EXPOSED_POST:
        lines.append(f"{who}: {post * 1000:.0f} mm of seat post showing, more than a 350-400 mm post holds above its "
                     f"minimum insertion ({MAX_EXPOSED_POST * 1000:.0f} mm): the frame is too small for this rider")
    if too_high is not None and too_high > SADDLE_TOO_HIGH:
        lines.append(f"{who}: the saddle, with its post fully in, is {too_high * 1000:.0f} mm above the rider's "
                     "saddle height (LeMond, 0.883 x inseam): the frame is too big for this rider")
    if solution is not None and hands in contacts.grips:
        elbow = solution.pose.angles.get("elbow")
        if elbow is not None and elbow < MIN_ELBOW_FLEXION:
            lines.append(f"{who}: elbows locked straight (bent {elbow:.0f} deg) to reach the {hands}: the bars are "
                         "too far away for this rider")
    clearance = standover_clearance(bicycle, chain.inseam)
    if clearance is not None and clearance < MIN_STANDOVER_CLEARANCE:
        lines.append(f"{who}: standover: the top tube is {standover_height(bicycle) * 1000:.0f} mm above the "
                     f"ground, {-clearance * 1000:.0f} mm above the crotch of the rider standing astride it "
                     f"(inseam {chain.inseam * 1000:.0f} mm + {SOLE * 1000:.0f} mm of shoe): the frame is too "
                     "big for this rider")
    overlap = toe_overlap(bicycle, contacts, chain.inseam)
    if overlap > TOE_OVERLAP:
        lines.append(f"{who}: toe overlap: the toe reaches {overlap * 1000:.0f} mm into the front wheel when it "
                     "is turned (crank forward)")
    return lines


def _saddle(bicycle, contacts, inseam):
    """``(seat post showing, lowest saddle above the LeMond height)`` in m, each None if unknown."""
    if contacts.saddle_fit is not None:
        rule, _, _, lowest = contacts.saddle_fit
        if lowest <= 0:
            return None, None
        wanted = SADDLE_RULES[rule] * inseam
        return max(wanted, lowest) - lowest, lowest - wanted
    points = bicycle.keypoints
    if "seat_top" in points and "seatpost_top" in points:
        return float(np.linalg.norm(np.asarray(points["seatpost_top"]) - points["seat_top"])), None
    return None, None


def toe_overlap(bicycle, contacts, inseam):
    """How far (m) the toe of a foot ``FOOT_PER_INSEAM x inseam`` long, ball over the spindle of a
    crank forward and level, reaches into the front wheel's circle (side view); 0 if clear."""
    foot = FOOT_PER_INSEAM * inseam
    spindle = contacts.pedal(0.0)
    toe = spindle + [TOE_AHEAD_OF_BALL * foot + SHOE, 0.0, 0.0]
    g = bicycle.geometry
    axle = g.front_axle
    gap = float(np.hypot(toe[0] - axle[0], toe[2] - axle[2]))
    return max(0.0, g.front_wheel_radius - gap)


def standover_height(bicycle):
    """Height (m) of the top of the top tube above the ground at its midpoint, as built (None
    for a bicycle without a ``top_tube``)."""
    return derived_chart(bicycle)["standover"]


def standover_clearance(bicycle, inseam):
    """Crotch above the top tube (m) for a rider of ``inseam`` (m, floor to crotch) standing
    flat-footed astride the frame in shoes (:data:`SOLE`); negative: the top tube is higher than
    the crotch. None without a top tube."""
    height = standover_height(bicycle)
    return None if height is None else inseam + SOLE - height
