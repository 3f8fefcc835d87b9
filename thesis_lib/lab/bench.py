"""Stored benchmark results (``benchmarks/results/<topic>.json``) as tables for the book."""

from __future__ import annotations

import json
from pathlib import Path

from .paths import repo_root

__all__ = ["topics", "load", "markdown"]


def _dir() -> Path:
    return repo_root() / "benchmarks" / "results"


def topics() -> list[str]:
    """Benchmarks with stored full results (``--quick`` smoke runs are left out)."""
    return sorted(p.stem for p in _dir().glob("*.json") if not p.stem.replace("-", "_").endswith("_quick"))


def load(topic: str) -> list[dict]:
    """Rows of one benchmark (a list of flat dicts), as ``make bench`` stored them."""
    path = _dir() / f"{topic}.json"
    if not path.exists():
        raise FileNotFoundError(f"no stored benchmark {topic!r} at {path}; run `make bench`")
    data = json.loads(path.read_text())
    rows = data["rows"] if isinstance(data, dict) else data
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise ValueError(f"{path} must hold a list of rows (dicts)")
    return rows


def _cell(value) -> str:
    if isinstance(value, float):
        return f"{value:.3g}"
    return "" if value is None else str(value)


def markdown(topic: str, columns: list[str] | None = None, *, where=None) -> str:
    """One benchmark as a Markdown table: the given ``columns``, or all in first-seen order; with
    ``where`` (a predicate on a row), only the rows it accepts."""
    rows = [r for r in load(topic) if where is None or where(r)]
    if columns is None:
        columns = []
        for row in rows:
            columns += [k for k in row if k not in columns and not isinstance(row[k], (list, dict))]
    else:
        missing = [c for c in columns if all(c not in r for r in rows)]
        if missing:
            raise ValueError(f"benchmark {topic!r} has no columns {missing}")
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    lines += ["| " + " | ".join(_cell(r.get(c)) for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"
