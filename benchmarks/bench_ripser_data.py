"""Rips persistence on Ripser's own benchmark data: thesis_lib against native Ripser 1.2, ripser.py and giotto-ph.

Usage: ``python benchmarks/bench_ripser_data.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``
writes ``benchmarks/results/ripser_data.json`` (``ripser_data_quick.json`` with ``--quick``, ``--output``
or ``ripser_data_partial.json`` with ``--cases``).

**Reference.**  Ripser 1.2 is the C++ program itself (``../shared/tools/ripser-1.2/ripser.cpp``, unchanged),
built when missing into ``build/ripser-1.2/`` of the checkout with ``c++ -std=c++11 -O3 -D NDEBUG`` (``ripser``)
and with ``-D USE_COEFFICIENTS`` as well (``ripser-coeff``, for ``--modulus 3``); ``$CXX`` replaces ``c++``.
The data are the three sets of ``../shared/data/ripser/`` (README there), run with Ripser's own command
lines.  Conventions: Ripser's ``--threshold t`` (a diameter) is our ``max_radius = t / 2``, its ``--dim k``
(the top homology dimension) our ``max_dim = k + 1``; our values are ε = diameter / 2, so our intervals
are doubled before they are compared.

**Barcodes first.**  Before anything is timed, every contender runs once untimed in a fresh process (the
warm-up: byte-compiled files and the file cache, as on a user's second run) and its barcode is compared
with ours, per dimension: the same number of bars, sorted births and sorted deaths equal to a relative
1e-5.  Ripser prints float32 values with 6 significant digits (its stdout is parsed: ``persistence
intervals in dim k:``, then `` [birth,death)``, an empty death infinite); ripser.py and giotto-ph give
float32 diameters.  Every tool leaves zero-length bars out, so ours (float64) are rounded to float32
first and bars whose two ends then coincide are dropped: in float32 they have zero length.

**Whole process** (``<tool>_whole_s``, ``<tool>_peak_mb``).  What a user waits for: a fresh process
that reads the file and computes the barcode — Ripser's binary on the file; for ours and the peers
``python -c`` with ``import numpy``, the file read (``read_lower_distance`` of this file, its source
copied into the program, or ``np.loadtxt`` for the point cloud), the library's import and one call.
Each process is started by a small C launcher (``build/ripser-1.2/peak-rss``, built with Ripser) that
forks, execs, and reads the wall time and ``ru_maxrss`` (KiB) of the child from ``wait4``: a child of the
Python parent itself would report at least the parent's own high-water mark (Linux records the parent's
peak at the exec of a vfork-ed child, its resident set at a fork).  The contenders take turns, round
after round (the harness's interleaved rounds); figures are medians over rounds.

**Warm call** (``<tool>_warm_s``).  In a worker process (``--worker TOOL CASE``, one per round and tool,
:func:`harness.run_worker`) the input is read, one call runs untimed, then the median over up to
``WARM_CALLS`` (5) timed calls of the call alone (as many as fit in ``WARM_BUDGET_S`` = 10 s, at least
one: a call of ten seconds is not noisy); ``<tool>_first_s`` is the median of the untimed first calls,
``<tool>_loaded_mb`` the worker's resident set before its first call (interpreter, numpy, library and
input).  Native Ripser has no warm call: its whole-process figure is the reference of
``ratio_ripser12_warm``.

**Ratios** (ours / peer, below 1: we are faster; medians over rounds of the ratio of one round's two
figures): ``ratio_ripser12_whole`` (whole / whole) and ``ratio_ripser12_warm`` (our warm call / Ripser's
whole process); ``ratio_ripserpy_whole`` and ``ratio_ripserpy_warm`` (whole / whole, warm / warm), and
likewise ``ratio_giotto_1t_*`` and ``ratio_giotto_2t_*`` (giotto-ph with ``n_threads=1`` and ``2``).  Ours
runs with its default threads (every core, used only in the search of apparent pairs); Ripser 1.2 and
ripser.py use one.

Cases (``--cases``):

* ``sphere_3_192`` — 192 points on S³, lower-distance matrix, ``--dim 2`` (our ``max_dim`` 3), Z/2;
* ``o3_1024`` — 1,024 orthogonal 3×3 matrices as points in R⁹, ``--dim 3 --threshold 1.8`` (``max_dim`` 4,
  ``max_radius`` 0.9), Z/2; ours and the peers get the points;
* ``rp2_600`` / ``rp2_600-z3`` — 600 points on RP², lower-distance CSV, ``--dim 2``, over Z/2 and over Z/3
  (``ripser-coeff --modulus 3``); native Ripser and ours only.  A run of Ripser 1.2 takes about 10 s
  here, a round (Ripser, our process, our worker's untimed and timed call) about four times as long.

Rounds: ``harness.default_rounds`` of the slowest whole process of the first round (5, or 15 under
0.1 s), or ``--rounds N``.

On the two smaller cases the peers are ripser.py (``ripser(D, maxdim=k, thresh=t, coeff=p,
distance_matrix=True)``, or the points) and giotto-ph (``ripser_parallel(D, maxdim=k, thresh=t, coeff=p,
metric="precomputed", n_threads=1 or 2)``, or the points).  ``--quick`` (``make bench-check``): only
``sphere_3_192``, whole process and warm call, against Ripser 1.2 only.
"""

