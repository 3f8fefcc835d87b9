"""Fuzzing the laboratory's edge: hostile experiment names, parameter values, grids,
shards, command lines, manifests and stored results.  Every call returns a correct value or raises
ValueError/TypeError with a message; never another exception, never a hang (a per-example deadline),
never a write outside the project.  `pytest --fuzz-long` runs 100 times more examples."""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import math
from pathlib import Path

import pytest
from helpers import fuzz_call, fuzz_settings
from hypothesis import given
from hypothesis import strategies as st
from lab_helpers import (
    PAYLOAD,
    root,  # noqa: F401 (the project fixture)
)

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab import data, execute, runner
from thesis_lib.lab.experiments import experiment_parameters, notebook_path, resolve_parameters, run_hash
from thesis_lib.lab.results import ResultsError, load, results_dir
from thesis_lib.lab.sweep import expand_grid, parse_shard

HOSTILE = ["..", ".", "", "/", "../toy", "/etc/passwd", "toy/../toy", "experiments/toy", "toy.ipynb", "to\x00y",
           "~", "$HOME", "toy\n", "ＴＯＹ", "toy ", "-p", "--project", "con", "a" * 300, "../" * 20 + "etc"]
names = st.one_of(st.sampled_from(HOSTILE + ["toy"]), st.text(max_size=30),
                  st.builds(lambda a, b: f"{a}/{b}", st.text(max_size=8), st.text(max_size=8)),
                  st.integers(), st.none(), st.binary(max_size=8), st.lists(st.text(max_size=3), max_size=2))
scalars = st.one_of(st.text(max_size=30), st.integers(), st.integers(min_value=10**300, max_value=10**400),
                    st.floats(allow_nan=True, allow_infinity=True), st.booleans(), st.none(),
                    st.from_regex(r" ?\[?[-+0-9., eEnaif]{0,12}\]? ?", fullmatch=True))
values = st.one_of(scalars, st.lists(scalars, max_size=4),
                   st.dictionaries(st.text(max_size=3), st.integers(), max_size=2),
                   st.tuples(st.integers(), st.integers()))
TOY_KEYS = ["n", "x", "label", "flag", "sizes", "fail", "sleep", "data_name", "output_mb", "work", "output_dir"]
keys = st.one_of(st.sampled_from(TOY_KEYS), st.text(max_size=10))


def _inside(path: Path, folder: Path) -> bool:
    return Path(path).resolve().is_relative_to(folder.resolve())


@fuzz_settings(150)
@given(name=names)
def test_fuzz_experiment_names(root, name):
    ok, path = fuzz_call("runner", notebook_path, name)
    if ok:
        assert name == "toy" and path == (root / "experiments" / "toy.ipynb").resolve()
    ok, folder = fuzz_call("runner", results_dir, name)
    if ok:
        assert folder.parent == root / "experiments" / "results" and folder.name == name
    ok, entry = fuzz_call("data", data.path, name)
    assert not ok or name == "toy-data"


def _well_typed(params: dict, defaults: dict) -> None:
    assert set(params) == set(defaults) - {"output_dir"}
    for key, value in params.items():
        default = defaults[key]
        if isinstance(default, list):
            assert isinstance(value, list) and value and all(type(v) is type(default[0]) for v in value)
        else:
            assert type(value) is type(default), (key, value)
        if isinstance(value, float):
            assert math.isfinite(value)
    json.dumps(params, allow_nan=False)
    assert len(run_hash(params)) == 10


@fuzz_settings(200)
@given(overrides=st.dictionaries(keys, values, max_size=4))
def test_fuzz_parameter_values(root, overrides):
    ok, params = fuzz_call("runner", resolve_parameters, "toy", overrides)
    if ok:
        _well_typed(params, experiment_parameters("toy"))


@fuzz_settings(100)
@given(grid=st.dictionaries(keys, st.lists(values, max_size=3), max_size=2),
       shard=st.one_of(st.none(), st.text(max_size=6), st.tuples(st.integers(-2, 4), st.integers(-2, 4))))
def test_fuzz_grids_and_shards(root, grid, shard):
    ok, points = fuzz_call("runner", expand_grid, "toy", grid)
    if ok:
        hashes = [run_hash(p) for p in points]
        assert len(set(hashes)) == len(hashes) and points  # each point once
        defaults = experiment_parameters("toy")
        for p in points:
            _well_typed(p, defaults)
    ok, part = fuzz_call("runner", parse_shard, shard)
    if ok and part is not None:
        i, n = part
        assert 1 <= i <= n


@fuzz_settings(60)
@given(pairs=st.lists(st.tuples(keys, st.text(max_size=20)), max_size=3),
       name=st.sampled_from(["toy", "../toy", "", "toy/x"]))
