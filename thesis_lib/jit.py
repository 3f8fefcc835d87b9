"""numba compilation on first use: ``from thesis_lib.jit import njit`` instead of ``numba.njit``.

``import thesis_lib.persistence`` should not pay for importing numba (about a third of a second)
when only the thesis's pure-Python Algorithms 1–2 or a barcode are wanted.  :func:`njit` returns a
proxy; on its first call numba is imported, every proxy in the defining module (and, as they are
compiled, in the modules they call into) is replaced by its numba dispatcher, and the call goes on
compiled.  Compiled code is cached on disk (``cache=True``) in numba's ``__pycache__`` beside the
source, or — when the installed package is read-only — in a per-user folder
(``$XDG_CACHE_HOME/thesis-lab/numba``, default ``~/.cache/thesis-lab/numba``), so that no process
pays the first compilation twice.  ``NUMBA_CACHE_DIR`` set by the user always wins.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable, Mapping
from pathlib import Path
from types import ModuleType
from typing import Any

__all__ = ["njit", "prange", "numba_cache_dir", "load_numba"]

_done_modules: set[int] = set()


def numba_cache_dir(package_dir: str | os.PathLike | None = None,
                    environ: Mapping[str, str] | None = None) -> str | None:
    """The folder numba should cache compiled kernels in.

    Parameters
    ----------
    package_dir : str or os.PathLike, optional
        The folder of the compiled sources; None: the installed ``thesis_lib`` package.
    environ : mapping of str to str, optional
        The environment to read ``NUMBA_CACHE_DIR`` and ``XDG_CACHE_HOME`` from; None: ``os.environ``.

    Returns
    -------
    str or None
        None (numba's default, beside the sources) when ``package_dir`` is writable or the user set
        ``NUMBA_CACHE_DIR``, else the per-user folder ``$XDG_CACHE_HOME/thesis-lab/numba`` (default
        ``~/.cache/thesis-lab/numba``).
    """
    env = os.environ if environ is None else environ
    if env.get("NUMBA_CACHE_DIR"):
        return None
    pkg = Path(package_dir) if package_dir is not None else Path(__file__).resolve().parent
    if os.access(pkg, os.W_OK):
        return None
    base = Path(env.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return str(base / "thesis-lab" / "numba")


def load_numba() -> ModuleType:
    """Import numba with the cache folder of :func:`numba_cache_dir` in force.

    Sets ``NUMBA_CACHE_DIR`` (unless the user did) when the package folder is read-only.

    Returns
    -------
    types.ModuleType
        The ``numba`` module.
    """
    import sys

    folder = numba_cache_dir()
    if folder is not None:
        os.environ.setdefault("NUMBA_CACHE_DIR", folder)
        if "numba" in sys.modules:  # imported already by someone else: point its config there too
            sys.modules["numba"].config.CACHE_DIR = folder
    import numba

    return numba


def prange(*args: int) -> range:
    """``numba.prange`` for lazily compiled kernels: ``from thesis_lib.jit import prange``.

    A plain ``range`` until numba is loaded; when a module's kernels are compiled, :func:`njit`'s proxy
    replaces this name in the module by ``numba.prange`` (so that importing the module does not import
    numba, and the loop is parallel once compiled with ``parallel=True``).

    Parameters
    ----------
    *args : int
        As for ``range``: ``stop``, or ``start, stop[, step]``.

    Returns
    -------
    range
        ``range(*args)``.
    """
    return range(*args)


def _materialize(module_globals: dict) -> None:
    """Replace every lazy kernel of a module's namespace by its numba dispatcher (once per module)."""
    key = id(module_globals)
    if key in _done_modules:
        return
    _done_modules.add(key)
    numba = load_numba()
    if module_globals.get("prange") is prange:  # the kernels' parallel loops become numba's
        module_globals["prange"] = numba.prange
    for name, obj in list(module_globals.items()):
        if isinstance(obj, _LazyKernel):
            module_globals[name] = obj.dispatcher()


class _LazyKernel:
    """A function to be compiled by ``numba.njit(**options)`` when first called."""

    def __init__(self, fn, options: dict):
        self.fn, self.options, self._dispatcher = fn, options, None
        functools.update_wrapper(self, fn)

    def dispatcher(self):
        if self._dispatcher is None:
            numba = load_numba()
            self._dispatcher = numba.njit(**self.options)(self.fn)
            _materialize(self.fn.__globals__)  # the kernels it calls must be dispatchers too
        return self._dispatcher

    def __call__(self, *args, **kwargs):
        return self.dispatcher()(*args, **kwargs)

    def __repr__(self) -> str:
        return f"<lazy numba kernel {self.fn.__module__}.{self.fn.__qualname__}>"


def njit(fn: Callable[..., Any] | None = None,
         **options: Any) -> _LazyKernel | Callable[[Callable[..., Any]], _LazyKernel]:
    """``numba.njit`` compiled on first call (``@njit(cache=True)`` or ``@njit``).

    Parameters
    ----------
    fn : callable, optional
        The Python function to compile; None when used as ``@njit(**options)``.
    **options : Any
        Passed to ``numba.njit`` when the kernel is first called (``cache``, ``parallel``,
        ``inline``, ...).

    Returns
    -------
    _LazyKernel or callable
        The lazy kernel standing in for ``fn`` (called like it), or, without ``fn``, a decorator
        that makes one.
    """
    if fn is None:
        return lambda f: _LazyKernel(f, options)
    return _LazyKernel(fn, options)
