"""Start-up cost: import + first call in a fresh process, against the reference libraries; install sizes.

Usage: ``python benchmarks/bench_startup.py [--quick] [--rounds N] [--cases NAME ...] [--output FILE]``
writes ``benchmarks/results/startup.json`` (``startup_quick.json`` with ``--quick``);
``python benchmarks/bench_startup.py --sizes`` writes ``benchmarks/results/startup_sizes.json``.

**Time.**  What a user waits for the first time a script runs one computation: every measurement is
one fresh interpreter (``python -c``), timed from the parent (start to exit).  Three kinds of process
take turns, round after round, so load hits them alike (the harness's interleaved rounds):

* ``baseline`` — ``import numpy, scipy`` and the case's input read with ``np.load`` (the input is
  made once beforehand: no tool pays for making it);
* ``ours`` — the same, then ``import thesis_lib...`` and the first call;
* the peer — the same, then its import and first call.

``ours_s`` and ``<peer>_s`` are medians over rounds of the process's wall time **minus the baseline
process of the same round**: the library's import, its first call (compilation or loading of its
kernels included) and its share of the interpreter's exit.  ``ratio_<peer>`` is the median of the
per-round ratios ours / peer of those differences (below 1: we start faster); ``noise_floor`` is
``RESOLUTION_S`` (0.05 s, what a difference of two fresh processes resolves) over the peer's figure.  Each process also
reports, from inside, its ``import`` and ``first call`` times (``ours_import_s``, ``ours_call_s``,
...: medians).  Before the timed rounds each contender runs once untimed (``warmup_s``: byte-compiled
files and any on-disk kernel cache are written then, as on a user's second run), and its result is
checked against the peer's.  Rounds: 5, or 15 when the slowest first round is under 0.1 s
(``harness.default_rounds``).

Cases:

* ``rips-100`` — ``rips_persistence(X, max_dim=3)`` (H₀–H₂) vs ripser.py ``ripser(X, maxdim=2)``,
  100 uniform random points in the unit cube (seed 0); barcodes equal to 1e-5 (ripser: diameters);
* ``alpha-1000`` — ``persistence(alpha(X))`` vs GUDHI ``AlphaComplex(points=X).create_simplex_tree()``
  + ``persistence()``, 1,000 uniform random points in R³ (seed 0); barcodes equal to 1e-9;
* ``mean-curvature-torus-10k`` — ``mean_curvature(V, F)`` on ``torus_grid(100)`` (10⁴ vertices) vs
  libigl's cotangent Laplacian and Voronoi mass matrix, ‖L V‖ / (2 M) (as ``bench_curvature``);
* ``homology-rp2`` — ``homology(rp2())`` over Z (the thesis's RP², Example 2.21), no peer.

**Sizes** (``--sizes``, needs the package index, takes minutes).  The wheel of this checkout is built
once (``pip wheel``, its CMake folder under ``build/``); a fresh venv under ``build/bench-sizes/``
gets ``numpy scipy`` (the baseline: pip, numpy, scipy); then for the core and for each extra a copy
of that venv gets ``pip install <wheel>[extra]``; a row reports ``du`` of ``site-packages`` minus
the baseline's (``mb``: disk usage, ``apparent_mb``: bytes) and the distributions it added.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import harness

TOPIC = "startup"
SIZES_TOPIC = "startup_sizes"
ROOT = harness.HERE.parent

#: case -> (peer name or None, input maker name)
CASES = {
    "rips-100": "ripser",
    "alpha-1000": "gudhi",
    "mean-curvature-torus-10k": "libigl",
    "homology-rp2": None,
}
FULL = list(CASES)
# make bench-check: the case whose peer's difference is well above the noise of a fresh process;
# mean curvature (libigl 0.15 s) and alpha (GUDHI 0.06 s) are not
QUICK = ["rips-100"]
# What the difference of two fresh processes resolves on a 2-core machine: ours above the baseline
# for rips-100 measured 0.037-0.074 s over four quiet runs on two machines; ratio_<peer> therefore
# carries noise_floor = RESOLUTION_S / <peer>_s, below which bench-check does not count a move
RESOLUTION_S = 0.05
EXTRAS = ("plot", "mesh", "proteins", "lab")

# What each contender imports and calls; ``X`` (or ``V``, ``F``) is the case's input, read before the
# clock of the import starts.  ``SUMMARY`` turns the result into JSON for the check (warm-up only).
CODE = {
    ("rips-100", "ours"): ("from thesis_lib.persistence import rips_persistence",
                           "rips_persistence(X, max_dim=3)"),
    ("rips-100", "ripser"): ("from ripser import ripser", "ripser(X, maxdim=2)"),
    ("alpha-1000", "ours"): ("from thesis_lib.complexes import alpha\nfrom thesis_lib.persistence import persistence",
                             "persistence(alpha(X))"),
    ("alpha-1000", "gudhi"): (
        "import gudhi",
        "(lambda st: (st.persistence(), st)[1])(gudhi.AlphaComplex(points=X).create_simplex_tree())"),
    ("mean-curvature-torus-10k", "ours"): ("from thesis_lib.curvature import mean_curvature", "mean_curvature(V, F)"),
    ("mean-curvature-torus-10k", "libigl"): (
        "import igl",
        "numpy.linalg.norm(-(igl.cotmatrix(V, F) @ V), axis=1)"
        " / (2 * igl.massmatrix(V, F, igl.MASSMATRIX_TYPE_VORONOI).diagonal())"),
    ("homology-rp2", "ours"): ("from thesis_lib.datasets import rp2\nfrom thesis_lib.homology import homology",
                               "homology(rp2())"),
}
SUMMARY = {
    "ours-rips": "[out.intervals(k).tolist() for k in range(3)]",
    "ripser": "[(d / 2).tolist() for d in out['dgms']]",
    "ours-alpha": "[out.intervals(k).tolist() for k in range(3)]",
    "gudhi": "[[list(p) for d, p in out.persistence() if d == k] for k in range(3)]",
    "ours-curvature": "out.tolist()",
    "libigl": "out.tolist()",
    "ours-homology": "out",
}


def _summary_key(case: str, tool: str) -> str:
    if tool != "ours":
        return tool
    return {"rips-100": "ours-rips", "alpha-1000": "ours-alpha", "mean-curvature-torus-10k": "ours-curvature",
            "homology-rp2": "ours-homology"}[case]


def make_inputs(folder: Path) -> dict[str, Path]:
    """The cases' inputs as .npz files in ``folder`` (made once, outside every timing)."""
    import numpy as np

    from thesis_lib.datasets import torus_grid

    paths = {}
    rng = np.random.default_rng(0)
    paths["rips-100"] = folder / "rips-100.npz"
    np.savez(paths["rips-100"], X=rng.random((100, 3)))
    paths["alpha-1000"] = folder / "alpha-1000.npz"
    np.savez(paths["alpha-1000"], X=np.random.default_rng(0).random((1000, 3)))
    V, F = torus_grid(100)
    assert len(V) == 10_000
    paths["mean-curvature-torus-10k"] = folder / "torus-100.npz"
    np.savez(paths["mean-curvature-torus-10k"], V=V, F=F)
    paths["homology-rp2"] = folder / "empty.npz"
    np.savez(paths["homology-rp2"])
    return paths


