"""The ``bikemass`` command line, a thin shell over the library: :mod:`~bikemass.cli.main` (the
entry point), the one dialect of every command (:mod:`~bikemass.cli.dialect`,
:mod:`~bikemass.cli.options`, :mod:`~bikemass.cli.figure_options`) and one module per group of
sub-commands, each with ``register(subparsers)``.

A command module imports the library inside its ``run`` functions so that ``bikemass --help``
stays fast.
"""