from __future__ import annotations

import argparse
import gc
import inspect
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from importlib import metadata
from pathlib import Path

import harness
import numpy as np

TOPIC = "ripser_data"
ROOT = harness.HERE.parent
SHARED = ROOT.parent / "shared"
RIPSER_SOURCE = SHARED / "tools" / "ripser-1.2" / "ripser.cpp"
DATA = SHARED / "data" / "ripser"
BUILD = ROOT / "build" / "ripser-1.2"
RTOL = 1e-5  # Ripser prints float32 values with 6 significant digits
WARM_CALLS = 5  # timed warm calls per worker, at most
WARM_BUDGET_S = 10.0  # ... as many as fit in this time after the untimed call, at least one

#: case -> Ripser's file, format, --dim, --threshold (None: none), --modulus, whether the peers run
CASES = {
    "sphere_3_192": ("sphere_3_192.lower_distance_matrix", "lower-distance", 2, None, 2, True),
    "o3_1024": ("o3_1024.txt", "point-cloud", 3, 1.8, 2, True),
    "rp2_600": ("rp2_600.lower_distance_matrix.csv", "lower-distance", 2, None, 2, False),
    "rp2_600-z3": ("rp2_600.lower_distance_matrix.csv", "lower-distance", 2, None, 3, False),
}
FULL = list(CASES)
QUICK = ["sphere_3_192"]
PEERS = ("ripserpy", "giotto_1t", "giotto_2t")

# The C launcher of every whole-process measurement: fork, exec, wait4 (see the module docstring).
LAUNCHER_SOURCE = r"""
#include <stdio.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: %s REPORT PROGRAM [ARGUMENT...]\n", argv[0]);
        return 2;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    if (pid < 0) { perror("fork"); return 2; }
    if (pid == 0) { execv(argv[2], argv + 2); perror("execv"); _exit(127); }
    int status;
    struct rusage usage;
    if (wait4(pid, &status, 0, &usage) < 0) { perror("wait4"); return 2; }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    FILE *report = fopen(argv[1], "w");
    if (report == NULL) { perror(argv[1]); return 2; }
    fprintf(report, "{\"wall_s\": %.9f, \"maxrss_kib\": %ld, \"exit\": %d}\n",
            (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec), usage.ru_maxrss, code);
    return fclose(report) == 0 ? code : 2;
}
"""


