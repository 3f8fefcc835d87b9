"""One experiment run where it executes (this process, a thread, or a Dask worker on another machine).

:func:`execute` needs no shared file system: the notebook and the input data travel in as bytes, the
run executes in a scratch folder (a small self-contained project: ``experiments/<name>.ipynb``,
``data/manifest.toml`` and the data files, checked by sha256), and the outputs travel back as bytes
(:class:`RunOutput`), bounded in size.  The client writes them into ``runs/`` (see ``runner``).

Kernels are started by :class:`LabKernelManager`: transport encryption on (so ipykernel does not
warn that it runs over TCP in plain text), the run's environment passed to the kernel alone, and
every live kernel registered so that :func:`kill_kernels` can stop them all when a run is cancelled.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import tempfile
import threading
import time
from collections.abc import Callable
from dataclasses import KW_ONLY, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ParamSpec, TypeVar

from .._optional import require
from . import atomic
from .experiments import OUTPUT_PARAMETER
from .paths import PROJECT_ENV

if TYPE_CHECKING:  # traitlets.config is imported only when a run is configured
    from traitlets.config import Config

# The kernel manager below subclasses jupyter_client's and declares traitlets: this module (the core
# of the laboratory) needs the [lab] extra to import, and says so when it is missing.
AsyncKernelManager = require("jupyter_client", extra="lab", purpose="running experiments").AsyncKernelManager
Dict = require("traitlets", extra="lab", purpose="running experiments").Dict
Unicode = require("traitlets", extra="lab", purpose="running experiments").Unicode

__all__ = [
    "RunSpec",
    "RunOutput",
    "OutputTooLarge",
    "DEFAULT_MAX_OUTPUT_MB",
    "execute",
    "LabKernelManager",
    "kernel_config",
    "kill_kernels",
    "cancel_runs",
    "cancellable",
    "missing_on_worker",
]

#: largest total size of one run's outputs that may travel back to the client, MB
DEFAULT_MAX_OUTPUT_MB = 64.0
_LIVE: dict[int, int] = {}  # kernel pid -> process group of every kernel this process started
_LIVE_LOCK = threading.Lock()
_CANCELLED = threading.Event()  # set while a cancelled sweep winds down: no new kernel may start
_P = ParamSpec("_P")
_T = TypeVar("_T")


class OutputTooLarge(ValueError):
    """A run's outputs exceed the size that may travel back to the client."""


@dataclass(frozen=True)
class RunSpec:
    """Everything one run needs, as plain data that pickles to any worker."""

    name: str
    params: dict
    notebook: bytes
    _: KW_ONLY
    timeout: int = 3600
    max_output_mb: float = DEFAULT_MAX_OUTPUT_MB
    #: a project folder the kernel may use in place (same machine), or None for a self-contained scratch project
    project: str | None = None


@dataclass
class RunOutput:
    """What comes back from a run: status, error text, wall time, worker and the output files' bytes."""

    status: str  # "ok" or "failed"
    _: KW_ONLY
    error: str = ""
    seconds: float = 0.0
    worker: str = ""
    files: dict[str, bytes] = field(default_factory=dict)


class LabKernelManager(AsyncKernelManager):
    """The kernel manager of every run: encrypted transport, a per-run environment, tracked kernels."""

    extra_env = Dict(config=True, help="variables added to the kernel's environment")
    kernel_log = Unicode("", config=True, help="file for the kernel process's own output (its log lines)")

    async def start_kernel(self, **kw: Any) -> None:
        """Start the kernel as the base class does, with ``extra_env`` added and the kernel registered.

        The kernel's stdout and stderr go to ``kernel_log`` when it is set.

        Parameters
        ----------
        **kw : Any
            Keyword arguments of ``AsyncKernelManager.start_kernel``; ``env`` (default
            ``os.environ``) is copied and updated with ``extra_env``.

        Raises
        ------
        RuntimeError
            If runs are cancelled (:func:`cancel_runs`) before the kernel starts.  A kernel that
            started while runs were cancelled is killed at once.
        """
        if _CANCELLED.is_set():
            raise RuntimeError("the run was cancelled before its kernel started")
        env = dict(kw.pop("env", None) or os.environ)
        env.update(self.extra_env)
        if self.kernel_log:  # the kernel's log lines (e.g. ipykernel's notice of an interrupt at shut-down)
            with open(self.kernel_log, "ab") as log:  # stay with the run, never on the user's terminal
                kw.update(stdout=log, stderr=log)
                await super().start_kernel(env=env, **kw)
        else:
            await super().start_kernel(env=env, **kw)
        process = getattr(self.provisioner, "process", None)
        if process is not None:
            with _LIVE_LOCK:
                _LIVE[process.pid] = getattr(self.provisioner, "pgid", None) or process.pid
        if _CANCELLED.is_set():  # cancelled while it started
            kill_kernels()

    async def cleanup_resources(self, restart: bool = False) -> None:
        """Forget the kernel (no longer killed by :func:`kill_kernels`), then clean up as the base class.

        Parameters
        ----------
        restart : bool, default False
            Passed on to ``AsyncKernelManager.cleanup_resources``.
        """
        process = getattr(self.provisioner, "process", None)
        if process is not None:
            with _LIVE_LOCK:
                _LIVE.pop(process.pid, None)
        await super().cleanup_resources(restart=restart)


