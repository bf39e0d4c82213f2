"""
Design by optimisation: hit a weave speed, widen the self-stable range
======================================================================

``bm.optimise`` searches a box of design inputs for the design that maximises, minimises or hits a
metric of the bicycle's dynamics, under constraints on others; its gradients are exact in the
model's parameters (eigenvalue derivatives), chained through the geometry where the inputs are a
chart's. The spec is what ``bikemass optimise SPEC.yaml`` reads (docs/optimise.md).
"""

import math

import bikemass as bm
from bikemass.design.figures import objective_slices
from bikemass.design.spec import Bounds, DesignVariable, OptimiseSpec

# %%
# The trail that puts the benchmark bicycle's weave speed at 5 m/s
# ----------------------------------------------------------------
spec = OptimiseSpec(source="gallery", bike="benchmark", variables=(DesignVariable("c", 0.02, 0.2),),
                    sense="target", objective="weave-speed", target=5.0)
result = bm.optimise(spec)
print(f"trail {result.variables['c'] * 1000:.2f} mm: weave speed {result.objective:.6f} m/s "
      f"({result.evaluations} designs built)")

# %%
# The widest self-stable range over trail and steer axis tilt
# -----------------------------------------------------------
# Trail kept between 50 and 90 mm and the wheel flop below 25 mm.
spec = OptimiseSpec(source="gallery", bike="benchmark",
                    variables=(DesignVariable("c", 0.03, 0.12), DesignVariable("lam", math.radians(10),
                                                                              math.radians(25))),
                    sense="maximise", objective="stable-range",
                    constraints=(Bounds("trail", 0.05, 0.09), Bounds("wheel-flop", None, 0.025)))
result = bm.optimise(spec)
print(f"trail {result.variables['c'] * 1000:.1f} mm, steer axis tilt "
      f"{math.degrees(result.variables['lam']):.2f} deg: stable over {result.objective:.3f} m/s")
for note in result.notes:
    print("note:", note)

# %%
# How the search went, and the objective along each variable's range through the design.
figure = bm.plot_optimisation(result, objective_slices(spec, result), title="Benchmark: the widest self-stable range")
