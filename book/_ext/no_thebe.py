"""No Thebe: the book runs no code in the browser, so sphinx-thebe adds nothing to its pages.

Jupyter Book always loads the ``sphinx_thebe`` extension, which writes its configuration script
(``const THEBE_JS_URL = ...``) into every page, whether or not Thebe is on (``launch_buttons.thebe``
is false here); the script came out twice per page, and the second declaration of the constant
raised ``Uncaught SyntaxError: Identifier 'THEBE_JS_URL' has already been declared``. This extension
disconnects sphinx-thebe's handlers that add scripts and page configuration, and drops its style
sheet.
"""

from __future__ import annotations


def _drop_thebe(app) -> None:
    for listeners in app.events.listeners.values():
        listeners[:] = [entry for entry in listeners
                        if getattr(entry.handler, "__module__", "") != "sphinx_thebe"
                        or entry.handler.__name__ not in ("init_thebe_core", "update_thebe_context")]
    app.registry.css_files[:] = [(name, attrs) for name, attrs in app.registry.css_files
                                 if name != "sphinx-thebe.css"]


def _config_inited(app, config) -> None:
    _drop_thebe(app)  # again, in case sphinx_thebe was set up after this extension


def setup(app):
    _drop_thebe(app)
    app.connect("config-inited", _config_inited)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