# ---------------------------------------------------------------------------- Ripser's formats
def read_lower_distance(path: str) -> np.ndarray:
    """Ripser's lower-distance format as a dense symmetric float64 matrix.

    The strict lower triangle row by row (the first row empty), values separated by whitespace or
    commas, as Ripser reads it: a flat sequence of m = n (n − 1) / 2 numbers.

    Parameters
    ----------
    path : str
        The file.

    Returns
    -------
    numpy.ndarray, shape (n, n)
        The distances, zero on the diagonal.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> f = pathlib.Path(tempfile.mkdtemp()) / "d.lower_distance_matrix"
    >>> _ = f.write_text("\\n1,\\n2,3,\\n")
    >>> read_lower_distance(str(f)).tolist()
    [[0.0, 1.0, 2.0], [1.0, 0.0, 3.0], [2.0, 3.0, 0.0]]
    """
    import numpy as np

    with open(path) as fh:
        values = np.array(fh.read().replace(",", " ").split(), dtype=np.float64)
    n = (1 + math.isqrt(1 + 8 * values.size)) // 2
    if n * (n - 1) // 2 != values.size:
        raise ValueError(f"{path}: {values.size} values are not a lower triangle (n (n - 1) / 2 for some n)")
    matrix = np.zeros((n, n))
    rows, cols = np.tril_indices(n, -1)
    matrix[rows, cols] = values
    matrix[cols, rows] = values
    return matrix


def parse_ripser_output(text: str) -> list[np.ndarray]:
    """The barcode that Ripser printed: one (m, 2) array of [birth, death) per dimension 0, 1, ...

    Parameters
    ----------
    text : str
        Ripser's stdout: ``persistence intervals in dim k:`` lines, each followed by `` [birth,death)``
        lines (an empty death is infinite); other lines (``value range: ...``) are skipped.

    Returns
    -------
    list of numpy.ndarray
        Per dimension, in the order printed.

    Examples
    --------
    >>> [d.tolist() for d in parse_ripser_output("persistence intervals in dim 0:\\n [0,1.5)\\n [0, )\\n")]
    [[[0.0, 1.5], [0.0, inf]]]
    """
    dims: list[list[tuple[float, float]]] = []
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("persistence intervals in dim "):
            k = int(stripped.removeprefix("persistence intervals in dim ").rstrip(":"))
            if k != len(dims):
                raise ValueError(f"Ripser's output: dimension {k} after {len(dims)} dimensions")
            dims.append([])
        elif stripped.startswith("[") and stripped.endswith(")"):
            if not dims:
                raise ValueError(f"Ripser's output: an interval before any dimension: {line!r}")
            birth, death = stripped[1:-1].split(",")
            dims[-1].append((float(birth), float(death) if death.strip() else math.inf))
    return [np.array(d, dtype=np.float64).reshape(-1, 2) for d in dims]


def as_float32(barcode: list[np.ndarray]) -> list[np.ndarray]:
    """A barcode as a float32 tool sees it: values rounded to float32, bars of zero length then dropped."""
    out = []
    for d in barcode:
        a = np.asarray(d, dtype=np.float64).reshape(-1, 2).astype(np.float32).astype(np.float64)
        out.append(a[a[:, 1] > a[:, 0]])
    return out