def test_fuzz_command_line(root, monkeypatch, pairs, name):
    """`thesis-lab run NAME -p K V ...` exits 0 (a run) or 2 (a clear error), never with a traceback."""
    monkeypatch.setattr(runner, "cancellable",
                        lambda fn, spec, **kw: execute.RunOutput("ok", seconds=0.1, worker="fuzz"))
    argv = ["run", name, "-q"] + [a for k, v in pairs for a in ("-p", k, v)]
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        ok, code = fuzz_call("runner", lab_cli.main, argv)
    assert ok and code in (0, 2), (argv, code, err.getvalue())
    if code == 2:
        assert err.getvalue().startswith("error: ") and "Traceback" not in err.getvalue()
    for folder in (root / "runs").glob("*/*"):
        assert _inside(folder, root / "runs" / "toy")
        if folder.name != "sweeps" and not folder.name.startswith("."):
            json.loads((folder / "params.json").read_text(),
                       parse_constant=lambda c: pytest.fail(f"{c} in params.json"))


FILES = ["x/toy.pdb", "../x", "/etc/passwd", "a/../../b", "x/./toy.pdb", "x//toy.pdb", "link/toy.pdb", "..", ".",
         "", "x\\toy.pdb", "x/toy.pdb\x00", "new/dir/toy.pdb"]


def _toml_value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    return json.dumps(value, ensure_ascii=True)


def _entry(draw_name, file, sha, size, url):
    return {"name": draw_name, "file": file, "sha256": sha, "size": size, "url": url, "origin": "o", "licence": "l"}


entries = st.builds(
    _entry,
    st.one_of(st.sampled_from(["toy", "toy-data", "../x", ""]), st.text(max_size=10)),
    st.one_of(st.sampled_from(FILES), st.text(max_size=15)),
    st.one_of(st.just(hashlib.sha256(PAYLOAD).hexdigest()), st.text(max_size=70), st.integers()),
    st.one_of(st.just(len(PAYLOAD)), st.integers(-5, 10**20), st.text(max_size=3), st.booleans()),
    st.sampled_from(["SOURCE", "ftp://x", "", "file:///nonexistent", "http://"]),
)
manifests = st.one_of(
    st.lists(entries, max_size=3).map(
        lambda items: "".join("[[file]]\n" + "".join(f"{k} = {_toml_value(v)}\n" for k, v in it.items())
                              for it in items)
    ),
    st.text(max_size=80),
    st.binary(max_size=40),
)


def _outside_snapshot(tmp_path: Path, root: Path) -> set[str]:
    data_dir = root / "data"
    return {str(p) for p in tmp_path.rglob("*") if not _inside(p, data_dir) and ".hypothesis" not in p.parts}


@fuzz_settings(200)
@given(text=manifests, name=st.sampled_from(["toy", "toy-data", "../x", ""]))
def test_fuzz_manifests(root, tmp_path, text, name):
    """A hostile manifest never makes `path` read or `fetch` write outside data/."""
    source = tmp_path / "source.pdb"
    source.write_bytes(PAYLOAD)
    outside = tmp_path / "outside"
    outside.mkdir(exist_ok=True)
    link = root / "data" / "link"
    if not link.is_symlink():
        link.symlink_to(outside)
    manifest = tmp_path / "manifest.toml"
    if isinstance(text, str):
        text = text.replace("SOURCE", source.as_uri())
        manifest.write_text(text, errors="surrogateescape")
    else:
        manifest.write_bytes(text)
    before = _outside_snapshot(tmp_path, root)
    ok, entries = fuzz_call("data", data.manifest, manifest)
    if ok:
        for entry in entries.values():  # a relative path with no way up (symlinks are checked where used)
            assert not entry.file.startswith("/") and ".." not in entry.file.split("/")
    ok, path = fuzz_call("data", data.path, name, manifest_file=manifest)
    if ok:
        assert _inside(path, root / "data") or _inside(path, tmp_path / "shared" / "data")
        assert hashlib.sha256(path.read_bytes()).hexdigest() == data.manifest(manifest)[name].sha256
    ok, target = fuzz_call("data", data.fetch, name, manifest_file=manifest, timeout=5)
    if ok:
        assert _inside(target, root / "data") and target.read_bytes() == PAYLOAD
    assert _outside_snapshot(tmp_path, root) == before, "something was written outside data/"


@fuzz_settings(100)
@given(blob=st.one_of(st.binary(max_size=60), st.text(max_size=60).map(str.encode),
                      st.dictionaries(st.text(max_size=5), st.one_of(st.integers(), st.floats(), st.text(max_size=3),
                                                                     st.none(), st.booleans()), max_size=3)
                      .map(lambda d: json.dumps(d).encode())))
def test_fuzz_stored_results(tmp_path, blob):
    (tmp_path / "results.json").write_bytes(blob)
    ok, value = fuzz_call("runner", load, "demo", output_dir=tmp_path)
    if ok:
        assert isinstance(value, dict)
        assert all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value.values())
    else:
        assert isinstance(value, ResultsError)