def child_code(case: str, tool: str, data: Path, summary: bool) -> str:
    """The ``python -c`` program of one measurement (``tool`` "baseline" stops after the input)."""
    lines = [
        "import time",
        "t0 = time.perf_counter()",
        "import json",
        "import numpy, scipy",
        f"_z = numpy.load({str(data)!r})",
        "globals().update({k: _z[k] for k in _z.files})",
        "t1 = time.perf_counter()",
    ]
    if tool != "baseline":
        imports, call = CODE[(case, tool)]
        lines += [*imports.splitlines(), "t2 = time.perf_counter()", f"out = {call}", "t3 = time.perf_counter()"]
        result = "{'base_s': t1 - t0, 'import_s': t2 - t1, 'call_s': t3 - t2}"
    else:
        result = "{'base_s': t1 - t0}"
    lines.append(f"res = {result}")
    if summary and tool != "baseline":
        lines.append(f"res['summary'] = {SUMMARY[_summary_key(case, tool)]}")
    lines.append("print(json.dumps(res))")
    return "\n".join(lines)


def run_process(case: str, tool: str, data: Path, summary: bool = False) -> dict:
    """One fresh interpreter: its wall time (``wall_s``, from the parent) and what it reported."""
    code = child_code(case, tool, data, summary)
    t0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False,
                          cwd=tempfile.gettempdir())
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        raise RuntimeError(f"{case} / {tool} failed (exit {proc.returncode}):\n{proc.stderr[-4000:]}")
    out = json.loads(proc.stdout.strip().splitlines()[-1])
    out["wall_s"] = wall
    return out


