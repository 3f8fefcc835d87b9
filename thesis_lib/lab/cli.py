"""The ``thesis-lab`` command line: run and sweep experiments, the report, the data layer.

Exit codes: 0 success; 1 a notebook or run failed (or runs are missing or corrupt), the disk is
full (nothing half-written is kept), or a package the command needs is not installed (one line
names it and the extra: ``pip install "thesis-lab[lab]"``; ``report`` and ``data`` need none);
2 bad input (an unknown experiment or parameter, a bad value, a path parameter outside the project,
a folder that is not a project, a malformed manifest, claims file or stored result, an unreachable
cluster); 130 / 143 cancelled by Ctrl-C / SIGTERM (running kernels are killed, nothing half-written
is kept).
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import os
import re
import signal
import sys

from .._optional import MissingExtraError

__all__ = ["main", "build_parser"]


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised in the main thread so that runs and sweeps cancel as on Ctrl-C."""


def _pairs(items: list[list[str]] | None) -> dict[str, str]:
    from .experiments import ParameterError

    out: dict[str, str] = {}
    for key, value in items or []:
        if key in out:
            raise ParameterError(f"parameter {key!r} given twice (-p {key} {out[key]} and -p {key} {value})")
        out[key] = value
    return out


def _grid(items: list[list[str]] | None) -> dict[str, list[str]]:
    from .experiments import ParameterError

    out: dict[str, list[str]] = {}
    for entry in items or []:
        if len(entry) < 2:
            raise ParameterError(f"-p {entry[0]} needs at least one value")
        if entry[0] in out:
            raise ParameterError(f"parameter {entry[0]!r} given twice; give all its values after one -p")
        out[entry[0]] = entry[1:]
    return out


