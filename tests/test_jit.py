"""Lazy numba: importing the persistence package does not import numba; the cache goes where it can."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np

from thesis_lib.jit import njit, numba_cache_dir


def test_import_persistence_does_not_import_numba():
    code = ("import sys, thesis_lib, thesis_lib.persistence; "
            "print('numba' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"


def test_lazy_kernels_compile_on_first_call_and_call_each_other():
    @njit(cache=False)
    def inner(x):
        return x + 1

    assert "lazy numba kernel" in repr(inner)
    assert inner(np.int64(1)) == 2
    from thesis_lib.persistence import kernels

    assert kernels.mod_inverse(np.int64(3), np.int64(7)) == 5  # 3 · 5 = 15 = 1 mod 7


def test_cache_folder_when_the_package_is_read_only(tmp_path):
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    assert numba_cache_dir(pkg, {}) is None  # writable: numba's default beside the sources
    os.chmod(pkg, 0o500)
    try:
        if os.access(pkg, os.W_OK):  # running as root: permissions do not bind
            return
        assert numba_cache_dir(pkg, {"XDG_CACHE_HOME": "/c"}) == "/c/thesis-lab/numba"
        assert numba_cache_dir(pkg, {"NUMBA_CACHE_DIR": "/mine"}) is None  # the user's choice wins
    finally:
        os.chmod(pkg, 0o700)


def test_read_only_install_compiles_once_into_the_user_cache(tmp_path):
    """A fresh process with a read-only package folder caches the kernels in the user cache folder."""
    code = ("import os, thesis_lib.jit as j; j.numba_cache_dir = lambda *a, **k: os.environ['TARGET']; "
            "import numpy as np; from thesis_lib.persistence import kernels; "
            "print(kernels.mod_inverse(np.int64(2), np.int64(5)))")
    env = dict(os.environ, TARGET=str(tmp_path / "cache"))
    env.pop("NUMBA_CACHE_DIR", None)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True).stdout
    assert out.strip() == "3"
    assert any(p.suffix in (".nbi", ".nbc") for p in (tmp_path / "cache").rglob("*"))
