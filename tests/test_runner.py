"""The experiment runner: names, parameter validation (lists too), runs, store, the command line."""

from __future__ import annotations

import fcntl
import json
import os
import pty
import re
import select
import shutil
import struct
import subprocess
import sys
import termios

import nbformat
import pytest
from lab_helpers import (
    TOY_RESULTS,
    cli,
    cli_env,
    commit_fake_results,
    popen_args,
    root,  # noqa: F401 (the project fixture)
    set_default,
    tree_bytes,
)

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab import execute, runner
from thesis_lib.lab.experiments import ParameterError
from thesis_lib.lab.results import DEFAULT_RUN_ENV
from thesis_lib.lab.sweep import sweep

TOY_DEFAULTS = {"n": 3, "x": 0.5, "label": "a", "flag": False, "sizes": [60, 100], "fail": False,
                "sleep": 0.0, "data_name": "", "output_mb": 0.0, "work": 0}


def test_parameters_are_read_from_the_tagged_cell(root):
    assert runner.experiment_parameters("toy") == {**TOY_DEFAULTS, "output_dir": ""}


def test_strings_are_converted_to_the_default_type(root):
    params = runner.resolve_parameters("toy", {"n": "7", "x": "2", "label": "b", "flag": "true", "sizes": "1,2"})
    assert params == {**TOY_DEFAULTS, "n": 7, "x": 2.0, "label": "b", "flag": True, "sizes": [1, 2]}


@pytest.mark.parametrize("text, value", [("60,100", [60, 100]), ("[60,100]", [60, 100]), (" [ 7 ] ", [7]),
                                         ("5", [5]), ([1, 2], [1, 2])])
def test_list_parameters_accept_lists_json_and_commas(root, text, value):
    assert runner.resolve_parameters("toy", {"sizes": text})["sizes"] == value


@pytest.mark.parametrize(
    "overrides, message",
    [
        ({"n": "1.5"}, "parameter 'n' expects int"),
        ({"x": "abc"}, "parameter 'x' expects float"),
        ({"x": "nan"}, "NaN and infinity are not parameter values"),
        ({"x": "-inf"}, "NaN and infinity"),
        ({"x": "1e999"}, "NaN and infinity"),
        ({"x": 10**400}, "too large for a float"),
        ({"flag": "maybe"}, "parameter 'flag' expects bool"),
        ({"n": 2.0}, "parameter 'n' expects int"),
        ({"n": True}, "parameter 'n' expects int"),
        ({"label": 3}, "parameter 'label' expects str"),
        ({"sizes": "a,b"}, "parameter 'sizes' expects a list of int"),
        ({"sizes": "[1, 2.5]"}, "parameter 'sizes' expects a list of int"),
        ({"sizes": "[]"}, "a non-empty list is needed"),
        ({"sizes": ""}, "a non-empty list is needed"),
        ({"sizes": "[1,"}, "not a JSON list"),
        ({"sizes": '{"a": 1}'}, "is not int"),
        ({"n": [1, 2]}, "parameter 'n' expects int"),
        ({"nn": 1}, "has no parameter 'nn'; its parameters are: n, x, label, flag, sizes, fail"),
        ({"output_dir": "/tmp"}, "set by the runner"),
    ],
)
def test_bad_parameters_are_refused_with_a_clear_message(root, overrides, message):
    with pytest.raises(ParameterError, match=message.replace("(", r"\(")):
        runner.resolve_parameters("toy", overrides)


def test_unknown_experiment_names_the_known_ones(root):
    with pytest.raises(ParameterError, match="unknown experiment 'nope'; known experiments: toy"):
        runner.resolve_parameters("nope")


HOSTILE_NAMES = ["../outside/evil", "/abs/toy", "toy/../toy", "experiments/toy", "toy.ipynb", "", ".", "..",
                 "to\x00y", "./toy", "TOY", " toy"]