def _err(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


def _cmd_run(args) -> int:
    from .runner import run

    result = run(args.experiment, _pairs(args.param), force=args.force, progress=None if not args.quiet else False)
    print(f"{result.status}: {result.path}")
    for key, value in sorted(result.results.items()):
        print(f"  {key} = {value}")
    if result.status == "failed":
        _err(f"error: the notebook failed: {result.error} (see {result.path / 'error.txt'})")
        return 1
    return 0


#: the widest line of the sweep summary on the terminal, and the widest cell in it
SUMMARY_WIDTH, CELL_WIDTH = 100, 14
#: rows of the sweep summary (the table file has them all)
SUMMARY_ROWS = 20


def _short(value: object, width: int = CELL_WIDTH) -> str:
    """A cell of the terminal summary: floats to 4 significant digits, lists joined, cut to ``width``."""
    from .tables import cell

    if isinstance(value, list):
        value = ",".join(_short(v, width) for v in value)
    return _cut(cell(value, digits=4), width)


def _cut(text: str, width: int) -> str:
    return text if len(text) <= width else text[: width - 1] + "…"


def _summary(runs, keys: list[str], *, width: int = SUMMARY_WIDTH, max_rows: int = SUMMARY_ROWS) -> list[str]:
    """The terminal summary of a sweep: status counts, the varied parameters and the results that fit.

    Parameters
    ----------
    runs : list of RunResult
        The sweep's runs, in grid order.
    keys : list of str
        The parameters of the grid.
    width : int, default 100
        The widest line: result columns are added, in the table's order, while the lines fit.
    max_rows : int, default 20
        The most runs shown; a last line says how many more the table holds.

    Returns
    -------
    list of str
        The lines: the counts, the parameters that had one value, the aligned columns, and a note
        naming the result columns left out.
    """
    counts = {}
    for r in runs:
        counts[r.status] = counts.get(r.status, 0) + 1
    order = ("ok", "skipped", "failed", "missing", "corrupt")
    lines = [f"{len(runs)} runs: " + ", ".join(f"{counts[s]} {'done before' if s == 'skipped' else s}"
                                              for s in order if counts.get(s))]
    varied = [k for k in keys if len({_short(r.params[k], 10**6) for r in runs}) > 1] or list(keys)
    fixed = [k for k in keys if k not in varied and runs]
    if fixed:
        lines.append(_cut("fixed: " + ", ".join(f"{k}={_short(runs[0].params[k])}" for k in fixed), width))
    shown = runs[:max_rows]
    columns = [(k, [_short(r.params[k]) for r in shown]) for k in varied]
    columns.append(("status", ["ok" if r.status == "skipped" else r.status for r in shown]))
    result_keys = sorted({k for r in runs for k in r.results})
    left_out = []
    for key in result_keys:
        cells = [_short(r.results.get(key, "")) for r in shown]
        trial = columns + [(key, cells)]
        if sum(max(len(t), *map(len, c)) for t, c in trial) + 2 * (len(trial) - 1) <= width:
            columns = trial
        else:
            left_out.append(key)
    widths = [max(len(t), *map(len, c)) for t, c in columns]
    lines.append("  ".join(t.ljust(w) for (t, _), w in zip(columns, widths)).rstrip())
    for i in range(len(shown)):
        lines.append("  ".join(c[i].ljust(w) for (_, c), w in zip(columns, widths)).rstrip())
    if len(runs) > len(shown):
        lines.append(f"... {len(runs) - len(shown)} more runs in the table")
    if left_out:
        lines.append(_cut(f"not shown ({len(left_out)} result columns): " + ", ".join(left_out), width))
    return lines


def _print_table(runs, table, what: str, keys: list[str]) -> int:
    md = table.with_suffix(".md")
    print(_cut(md.read_text().split("\n", 1)[0], SUMMARY_WIDTH))  # the command that gives the table
    print("\n".join(_summary(runs, keys)))
    print(f"full table: {table} (and {md.name})")
    bad = [r for r in runs if r.status in ("failed", "missing", "corrupt")]
    for r in bad:
        detail = {"failed": f"{r.error} (see {r.path / 'error.txt'})", "missing": f"no run folder {r.path}",
                  "corrupt": r.error}[r.status]
        _err(f"{r.status}: {r.params} -> {detail}")
    if bad:
        counts = {s: sum(r.status == s for r in bad) for s in ("failed", "missing", "corrupt")}
        _err(f"{what}: {counts['failed']} failed, {counts['missing']} missing"
             + (f", {counts['corrupt']} corrupt" if counts["corrupt"] else ""))
    return 1 if bad else 0


def _cmd_sweep(args) -> int:
    from .sweep import dask_client, sweep

    grid = _grid(args.param)
    progress = not args.quiet and sys.stderr.isatty()
    common = dict(progress=progress, keep=args.keep, shard=args.shard, retries=args.retries,
                  max_output_mb=args.max_output_mb, jobs=args.jobs)
    if args.executor == "dask":
        with dask_client(scheduler=args.scheduler, jobs=args.jobs, retries=args.retries, log=_err) as client:
            runs, table = sweep(args.experiment, grid, executor=client, **common)
    else:
        if args.scheduler:
            from .experiments import ParameterError

            raise ParameterError("--scheduler needs --executor dask")
        runs, table = sweep(args.experiment, grid, **common)
    if args.shard:
        print(f"shard {args.shard} done; when every shard is done: thesis-lab collect {args.experiment} "
              + " ".join(f"-p {k} " + " ".join(v) for k, v in grid.items()))
    return _print_table(runs, table, "sweep", list(grid))


def _cmd_collect(args) -> int:
    from .sweep import collect

    grid = _grid(args.param)
    runs, table = collect(args.experiment, grid, keep=args.keep)
    return _print_table(runs, table, "collect", list(grid))


def _cmd_store(args) -> int:
    from .experiments import list_experiments
    from .runner import store

    targets = args.targets or list_experiments()
    for target in targets:
        print(f"executing {target} ...", flush=True)
        store(target)
    return 0


def _cmd_list(args) -> int:
    from .experiments import OUTPUT_PARAMETER, experiment_parameters, list_experiments

    for name in list_experiments():
        params = experiment_parameters(name)
        params.pop(OUTPUT_PARAMETER, None)
        print(name + ": " + ", ".join(f"{k}={_display(v)}" for k, v in params.items()))
    return 0


def _display(value: object, *, digits: int = 6) -> str:
    """A parameter value as ``thesis-lab list`` prints it: ``repr``, floats to ``digits`` significant digits.

    Only the display is shortened; the stored value and the run hash keep every digit.

    Parameters
    ----------
    value : object
        A parameter's value (a scalar or a list of scalars).
    digits : int, default 6
        Significant digits of a float; a float keeps a point (``2.0``), so it reads as a float.

    Returns
    -------
    str
        The text.

    Examples
    --------
    >>> _display(0.7853981633974483), _display(2.0), _display([1e-07, 0.5]), _display("a")
    ('0.785398', '2.0', '[1e-07, 0.5]', "'a'")
    """
    if isinstance(value, list):
        return "[" + ", ".join(_display(v, digits=digits) for v in value) + "]"
    if isinstance(value, float):
        text = f"{value:.{digits}g}"
        return text if any(c in text for c in ".eEn") else text + ".0"
    return repr(value)


def _cmd_report(args) -> int:
    from .report import markdown, report, to_json

    rows = report()
    print(to_json(rows) if args.json else markdown(rows, with_summary=True))
    return 0


def _cmd_data(args) -> int:
    from . import data

    if args.action == "verify":
        rows = data.verify(names=args.names)
        for name, status, detail in rows:
            print(f"{status:5s} {name}: {detail}")
        return 0 if all(s == "ok" for _, s, _ in rows) else 1
    names = args.names or sorted(data.manifest())
    for name in names:
        print(f"fetched {name}: {data.fetch(name)}")
    return 0


def _int_from(low: int):
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer >= {low}, got {text!r}") from None
        if value < low:
            raise argparse.ArgumentTypeError(f"expected an integer >= {low}, got {value}")
        return value

    return parse


def _positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not value > 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}")
    return value