def _bars(dims: list) -> list:
    import numpy as np

    out = []
    for d in dims:
        a = np.asarray(d, dtype=float).reshape(-1, 2)
        a = a[a[:, 1] > a[:, 0]]  # positive length only (every tool leaves zero-length bars out, or not)
        out.append(a[np.lexsort((a[:, 1], a[:, 0]))])
    return out


def check(case: str, results: dict) -> str:
    """Every contender computed the same thing (raises otherwise); returns what was compared."""
    import numpy as np

    ours = results["ours"]["summary"]
    if case == "homology-rp2":
        if [tuple(h) for h in ours] != [(1, []), (0, [2]), (0, [])]:
            raise AssertionError(f"homology(rp2()) over Z: {ours}")
        return "H0 = Z, H1 = Z/2, H2 = 0"
    peer = CASES[case]
    theirs = results[peer]["summary"]
    if case == "mean-curvature-torus-10k":
        diff = float(np.nanmax(np.abs(np.asarray(ours) - np.asarray(theirs))))
        if not diff < 1e-9:
            raise AssertionError(f"{case}: mean curvature differs from libigl's by {diff}")
        return f"max |H - H_libigl| = {diff:.1e}"
    tol = 1e-5 if peer == "ripser" else 1e-9  # ripser computes in float32
    a, b = _bars(ours), _bars(theirs)
    for k, (x, y) in enumerate(zip(a, b)):
        finite = np.isfinite(x) & np.isfinite(y) if x.shape == y.shape else None
        if x.shape != y.shape or not np.array_equal(np.isinf(x), np.isinf(y)) or not np.allclose(
                x[finite], y[finite], rtol=0, atol=tol):
            raise AssertionError(f"{case}: H{k} differs from {peer}'s ({len(x)} vs {len(y)} bars)")
    return "bars per dimension " + ", ".join(str(len(x)) for x in a) + f" (equal to {tol:g})"


