"""
Sensitivity and uncertainty of the critical speeds
==================================================

How much does each parameter move the weave and capsize speeds, and how uncertain are they when
the inputs are? ``bm.sensitivity`` differentiates the critical speeds exactly (implicit function
theorem on the crossing eigenvalue, complex-step matrices); ``bm.uncertainty`` carries spreads of
the inputs to spreads of the outputs, linearly or by seeded Monte Carlo sampling.
"""

import bikemass as bm
from bikemass.analysis.sensitivity import sensitivity_figure
from bikemass.analysis.uncertainty import uncertainty_figure

# %%
# Elasticities of the benchmark bicycle
# -------------------------------------
# ``(p / v) dv/dp``: the percentage change of the speed per percent of the parameter.
benchmark = bm.parameters("benchmark")
sens = bm.sensitivity(benchmark)
sens

# %%
fig = sensitivity_figure(sens, title="Benchmark bicycle: elasticities of the critical speeds")

# %%
# An exact derivative agrees with a central difference of two stability analyses:
h = 1e-5
weave = lambda c: bm.stability(benchmark.replace(c=c), speeds=bm.speeds(3, 6, 0.5)).weave_speeds[0]  # noqa: E731
difference = (weave(0.08 + h) - weave(0.08 - h)) / (2 * h)
print(f"exact {sens.d_weave_speed['c']:.6f}, central difference {difference:.6f} (m/s)/m")

# %%
# Uncertainty: linear propagation and Monte Carlo
# -----------------------------------------------
# Standard deviations of the trail (m) and the rear frame's mass (kg) and CoM height (m).
spreads = {"c": 0.004, "mB": 2.0, "zB": 0.02}
linear = bm.uncertainty("benchmark", spreads)
sampled = bm.uncertainty("benchmark", spreads, method="montecarlo", samples=300, seed=0)
for key in ("weave_speed", "capsize_speed"):
    a, b = linear.speeds[key], sampled.speeds[key]
    print(f"{key}: {a['nominal']:.4f} m/s, std {a['std']:.4f} (linear) / {b['std']:.4f} (Monte Carlo)")

# %%
fig = uncertainty_figure(sampled, title="Benchmark bicycle: 95 % bands of 300 draws")
