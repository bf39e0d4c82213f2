"""
A tour: bicycle, rider, parameters, stability
=============================================

The whole chain in six calls: a bicycle and a rider from shipped YAML, their mass properties
combined into the 26 benchmark parameters of Meijaard et al. (2007), the rear frame's stiffness
from beam finite elements, and the eigenvalues over speed with the exact critical speeds.
Everything is SI in the benchmark frame (x forward, y right, z down, origin at the rear contact).
"""

import bikemass as bm

# %%
# A bicycle and a rider
# ---------------------
# Names are shipped files (``frames/jamis.yaml``, ``bodies/poses/relaxed.yaml``); a path to your
# own YAML file or a Python mapping with the same keys works the same way.
bike = bm.load_bicycle("jamis")
rider = bm.load_rider("relaxed")
print(bike)
print(rider)

# %%
# The side view shows every part in its body's colour, each body's centre of mass and its
# ellipse of gyration. ``seated_rider`` puts the rider on this bicycle's saddle, grips and pedals.
side = bm.plot_side_view(bike, bm.seated_rider(bike, rider))

# %%
# The benchmark parameters
# ------------------------
# The rider joins the rear frame by the parallel-axis theorem (the thesis added the central
# inertias, ``combine="thesis"``). In a notebook the result shows as a table with units.
params = bm.parameters(bike, rider)
params

# %%
# Stability with a steel rear frame
# ---------------------------------
# ``stiffness`` is the 2x2 rear-frame stiffness S (N m/rad, roll and steer) of the beam model;
# ``stability`` follows the modes over 0..30 m/s and finds the critical speeds exactly.
S = bm.stiffness(bike, "steel")
result = bm.stability(params, stiffness=S)
print(f"weave {result.weave_speeds[0]:.4f} m/s, capsize {result.capsize_speeds[0]:.4f} m/s")
result

# %%
# The eigenvalues against speed in the field's convention: real parts solid, imaginary parts
# dashed, the stable speeds shaded. The Figure is a matplotlib Figure: change it or save it
# with ``bm.save_figure(fig, "eig.pdf")``.
fig = bm.plot_eigenvalues(result, title="Jamis + Relaxed, steel frame")