def make_row(case: str, rounds: int | None, inputs: dict[str, Path]) -> dict:
    """One case: warm-up and check, then interleaved rounds baseline / ours / peer in fresh processes."""
    peer = CASES[case]
    tools = ["ours"] + ([peer] if peer else [])
    data = inputs[case]
    warm = {tool: run_process(case, tool, data, summary=True) for tool in tools}
    compared = check(case, warm)
    run_process(case, "baseline", data)
    runs: dict[str, list[dict]] = {t: [] for t in ["baseline", *tools]}
    n = rounds
    done = 0
    while n is None or done < n:
        for tool in runs:
            runs[tool].append(run_process(case, tool, data))
        done += 1
        if n is None:  # the first timed round sets the count, as harness.compare
            n = harness.default_rounds(max(runs[t][0]["wall_s"] for t in tools))
    above = {t: [r["wall_s"] - b["wall_s"] for r, b in zip(runs[t], runs["baseline"])] for t in tools}
    row = {
        "case": case,
        "peer": peer,
        "baseline_s": statistics.median(r["wall_s"] for r in runs["baseline"]),
        "baseline_import_s": statistics.median(r["base_s"] for r in runs["baseline"]),
    }
    for t in tools:
        key = harness._key(t)
        row[f"{key}_s"] = statistics.median(above[t])
        row[f"{key}_wall_s"] = statistics.median(r["wall_s"] for r in runs[t])
        row[f"{key}_import_s"] = statistics.median(r["import_s"] for r in runs[t])
        row[f"{key}_call_s"] = statistics.median(r["call_s"] for r in runs[t])
    if peer:
        row[f"ratio_{harness._key(peer)}"] = statistics.median(
            x / y if y > 0 else float("nan") for x, y in zip(above["ours"], above[peer]))
        row["noise_floor"] = RESOLUTION_S / row[f"{harness._key(peer)}_s"]
    row.update({
        "rounds": n,
        "warmup_s": {t: warm[t]["wall_s"] for t in tools},
        "times_s": {t: [r["wall_s"] for r in runs[t]] for t in runs},
        "check": compared,
        "ours": CODE[(case, "ours")][1],
        "reference": CODE[(case, peer)][1] if peer else None,
    })
    return row


def _fmt(x, spec: str) -> str:
    return "—" if x is None else format(x, spec)


COLUMNS = [
    ("case", "{case}"),
    ("baseline s", "{baseline_s:.3f}"),
    ("ours s", "{ours_s:.3f}"),
    ("ours import s", "{ours_import_s:.3f}"),
    ("ours call s", "{ours_call_s:.3f}"),
    ("peer", lambda r: r["peer"] or "—"),
    ("peer s", lambda r: _fmt(r.get(f"{r['peer']}_s") if r["peer"] else None, ".3f")),
    ("peer import s", lambda r: _fmt(r.get(f"{r['peer']}_import_s") if r["peer"] else None, ".3f")),
    ("ratio", lambda r: _fmt(r.get(f"ratio_{r['peer']}") if r["peer"] else None, ".2f")),
    ("rounds", "{rounds}"),
]


# ---------------------------------------------------------------------------- install sizes
def _du(folder: Path) -> tuple[float, float]:
    """(disk usage, apparent size) of ``folder`` in MB, as ``du -sk`` and ``du -sb``."""
    def du(flag: str) -> int:
        out = subprocess.run(["du", flag, str(folder)], capture_output=True, text=True, check=True).stdout
        return int(out.split()[0])

    return du("-sk") / 1024, du("-sb") / 2**20


def _site_packages(venv: Path) -> Path:
    out = subprocess.run([str(venv / "bin" / "python"), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                         capture_output=True, text=True, check=True)
    return Path(out.stdout.strip())


def _pip(venv: Path, *args: str) -> None:
    cmd = [str(venv / "bin" / "python"), "-m", "pip", "--disable-pip-version-check", *args]
    print("$", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")


def _installed(venv: Path) -> dict[str, str]:
    out = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "list", "--format=json"],
                         capture_output=True, text=True, check=True)
    return {d["name"].lower(): d["version"] for d in json.loads(out.stdout)}


