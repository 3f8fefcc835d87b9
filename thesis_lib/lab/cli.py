"""The ``thesis-lab`` command line: run and sweep experiments, the report, the data layer."""

from __future__ import annotations

import argparse
import sys

__all__ = ["main"]


def _pairs(items: list[list[str]] | None) -> dict[str, str]:
    out: dict[str, str] = {}
    for key, value in items or []:
        if key in out:
            raise SystemExit(f"error: parameter {key!r} given twice")
        out[key] = value
    return out


def _grid(items: list[list[str]] | None) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for entry in items or []:
        if len(entry) < 2:
            raise SystemExit(f"error: -p {entry[0]} needs at least one value")
        if entry[0] in out:
            raise SystemExit(f"error: parameter {entry[0]!r} given twice")
        out[entry[0]] = entry[1:]
    return out


def _cmd_run(args) -> int:
    from .runner import run

    result = run(args.experiment, _pairs(args.param), force=args.force)
    print(f"{result.status}: {result.path}")
    for key, value in sorted(result.results.items()):
        print(f"  {key} = {value}")
    if result.status == "failed":
        print(f"error: the notebook failed: {result.error} (see {result.path / 'error.txt'})", file=sys.stderr)
        return 1
    return 0


def _cmd_sweep(args) -> int:
    from .runner import sweep

    runs, table = sweep(args.experiment, _grid(args.param), jobs=args.jobs, progress=not args.quiet, keep=args.keep)
    print(table.with_suffix(".md").read_text())
    print(f"table: {table} (and {table.with_suffix('.md').name})")
    failed = [r for r in runs if r.status == "failed"]
    for r in failed:
        print(f"failed: {r.params} -> {r.error} (see {r.path / 'error.txt'})", file=sys.stderr)
    return 1 if failed else 0


def _cmd_store(args) -> int:
    from .runner import list_experiments, store

    targets = args.targets or list_experiments()
    for target in targets:
        print(f"executing {target} ...", flush=True)
        store(target)
    return 0


def _cmd_list(args) -> int:
    from .runner import experiment_parameters, list_experiments

    for name in list_experiments():
        params = experiment_parameters(name)
        params.pop("output_dir", None)
        print(name + ": " + ", ".join(f"{k}={v!r}" for k, v in params.items()))
    return 0


def _cmd_report(args) -> int:
    from .report import markdown, report, to_json

    rows = report()
    print(to_json(rows) if args.json else markdown(rows))
    return 0


def _cmd_data(args) -> int:
    from . import data

    if args.action == "verify":
        rows = data.verify()
        for name, status, detail in rows:
            print(f"{status:5s} {name}: {detail}")
        return 0 if all(s == "ok" for _, s, _ in rows) else 1
    names = args.names or sorted(data.manifest())
    for name in names:
        print(f"fetched {name}: {data.fetch(name)}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``thesis-lab``."""
    parser = argparse.ArgumentParser(prog="thesis-lab", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("run", help="run one experiment into runs/NAME/<hash>/")
    p.add_argument("experiment")
    p.add_argument("-p", "--param", nargs=2, action="append", metavar=("NAME", "VALUE"))
    p.add_argument("--force", action="store_true", help="run again even if complete")
    p.set_defaults(func=_cmd_run)

    p = sub.add_parser("sweep", help="run the Cartesian grid of parameter values")
    p.add_argument("experiment")
    p.add_argument("-p", "--param", nargs="+", action="append", metavar="NAME VALUE")
    p.add_argument("-j", "--jobs", type=int, default=1)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.add_argument("--keep", action="store_true", help="also store the table with the default run (for the book)")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("store", help="re-execute stored default runs in place (all experiments by default)")
    p.add_argument("targets", nargs="*", help="experiment names or notebook paths")
    p.set_defaults(func=_cmd_store)

    p = sub.add_parser("list", help="list experiments and their default parameters")
    p.set_defaults(func=_cmd_list)

    p = sub.add_parser("report", help="the reproduction report")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=_cmd_report)

    p = sub.add_parser("data", help="the data layer")
    p.add_argument("action", choices=["verify", "fetch"])
    p.add_argument("names", nargs="*", help="data sets to fetch (default: all)")
    p.set_defaults(func=_cmd_data)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``thesis-lab`` console script."""
    from .data import DataError
    from .report import ClaimError
    from .runner import ParameterError

    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (ParameterError, DataError, ClaimError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
