"""Atomic writes: nothing a reader can see is ever half-written, and nothing committed is lost.

Files are written to a temporary sibling and renamed over the target (``os.replace``).  A folder is
built in a temporary sibling (:func:`staging`) and swapped with the target in one step: Linux's
``renameat2(RENAME_EXCHANGE)``, or where that is missing two renames with the old folder kept until
the new one is in place (:func:`recover` puts it back if the process died in between).  Temporary
siblings carry the writer's process id, so :func:`clean_stale` removes only those whose writer is gone.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

__all__ = ["replacing", "write_bytes", "write_text", "staging", "replace_dir", "recover", "clean_stale"]

_TMP = ".tmp-"
_OLD = ".old-"


def _sibling(target: Path, kind: str) -> Path:
    return target.parent / f".{target.name}{kind}{os.getpid()}-{os.urandom(4).hex()}"


@contextlib.contextmanager
def replacing(path: str | Path) -> Iterator[Path]:
    """A temporary file path beside ``path``; once the body succeeds it replaces ``path`` in one step.

    If the body raises (or the process dies), ``path`` is left exactly as it was.

    Parameters
    ----------
    path : str or pathlib.Path
        The file to write; its parent folders are created.

    Yields
    ------
    pathlib.Path
        A hidden temporary sibling of ``path`` (named with this process's id) for the body to write;
        it is renamed over ``path`` on success and removed otherwise.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = _sibling(path, _TMP)
    try:
        yield tmp
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)


def write_bytes(path: str | Path, data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (a reader sees the old file or the new one, never a part).

    Parameters
    ----------
    path : str or pathlib.Path
        The file to write; its parent folders are created.
    data : bytes
        The new contents, flushed to disk (``fsync``) before the rename.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    with replacing(path) as tmp:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
    return Path(path)


def write_text(path: str | Path, text: str) -> Path:
    """:func:`write_bytes` of ``text`` encoded as UTF-8.

    Parameters
    ----------
    path : str or pathlib.Path
        As for :func:`write_bytes`.
    text : str
        The new contents.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    return write_bytes(path, text.encode("utf-8"))


def _exchange(a: Path, b: Path) -> bool:
    """Swap two existing paths in one step (Linux renameat2); False where the call is unavailable."""
    libc_name = ctypes.util.find_library("c")
    if not libc_name:
        return False
    libc = ctypes.CDLL(libc_name, use_errno=True)
    fn = getattr(libc, "renameat2", None)
    if fn is None:
        return False
    at_fdcwd, rename_exchange = -100, 2
    if fn(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    err = ctypes.get_errno()
    if err in (22, 38, 95):  # EINVAL, ENOSYS, EOPNOTSUPP: the file system cannot exchange
        return False
    raise OSError(err, os.strerror(err), str(a))


def replace_dir(new: str | Path, target: str | Path) -> None:
    """Put folder ``new`` in place of ``target`` (created or replaced) in one step; ``new`` is consumed.

    Parameters
    ----------
    new : str or pathlib.Path
        The folder with the new contents, on the same file system as ``target``.
    target : str or pathlib.Path
        The folder to create or replace; its old contents are deleted once the new are in place.

    Raises
    ------
    OSError
        If a rename (or ``renameat2``, other than for lack of support) fails.
    """
    new, target = Path(new), Path(target)
    if not target.exists():
        os.rename(new, target)
        return
    if _exchange(new, target):
        shutil.rmtree(new, ignore_errors=True)  # `new` now holds the old contents
        return
    old = _sibling(target, _OLD)
    os.rename(target, old)
    os.rename(new, target)
    shutil.rmtree(old, ignore_errors=True)


def recover(target: str | Path) -> None:
    """Undo an interrupted two-rename :func:`replace_dir`: put the old folder back if ``target`` is gone.

    Parameters
    ----------
    target : str or pathlib.Path
        The folder that was being replaced.  Nothing happens if it exists; otherwise the first (by
        name) ``.old-`` sibling whose writer process is gone is renamed back to it.
    """
    target = Path(target)
    if target.exists():
        return
    for old in sorted(target.parent.glob(f".{target.name}{_OLD}*")):
        if not _writer_alive(old.name):
            os.rename(old, target)
            return


@contextlib.contextmanager
def staging(target: str | Path) -> Iterator[Path]:
    """A fresh temporary folder beside ``target``; on success it replaces ``target`` atomically.

    If the body raises (or the process is interrupted), ``target`` is left exactly as it was and the
    temporary folder is removed.

    Parameters
    ----------
    target : str or pathlib.Path
        The folder to create or replace; its parent folders are created and an interrupted earlier
        replacement is first undone (:func:`recover`).

    Yields
    ------
    pathlib.Path
        An empty hidden temporary folder beside ``target`` for the body to fill.
    """
    target = Path(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    recover(target)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}{_TMP}{os.getpid()}-", dir=target.parent))
    try:
        yield tmp
        replace_dir(tmp, target)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _writer_alive(name: str) -> bool:
    for kind in (_TMP, _OLD):
        if kind in name:
            pid = name.split(kind, 1)[1].split("-", 1)[0]
            if not pid.isdigit():
                return False
            try:
                os.kill(int(pid), 0)
            except ProcessLookupError:
                return False
            except PermissionError:
                return True
            return int(pid) != 0
    return False


def clean_stale(folder: str | Path) -> list[Path]:
    """Remove temporary siblings in ``folder`` left by writers that died.

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder to clean; a missing folder is not an error.

    Returns
    -------
    list of pathlib.Path
        The files and folders removed (hidden ``.tmp-`` siblings whose writer process is gone).
    """
    folder = Path(folder)
    removed = []
    if not folder.is_dir():
        return removed
    for item in folder.iterdir():
        if item.name.startswith(".") and _TMP in item.name and not _writer_alive(item.name):
            if item.is_dir() and not item.is_symlink():
                shutil.rmtree(item, ignore_errors=True)
            else:
                item.unlink(missing_ok=True)
            removed.append(item)
    return removed