@pytest.mark.parametrize("name", HOSTILE_NAMES)
def test_only_listed_experiment_names_are_accepted(root, name):
    """Only listed names run: `run ../x/y` never executes a notebook outside experiments/ nor writes outside runs/."""
    (root / "outside").mkdir()
    shutil.copy(root / "experiments" / "toy.ipynb", root / "outside" / "evil.ipynb")
    with pytest.raises(ParameterError, match="unknown experiment"):
        runner.run(name)
    with pytest.raises(ParameterError, match="unknown experiment"):
        sweep(name, {"n": [1]}, progress=False)
    if name.endswith(".ipynb") or not name:
        return
    with pytest.raises(ParameterError, match="unknown experiment"):
        runner.store(name)
    assert not (root / "runs").exists() and not (root / "outside" / "results.json").exists()


def test_store_refuses_notebooks_outside_the_project(root, tmp_path):
    shutil.copy(root / "experiments" / "toy.ipynb", tmp_path / "evil.ipynb")
    for target in (tmp_path / "evil.ipynb", str(root / "experiments" / ".." / ".." / "evil.ipynb")):
        with pytest.raises(ParameterError, match="is not a notebook of this project"):
            runner.store(target)
    assert lab_cli.main(["store", str(tmp_path / "evil.ipynb")]) == 2


def test_bad_parameters_never_start_a_kernel(root, monkeypatch):
    monkeypatch.setattr(execute, "execute", lambda *a, **k: pytest.fail("a kernel started"))
    monkeypatch.setattr(runner, "execute", lambda *a, **k: pytest.fail("a kernel started"))
    with pytest.raises(ParameterError):
        runner.run("toy", {"n": "x"})
    with pytest.raises(ParameterError):
        sweep("toy", {"n": ["1", "oops"]}, progress=False)


@pytest.mark.parametrize(
    "argv, message",
    [
        (["run", "toy", "-p", "n", "1.5"], "expects int"),
        (["run", "toy", "-p", "seed", "1", "-p", "seed", "2"], "given twice"),
        (["run", "toy", "-p", "n", "1", "-p", "n", "2"], "'n' given twice"),
        (["run", "toy", "-p", "x", "nan"], "NaN and infinity"),
        (["run", "../toy"], "unknown experiment"),
        (["sweep", "toy", "-p", "n", "1", "-p", "n", "2"], "given twice"),
        (["sweep", "toy", "-p", "n", "1", "--shard", "3/2"], "1 <= I <= N"),
        (["sweep", "toy", "-p", "n", "1", "--scheduler", "tcp://127.0.0.1:1"], "--scheduler needs --executor dask"),
        (["collect", "toy"], "at least one parameter"),
    ],
)
def test_cli_reports_bad_input_with_exit_code_2(root, capsys, argv, message):
    """Every parameter error, `-p seed 1 -p seed 2` among them, exits 2 with an error naming it."""
    assert lab_cli.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and message in err


@pytest.mark.parametrize("argv", [["sweep", "toy", "-p", "n", "1", "-j", "0"],
                                  ["sweep", "toy", "-p", "n", "1", "-j", "x"],
                                  ["sweep", "toy", "-p", "n", "1", "--retries", "-1"]])
def test_cli_refuses_bad_counts(root, argv, capsys):
    """`-j 0`, `-j x` and `--retries -1` are refused (exit 2)."""
    assert lab_cli.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and "expected an integer" in err


@pytest.mark.parametrize("argv", [["run", "toy", "-p", "n", "-:"], ["run"], ["bogus"], ["sweep", "toy", "--shard"]])
def test_cli_usage_errors_are_one_clear_line(root, argv, capsys):
    """A value that reads as an option (`-p n -:`) is one clear error line from main(), not an argparse exit."""
    assert lab_cli.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and "--help" in err and "usage:" not in err
    with pytest.raises(ParameterError, match="jobs must be a positive integer"):
        sweep("toy", {"n": [1]}, jobs=0, progress=False)


