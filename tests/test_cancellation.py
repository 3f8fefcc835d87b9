"""Atomicity and cancellation: `store`, `run` and a sweep killed at random moments with
SIGINT, SIGTERM and SIGKILL.  After each kill: the committed results are byte-identical to before (or
to a whole new run, if the command had finished), no run folder is complete without its results, no
process of ours survives; then a re-run finishes the work."""

from __future__ import annotations

import json
import random
import signal
import subprocess
import uuid

import pytest
from lab_helpers import (
    TOY_RESULTS,
    cli,
    cli_env,
    commit_fake_results,
    complete_runs_are_whole,
    make_project,
    popen_args,
    set_default,
    tagged_processes,
    tree_bytes,
    wait_until,
)

COMMANDS = {
    "store": ["store", "toy"],
    "run": ["run", "toy", "-p", "n", "5"],
    "sweep": ["sweep", "toy", "-q", "-j", "2", "-p", "n", "1", "2", "3"],
}
SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGKILL)


def _stored_whole(folder) -> bool:
    """The committed folder is a whole new store: the toy's results, its sweeps kept, nothing stale."""
    files = tree_bytes(folder)
    return set(files) == {"results.json", "sweeps/kept.md"} and json.loads(files["results.json"]) == TOY_RESULTS


def _leftovers(root) -> list[str]:
    """Temporary folders or files a writer left (after a re-run has cleaned what dead writers left)."""
    places = [root / "experiments" / "results", root / "runs" / "toy"]
    return [str(p) for place in places if place.is_dir() for p in place.iterdir() if ".tmp-" in p.name]


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_killed_at_random_moments_loses_nothing_and_leaves_nothing_running(tmp_path, command):
    root = make_project(tmp_path / "project")
    set_default(root, "toy", "sleep", "1.5")
    committed = commit_fake_results(root)
    before = tree_bytes(committed)
    rng = random.Random()
    for sig in SIGNALS:
        delay = rng.uniform(0.3, 5.0)
        tag = uuid.uuid4().hex
        proc = subprocess.Popen(popen_args(root, *COMMANDS[command]), env=cli_env(root, tag),
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        try:
            proc.wait(timeout=delay)
        except subprocess.TimeoutExpired:
            proc.send_signal(sig)
        out, err = proc.communicate(timeout=120)
        moment = f"{command} killed by {sig.name} after {delay:.2f} s (exit {proc.returncode})"
        if sig != signal.SIGKILL and proc.returncode not in (0, -sig):  # -sig: killed while Python started
            assert proc.returncode == 128 + sig, f"{moment}: {err}"
            assert "cancelled" in err and "Traceback" not in err, f"{moment}: {err}"
        wait_until(lambda tag=tag: not tagged_processes(tag), timeout=60, what=f"no process of ours after {moment}")
        assert tree_bytes(committed) == before or _stored_whole(committed), moment
        assert complete_runs_are_whole(root / "runs") == [], moment
    proc = cli(root, *COMMANDS[command])
    assert proc.returncode == 0, proc.stderr
    if command == "store":
        assert _stored_whole(committed)
    else:
        expected = 1 if command == "run" else 3
        complete = list((root / "runs" / "toy").glob("*/complete.json"))
        assert len(complete) == expected and complete_runs_are_whole(root / "runs") == []
        assert tree_bytes(committed) == before
    assert _leftovers(root) == []
