"""Plumbing every other package stands on: units, the benchmark frame's convention, the one error
type, the YAML reader and input gate, output and atomic writes, shipped-data paths, the named
choices, progress, immutable values, BLAS threads and stop signals.  Imports nothing of bikemass
outside this package."""