def test_run_writes_results_into_a_folder_named_by_the_parameters(root):
    result = runner.run("toy", {"n": "4"})
    assert result.status == "ok"
    assert result.results == {**TOY_RESULTS, "square": 16}
    params = runner.resolve_parameters("toy", {"n": 4})
    assert result.path == root / "runs" / "toy" / runner.run_hash(params)
    assert json.loads((result.path / "params.json").read_text()) == params
    assert (result.path / "toy.ipynb").is_file() and (result.path / "complete.json").is_file()
    info = json.loads((result.path / "complete.json").read_text())
    assert info["seconds"] > 0 and info["worker"]
    again = runner.run("toy", {"n": 4})
    assert again.status == "skipped" and again.results == result.results
    assert sorted(p.name for p in (root / "runs" / "toy").iterdir()) == [result.path.name]  # nothing temporary left


def test_a_failed_run_is_never_marked_complete_and_its_params_are_json(root):
    result = runner.run("toy", {"fail": "yes"})
    assert result.status == "failed" and "asked to fail" in result.error
    files = {p.name for p in result.path.iterdir()}
    assert "complete.json" not in files and {"error.txt", "failed.json", "params.json", "toy.ipynb"} <= files
    assert json.loads((result.path / "params.json").read_text())["fail"] is True
    assert runner.read_run("toy", result.params).status == "failed"


def test_a_failed_rerun_never_replaces_a_complete_run(root, monkeypatch):
    good = runner.run("toy")
    before = tree_bytes(good.path)
    monkeypatch.setattr(runner, "execute", lambda spec, **kw: execute.RunOutput("failed", error="boom"))
    bad = runner.run("toy", force=True)
    assert bad.status == "failed" and bad.path.name == f"{good.path.name}.failed"
    assert tree_bytes(good.path) == before


def test_default_parameters_given_explicitly_hash_like_defaults(root):
    assert runner.run_hash(runner.resolve_parameters("toy", {"n": "3"})) == runner.run_hash(
        runner.resolve_parameters("toy")
    )


def test_run_hash_refuses_non_json_values():
    with pytest.raises(ValueError, match="not JSON compliant"):
        runner.run_hash({"x": float("nan")})


def test_store_executes_in_place_and_replaces_results_keeping_sweeps(root, monkeypatch, tmp_path):
    monkeypatch.setenv(DEFAULT_RUN_ENV, str(tmp_path / "elsewhere"))  # storing is never redirected
    folder = commit_fake_results(root)
    path = runner.store("toy")
    nb = nbformat.read(path, as_version=4)
    assert all(c.execution_count for c in nb.cells if c.cell_type == "code")
    assert json.loads((folder / "results.json").read_text()) == TOY_RESULTS
    assert not (folder / "old.png").exists()  # a stored run holds what the notebook made, nothing stale
    assert (folder / "sweeps" / "kept.md").read_text().startswith("| n |")
    assert not [p for p in folder.parent.iterdir() if p.name.startswith(".")]
    assert not (tmp_path / "elsewhere").exists()


def test_a_failing_store_leaves_committed_results_byte_identical(root):
    """A store whose notebook fails leaves results.json and the rest of the committed folder unchanged."""
    folder = commit_fake_results(root)
    before, notebook = tree_bytes(folder), (root / "experiments" / "toy.ipynb").read_bytes()
    set_default(root, "toy", "fail", "True")
    notebook = (root / "experiments" / "toy.ipynb").read_bytes()
    assert lab_cli.main(["store", "toy"]) == 1
    assert tree_bytes(folder) == before
    assert (root / "experiments" / "toy.ipynb").read_bytes() == notebook
    assert not [p for p in folder.parent.iterdir() if p.name.startswith(".")]


def test_store_takes_book_notebooks_by_path(root):
    (root / "book").mkdir()
    shutil.copy(root / "experiments" / "toy.ipynb", root / "book" / "chapter.ipynb")
    runner.store(root / "book" / "chapter.ipynb")
    assert json.loads((root / "experiments" / "results" / "toy" / "results.json").read_text()) == TOY_RESULTS


