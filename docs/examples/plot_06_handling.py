"""
Handling: transfer functions, Bode plots, responses and a rider in the loop
===========================================================================

The linear model at one speed is a state-space system with steer torque and roll torque as
inputs. Its transfer functions, frequency responses and time responses are what a handling
study looks at; a rider model in the loop (Hess, Moore & Hubbard 2012) gives the handling
quality metric (HQM) and carries the bicycle through a lane change.
"""

import bikemass as bm

benchmark = bm.parameters("benchmark")

# %%
# Steer torque to roll angle
# --------------------------
# Zeros, poles (1/s) and gain at 5 m/s, inside the benchmark's stable range (4.29..6.02 m/s):
# every pole has a negative real part.
tf = bm.transfer_function(benchmark, 5.0, "steer-torque", "roll-angle")
print(tf)
print("poles:", ", ".join(f"{p.real:.4f}{p.imag:+.4f}j" for p in tf.poles))

# %%
# Bode plot at three speeds: below, inside and above the stable range.
responses = [bm.frequency_response(benchmark, v, "steer-torque", "roll-angle") for v in (3.0, 5.0, 8.0)]
bode = bm.plot_bode(responses, title="Benchmark: steer torque to roll angle")

# %%
# A push on the roll rate
# -----------------------
# Meijaard et al. (2007), Fig. 4: 0.5 rad/s of roll rate at 4.6 m/s, a stable weave.
response = bm.simulate(benchmark, 4.6, initial={"roll-rate": 0.5}, duration=5.0)
time_figure = bm.plot_time_response(response)

# %%
# A rider in the loop
# -------------------
# The five gains tuned at each speed, the closed loop's stability and the HQM peak.
survey = bm.handling(benchmark, [2.0, 4.0, 6.0, 8.0])
survey

# %%
hqm = bm.plot_handling(survey, title="Benchmark", stable_speeds=bm.stability(benchmark).stable_speeds)

# %%
# The same rider through a double lane change at two speeds.
runs = [bm.lane_change(benchmark, v) for v in (4.0, 7.0)]
lane = bm.plot_lane_change(runs, title="Benchmark: double lane change")