def barcode_difference(ours: list[np.ndarray], theirs: list[np.ndarray], *, rtol: float = RTOL) -> str | None:
    """None when two barcodes (lists of (m, 2) arrays per dimension) agree, else what differs.

    Per dimension: the same number of bars of positive length (the others are left out), and the
    sorted births and the sorted deaths equal to the relative tolerance ``rtol`` (infinite deaths
    in the same number).

    Examples
    --------
    >>> a = [np.array([[0.0, 1.0], [0.0, np.inf]])]
    >>> barcode_difference(a, [np.array([[0.0, np.inf], [0.0, 1.000001]])]) is None
    True
    >>> barcode_difference(a, [np.array([[0.0, 1.1], [0.0, np.inf]])])
    'H0: deaths differ (largest relative difference 0.0909)'
    """
    if len(ours) != len(theirs):
        return f"{len(ours)} dimensions against {len(theirs)}"
    for k, (x, y) in enumerate(zip(ours, theirs)):
        x = np.asarray(x, dtype=np.float64).reshape(-1, 2)
        y = np.asarray(y, dtype=np.float64).reshape(-1, 2)
        x, y = x[x[:, 1] > x[:, 0]], y[y[:, 1] > y[:, 0]]
        if len(x) != len(y):
            return f"H{k}: {len(x)} bars against {len(y)}"
        for j, what in ((0, "births"), (1, "deaths")):
            a, b = np.sort(x[:, j]), np.sort(y[:, j])
            finite = np.isfinite(a)
            if not np.array_equal(finite, np.isfinite(b)):
                return f"H{k}: {np.count_nonzero(~finite)} infinite {what} against {np.count_nonzero(~np.isfinite(b))}"
            a, b = a[finite], b[finite]
            if not np.allclose(a, b, rtol=rtol, atol=0.0):
                worst = float(np.max(np.abs(a - b) / np.maximum(np.abs(b), np.finfo(float).tiny)))
                return f"H{k}: {what} differ (largest relative difference {worst:.3g})"
    return None


# ---------------------------------------------------------------------------- builds
def _compiler() -> str:
    cxx = os.environ.get("CXX", "c++")
    path = shutil.which(cxx)
    if path is None:
        raise SystemExit(f"no C++ compiler {cxx!r} on PATH: Ripser 1.2 and the launcher are built with it "
                         "(install g++ or set CXX)")
    return path


