"""Helpers shared by the tests (imported as ``from helpers import ...``; pytest puts tests/ on sys.path)."""

import collections as _collections
import contextlib as _contextlib
import os as _os
import signal as _signal

import numpy as np
from sympy import Matrix
from sympy.matrices.normalforms import invariant_factors

# M_2 of Example 2.21, rows ab ac ad ae af bc bd be bf cd ce cf de df ef,
# columns abd adf afc bcd ced cae abe bfe bcf def (copied from the thesis).
THESIS_M2 = np.array(
    [
        [1, 0, 0, 0, 0, 0, 1, 0, 0, 0],
        [0, 0, -1, 0, 0, -1, 0, 0, 0, 0],
        [-1, 1, 0, 0, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 0, 1, -1, 0, 0, 0],
        [0, -1, 1, 0, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 1, 0, 0, 0, 0, 1, 0],
        [1, 0, 0, -1, 0, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 0, 0, 1, -1, 0, 0],
        [0, 0, 0, 0, 0, 0, 0, 1, -1, 0],
        [0, 0, 0, 1, -1, 0, 0, 0, 0, 0],
        [0, 0, 0, 0, 1, -1, 0, 0, 0, 0],
        [0, 0, -1, 0, 0, 0, 0, 0, 1, 0],
        [0, 0, 0, 0, -1, 0, 0, 0, 0, 1],
        [0, 1, 0, 0, 0, 0, 0, 0, 0, -1],
        [0, 0, 0, 0, 0, 0, 0, -1, 0, 1],
    ],
    dtype=np.int64,
)


def sympy_invariants(a) -> list[int]:
    """Reference: the nonzero invariant factors of an integer matrix (absolute values), from sympy."""
    a = np.asarray(a, dtype=object)
    if a.size == 0:
        return []
    return [abs(int(x)) for x in invariant_factors(Matrix(a.tolist())) if x != 0]


_PARI = []


def pari_invariants(a) -> list[int]:
    """Reference: the nonzero invariant factors (ascending) from PARI's ``matsnf`` (cypari2)."""
    if not _PARI:
        import cypari2

        pari = cypari2.Pari()
        pari.allocatemem(10**8, 2 * 10**9, silent=True)
        _PARI.append(pari)
    pari = _PARI[0]
    rows = np.asarray(a, dtype=object)
    if rows.size == 0:
        return []
    text = "[" + ";".join(",".join(str(int(x)) for x in row) for row in rows) + "]"
    return sorted(abs(int(x)) for x in pari.matsnf(pari(text)) if x != 0)


# ---------------------------------------------------------------------------- fuzz tests

#: outcomes of fuzzed calls per module, printed at the end of the run (conftest.py)
FUZZ_TALLY: dict = _collections.defaultdict(_collections.Counter)


def fuzz_long() -> bool:
    """Whether pytest runs with ``--fuzz-long`` (conftest.py sets the variable in every process)."""
    return _os.environ.get("THESIS_LAB_FUZZ_LONG") == "1"


def fuzz_settings(n: int, **kw):
    """hypothesis settings for a fuzz test: ``n`` examples (derandomized: the same in every run), or
    ``100 * n`` random ones with ``--fuzz-long``.  Hangs are caught by :func:`fuzz_call`'s deadline."""
    from hypothesis import HealthCheck, settings

    long = fuzz_long()
    return settings(
        max_examples=100 * n if long else n,
        deadline=None,
        derandomize=not long,
        suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                               HealthCheck.filter_too_much, HealthCheck.data_too_large],
        **kw,
    )


class Hang(BaseException):
    """A fuzzed call ran past its deadline (BaseException: the code under test cannot swallow it)."""


