"""The nonlinear Whipple bicycle in motion: time responses (:mod:`.simulate`, ``bm.simulate(...,
nonlinear=True)``) and steady turns (:mod:`.turn`, ``bm.steady_turn``), on the equations of
:mod:`bikemass.models.nonlinear` (docs/nonlinear.md)."""
