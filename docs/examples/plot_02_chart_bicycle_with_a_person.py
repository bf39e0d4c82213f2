"""
A bicycle from its geometry chart, with a person on it
======================================================

A manufacturer's geometry chart (stack, reach, angles, ...) is enough to build a bicycle:
``frames/bmc_roadmachine.yaml`` holds the BMC Roadmachine's chart for six sizes. Here size 56
gets a rider made from a height, a mass and a sex (segment proportions of Drillis & Contini,
masses of de Leva), posed by joint angles on the bicycle's saddle, grips and pedals.
"""

import bikemass as bm

# %%
# The chart and what it gives
# ---------------------------
# ``geometry_chart`` lists what the chart derives: the maker prints stack 590 mm and reach
# 388 mm for this size; trail and wheelbase follow from the angles and the fork offset.
bike = bm.load_bicycle("bmc-roadmachine@56")
chart = bm.geometry_chart(bike)
for key in ("stack", "reach", "head_tube_angle", "trail", "wheelbase"):
    unit = "deg" if key.endswith("angle") else "m"
    print(f"{key:16s} {chart[key]:.4f} {unit}")
chart_figure = bm.plot_chart(bike)

# %%
# A person, posed on the contacts
# -------------------------------
# Hands on the hoods, the torso leaning 50 degrees; the remaining joint angles are solved so
# that the hips sit on the saddle, the hands on the hoods and the feet on the pedals.
person = {"height": "1.78 m", "mass": "72 kg", "sex": "female"}
posed = bm.pose_rider(bike, body=person, hands="hoods", fixed={"torso_lean": 50}, name="1.78 m, 72 kg")
print(posed)
pose_figure = bm.plot_pose(bike, posed.rider, posed.solution)

# %%
# Her weave and capsize speeds on this bicycle
# --------------------------------------------
# The frame is aluminium (the chart bicycle's material); the beam model gives its stiffness.
params = bm.parameters(bike, posed.rider)
result = bm.stability(params, stiffness=bm.stiffness(bike, "aluminum"))
result
