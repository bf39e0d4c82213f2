"""Analyses over many bicycles or parameters: exact sensitivities of the critical speeds,
uncertainty propagation and design sweeps.  Built on the one engine, :mod:`bikemass.analysis.engine`."""