_EXPERIMENT_HELP = "the experiment: a name that `thesis-lab list` shows (listed below)"


def _grid_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("experiment", help=_EXPERIMENT_HELP)
    p.add_argument("-p", "--param", nargs="+", action="append", metavar="NAME VALUE",
                   help="a parameter and its values (repeat -p for more parameters); a list parameter's "
                        "value is comma-separated (60,100) or a JSON list")
    p.add_argument("--keep", action="store_true", help="also store the table with the default run (for the book)")


class UsageError(Exception):
    """A command line that argparse cannot read (reported as ``error: ...``, exit status 2)."""


def _plain(text: str | None) -> str | None:
    """Help text without reStructuredText's double backticks (``x`` reads as x on a terminal)."""
    return re.sub(r"``(.+?)``", r"\1", text) if text else text


class _Formatter(argparse.RawDescriptionHelpFormatter):
    """Help without RST markup; descriptions and epilogs keep their lines (the list of experiments)."""

    def _format_text(self, text: str) -> str:
        return super()._format_text(_plain(text))

    def _expand_help(self, action) -> str:
        return _plain(super()._expand_help(action))


class _Parser(argparse.ArgumentParser):
    """argparse that raises :class:`UsageError` instead of printing the usage and exiting.

    ``epilog_of``, a function of no arguments, gives the epilog when the help is printed (the
    experiments of the project the command runs on); an unknown option after a subcommand is
    reported with that subcommand's usage (on the one line of the error).
    """

    def __init__(self, *args, epilog_of=None, **kwargs):
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)
        self.epilog_of = epilog_of
        self.commands = None

    def add_subparsers(self, **kwargs):
        self.commands = super().add_subparsers(**kwargs)
        return self.commands

    def format_help(self) -> str:
        if self.epilog_of is not None:
            self.epilog = self.epilog_of()
        return super().format_help()

    def parse_known_args(self, args=None, namespace=None):
        parsed, extra = super().parse_known_args(args, namespace)
        commands = self.commands.choices if self.commands is not None else {}
        if extra and getattr(parsed, "command", None) in commands:
            commands[parsed.command].error("unrecognized arguments: " + " ".join(extra))
        return parsed, extra

    def error(self, message: str):
        synopsis = " ".join(self.format_usage().split()[1:])  # one line: "usage: prog ..." without "usage:"
        raise UsageError(f"{message}; expected: {synopsis} (see `{self.prog} --help`)")


