"""The data layer: every input that code cannot generate, found by name and checked by sha256.

Resolution order for ``path(name)``: the local cache ``data/<file>`` of the project, then
``../shared/data/<file>`` beside it.  Only :func:`fetch` downloads, from the manifest's URL.
A manifest entry's ``file`` must stay inside ``data/``: ``..``, absolute paths and symlinks that lead
out are refused, by :func:`manifest` and again where a file is read or written.
"""

from __future__ import annotations

import hashlib
import re
import shutil
import urllib.request
from collections.abc import Mapping
from dataclasses import dataclass, fields
from pathlib import Path, PurePosixPath

from . import atomic
from .experiments import did_you_mean
from .paths import project_root, shared_dir
from .registry import read_tables

__all__ = ["DataError", "Entry", "manifest", "manifest_path", "path", "verify", "fetch", "sha256_of", "check", "inside",
           "check_parameter_paths", "resolve_structure"]


class DataError(ValueError):
    """A data file is missing, unknown, outside ``data/``, or does not match its recorded sha256."""


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


_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}")
_SHA = re.compile(r"[0-9a-f]{64}")
_SCHEMES = ("https://", "http://", "file://")


def manifest_path() -> Path:
    """The project's data manifest.

    Returns
    -------
    Path
        ``data/manifest.toml`` below the project root (it need not exist).
    """
    return project_root() / "data" / "manifest.toml"


def _relative(file: object) -> str:
    """``file`` as a relative POSIX path that names something below ``data/``, or a DataError."""
    if not isinstance(file, str) or not file or "\x00" in file or "\\" in file:
        raise DataError(f"file {file!r} must be a relative path below data/ (forward slashes)")
    parts = PurePosixPath(file).parts
    if file.startswith("/") or ".." in parts or not parts or any(p in ("", ".") for p in file.split("/")):
        raise DataError(f"file {file!r} must be a relative path below data/ (no '..', '.', empty or absolute parts)")
    return file


def inside(base: str | Path, file: str) -> Path:
    """``base/file`` after checking that it stays inside ``base`` once symlinks are resolved.

    Parameters
    ----------
    base : str or pathlib.Path
        The folder ``file`` must stay in.
    file : str
        A relative POSIX path (forward slashes; no ``..``, ``.``, empty or absolute parts).

    Returns
    -------
    pathlib.Path
        ``base/file`` with symlinks resolved; it need not exist.

    Raises
    ------
    DataError
        If ``file`` is not such a relative path, or leads outside ``base`` (or to ``base`` itself).
    """
    base = Path(base).resolve()
    target = (base / _relative(file)).resolve()
    if not target.is_relative_to(base) or target == base:
        raise DataError(f"file {file!r} leads outside {base} (through a symlink); refused")
    return target


def _validated(item: object, source: Path) -> Entry:
    if not isinstance(item, dict):
        raise DataError(f"{source}: a [[file]] entry must be a table, got {item!r}")
    names = [f.name for f in fields(Entry)]
    unknown, missing = set(item) - set(names), set(names) - set(item)
    if unknown or missing:
        raise DataError(f"{source}: entry {item.get('name', '?')!r}: unknown keys {sorted(unknown)}, "
                        f"missing {sorted(missing)}")
    name, size, url = item["name"], item["size"], item["url"]
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise DataError(f"{source}: entry name {name!r} must be 1-64 letters, digits, '.', '_' or '-'")
    where = f"{source}: entry {name!r}"
    try:
        _relative(item["file"])
    except DataError as exc:
        raise DataError(f"{where}: {exc}") from None
    if not isinstance(item["sha256"], str) or not _SHA.fullmatch(item["sha256"]):
        raise DataError(f"{where}: sha256 must be 64 lowercase hex digits, got {item['sha256']!r}")
    if isinstance(size, bool) or not isinstance(size, int) or size < 0:
        raise DataError(f"{where}: size must be a non-negative integer, got {size!r}")
    if not isinstance(url, str) or not url.startswith(_SCHEMES):
        raise DataError(f"{where}: url must start with one of {_SCHEMES}, got {url!r}")
    for key in ("origin", "licence"):
        if not isinstance(item[key], str):
            raise DataError(f"{where}: {key} must be a string, got {item[key]!r}")
    return Entry(**item)


