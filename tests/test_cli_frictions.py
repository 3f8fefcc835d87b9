"""What a new user of ``thesis-lab`` met: data verify of a name that matches nothing, a sweep table too
wide for the terminal, help without the experiments, an unknown option answered with the top-level
help, no "did you mean", ranges checked only inside a kernel, floats printed with every digit, RST
markup in the help."""

from __future__ import annotations

from pathlib import Path

import pytest
from lab_helpers import (
    root,  # noqa: F401 (the project fixture)
    )

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab import runner as lab_runner
from thesis_lib.lab import sweep as lab_sweep
from thesis_lib.lab.experiments import (
    did_you_mean,
)

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def no_kernels(monkeypatch):
    """Any attempt to execute a notebook fails the test (a check must come before any kernel starts)."""
    started = []

    def refuse(*args, **kwargs):
        started.append(args)
        raise AssertionError("a kernel was asked to start")

    monkeypatch.setattr(lab_runner, "cancellable", refuse)
    monkeypatch.setattr(lab_runner, "execute", refuse)
    monkeypatch.setattr(lab_sweep, "execute", refuse)
    return started


# 5. a misspelled experiment or parameter gets a "did you mean"


def test_a_misspelled_experiment_or_parameter_gets_did_you_mean(root, capsys, no_kernels):
    assert lab_cli.main(["run", "tyo"]) == 2
    assert capsys.readouterr().err == "error: unknown experiment 'tyo'; known experiments: toy; did you mean 'toy'?\n"
    assert lab_cli.main(["sweep", "toy", "-p", "sizez", "1"]) == 2
    assert capsys.readouterr().err.endswith("has no parameter 'sizez'; its parameters are: n, x, label, flag, sizes, "
                                            "fail, sleep, data_name, output_mb, work; did you mean 'sizes'?\n")
    assert lab_cli.main(["run", "nope"]) == 2  # nothing close: no suggestion
    assert capsys.readouterr().err == "error: unknown experiment 'nope'; known experiments: toy\n"
    assert did_you_mean("two-circle", ["two-circles", "two-circles-landmarks", "proteins"]) == \
        "; did you mean 'two-circles' or 'two-circles-landmarks'?"
    assert no_kernels == []