def _experiments_epilog() -> str:
    """The experiments of the project, one a line (or why there are none), for the help's epilog."""
    from .experiments import list_experiments
    from .paths import ProjectError

    try:
        names = list_experiments()
    except ProjectError as exc:
        return f"experiments: none found ({exc})"
    return "experiments (thesis-lab list shows their parameters):\n" + "\n".join(f"  {n}" for n in names)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``thesis-lab``.

    Returns
    -------
    argparse.ArgumentParser
        The parser, with the subcommands ``run``, ``sweep``, ``collect``, ``store``, ``list``,
        ``report`` and ``data``; each sets ``func`` to its handler.  A command line it cannot read
        raises ``UsageError`` instead of exiting.
    """
    parser = _Parser(prog="thesis-lab", description=__doc__.split("\n", 1)[0])
    parser.add_argument("--project", metavar="DIR",
                        help="the project folder (default: $THESIS_LAB_PROJECT, else the current folder or above)")
    sub = parser.add_subparsers(dest="command", required=True)

    def command(name: str, text: str, **kwargs) -> argparse.ArgumentParser:
        return sub.add_parser(name, help=text, description=text[0].upper() + text[1:] + ".", **kwargs)

    p = command("run", "run one experiment into runs/NAME/<hash>/", epilog_of=_experiments_epilog)
    p.add_argument("experiment", help=_EXPERIMENT_HELP)
    p.add_argument("-p", "--param", nargs=2, action="append", metavar=("NAME", "VALUE"),
                   help="set a parameter (repeat -p for more); `thesis-lab list` shows each experiment's "
                        "parameters and defaults; a list parameter's value is comma-separated (60,100) or "
                        "a JSON list")
    p.add_argument("--force", action="store_true", help="run again even if complete")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress (shown only on a terminal anyway)")
    p.set_defaults(func=_cmd_run)

    p = command("sweep", "run the Cartesian grid of parameter values", epilog_of=_experiments_epilog)
    _grid_options(p)
    p.add_argument("-j", "--jobs", type=_int_from(1), default=1,
                   help="runs at a time (local), or worker processes of the LocalCluster (dask, no --scheduler)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.add_argument("--executor", choices=["local", "dask"], default="local")
    p.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler (tcp://host:8786)")
    p.add_argument("--shard", metavar="I/N", help="run only the I-th of N slices of the grid (job arrays)")
    p.add_argument("--retries", type=_int_from(0), default=2,
                   help="Dask: retries of a run whose worker died (default 2)")
    p.add_argument("--max-output-mb", type=_positive_float, default=64.0,
                   help="largest total size of one run's outputs sent back from a worker (default 64)")
    p.set_defaults(func=_cmd_sweep)

    p = command("collect", "the sweep table from the run folders that exist (after --shard runs)",
                epilog_of=_experiments_epilog)
    _grid_options(p)
    p.set_defaults(func=_cmd_collect)

    p = command("store", "re-execute stored default runs in place (all experiments by default)")
    p.add_argument("targets", nargs="*", help="experiment names or notebook paths")
    p.set_defaults(func=_cmd_store)

    p = command("list", "list experiments and their default parameters")
    p.set_defaults(func=_cmd_list)

    p = command("report", "the reproduction report")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=_cmd_report)

    p = command("data", "the data layer")
    p.add_argument("action", choices=["verify", "fetch"])
    p.add_argument("names", nargs="*",
                   help="the data sets: verify takes names, their starts or sha256 prefixes (4+ hex digits); "
                        "fetch takes names (default: all)")
    p.set_defaults(func=_cmd_data)
    return parser


def _on_sigterm(signum, frame):
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``thesis-lab`` console script.

    In the main thread, SIGTERM is turned into a cancellation (like Ctrl-C) while the command runs;
    errors are printed to stderr as ``error: ...``.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name; by default ``sys.argv[1:]``.

    Returns
    -------
    int
        The exit status: 0 success; 1 a notebook or run failed (or runs are missing or corrupt),
        no space was left on the device, or a package of the ``[lab]`` extra the command needs is
        not installed (one line names it and the install command); 2 bad input;
        130 / 143 cancelled by Ctrl-C / SIGTERM; 141 the reader of stdout went away.
    """
    previous = signal.signal(signal.SIGTERM, _on_sigterm) if _main_thread() else None
    try:
        return _main(argv)
    except KeyboardInterrupt as exc:
        with contextlib.suppress(MissingExtraError):  # without the [lab] extra no kernel was started
            from .execute import kill_kernels

            kill_kernels()
        _err("cancelled: running kernels stopped; completed runs are kept, nothing partial is marked complete")
        return 143 if isinstance(exc, Terminated) else 130
    except BrokenPipeError:  # `thesis-lab list | head -1`: the reader left; say nothing more
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141
    finally:
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _main(argv: list[str] | None) -> int:
    from .paths import PROJECT_ENV, is_project

    folder = _project_option(argv)
    if folder:
        if not is_project(folder):
            why = "does not exist" if not os.path.exists(folder) else (
                "is not a folder" if not os.path.isdir(folder) else "has no experiments/ and data/manifest.toml")
            _err(f"error: --project {folder!r} is not a thesis-lab project: it {why}")
            return 2
    with _project_named(PROJECT_ENV, folder):  # before parsing: the help lists the project's experiments
        try:
            args = build_parser().parse_args(argv)
        except UsageError as exc:
            _err(f"error: {exc}")
            return 2
        except SystemExit as exc:  # --help printed the usage
            return exc.code if isinstance(exc.code, int) else 0
        return _run(args)


