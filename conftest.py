"""Session set-up shared by every collected file (tests/, and the notebooks nbval re-executes)."""

from __future__ import annotations

import os
import shutil
import tempfile

from thesis_lib.lab.results import DEFAULT_RUN_ENV

_SCRATCH: str | None = None


def pytest_configure(config):
    """Send the notebooks' default-run writes to a scratch folder.

    nbval re-executes experiment notebooks while others (the report, the chapters) read the
    committed results in ``experiments/results``; a re-run clearing ``results.json`` there would race
    with those readers and leave the checkout modified.
    """
    global _SCRATCH
    if DEFAULT_RUN_ENV not in os.environ:
        _SCRATCH = tempfile.mkdtemp(prefix="thesis-lab-default-run-")
        os.environ[DEFAULT_RUN_ENV] = _SCRATCH


def pytest_unconfigure(config):
    if _SCRATCH is not None:
        shutil.rmtree(_SCRATCH, ignore_errors=True)
        os.environ.pop(DEFAULT_RUN_ENV, None)
