"""Session set-up shared by every collected file (tests/, and the notebooks nbval re-executes).

Options
-------
``--fuzz-long``
    Run every fuzz test with 100 times its usual number of examples (thousands of hostile inputs
    per function instead of a few seconds' worth), and every hypothesis test draws at random instead
    of the fixed, derandomized examples of an ordinary run.  Fuzz tests read it through
    ``helpers.fuzz_settings(n)`` (n examples normally, 100·n with ``--fuzz-long``), or directly as
    ``request.config.getoption("--fuzz-long")``.  With ``-s`` or at the end of the run, the tally of
    fuzz outcomes (inputs tried, clear errors, values returned) is printed per module.
"""

from __future__ import annotations

import os
import shutil
import tempfile

from thesis_lib.lab.results import DEFAULT_RUN_ENV

#: the fixture notebooks of the laboratory's tests are data, not notebooks for nbval to re-run
collect_ignore_glob = ["tests/fixtures/*"]

#: read by tests/helpers.py (set in each pytest process, xdist workers included)
FUZZ_LONG_ENV = "THESIS_LAB_FUZZ_LONG"

_SCRATCH: str | None = None


def pytest_addoption(parser):
    parser.addoption(
        "--fuzz-long",
        action="store_true",
        default=False,
        help="fuzz tests run 100x their usual number of examples (see helpers.fuzz_settings)",
    )


def pytest_configure(config):
    """Send the notebooks' default-run writes to a scratch folder; pass --fuzz-long to the fuzz tests.

    nbval re-executes experiment notebooks while others (the report, the chapters) read the
    committed results in ``experiments/results``; a re-run clearing ``results.json`` there would race
    with those readers and leave the checkout modified.
    """
    global _SCRATCH
    if DEFAULT_RUN_ENV not in os.environ:
        _SCRATCH = tempfile.mkdtemp(prefix="thesis-lab-default-run-")
        os.environ[DEFAULT_RUN_ENV] = _SCRATCH
    long = config.getoption("--fuzz-long", default=False)
    if long:
        os.environ[FUZZ_LONG_ENV] = "1"
    # every hypothesis test draws the same examples on every machine and every run (a CI run cannot
    # fail on a draw nobody saw locally); --fuzz-long explores at random, and what it finds becomes
    # an explicit regression test
    from hypothesis import settings

    settings.register_profile("thesis-lab", derandomize=not long, database=None)
    settings.load_profile("thesis-lab")


def pytest_unconfigure(config):
    if _SCRATCH is not None:
        shutil.rmtree(_SCRATCH, ignore_errors=True)
        os.environ.pop(DEFAULT_RUN_ENV, None)


def pytest_terminal_summary(terminalreporter):
    """The fuzz tally of this process (without xdist: the whole run), when fuzz tests ran."""
    import sys

    helpers = sys.modules.get("helpers")
    tally = getattr(helpers, "FUZZ_TALLY", None)
    if not tally:
        return
    terminalreporter.section("fuzz tally (inputs tried / clear errors / values returned)")
    for module in sorted(tally):
        counts = tally[module]
        terminalreporter.write_line(
            f"{module}: {counts['tried']} tried, {counts['error']} clear errors, {counts['value']} values, "
            f"{counts['crash']} crashes, {counts['hang']} hangs"
        )
