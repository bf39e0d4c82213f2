"""
The study's key figures, small
==============================

``bikemass study`` reproduces Williams (2015) end to end. Its two key figures are remade here
from the Python API for the Jamis: the stable speeds of every thesis rider on every frame
material, and the handling quality of each rider position with a rider in the loop. (The full
study also runs the Cargo bicycles, the thesis's printed inputs and every table: minutes.)
"""

import bikemass as bm

bike = bm.load_bicycle("jamis")
riders = ("no-hands", "relaxed", "on-hoods", "aerobars", "aero-tuck")
frames = {"rigid": "infinite", "steel": "steel", "titanium": "titanium", "aluminium": "aluminum"}

# %%
# Stable speeds of every rider and frame
# --------------------------------------
# One line per configuration: circle at the weave speed, square at the capsize speed, bar over
# the stable speeds. A softer frame shrinks the stable range of every rider.
params = {rider: bm.parameters(bike, rider) for rider in riders}
stiffness = {name: bm.stiffness(bike, which) for name, which in frames.items()}
results = {rider: {name: bm.stability(params[rider], stiffness=S) for name, S in stiffness.items()}
           for rider in riders}
fig = bm.plot_critical_speeds(results, title="Jamis: stable speeds of every rider and frame")

# %%
# The handling quality of each rider position
# -------------------------------------------
# The Hess-Moore-Hubbard rider model, tuned at each speed by the published procedure; the
# handling quality metric's peak below 5 is Level 1 (good), above 10 Level 3.
speeds = [3.0, 5.0, 7.0, 9.0]
for rider in ("relaxed", "aero-tuck"):
    survey = bm.handling(params[rider], speeds)
    print(rider, ", ".join(f"{v:g} m/s: {q:.2f}" for v, q in zip(speeds, survey.hqm_peak)))
survey = bm.handling(params["relaxed"], speeds)
fig_hqm = bm.plot_handling(survey, title="Jamis + Relaxed, rigid frame",
                           stable_speeds=results["relaxed"]["rigid"].stable_speeds)