def _project_option(argv: list[str] | None) -> str | None:
    """The value of ``--project`` in ``argv`` (None if absent or unreadable: the full parse reports it)."""
    pre = _Parser(add_help=False)
    pre.add_argument("--project")
    try:
        return pre.parse_known_args(sys.argv[1:] if argv is None else argv)[0].project
    except UsageError:
        return None


@contextlib.contextmanager
def _project_named(variable: str, folder: str | None):
    """``variable`` names ``folder`` while the command runs (its kernels inherit it), then is restored."""
    previous = os.environ.get(variable)
    if folder:
        os.environ[variable] = os.path.abspath(folder)
    try:
        yield
    finally:
        if folder and previous is None:
            os.environ.pop(variable, None)
        elif folder:
            os.environ[variable] = previous


def _lab_errors() -> tuple[tuple[type[Exception], ...], tuple[type[Exception], ...]]:
    """(the sweep's ClusterError,), (nbclient's CellExecutionError,); both empty without the [lab] extra."""
    try:
        from nbclient.exceptions import CellExecutionError

        from .sweep import ClusterError
    except ImportError:  # report and data run without [lab]; the other commands say what is missing
        return (), ()
    return (ClusterError,), (CellExecutionError,)


def _run(args) -> int:
    from .data import DataError
    from .experiments import ParameterError
    from .paths import ProjectError
    from .report import ClaimError
    from .results import ResultsError

    cluster_error, cell_error = _lab_errors()
    try:
        code = args.func(args)
        sys.stdout.flush()  # inside the try: a closed pipe is reported here, not at exit
        return code
    except MissingExtraError as exc:
        _err(f"error: {exc}")
        return 1
    except (ParameterError, DataError, ClaimError, ResultsError, ProjectError, *cluster_error) as exc:
        _err(f"error: {exc}")
        return 2
    except OSError as exc:
        if exc.errno not in (errno.ENOSPC, errno.EDQUOT):
            raise
        where = f" writing {exc.filename}" if exc.filename else ""
        _err(f"error: no space left on the device{where}: nothing of this step was written or marked "
             "complete (every write goes to a temporary file or folder first, and it was removed; runs "
             "completed before are kept); free some space and run the command again")
        return 1
    except cell_error as exc:
        _err(f"error: the notebook failed; nothing was stored:\n{str(exc).strip()[-2000:]}")
        return 1


def _main_thread() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()


if __name__ == "__main__":
    sys.exit(main())
