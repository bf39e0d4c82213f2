"""
The nonlinear bicycle: Meijaard's push, a fall and hands-free circles
=====================================================================

The same benchmark parameters drive the nonlinear Whipple bicycle (``nonlinear=True``): the
forward speed changes, large leans and tight turns are allowed, and a bicycle that falls stops the
run with one line instead of leaning on for ever. See docs/nonlinear.md for the equations and
their checks.
"""

import warnings

import bikemass as bm

benchmark = bm.parameters("benchmark")

# %%
# Meijaard et al. (2007), Fig. 4: nonlinear beside linear
# -------------------------------------------------------
push = {"roll-rate": 0.5}
nonlinear = bm.simulate(benchmark, 4.6, initial=push, duration=5.0, nonlinear=True)
linear = bm.simulate(benchmark, 4.6, initial=push, duration=5.0)
print(f"roll rate at 1 s: {nonlinear['roll-rate'][100]:.4f} rad/s (linear {linear['roll-rate'][100]:.4f})")
print(f"forward speed {nonlinear['forward-speed'].min():.3f}..{nonlinear['forward-speed'].max():.3f} m/s, "
      f"energy drift {abs(nonlinear['energy'][-1] / nonlinear['energy'][0] - 1):.1e}")
figure = bm.plot_nonlinear_response(nonlinear, linear)

# %%
# Too slow to be stable: the bicycle falls
# ----------------------------------------
with warnings.catch_warnings(record=True):
    warnings.simplefilter("always")
    fall = bm.simulate(benchmark, 1.0, initial={"roll-rate": 0.05}, duration=30.0, nonlinear=True)
print(fall.stopped)

# %%
# Steady turns, and the circles that need no hands
# ------------------------------------------------
turn = bm.steady_turn(benchmark, 5.0, radius=10.0)
print(f"10 m at 5 m/s: lean {turn.roll:.3f} rad (linear {turn.linear_roll:.3f}), "
      f"steer torque {turn.steer_torque:.3f} N m (linear {turn.linear_steer_torque:.3f})")
family = bm.hands_free_turns(benchmark, [0.02 * k for k in range(1, 51)])
circles = bm.plot_hands_free_turns(family)