def sizes(work: Path, keep: bool = False) -> list[dict]:
    """Install sizes of the core and of each extra above numpy + scipy + pip (see the module doc)."""
    meta = harness.environment()
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    wheels = work / "wheel"
    build = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-w", str(wheels),
                            "-C", f"build-dir={work / 'cmake'}", str(ROOT)],
                           capture_output=True, text=True, check=False, cwd=work)
    if build.returncode != 0:
        raise RuntimeError(f"pip wheel of the checkout failed:\n{build.stdout[-3000:]}\n{build.stderr[-3000:]}")
    [wheel] = wheels.glob("thesis_lab-*.whl")
    base = work / "venv-base"
    subprocess.run([sys.executable, "-m", "venv", str(base)], check=True)
    _pip(base, "install", "--quiet", "numpy", "scipy")
    base_disk, base_apparent = _du(_site_packages(base))
    base_dists = _installed(base)
    rows = [{"case": "baseline", "install": "pip install numpy scipy (a fresh venv)", "site_packages_mb": base_disk,
             "site_packages_apparent_mb": base_apparent, "distributions": base_dists}]
    listed = ", ".join(f"{k} {v}" for k, v in sorted(base_dists.items()))
    print(f"baseline: site-packages {base_disk:.1f} MB ({listed})")
    for extra in (None, *EXTRAS):
        name = "core" if extra is None else extra
        venv = work / f"venv-{name}"
        shutil.copytree(base, venv, symlinks=True)
        spec = str(wheel) if extra is None else f"{wheel}[{extra}]"
        _pip(venv, "install", "--quiet", spec)
        disk, apparent = _du(_site_packages(venv))
        dists = _installed(venv)
        added = {k: v for k, v in dists.items() if base_dists.get(k) != v}
        rows.append({
            "case": name,
            "install": f"pip install thesis-lab{'' if extra is None else f'[{extra}]'} (the wheel of this checkout)",
            "mb": disk - base_disk, "apparent_mb": apparent - base_apparent,
            "site_packages_mb": disk, "n_added": len(added), "added": added,
        })
        print(f"{name}: +{disk - base_disk:.1f} MB ({len(added)} distributions)", flush=True)
        if not keep:
            shutil.rmtree(venv)
    rows[0]["wheel"] = wheel.name
    rows[0]["wheel_mb"] = wheel.stat().st_size / 2**20
    if not keep:
        shutil.rmtree(work)
    harness.write_results(SIZES_TOPIC, rows, meta=meta)
    harness.print_table([("install", "{case}"), ("site-packages MB", "{site_packages_mb:.1f}"),
                         ("MB above numpy+scipy", lambda r: _fmt(r.get("mb"), ".1f")),
                         ("apparent MB", lambda r: _fmt(r.get("apparent_mb"), ".1f")),
                         ("distributions added", lambda r: str(r.get("n_added", "—")))], rows)
    return rows


# ---------------------------------------------------------------------------- command line
def main(argv: list[str] | None = None) -> list[dict]:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="the make bench-check cases only")
    ap.add_argument("--rounds", type=int, default=None, help="interleaved rounds (default 5, or 15 under 0.1 s)")
    ap.add_argument("--cases", nargs="+", choices=FULL, default=None, metavar="CASE",
                    help="run only these cases: " + ", ".join(FULL))
    ap.add_argument("--output", default=None, help="JSON file for the rows (default: benchmarks/results)")
    ap.add_argument("--update", action="store_true",
                    help="with --cases: replace (or add) those rows in the stored results")
    ap.add_argument("--sizes", action="store_true",
                    help="instead of timing: install sizes of the core and each extra (results/startup_sizes.json)")
    ap.add_argument("--keep", action="store_true", help="with --sizes: keep the venvs under build/bench-sizes")
    args = ap.parse_args(argv)
    if args.sizes:
        return sizes(ROOT / "build" / "bench-sizes", keep=args.keep)
    if args.update and (not args.cases or args.quick or args.output):
        raise SystemExit("--update needs --cases (and neither --quick nor --output)")
    meta = harness.environment()
    names = args.cases or (QUICK if args.quick else FULL)
    output = args.output or (str(harness.RESULTS / f"{TOPIC}_partial.json") if args.cases and not args.update else None)
    rows: list[dict] = []
    with tempfile.TemporaryDirectory(prefix="bench-startup-") as tmp:
        inputs = make_inputs(Path(tmp))

        def row(name: str) -> dict:
            rows.append(make_row(name, args.rounds, inputs))
            if args.update:
                harness.update_results(TOPIC, rows[-1], meta, order=FULL)
            else:
                harness.write_results(TOPIC, rows, args.quick, output, meta)
            return rows[-1]

        harness.stream_table(COLUMNS, names, row)
    return rows


if __name__ == "__main__":
    main()
