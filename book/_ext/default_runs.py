"""Building the book never rewrites the committed default runs of the experiments.

Executing an experiment notebook writes its default run through ``thesis_lib.lab.results.Recorder``
into ``experiments/results/<name>/``, which is committed and read by other pages while the book is
built. This extension points the Recorder at ``_build/default-runs/`` (beside the HTML) before any
kernel starts, unless ``THESIS_LAB_DEFAULT_RUN_DIR`` is already set; the pages show the committed
results, and ``thesis-lab store`` / ``make experiments`` remain the only writers of them.
"""

from __future__ import annotations

import os
from pathlib import Path

ENV = "THESIS_LAB_DEFAULT_RUN_DIR"  # thesis_lib.lab.results.DEFAULT_RUN_ENV


def _config_inited(app, config) -> None:
    if ENV not in os.environ:
        scratch = Path(app.outdir).parent / "default-runs"
        scratch.mkdir(parents=True, exist_ok=True)
        os.environ[ENV] = str(scratch)


def setup(app):
    app.connect("config-inited", _config_inited)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
