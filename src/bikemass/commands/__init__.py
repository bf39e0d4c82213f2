"""One module per group of sub-commands; each has ``register(subparsers)``.

A command module imports heavy dependencies inside its ``run`` functions so that
``bikemass --help`` stays fast.
"""
