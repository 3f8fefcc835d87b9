"""Helpers shared by the tests (imported as ``from helpers import ...``; pytest puts tests/ on sys.path)."""

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


# ---------------------------------------------------------------------------- fuzz tests (issue 11.3)
import collections as _collections
import contextlib as _contextlib
import os as _os
import signal as _signal

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
