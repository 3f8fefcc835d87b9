"""Sweeps on a real Dask cluster: a LocalCluster of 2 worker processes, no shared file
system assumed (runs are self-contained), a worker killed mid-run, cancellation, bad clusters."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import uuid
from pathlib import Path

import pytest
from lab_helpers import (
    cli,
    cli_env,
    complete_runs_are_whole,
    popen_args,
    root,  # noqa: F401 (the project fixture)
    table_rows,
    tagged_processes,
    wait_until,
)

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab.paths import project_root
from thesis_lib.lab.sweep import ClusterError, dask_client, sweep

pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def client():
    """A LocalCluster of 2 single-threaded worker processes, started the way `--executor dask` does."""
    with dask_client(scheduler=None, jobs=2, retries=2) as c:
        yield c


def test_two_circles_landmarks_on_the_cluster_equals_the_local_sweep(client, tmp_path):
    """The real experiment, a 2 x 3 grid: same values and statuses with Dask as with the local executor."""
    grid = {"n_landmarks": ["20", "30"], "seed": ["0", "1", "2"], "n_per_circle": ["500"]}
    assert (project_root() / "experiments" / "two-circles-landmarks.ipynb").is_file()
    runs, dask_table = sweep("two-circles-landmarks", grid, executor=client, root=tmp_path / "dask", progress=False)
    assert [r.status for r in runs] == ["ok"] * 6, [r.error for r in runs]
    assert {r.worker for r in runs} <= {"dask:0", "dask:1"}
    _, local_table = sweep("two-circles-landmarks", grid, jobs=2, root=tmp_path / "local", progress=False)
    dask_rows, local_rows = table_rows(dask_table), table_rows(local_table)
    assert dask_rows == local_rows
    assert len({row["covering_radius_maxmin"] for row in dask_rows}) > 1  # the grid really varies the runs


def _running_scratch(pids: set[int]) -> tuple[int, Path] | None:
    """(worker pid, scratch folder) of a toy run whose kernel has started recording on a worker."""
    parent = Path(tempfile.gettempdir()) / "thesis-lab-runs"
    for folder in parent.glob(".toy.tmp-*"):
        pid = int(folder.name.split(".tmp-", 1)[1].split("-", 1)[0])
        if pid in pids and (folder / "out" / "results.json").is_file():
            return pid, folder
    return None


def test_a_worker_killed_mid_run_has_its_run_retried(client, root):
    pids = set(client.run(os.getpid).values())
    import threading

    result = {}
    thread = threading.Thread(target=lambda: result.update(out=sweep(
        "toy", {"n": ["7", "8"], "sleep": ["4"]}, executor=client, progress=False)))
    thread.start()
    pid, scratch = wait_until(lambda: _running_scratch(pids), timeout=180, what="a toy run mid-way on a worker")
    os.kill(pid, signal.SIGKILL)
    thread.join(timeout=600)
    runs, table = result["out"]
    assert [r.status for r in runs] == ["ok", "ok"], [r.error for r in runs]
    assert [r.results["square"] for r in runs] == [49, 64]
    assert pid not in set(client.run(os.getpid).values())
    assert complete_runs_are_whole(root / "runs") == []


def test_client_executor_runs_self_contained_and_refuses_large_outputs(client, root):
    runs, _ = sweep("toy", {"data_name": ["toy-data"], "output_mb": ["0", "2"]}, executor=client.get_executor(),
                    progress=False, max_output_mb=1.0)
    assert [r.status for r in runs] == ["ok", "failed"]
    assert runs[0].results["data_bytes"] == 27  # the data set reached the worker as sha256-checked bytes
    assert "over the limit of 1 MB" in runs[1].error


def test_unreachable_scheduler_is_a_clear_error_and_starts_nothing(root, capsys):
    with pytest.raises(ClusterError, match="could not reach the Dask scheduler at 'tcp://127.0.0.1:9'"):
        with dask_client(scheduler="tcp://127.0.0.1:9", timeout=3):
            pytest.fail("connected to nothing")
    argv = ["sweep", "toy", "-q", "-p", "n", "1", "--executor", "dask", "--scheduler", "tcp://127.0.0.1:9"]
    assert lab_cli.main(argv) == 2
    assert "could not reach the Dask scheduler" in capsys.readouterr().err
    assert not (root / "runs" / "toy").exists() or not any((root / "runs" / "toy").iterdir())


def test_a_worker_without_the_project_is_named(tmp_path):
    """A worker whose Python cannot import thesis_lib: the sweep refuses with the package named."""
    from distributed import LocalCluster

    shadow = tmp_path / "shadow" / "thesis_lib"
    shadow.mkdir(parents=True)
    (shadow / "__init__.py").write_text("raise ImportError('thesis_lib is not installed here')\n")
    with LocalCluster(n_workers=0, processes=False, protocol="tcp", host="127.0.0.1",
                      dashboard_address=None) as cluster:
        env = {**os.environ, "PYTHONPATH": str(shadow.parent)}
        # the shadow package comes first on PYTHONPATH; an editable install's import hook (which would
        # hand out the checkout's thesis_lib whatever the path says) is taken out of the worker
        launch = ("import sys; sys.meta_path[:] = [f for f in sys.meta_path "
                  "if not type(f).__module__.startswith('_editable')]; "
                  "from distributed.cli.dask_worker import main; sys.argv[0] = 'dask-worker'; main()")
        worker = subprocess.Popen([sys.executable, "-c", launch, cluster.scheduler_address,
                                   "--nworkers", "1", "--nthreads", "1", "--no-nanny", "--no-dashboard"],
                                  env=env, cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            with pytest.raises(ClusterError, match=r"missing thesis_lib; install the project there"):
                with dask_client(scheduler=cluster.scheduler_address, timeout=60):
                    pytest.fail("a worker without thesis_lib was accepted")
        finally:
            worker.kill()
            worker.wait(timeout=60)


def test_cancelled_dask_sweep_leaves_nothing_running_and_resumes(root):
    args = ["sweep", "toy", "-q", "--executor", "dask", "-j", "2", "-p", "n", "1", "2", "-p", "sleep", "1"]
    for sig in (signal.SIGTERM, signal.SIGKILL):
        tag = uuid.uuid4().hex
        proc = subprocess.Popen(popen_args(root, *args), env=cli_env(root, tag), stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        # a run of this sweep has started: a scratch folder of one of its processes holds results
        # (other tests' toy runs, in parallel, write scratch folders of their own processes)
        wait_until(lambda proc=proc, tag=tag: proc.poll() is not None
                   or _running_scratch(set(tagged_processes(tag))) is not None,
                   timeout=180, what="a run to start")
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=180)
        if sig == signal.SIGTERM and proc.returncode != 0:
            assert proc.returncode == 143 and "cancelled" in err, err
        wait_until(lambda tag=tag: not tagged_processes(tag), timeout=90, what=f"no process of ours after {sig.name}")
        assert complete_runs_are_whole(root / "runs") == []
    proc = cli(root, *args)
    assert proc.returncode == 0, proc.stderr
    assert len(list((root / "runs" / "toy").glob("*/complete.json"))) == 2
    shutil.rmtree(root / "runs")