def manifest(manifest_file: str | Path | None = None) -> dict[str, Entry]:
    """All entries of ``data/manifest.toml`` by name, each validated.

    Parameters
    ----------
    manifest_file : str or pathlib.Path, optional
        The manifest to read; by default the project's ``data/manifest.toml``.

    Returns
    -------
    dict of str to Entry
        The entries by name, in the manifest's order.

    Raises
    ------
    DataError
        If the file is missing or is not valid TOML, or an entry is malformed (wrong keys or types,
        a ``file`` outside ``data/``, a repeated name).
    """
    path = Path(manifest_file) if manifest_file else manifest_path()
    items = read_tables(path, key="file", error=DataError)
    entries: dict[str, Entry] = {}
    for item in items:
        entry = _validated(item, path)
        if entry.name in entries:
            raise DataError(f"{path}: data set {entry.name!r} is listed twice")
        entries[entry.name] = entry
    return entries


def sha256_of(file: Path) -> str:
    """Hex sha256 of a file's bytes.

    Parameters
    ----------
    file : pathlib.Path
        The file, read in chunks of 1 MiB.

    Returns
    -------
    str
        The 64 lowercase hex digits of the digest.
    """
    h = hashlib.sha256()
    with open(file, "rb") as fh:
        for chunk in iter(lambda: fh.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _entry(name: object, manifest_file: str | Path | None) -> Entry:
    entries = manifest(manifest_file)
    if not isinstance(name, str) or name not in entries:
        known = ", ".join(sorted(entries))
        raise DataError(f"unknown data set {name!r}; the manifest lists: {known}{did_you_mean(name, sorted(entries))}")
    return entries[name]


#: the fewest hex digits of a sha256 that select data sets by checksum
_MIN_SHA_PREFIX = 4


def _matching(patterns: list[str], entries: dict[str, Entry]) -> list[str]:
    """The names that ``patterns`` select (a name, the start of one, or a sha256 prefix), or a DataError."""
    chosen: set[str] = set()
    for pattern in patterns:
        digits = pattern.lower()
        hits = {name for name, e in entries.items()
                if name.startswith(pattern) or (len(digits) >= _MIN_SHA_PREFIX and e.sha256.startswith(digits))}
        if not hits:
            known = ", ".join(sorted(entries)) or "none"
            raise DataError(f"no data set matches {pattern!r} (give a name, the start of one, or at least "
                            f"{_MIN_SHA_PREFIX} hex digits of a sha256); the manifest lists: {known}"
                            + did_you_mean(pattern, sorted(entries)))
        chosen |= hits
    return sorted(chosen)


def _candidates(entry: Entry) -> list[Path]:
    return [inside(project_root() / "data", entry.file), inside(shared_dir() / "data", entry.file)]


def check(entry: Entry, file: Path) -> Path:
    """``file`` if its sha256 is the manifest's, else a DataError saying what to do.

    Parameters
    ----------
    entry : Entry
        The manifest entry with the expected sha256.
    file : pathlib.Path
        The file to check.

    Returns
    -------
    pathlib.Path
        ``file``, unchanged.

    Raises
    ------
    DataError
        If the file's sha256 differs from ``entry.sha256``.
    """
    digest = sha256_of(file)
    if digest != entry.sha256:
        raise DataError(
            f"{file} does not match its sha256 in data/manifest.toml (expected {entry.sha256}, "
            f"got {digest}): the file is corrupt or a different version; delete it and run "
            f"`thesis-lab data fetch {entry.name}`, or restore ../shared/data/{entry.file}"
        )
    return file


def path(name: str, *, manifest_file: str | Path | None = None) -> Path:
    """Local path of data set ``name`` after checking its sha256.

    Parameters
    ----------
    name : str
        The data set's name in the manifest.
    manifest_file : str or pathlib.Path, optional
        The manifest naming the data set (default: the project's ``data/manifest.toml``).

    Returns
    -------
    pathlib.Path
        The first copy that exists: ``data/<file>`` of the project, else ``../shared/data/<file>``.

    Raises
    ------
    DataError
        If the name is unknown, the entry leads outside ``data/``, no copy exists, or the copy's
        sha256 does not match.
    """
    entry = _entry(name, manifest_file)
    candidates = _candidates(entry)
    for candidate in candidates:
        if candidate.is_file():
            return check(entry, candidate)
    tried = " and ".join(str(c) for c in candidates)
    raise DataError(
        f"data set {name!r} ({entry.file}) is missing: looked in {tried}. Put ../shared beside the "
        f"project, or run `thesis-lab data fetch {name}` to download it from {entry.url}"
    )


def verify(manifest_file: str | Path | None = None, *, names: list[str] | None = None) -> list[tuple[str, str, str]]:
    """Check every manifest entry, or those ``names`` selects (that a copy exists and its sha256 matches).

    Parameters
    ----------
    manifest_file : str or pathlib.Path, optional
        The manifest whose entries are checked (default: the project's, see :func:`manifest`).
    names : list of str, optional
        Check only the entries these select: each is a data set's name, the start of one (``1e``),
        or at least four hex digits that begin an entry's sha256.  By default (None or empty) all.

    Returns
    -------
    list of tuple (str, str, str)
        ``(name, status, detail)`` by name: status ``"ok"`` with the file's path, or ``"error"`` with
        the message of the DataError.

    Raises
    ------
    DataError
        If the manifest itself is missing or malformed, or one of ``names`` selects no entry (the
        message lists the manifest's names).
    """
    entries = manifest(manifest_file)
    rows = []
    for name in _matching(names, entries) if names else sorted(entries):
        try:
            rows.append((name, "ok", str(path(name, manifest_file=manifest_file))))
        except DataError as exc:
            rows.append((name, "error", str(exc)))
    return rows


def fetch(name: str, *, manifest_file: str | Path | None = None, timeout: float = 60.0) -> Path:
    """Download data set ``name`` from its public source into ``data/<file>`` and check its sha256.

    The download goes to a temporary file beside the target and replaces it only once its sha256
    is right: an interrupted or wrong download leaves ``data/`` as it was.  This is the only
    function of thesis-lab that touches the network; it runs only when asked.

    Parameters
    ----------
    name : str
        The data set's name in the manifest.
    manifest_file : str or pathlib.Path, optional
        The manifest with the data set's URL and sha256 (default: the project's).
    timeout : float, default 60.0
        Seconds to wait for the server (``urllib.request.urlopen``).

    Returns
    -------
    pathlib.Path
        The downloaded file, ``data/<file>`` of the project.

    Raises
    ------
    DataError
        If the name is unknown, the entry leads outside ``data/``, the download fails, or its sha256
        does not match.
    """
    entry = _entry(name, manifest_file)
    target = inside(project_root() / "data", entry.file)
    target.parent.mkdir(parents=True, exist_ok=True)
    atomic.clean_stale(target.parent)
    with atomic.replacing(target) as tmp:
        try:
            with urllib.request.urlopen(entry.url, timeout=timeout) as response, open(tmp, "wb") as fh:
                shutil.copyfileobj(response, fh)
        except (OSError, ValueError) as exc:
            raise DataError(f"could not download {name!r} from {entry.url}: {exc}") from None
        check(entry, tmp)
        inside(project_root() / "data", entry.file)  # the folders may have changed meanwhile
    return target


def _path_like(value: str, base: Path) -> bool:
    """Whether a string parameter names a file or folder (a separator, ``~``, or it exists there)."""
    if "/" in value or "\\" in value or value.startswith("~") or value in (".", ".."):
        return True
    try:
        return (base / value).exists()
    except (OSError, ValueError):
        return True


def check_parameter_paths(params: Mapping[str, object], *, base: str | Path) -> None:
    """Refuse parameters that name files outside the project, unless the manifest lists the file.

    A string parameter (or a string in a list parameter) is a path when it holds a separator,
    starts with ``~``, or names something that exists relative to ``base`` (the folder the notebook
    runs in).  Such a path must resolve (symlinks included) inside the project folder, or be a
    file whose sha256 is that of a manifest entry (a copy of a listed data set, e.g. in
    ``../shared/data/``).  Names that are no path (``"1grm"``, a label) are left to the notebook,
    which looks them up through :func:`path`.

    Parameters
    ----------
    params : mapping of str to object
        Resolved parameters of a run.
    base : str or pathlib.Path
        The folder relative paths are read from (the project's ``experiments/``).

    Raises
    ------
    DataError
        Naming the parameter, its value and where it leads.
    """
    root = project_root().resolve()
    base = Path(base)
    listed: dict[tuple[int, str], str] | None = None
    for key, value in params.items():
        for item in value if isinstance(value, (list, tuple)) else [value]:
            if not isinstance(item, str) or not item:
                continue
            if "\x00" in item:
                raise DataError(f"parameter {key} = {item!r} holds a NUL character; refused")
            if not _path_like(item, base):
                continue
            try:
                target = (base / item).resolve()
            except (OSError, RuntimeError, ValueError) as exc:
                raise DataError(f"parameter {key} = {item!r} is not a usable path ({exc}); refused") from None
            if target.is_relative_to(root):
                continue
            if target.is_file():
                if listed is None:
                    listed = {(e.size, e.sha256): name for name, e in manifest().items()}
                size = target.stat().st_size
                if any(s == size for s, _ in listed) and (size, sha256_of(target)) in listed:
                    continue
            raise DataError(
                f"parameter {key} = {item!r} leads to {target}, outside the project {root}, and is no "
                "data set of data/manifest.toml (no entry has its sha256); refused. Put the file inside "
                "the project, or add it to the manifest with its sha256 and give its name"
            )


_PDB_ID = re.compile(r"^[0-9][A-Za-z0-9]{3}$")


def resolve_structure(path_or_name: str | Path) -> Path:
    """Path of a PDB file given as a path or as a 4-character PDB id (``"1grm"``).

    Thesis: §2.2.2 (the coordinates come from the Protein Data Bank).

    Parameters
    ----------
    path_or_name : str or pathlib.Path
        A file path, or a PDB id (a digit and three letters or digits).  An id is looked up through
        :func:`path` (checked by sha256); when the manifest has no
        entry for it, ``../shared/data/pdb/<id>.pdb`` is used.

    Returns
    -------
    pathlib.Path
        An existing file.

    Raises
    ------
    ValueError
        No file at the path, an unknown id, or a data file whose sha256 does not match the manifest.
    """
    if isinstance(path_or_name, Path) or not _PDB_ID.match(str(path_or_name)):
        file = Path(path_or_name)
        if not file.is_file():
            raise ValueError(f"no PDB file at {file}")
        return file
    name = str(path_or_name).lower()
    for key in (name, f"pdb-{name}", f"{name}.pdb"):
        try:
            return path(key)
        except (DataError, FileNotFoundError) as exc:
            if "does not match its sha256" in str(exc):
                raise ValueError(str(exc)) from None
    fallback = shared_dir() / "data" / "pdb" / f"{name}.pdb"
    if fallback.is_file():
        return fallback
    raise ValueError(f"unknown structure {path_or_name!r}: not in data/manifest.toml and no {fallback}")
