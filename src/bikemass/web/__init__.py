"""The ``bikemass serve`` web page: a Dash application over the library, with a JSON API.

Needs the ``web`` extra (Dash).  :func:`create_app` builds the application;
its Flask server (``app.server``) also answers ``/api/stability``,
``/api/params`` and ``/download/<file>``.
"""

from .page import create_app

__all__ = ["create_app"]