def kernel_config(*, extra_env: dict[str, str] | None = None, log: str | Path | None = None) -> Config:
    """traitlets configuration for a notebook client: :class:`LabKernelManager` with encryption.

    ipykernel warns ``Kernel is running over TCP without encryption`` when its manager gives it no
    CurveZMQ keys; ``transport_encryption = "auto"`` makes jupyter_client provision them (the
    kernelspec declares support).  Where pyzmq lacks CurveZMQ, local IPC sockets are used instead.

    Parameters
    ----------
    extra_env : dict of str to str, optional
        Variables added to the kernel's environment (``LabKernelManager.extra_env``).
    log : str or pathlib.Path, optional
        File for the kernel process's own output (``LabKernelManager.kernel_log``); by default it
        goes where the client's does.

    Returns
    -------
    traitlets.config.Config
        The ``LabKernelManager`` settings, for papermill's or nbclient's ``config``.
    """
    zmq = require("zmq", extra="lab", purpose="encrypted kernel connections")
    from traitlets.config import Config

    cfg = Config()
    if "transport_encryption" not in LabKernelManager.class_trait_names():
        pass  # jupyter_client before transport encryption: its kernels do not warn either
    elif zmq.has("curve"):
        cfg.LabKernelManager.transport_encryption = "auto"
    else:
        cfg.LabKernelManager.transport = "ipc"
    cfg.LabKernelManager.extra_env = dict(extra_env or {})
    cfg.LabKernelManager.kernel_log = str(log or "")
    return cfg


def cancel_runs(*, cancelled: bool = True) -> None:
    """Refuse (``cancelled``) or allow again new kernel starts in this process.

    Parameters
    ----------
    cancelled : bool, default True
        True: every later :meth:`LabKernelManager.start_kernel` raises; False: kernels may start again.
    """
    if cancelled:
        _CANCELLED.set()
    else:
        _CANCELLED.clear()