def _build(target: Path, command: list[str]) -> Path:
    """Run ``command + [temporary]`` (a compiler call ending in ``-o``), then rename onto ``target``."""
    if target.exists():
        return target
    BUILD.mkdir(parents=True, exist_ok=True)
    tmp = target.with_name(f".{target.name}.{os.getpid()}.tmp")
    print(f"building {target.relative_to(ROOT)}", flush=True)
    proc = subprocess.run([*command, str(tmp)], capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        tmp.unlink(missing_ok=True)
        raise SystemExit(f"building {target.name} failed:\n{proc.stderr[-4000:]}")
    os.replace(tmp, target)
    return target


def build_tools() -> dict[str, Path]:
    """Native Ripser 1.2 (``ripser``, ``ripser-coeff``) and the launcher ``peak-rss``, built when missing."""
    if not RIPSER_SOURCE.is_file() or not DATA.is_dir():
        raise SystemExit(f"Ripser 1.2 or its data are missing: expected {RIPSER_SOURCE} and {DATA} "
                         "(the shared folder beside the checkout)")
    cxx = _compiler()
    flags = [cxx, "-std=c++11", "-O3", "-D", "NDEBUG", str(RIPSER_SOURCE)]
    tools = {
        "ripser": _build(BUILD / "ripser", [*flags, "-o"]),
        "ripser-coeff": _build(BUILD / "ripser-coeff", [*flags[:-1], "-D", "USE_COEFFICIENTS", flags[-1], "-o"]),
    }
    with tempfile.TemporaryDirectory(prefix="peak-rss-") as tmp:
        source = Path(tmp) / "peak-rss.cpp"
        source.write_text(LAUNCHER_SOURCE)
        tools["launcher"] = _build(BUILD / "peak-rss", [cxx, "-O2", str(source), "-o"])
    return tools


# ---------------------------------------------------------------------------- what each contender runs
def ripser_command(name: str, tools: dict[str, Path]) -> list[str]:
    """Native Ripser's command line for case ``name`` (absolute paths)."""
    file, fmt, dim, threshold, modulus, _ = CASES[name]
    cmd = [str(tools["ripser" if modulus == 2 else "ripser-coeff"]), "--format", fmt, "--dim", str(dim)]
    if threshold is not None:
        cmd += ["--threshold", str(threshold)]
    if modulus != 2:
        cmd += ["--modulus", str(modulus)]
    return [*cmd, str(DATA / file)]


def python_code(name: str, tool: str) -> tuple[str, str, str, str]:
    """``(read, imports, call, summary)`` of a Python contender: statements reading the input into
    ``D`` (distances) or ``X`` (points), the library's import, the call (an expression, its result
    ``out``) and the expression of its barcode in diameters (a list per dimension)."""
    file, fmt, dim, threshold, modulus, _ = CASES[name]
    path = str(DATA / file)
    if fmt == "lower-distance":
        read, data = f"D = read_lower_distance({path!r})", "D"
    else:
        read, data = f"X = numpy.loadtxt({path!r})", "X"
    thresh = "numpy.inf" if threshold is None else repr(threshold)
    if tool == "ours":
        radius = "numpy.inf" if threshold is None else repr(threshold / 2)
        arg = "distance_matrix=D" if data == "D" else "X"
        return (read, "from thesis_lib.persistence import rips_persistence",
                f"rips_persistence({arg}, max_radius={radius}, max_dim={dim + 1}, coefficients={modulus})",
                f"[(2 * out.intervals(k)).tolist() for k in range({dim + 1})]")
    if tool == "ripserpy":
        return (read, "from ripser import ripser",
                f"ripser({data}, maxdim={dim}, thresh={thresh}, coeff={modulus}, distance_matrix={data == 'D'})",
                "[d.tolist() for d in out['dgms']]")
    if tool in ("giotto_1t", "giotto_2t"):
        metric = ", metric='precomputed'" if data == "D" else ""
        return (read, "from gph import ripser_parallel",
                f"ripser_parallel({data}, maxdim={dim}, thresh={thresh}, coeff={modulus}{metric}, "
                f"n_threads={tool[-2]})",
                "[d.tolist() for d in out['dgms']]")
    raise ValueError(f"unknown tool {tool!r}")


def child_program(name: str, tool: str, *, summary: bool) -> str:
    """The ``python -c`` program of one whole-process run (printing the barcode as JSON when ``summary``)."""
    read, imports, call, barcode = python_code(name, tool)
    lines = ["from __future__ import annotations", "import math", "import numpy", "",
             inspect.getsource(read_lower_distance), read, imports,
             f"out = {call}"]
    if summary:
        lines += ["import json", f"print(json.dumps({barcode}))"]
    return "\n".join(lines) + "\n"


def tool_names() -> dict[str, str]:
    """Each contender's name as published."""
    def version(dist: str) -> str:
        try:
            return metadata.version(dist)
        except metadata.PackageNotFoundError:
            return "(not installed)"

    return {"ripser12": "Ripser 1.2 (native C++, ripser.cpp -O3)", "ours": f"thesis-lab {version('thesis-lab')}",
            "ripserpy": f"ripser.py {version('ripser')}",
            "giotto_1t": f"giotto-ph {version('giotto-ph')} (n_threads=1)",
            "giotto_2t": f"giotto-ph {version('giotto-ph')} (n_threads=2)"}


# ---------------------------------------------------------------------------- measurements
def whole_process(name: str, tool: str, tools: dict[str, Path], *, summary: bool = False) -> dict:
    """One fresh process of ``tool`` on case ``name`` under the launcher: ``wall_s``, ``peak_mb`` and
    ``stdout`` (Ripser's intervals, or the JSON barcode that a Python contender printed when ``summary``)."""
    if tool == "ripser12":
        argv = ripser_command(name, tools)
    else:
        argv = [sys.executable, "-c", child_program(name, tool, summary=summary)]
    with tempfile.TemporaryDirectory(prefix="bench-ripser-") as tmp:
        report, out = Path(tmp) / "report.json", Path(tmp) / "stdout"
        with open(out, "w") as fh:
            proc = subprocess.run([str(tools["launcher"]), str(report), *argv], stdout=fh, stderr=subprocess.PIPE,
                                  text=True, check=False, cwd=tmp)
        if proc.returncode != 0 or not report.exists():
            raise RuntimeError(f"{name} / {tool} failed (exit {proc.returncode}):\n{proc.stderr[-4000:]}")
        res = json.loads(report.read_text())
        return {"wall_s": res["wall_s"], "peak_mb": res["maxrss_kib"] / 1024, "stdout": out.read_text()}


def worker(tool: str, name: str) -> dict:
    """In a worker process: read the input, one untimed call, then the timed calls (see the module docstring)."""
    read, imports, call, _ = python_code(name, tool)
    scope: dict = {"numpy": np, "read_lower_distance": read_lower_distance}
    exec(read, scope)
    exec(imports, scope)
    run = eval(f"lambda: {call}", scope)
    loaded_mb = harness._status_kb("VmRSS") / 1024
    t0 = time.perf_counter()
    out = run()
    first = time.perf_counter() - t0
    del out
    times = []
    for _ in range(max(1, min(WARM_CALLS, int(WARM_BUDGET_S // first)))):
        gc.collect()
        t0 = time.perf_counter()
        out = run()
        times.append(time.perf_counter() - t0)
        del out
    return {"first_s": first, "times_s": times, "warm_s": statistics.median(times), "loaded_mb": loaded_mb}


def check(name: str, runs: dict[str, dict]) -> str:
    """Every contender's barcode (from its warm-up process) equals ours; raises otherwise."""
    ours = json.loads(runs["ours"]["stdout"])
    seen = as_float32(ours)
    for tool, run in runs.items():
        if tool == "ours":
            continue
        theirs = parse_ripser_output(run["stdout"]) if tool == "ripser12" else json.loads(run["stdout"])
        diff = barcode_difference(seen, theirs)
        if diff is not None:
            raise AssertionError(f"{name}: the barcode of {tool} differs from ours: {diff}")
    counts = ", ".join(str(len(d)) for d in seen)
    peers = "; ".join(tool_names()[t] for t in runs if t != "ours")
    return f"bars per dimension {counts}: {peers} equal to ours (rel {RTOL:g})"


def _paired(a: list[float], b: list[float]) -> float:
    return statistics.median(x / y for x, y in zip(a, b))


def run_case(name: str, rounds: int | None, tools: dict[str, Path], *, peers: bool) -> dict:
    """One row: the barcode check, then interleaved rounds of whole processes and warm workers."""
    file, fmt, dim, threshold, modulus, with_peers = CASES[name]
    contenders = ["ripser12", "ours", *(PEERS if peers and with_peers else ())]
    python = contenders[1:]
    warmup = {tool: whole_process(name, tool, tools, summary=tool != "ripser12") for tool in contenders}
    compared = check(name, warmup)
    whole: dict[str, list[dict]] = {t: [] for t in contenders}
    warm: dict[str, list[dict]] = {t: [] for t in python}
    n = rounds
    done = 0
    while n is None or done < n:
        for tool in contenders:
            whole[tool].append(whole_process(name, tool, tools))
        for tool in python:
            warm[tool].append(harness.run_worker(__file__, tool, name))
        done += 1
        if n is None:  # the first timed round sets the count, as harness.compare
            n = harness.default_rounds(max(whole[t][0]["wall_s"] for t in contenders))
    names = tool_names()
    row: dict = {"case": name, "file": file, "format": fmt, "n_points": int(len(_points_or_distances(name))),
                 "ripser_command": " ".join(["ripser" if modulus == 2 else "ripser-coeff",
                                             *ripser_command(name, tools)[1:-1], file]),
                 "max_radius": None if threshold is None else threshold / 2, "max_dim": dim + 1,
                 "coefficients": modulus, "rounds": n, "check": compared,
                 "tools": {t: names[t] for t in contenders}}
    wall = {t: [r["wall_s"] for r in whole[t]] for t in contenders}
    warm_s = {t: [r["warm_s"] for r in warm[t]] for t in python}
    for tool in contenders:
        row[f"{tool}_whole_s"] = statistics.median(wall[tool])
        row[f"{tool}_peak_mb"] = statistics.median(r["peak_mb"] for r in whole[tool])
        if tool in warm:
            row[f"{tool}_warm_s"] = statistics.median(warm_s[tool])
            row[f"{tool}_first_s"] = statistics.median(r["first_s"] for r in warm[tool])
            row[f"{tool}_loaded_mb"] = statistics.median(r["loaded_mb"] for r in warm[tool])
    row["ratio_ripser12_whole"] = _paired(wall["ours"], wall["ripser12"])
    row["ratio_ripser12_warm"] = _paired(warm_s["ours"], wall["ripser12"])
    for tool in python[1:]:
        row[f"ratio_{tool}_whole"] = _paired(wall["ours"], wall[tool])
        row[f"ratio_{tool}_warm"] = _paired(warm_s["ours"], warm_s[tool])
    row["warmup_s"] = {t: warmup[t]["wall_s"] for t in contenders}
    row["times_s"] = {"whole": wall, "warm": warm_s}
    row["warm_calls"] = {t: [len(r["times_s"]) for r in warm[t]] for t in python}
    return row


def _points_or_distances(name: str) -> np.ndarray:
    file, fmt = CASES[name][:2]
    path = str(DATA / file)
    return read_lower_distance(path) if fmt == "lower-distance" else np.loadtxt(path)


def _fmt(row: dict, key: str, spec: str) -> str:
    return format(row[key], spec) if key in row else "—"


COLUMNS = [
    ("case", "{case}"),
    ("Ripser 1.2 s", "{ripser12_whole_s:.3g}"),
    ("ours s", "{ours_whole_s:.3g}"),
    ("ours warm s", "{ours_warm_s:.3g}"),
    ("ours/Ripser whole", "{ratio_ripser12_whole:.2f}"),
    ("ours warm/Ripser", "{ratio_ripser12_warm:.2f}"),
    ("ours/ripser.py warm", lambda r: _fmt(r, "ratio_ripserpy_warm", ".2f")),
    ("ours/giotto-ph 2t warm", lambda r: _fmt(r, "ratio_giotto_2t_warm", ".2f")),
    ("Ripser MB", "{ripser12_peak_mb:.0f}"),
    ("ours MB", "{ours_peak_mb:.0f}"),
    ("rounds", "{rounds}"),
]


# ---------------------------------------------------------------------------- command line
def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="sphere_3_192 against Ripser 1.2 only (make bench-check)")
    ap.add_argument("--rounds", type=int, default=None,
                    help="interleaved rounds (default 5, or 15 under 0.1 s)")
    ap.add_argument("--cases", nargs="+", choices=FULL, default=None, metavar="CASE",
                    help="run only these cases: " + ", ".join(FULL))
    ap.add_argument("--output", default=None, help="JSON file for the rows (default: benchmarks/results)")
    ap.add_argument("--update", action="store_true",
                    help="with --cases: replace (or add) those rows in the stored results")
    ap.add_argument("--worker", nargs=2, metavar=("TOOL", "CASE"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.worker:
        print(json.dumps(worker(*args.worker)))
        return []
    if args.update and (not args.cases or args.quick or args.output):
        raise SystemExit("--update needs --cases (and neither --quick nor --output)")
    if args.rounds is not None and args.rounds < 1:
        raise SystemExit(f"--rounds must be at least 1, got {args.rounds}")
    tools = build_tools()
    meta = harness.environment()
    names = args.cases or (QUICK if args.quick else FULL)
    output = args.output or (str(harness.RESULTS / f"{TOPIC}_partial.json") if args.cases and not args.update else None)
    rows: list[dict] = []

    def row(name: str) -> dict:
        rows.append(run_case(name, args.rounds, tools, peers=not args.quick))
        if args.update:
            harness.update_results(TOPIC, rows[-1], meta, order=FULL)
        else:
            harness.write_results(TOPIC, rows, args.quick, output, meta)
        return rows[-1]

    harness.stream_table(COLUMNS, names, row)
    return rows


if __name__ == "__main__":
    main(sys.argv[1:])
