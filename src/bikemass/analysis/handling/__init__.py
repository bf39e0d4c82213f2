"""Handling: inputs and outputs of any linear bicycle model, and a rider in the loop.

* :mod:`.plant`: a system (a :class:`~bikemass.models.linear.LinearModel`, or a benchmark
  parameter set for the Whipple bicycle) at one speed, its inputs and outputs by name;
* :mod:`.transfer`: transfer functions as zeros, poles and gain (``bm.transfer_function``);
* :mod:`.frequency`: frequency responses in dB and degrees (``bm.frequency_response``);
* :mod:`.time_response` and :mod:`.discrete`: responses to initial conditions, steps and
  impulses, exact by the matrix exponential (``bm.simulate``);
* :mod:`.mode_shapes`: each mode's eigenvector as amplitudes and phases (``bm.mode_shapes``);
* the Hess, Moore & Hubbard (2012) rider: :mod:`.rider` (the loops), :mod:`.gains`,
  :mod:`.tuning` (the published gain procedure), :mod:`.quality` (the handling quality metric),
  :mod:`.lane_change` (``bm.lane_change``) and :mod:`.survey` (``bm.handling``: all of it
  against speed).

Figures: :mod:`bikemass.analysis.handling.figures`.  Sources, checks and tolerances: docs/handling.md.
"""