def kill_kernels() -> int:
    """Kill every kernel this process started and has not shut down (their whole process groups).

    Used when a run or a sweep is cancelled (Ctrl-C, SIGTERM).

    Returns
    -------
    int
        How many kernels were registered and sent SIGKILL (those already gone included).
    """
    with _LIVE_LOCK:
        live = dict(_LIVE)
        _LIVE.clear()
    for pid, group in live.items():
        for kill, target in ((os.killpg, group), (os.kill, pid)):
            try:
                kill(target, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
    return len(live)


def cancellable(fn: Callable[_P, _T], *args: _P.args, **kwargs: _P.kwargs) -> _T:
    """``fn(*args, **kwargs)`` in a worker thread, so that Ctrl-C or SIGTERM reach this (main) thread
    at once: then no new kernel may start, the running ones are killed, and the interrupt goes on.

    Parameters
    ----------
    fn : callable
        The function to call.
    *args : Any
        Its positional arguments.
    **kwargs : Any
        Its keyword arguments.

    Returns
    -------
    object
        What ``fn`` returns; what it raises is raised here.
    """
    import concurrent.futures as cf

    pool = cf.ThreadPoolExecutor(max_workers=1, thread_name_prefix="thesis-lab-run")
    future = pool.submit(fn, *args, **kwargs)
    try:
        while True:
            try:
                return future.result(timeout=0.5)
            except cf.TimeoutError:
                continue
    except BaseException:
        cancel_runs(cancelled=True)
        try:
            kill_kernels()
            pool.shutdown(wait=True, cancel_futures=True)
            kill_kernels()
        finally:
            cancel_runs(cancelled=False)
        raise
    finally:
        pool.shutdown(wait=True)


def _worker_name() -> str:
    import sys

    if "distributed" in sys.modules:
        try:
            from distributed import get_worker

            return f"dask:{get_worker().name}"
        except ValueError:  # not inside a Dask task
            pass
    return f"{socket.gethostname()}:{os.getpid()}"


def _unpack_data(bundle: dict | None, data_dir: Path) -> None:
    """Write the manifest and data files of ``bundle`` into ``data_dir``, each checked by sha256."""
    from . import data

    data_dir.mkdir(parents=True)
    manifest = data_dir / "manifest.toml"
    manifest.write_bytes((bundle or {}).get("manifest", b""))
    entries = {e.file: e for e in data.manifest(manifest).values()}
    for rel, payload in (bundle or {}).get("files", {}).items():
        entry = entries.get(rel)
        if entry is None:
            raise data.DataError(f"data file {rel!r} sent to the worker is not in the manifest")
        target = data.inside(data_dir, rel)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(payload)
        data.check(entry, target)


def _collect(out: Path, limit_mb: float) -> dict[str, bytes]:
    files = [p for p in sorted(out.rglob("*")) if p.is_file() and not p.is_symlink()]
    sizes = {p: p.stat().st_size for p in files}
    total = sum(sizes.values())
    if total > limit_mb * 2**20:
        largest = max(sizes, key=sizes.get)
        raise OutputTooLarge(
            f"the run's outputs are {total / 2**20:.1f} MB, over the limit of {limit_mb:g} MB that may travel "
            f"back from a worker (largest: {largest.relative_to(out)}, {sizes[largest] / 2**20:.1f} MB); "
            "write smaller figures or raise --max-output-mb"
        )
    return {str(p.relative_to(out)): p.read_bytes() for p in files}


def _scratch(name: str) -> Path:
    """A fresh scratch folder for one run; those left by dead processes are removed first."""
    parent = Path(tempfile.gettempdir()) / "thesis-lab-runs"
    parent.mkdir(exist_ok=True)
    atomic.clean_stale(parent)
    return Path(tempfile.mkdtemp(prefix=f".{name}.tmp-{os.getpid()}-", dir=parent))


def _error_text(exc: BaseException) -> str:
    text = str(exc).strip()
    return f"{type(exc).__name__}: {text.splitlines()[-1] if text else ''}"


def execute(spec: RunSpec, *, bundle: dict | None = None, progress: bool = False) -> RunOutput:
    """Execute one run in a scratch folder and return its outputs as bytes.

    Parameters
    ----------
    spec : RunSpec
        The run (experiment name, resolved parameters, the notebook's bytes, limits).
    bundle : dict, optional
        ``{"manifest": bytes, "files": {path below data/: bytes}}``, the input data for a
        self-contained run (``spec.project`` None); each file is checked against the manifest's sha256.
    progress : bool, default False
        Show papermill's cell progress bar (cell n of m, elapsed time) on stderr.

    Returns
    -------
    RunOutput
        ``status`` "ok" or "failed" (the notebook raised, the kernel died, the outputs were too
        large): never raises for a failing notebook.
    """
    from .results import check_name

    pm = require("papermill", extra="lab", purpose="running experiments")

    start = time.perf_counter()
    scratch = _scratch(check_name(spec.name))
    result = RunOutput("ok", worker=_worker_name())
    try:
        out = scratch / "out"
        out.mkdir()
        if spec.project is None:
            project = scratch / "project"
            (project / "experiments").mkdir(parents=True)
            _unpack_data(bundle, project / "data")
        else:
            project = Path(spec.project)
        source = scratch / f"{spec.name}.ipynb"
        source.write_bytes(spec.notebook)
        env = {PROJECT_ENV: str(project), "PYDEVD_DISABLE_FILE_VALIDATION": "1"}
        try:
            pm.execute_notebook(
                str(source),
                str(out / f"{spec.name}.ipynb"),
                parameters={**spec.params, OUTPUT_PARAMETER: str(out)},
                kernel_name="python3",
                progress_bar=progress,
                execution_timeout=spec.timeout,
                resources={"metadata": {"path": str(project / "experiments")}},
                kernel_manager_class=LabKernelManager,
                config=kernel_config(extra_env=env, log=scratch / "kernel.log"),
            )
        except Exception as exc:  # papermill re-raises the notebook's error; keep its message
            result.status = "failed"
            result.error = _error_text(exc)
            (out / "error.txt").write_text(str(exc))
            log = scratch / "kernel.log"
            if log.is_file() and log.stat().st_size:
                shutil.copy(log, out / "kernel.log")
        try:
            result.files = _collect(out, spec.max_output_mb)
        except OutputTooLarge as exc:
            result.status, result.error, result.files = "failed", str(exc), {"error.txt": str(exc).encode()}
    except Exception as exc:  # the scratch project could not be made (bad data, full disk): a failed run
        result.status, result.error = "failed", _error_text(exc)
        result.files = {"error.txt": str(exc).encode()}
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    result.seconds = time.perf_counter() - start
    return result


def missing_on_worker(*, modules: tuple[str, ...] = ("thesis_lib", "papermill", "ipykernel", "nbformat")) -> list[str]:
    """Modules a worker needs that do not import there, and ``kernel python3`` if it has no such kernel.

    Sent to every Dask worker before a sweep (by value: it must run where thesis_lib is missing).

    Parameters
    ----------
    modules : tuple of str, default ("thesis_lib", "papermill", "ipykernel", "nbformat")
        The modules to import.

    Returns
    -------
    list of str
        The modules that failed to import, then ``"kernel python3"`` if no ``python3`` kernelspec
        is found (not looked for when ``jupyter_client`` is listed and failed); empty when the
        worker can run experiments.
    """
    import importlib

    missing = []
    for module in modules:
        try:
            importlib.import_module(module)
        except Exception:  # noqa: BLE001 (any failure to import means the worker cannot run)
            missing.append(module)
    if "jupyter_client" not in missing:
        try:
            from jupyter_client.kernelspec import KernelSpecManager

            KernelSpecManager().get_kernel_spec("python3")
        except Exception:  # noqa: BLE001
            missing.append("kernel python3")
    return missing
