"""Serve MathJax 3 from the built book so that math renders with no network.

MathJax comes from the PyPI package ``django-static-mathjax`` (plain static files, no Django
needed); this extension points Sphinx's ``mathjax_path`` at ``_static/mathjax/tex-chtml.js`` and
copies the files that component loads (input and output jax, fonts, menu) into the build.
"""

from __future__ import annotations

import shutil
from pathlib import Path

PARTS = ["tex-chtml.js", "input", "output", "ui", "a11y", "adaptors"]


def _mathjax_source() -> Path:
    import mathjax  # django-static-mathjax

    source = Path(mathjax.__file__).parent / "static" / "mathjax" / "es5"
    if not (source / "tex-chtml.js").is_file():
        raise RuntimeError(f"MathJax files not found under {source}; reinstall django-static-mathjax")
    return source


def _config_inited(app, config) -> None:
    _mathjax_source()  # fail early, before any notebook runs
    config.mathjax_path = "mathjax/tex-chtml.js"


def _build_finished(app, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    source = _mathjax_source()
    target = Path(app.outdir) / "_static" / "mathjax"
    for part in PARTS:
        src = source / part
        if src.is_dir():
            shutil.copytree(src, target / part, dirs_exist_ok=True)
        elif src.is_file():
            target.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, target / part)


def setup(app):
    app.connect("config-inited", _config_inited)
    app.connect("build-finished", _build_finished)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