@_contextlib.contextmanager
def deadline(seconds: float):
    """Interrupt the body with :class:`Hang` after ``seconds`` of wall time (main thread only)."""
    def on_alarm(signum, frame):
        raise Hang(f"no answer within {seconds} s")

    previous = _signal.signal(_signal.SIGALRM, on_alarm)
    _signal.setitimer(_signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        _signal.setitimer(_signal.ITIMER_REAL, 0)
        _signal.signal(_signal.SIGALRM, previous)


def fuzz_call(module: str, fn, *args, seconds: float = 30.0, **kwargs):
    """Call ``fn`` on a (hostile) input: return ``(True, value)``, or ``(False, error)`` when it raised
    ValueError or TypeError with a message.  Any other exception, an empty message or running past
    ``seconds`` is counted under ``module`` and fails the test."""
    tally = FUZZ_TALLY[module]
    tally["tried"] += 1
    try:
        with deadline(seconds):
            value = fn(*args, **kwargs)
    except Hang:
        tally["hang"] += 1
        raise AssertionError(f"{module}: {getattr(fn, '__name__', fn)} hung on {args!r} {kwargs!r}") from None
    except (ValueError, TypeError) as exc:
        if not str(exc).strip():
            tally["crash"] += 1
            raise AssertionError(f"{module}: {type(exc).__name__} without a message on {args!r}") from exc
        tally["error"] += 1
        return False, exc
    except BaseException:
        tally["crash"] += 1
        raise
    tally["value"] += 1
    return True, value


def claims_of(name: str) -> list[dict]:
    """The ``[[claim]]`` tables of ``experiments/claims/<name>.toml``."""
    import tomllib

    from thesis_lib.lab.paths import project_root

    with open(project_root() / "experiments" / "claims" / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)["claim"]


def page_labels(page: str) -> set[str]:
    """The MyST labels of a book page: ``(label)=`` targets and ``:name:`` options of its Markdown cells."""
    import re

    import nbformat

    from thesis_lib.lab.paths import project_root

    nb = nbformat.read(project_root() / "book" / f"{page}.ipynb", as_version=4)
    text = "\n".join(c.source for c in nb.cells if c.cell_type == "markdown")
    return set(re.findall(r"^\(([\w-]+)\)=\s*$", text, re.M)) | set(re.findall(r"^:name:\s*([\w-]+)\s*$", text, re.M))


def check_claim_file(name: str) -> None:
    """Every claim of ``experiments/claims/<name>.toml`` has a provenance and a link to a label of its
    book page, and (for an experiment) none compares one of the experiment's input parameters."""
    from thesis_lib.lab import runner
    from thesis_lib.lab.report import PROVENANCES

    params = set(runner.experiment_parameters(name)) if name in runner.list_experiments() else set()
    for claim in claims_of(name):
        assert claim.get("provenance") in PROVENANCES, claim["id"]
        page, _, label = claim["link"].partition("#")
        assert label in page_labels(page), f"{claim['id']}: no label {label!r} on book/{page}.ipynb"
        results = claim.get("result", [])
        for ref in results if isinstance(results, list) else [results]:
            experiment, key = ref.split(":", 1)
            assert experiment != name or key not in params, f"{claim['id']} compares the parameter {key!r} of {name}"


def rips_engine_options(max_dim: int, p: int, dense: bool, n_threads: int, parallel_min: int, cocycles: bool = False):
    """The compiled Rips engine's options (``thesis_lib._core.implicit_rips.Options``) with these fields."""
    from thesis_lib._core import implicit_rips

    options = implicit_rips.Options()
    options.max_dim, options.p, options.dense, options.n_threads = max_dim, p, dense, n_threads
    options.parallel_min, options.cocycles = parallel_min, cocycles
    return options


def facet_signs(k: int) -> np.ndarray:
    """The signs of a k-simplex's facets in its boundary: the facet omitting vertex i has (−1)^i."""
    return 1 - 2 * (np.arange(k + 1) & 1)


def simplex_vector(K, k: int, rows: np.ndarray) -> np.ndarray:
    """A chain or cochain in ripser.py's row format (vertices in any order, then the coefficient) as a
    vector on the k-simplices of the filtration K."""
    index = {tuple(s): i for i, s in enumerate(K.simplices[k].tolist())}
    c = np.zeros(len(index), dtype=np.int64)
    for row in rows.tolist():
        c[index[tuple(sorted(row[:-1]))]] = row[-1]
    return c


def check_every_bar(barcode, representatives, dims, check) -> int:
    """``check(k, bar, representative)`` on every bar of the dimensions ``dims``, after checking that
    there is one representative per bar; the number of bars checked."""
    count = 0
    for k in dims:
        bars = barcode.intervals(k)
        assert len(representatives[k]) == bars.shape[0]
        for bar, representative in zip(bars, representatives[k]):
            check(k, bar, representative)
            count += 1
    return count