def test_cli_run_is_quiet_when_piped_and_starts_kernels_without_the_tcp_warning(root):
    """No `[IPKernelApp] WARNING | Kernel is running over TCP without encryption`, nothing
    extra on a pipe: the result lines only."""
    proc = cli(root, "run", "toy", "-p", "n", "2")
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""
    lines = proc.stdout.splitlines()
    assert lines[0].startswith("ok: ") and "  square = 4" in lines


def test_cli_run_shows_progress_on_a_terminal(root):
    """`thesis-lab run` shows which cell runs (n of m) and the elapsed time on a terminal."""
    controller, terminal = pty.openpty()
    fcntl.ioctl(terminal, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 100, 0, 0))  # a terminal 100 wide
    proc = subprocess.Popen(popen_args(root, "run", "toy"), env=cli_env(root), stdout=subprocess.PIPE, stderr=terminal)
    os.close(terminal)
    shown = b""
    while True:
        ready, _, _ = select.select([controller], [], [], 120)
        if not ready:
            break
        try:
            chunk = os.read(controller, 4096)
        except OSError:  # the terminal closed with the process
            break
        if not chunk:
            break
        shown += chunk
    out, _ = proc.communicate(timeout=120)
    os.close(controller)
    text = shown.decode(errors="replace")
    assert proc.returncode == 0, (out, text)
    assert "Executing:" in text and "cell/s" in text
    assert re.search(r"\| 1/(\d+) \[\d\d:\d\d<", text)  # cell 1 of m, elapsed mm:ss
    assert re.search(r"\| (\d+)/\1 \[\d\d:\d\d<", text)  # all m cells done
    assert out.decode().startswith("ok: ")


def test_cli_list_shows_list_parameters_and_survives_a_closed_pipe(root):
    proc = cli(root, "list")
    assert proc.returncode == 0
    assert proc.stdout.startswith("toy: n=3, x=0.5, label='a', flag=False, sizes=[60, 100], fail=False")
    code = ("import os, sys; r, w = os.pipe(); os.close(r); os.dup2(w, 1); "
            "from thesis_lib.lab.cli import main; sys.exit(main(['--project', sys.argv[1], 'list']))")
    proc = subprocess.run([sys.executable, "-c", code, str(root)], capture_output=True, text=True, env=cli_env(root))
    assert proc.returncode == 141 and proc.stderr == ""  # `thesis-lab list | head -1`: no BrokenPipeError


def test_cli_works_from_any_folder_with_project(root, tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    proc = cli(root, "list", cwd=elsewhere)
    assert proc.returncode == 0 and proc.stdout.startswith("toy: ")
    env = {k: v for k, v in cli_env(root).items()}
    proc = subprocess.run([sys.executable, "-m", "thesis_lib.lab.cli", "list"], cwd=root / "experiments",
                          env=env, capture_output=True, text=True)
    assert proc.returncode == 0 and proc.stdout.startswith("toy: ")  # found upward from the current folder


def test_kernels_start_with_transport_encryption_so_ipykernel_does_not_warn(tmp_path):
    """The cause of `Kernel is running over TCP without encryption` is a manager that gives
    the kernel no CurveZMQ keys; LabKernelManager provisions them (the kernelspec declares support)."""
    import asyncio

    from thesis_lib.lab.execute import LabKernelManager, kernel_config

    log = tmp_path / "kernel.log"

    async def start_and_stop():
        km = LabKernelManager(kernel_name="python3", config=kernel_config(log=log))
        await km.start_kernel()
        kc = km.client()
        kc.start_channels()
        await kc.wait_for_ready(timeout=120)
        info = km.get_connection_info()
        kc.stop_channels()
        await km.shutdown_kernel(now=True)
        return info

    info = asyncio.run(start_and_stop())
    assert info["transport"] == "tcp" and info.get("curve_publickey")
    assert "without encryption" not in log.read_text()
