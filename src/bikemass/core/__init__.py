"""Plumbing: units, conventions, errors, YAML gate, output, paths, choices, progress, results."""
