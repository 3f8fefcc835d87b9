"""The data layer: every input that code cannot generate, found by name and checked by sha256.

Resolution order for ``path(name)``: the local cache ``data/<file>`` of the checkout, then
``../shared/data/<file>`` beside it.  Only :func:`fetch` downloads, from the manifest's URL.
"""

from __future__ import annotations

import hashlib
import shutil
import tempfile
import tomllib
import urllib.request
from dataclasses import dataclass
from pathlib import Path

from .paths import repo_root, shared_dir

__all__ = ["DataError", "Entry", "manifest", "path", "verify", "fetch", "sha256_of"]


class DataError(Exception):
    """A data file is missing, unknown or does not match its recorded sha256."""


@dataclass(frozen=True)
class Entry:
    """One manifest line: a named input with its checksum and public source."""

    name: str
    file: str
    sha256: str
    size: int
    url: str
    origin: str
    licence: str


def _manifest_path() -> Path:
    return repo_root() / "data" / "manifest.toml"


def manifest(manifest_file: str | Path | None = None) -> dict[str, Entry]:
    """All entries of ``data/manifest.toml`` by name."""
    path = Path(manifest_file) if manifest_file else _manifest_path()
    with open(path, "rb") as fh:
        raw = tomllib.load(fh)
    entries = {}
    for item in raw.get("file", []):
        try:
            entry = Entry(**item)
        except TypeError as exc:
            raise DataError(f"{path}: malformed entry {item!r} ({exc})") from None
        entries[entry.name] = entry
    return entries


def sha256_of(file: Path) -> str:
    """Hex sha256 of a file's bytes."""
    h = hashlib.sha256()
    with open(file, "rb") as fh:
        for chunk in iter(lambda: fh.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _entry(name: str, manifest_file: str | Path | None) -> Entry:
    entries = manifest(manifest_file)
    if name not in entries:
        known = ", ".join(sorted(entries))
        raise DataError(f"unknown data set {name!r}; the manifest lists: {known}")
    return entries[name]


def _candidates(entry: Entry) -> list[Path]:
    return [repo_root() / "data" / entry.file, shared_dir() / "data" / entry.file]


def _check(entry: Entry, file: Path) -> Path:
    digest = sha256_of(file)
    if digest != entry.sha256:
        raise DataError(
            f"{file} does not match its sha256 in data/manifest.toml (expected {entry.sha256}, "
            f"got {digest}): the file is corrupt or a different version; delete it and run "
            f"`thesis-lab data fetch {entry.name}`, or restore ../shared/data/{entry.file}"
        )
    return file


def path(name: str, manifest_file: str | Path | None = None) -> Path:
    """Local path of data set ``name`` after checking its sha256.

    Raises
    ------
    DataError
        If the name is unknown, no copy exists, or the copy's sha256 does not match.
    """
    entry = _entry(name, manifest_file)
    for candidate in _candidates(entry):
        if candidate.is_file():
            return _check(entry, candidate)
    tried = " and ".join(str(c) for c in _candidates(entry))
    raise DataError(
        f"data set {name!r} ({entry.file}) is missing: looked in {tried}. Put ../shared beside the "
        f"checkout, or run `thesis-lab data fetch {name}` to download it from {entry.url}"
    )


def verify(manifest_file: str | Path | None = None) -> list[tuple[str, str, str]]:
    """Check every manifest entry: a list of ``(name, status, detail)`` with status ``ok`` or ``error``."""
    rows = []
    for name in sorted(manifest(manifest_file)):
        try:
            rows.append((name, "ok", str(path(name, manifest_file))))
        except DataError as exc:
            rows.append((name, "error", str(exc)))
    return rows


def fetch(name: str, manifest_file: str | Path | None = None, timeout: float = 60.0) -> Path:
    """Download data set ``name`` from its public source into ``data/<file>`` and check its sha256.

    This is the only function of thesis-lab that touches the network; it runs only when asked.
    """
    entry = _entry(name, manifest_file)
    target = repo_root() / "data" / entry.file
    target.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile(dir=target.parent, delete=False) as tmp:
        tmp_path = Path(tmp.name)
        try:
            with urllib.request.urlopen(entry.url, timeout=timeout) as response:
                shutil.copyfileobj(response, tmp)
        except OSError as exc:
            tmp_path.unlink(missing_ok=True)
            raise DataError(f"could not download {name!r} from {entry.url}: {exc}") from None
    try:
        _check(entry, tmp_path)
    except DataError:
        tmp_path.unlink(missing_ok=True)
        raise
    tmp_path.replace(target)
    return target
