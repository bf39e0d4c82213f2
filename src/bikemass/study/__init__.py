"""The study: ``bikemass study`` reproduces Williams (2015) end to end, then corrects it.

:func:`~bikemass.study.pipeline.compute` runs the 73 configurations three ways
(:mod:`~bikemass.study.runs`), computes the frame models (:mod:`~bikemass.study.frames`)
and compares everything with the thesis's tables (:mod:`~bikemass.study.stability_tables`,
:mod:`~bikemass.study.body_tables`, :mod:`~bikemass.study.frame_tables`), explaining each
miss (:mod:`~bikemass.study.explain`); :func:`~bikemass.study.pipeline.write_files`,
:func:`~bikemass.study.pipeline.draw` and :func:`~bikemass.study.pipeline.write_html` write
the reports, JSON, CSV and figures.
"""

from .pipeline import StudyResults, compute, draw, write_files, write_html

__all__ = ["StudyResults", "compute", "draw", "write_files", "write_html"]
