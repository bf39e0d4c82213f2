"""
Richer models: a leaning rider, tyres that slip, a flexible frame and fork
==========================================================================

The Whipple bicycle has a rigid rider, knife-edge wheels and rigid frames. bikemass's model
family adds, one member at a time or together: the rider's upper body leaning on a spring and
damper at the hips, tyres with side-slip (relaxation length), and the compliance of the rear
frame (twist) and the fork (bending) with the tubes' inertia, from the beam models. Every
member is a :class:`~bikemass.LinearModel`, so ``bm.stability`` analyses it like the Whipple
bicycle.
"""

import bikemass as bm
from bikemass.fe.flexible import compliances
from bikemass.models.family import build
from bikemass.rider.lean_split import rider_lean_parameters

bike = bm.load_bicycle("jamis")
rider = bm.seated_rider(bike, "relaxed")
params = bm.parameters(bike, "relaxed")     # seated on this bicycle, as `rider` is
grid = bm.speeds(0.5, 15, 0.1)

# %%
# Four models of one bicycle and rider
# ------------------------------------
lean = rider_lean_parameters(bike, rider)        # the rider split at the hips
steel = compliances(bike, "steel")               # frame and fork from their beam models
models = {
    "Whipple": bm.linear_model(params),
    "leaning rider": build("rider-lean", lean),
    "tyres": build("tyre", params),
    "flexible frame and fork": build("flexible", params, compliances=steel),
}
results = {name: bm.stability(model, speeds=grid) for name, model in models.items()}
for name, r in results.items():
    extra = f", wobble {r.wobble_speeds[0]:.3f}" if r.wobble_speeds else ""
    print(f"{name:24s} {r.model.name:22s} weave {', '.join(f'{v:.3f}' for v in r.weave_speeds) or '-'}, "
          f"capsize {', '.join(f'{v:.3f}' for v in r.capsize_speeds) or '-'}{extra} m/s")

# %%
# Their critical speeds side by side
# ----------------------------------
# Two of them have no stable speed although their weave stabilises: a mode the Whipple bicycle
# does not have is unstable at every speed. The leaning rider's upper body weighs more over its
# hip axis (``m g h``) than the hip joint's 128 N m/rad holds, so a lean root grows
# (docs/models.md); the flexible frame and fork, modelled without structural damping, add the
# wobble family, which this model finds unstable at every speed (docs/models-flexible.md, "The
# wobble of the Jamis").
for name, r in results.items():
    never = [label for label, ranges in r.mode_ranges.items() if not ranges["strict"]["exact"]]
    print(f"{name:24s} unstable at every speed: {', '.join(never) or 'none'}")
fig = bm.plot_critical_speeds({name: {"Jamis + Relaxed": r} for name, r in results.items()},
                              title="One bicycle, four models")

# %%
# The flexible frame and fork add the wobble family: a steer-dominated oscillation at 6-9 Hz
# (7.35 Hz at 8 m/s) beside the fork's own 64 Hz bending.
flexible = results["flexible frame and fork"]
flexible

# %%
fig_flexible = bm.plot_eigenvalues(flexible, title="Jamis + Relaxed, flexible steel frame and fork",
                                   ylim=(-15, 60))
