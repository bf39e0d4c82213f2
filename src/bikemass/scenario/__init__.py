"""Scenarios: names, files and mappings -> loaded bicycles, seated riders, parameter sets and frame
stiffness (what ``bm.load_bicycle``, ``bm.parameters``, ``bm.stiffness``, ``bm.frame_stiffness`` and
``bm.pose_rider`` do), and the builder that rebuilds them with changed inputs (sensitivities,
uncertainty, sweeps)."""
