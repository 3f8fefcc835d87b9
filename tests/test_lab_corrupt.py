"""The laboratory on hostile state: a folder that is not a project, path parameters that
lead out of the project, corrupt run folders and stored results, a full disk.

Runs here execute no kernel: ``execute`` is replaced by a stub that returns the toy's outputs, so
each test checks the runner's reading and writing of run folders, not the notebook.
"""

from __future__ import annotations

import errno
import hashlib
import json
import os

import pytest
from lab_helpers import PAYLOAD, TOY_RESULTS, root  # noqa: F401 (the project fixture)

from thesis_lib.lab import atomic, execute, runner, sweep
from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab.data import DataError
from thesis_lib.lab.paths import PROJECT_ENV, project_root
from thesis_lib.lab.results import ResultsError, load

CALLS: list[dict] = []


@pytest.fixture
def stub(monkeypatch):
    """``execute`` returns the toy's results without a kernel; the calls are counted."""
    CALLS.clear()

    def fake(spec, *args, **kwargs):
        CALLS.append(dict(spec.params))
        body = json.dumps({**TOY_RESULTS, "square": int(spec.params["n"]) ** 2}).encode()
        return execute.RunOutput("ok", seconds=0.25, worker="stub", files={"results.json": body})

    monkeypatch.setattr(runner, "execute", fake)
    monkeypatch.setattr(sweep, "execute", fake)
    return CALLS


# ----------------------------------------------------------------------------- --project
@pytest.mark.parametrize("kind", ["missing", "empty", "file", "half"])
def test_project_that_is_not_a_project_is_an_error(tmp_path, capsys, kind):
    """`--project` on a folder that is no project is an error (exit 2) saying why, never an empty report."""
    folder = tmp_path / "not-a-project"
    if kind == "empty":
        folder.mkdir()
    elif kind == "file":
        folder.write_text("x")
    elif kind == "half":
        (folder / "experiments").mkdir(parents=True)
    for argv in (["report"], ["report", "--json"], ["list"], ["run", "toy"]):
        assert lab_cli.main(["--project", str(folder), *argv]) == 2
        err = capsys.readouterr().err
        why = {"missing": "does not exist", "file": "is not a folder"}.get(
            kind, "has no experiments/ and data/manifest.toml")
        assert err.startswith(f"error: --project {str(folder)!r} is not a thesis-lab project: it {why}")


def test_project_that_is_a_project_still_works(root, capsys):
    assert lab_cli.main(["--project", str(root), "list"]) == 0
    assert capsys.readouterr().out.startswith("toy: n=3")


def test_project_is_named_for_the_command_only(root, tmp_path, monkeypatch, capsys):
    """--project names the project while its command runs, then the environment is as it was: a later
    caller in the same process (a test that names another folder) is not sent to this project."""
    monkeypatch.delenv(PROJECT_ENV, raising=False)
    assert lab_cli.main(["--project", str(root), "list"]) == 0
    assert PROJECT_ENV not in os.environ
    monkeypatch.setenv(PROJECT_ENV, str(tmp_path))
    assert lab_cli.main(["--project", str(root), "list"]) == 0
    assert os.environ[PROJECT_ENV] == str(tmp_path)
    assert capsys.readouterr().out.count("toy: n=3") == 2


# ----------------------------------------------------------------------------- path parameters
def test_path_parameters_outside_the_project_are_refused(root, tmp_path, stub, capsys):
    """A path parameter that leads outside the project (`run proteins -p rings_structure
    ../../../../outside/evil.pdb`), with no manifest entry and no sha256, is refused before any run."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "evil.pdb").write_bytes(b"ATOM evil\n")
    (root.parent / "link").symlink_to(outside)
    (root / "experiments" / "sneaky").symlink_to(outside)  # inside by name, outside once resolved
    relative = "../" * (len((root / "experiments").parts) - 1) + str(outside / "evil.pdb").lstrip("/")
    for value in (str(outside / "evil.pdb"), relative, "../../outside/evil.pdb", "sneaky/evil.pdb", "/etc",
                  "../../link/evil.pdb", str(outside)):
        with pytest.raises(DataError, match=r"parameter label = .* outside the project .* refused"):
            runner.run("toy", {"label": value})
        assert lab_cli.main(["run", "toy", "-p", "label", value]) == 2
        assert "outside the project" in capsys.readouterr().err
        with pytest.raises(DataError, match="outside the project"):
            sweep.sweep("toy", {"label": ["a", value]}, progress=False)
    assert stub == [] and not (root / "runs" / "toy").exists()
    with pytest.raises(DataError, match="NUL"):
        runner.run("toy", {"label": "a\x00b"})


def test_path_parameters_inside_the_project_or_listed_by_sha256_are_kept(root, tmp_path, stub):
    copy = tmp_path / "elsewhere" / "copy.pdb"
    copy.parent.mkdir()
    copy.write_bytes(PAYLOAD)  # the toy data set's bytes: its sha256 is in the manifest
    assert hashlib.sha256(copy.read_bytes()).hexdigest() in (root / "data" / "manifest.toml").read_text()
    for value in ("a", "1grm", "../data/x/toy.pdb", str(root / "data" / "x" / "toy.pdb"), str(copy), "x/y"):
        assert runner.run("toy", {"label": value}).status == "ok"
    assert len(stub) == 6


def test_the_proteins_experiment_refuses_a_structure_outside_the_project(tmp_path, monkeypatch, capsys):
    """On the real project: a structure outside it is refused before any kernel starts."""
    evil = tmp_path / "evil.pdb"
    evil.write_text("ATOM      1  N   GLY A   1      0.0 0.0 0.0\n")
    monkeypatch.setattr(runner, "execute", lambda *a, **k: pytest.fail("a kernel started"))
    project = project_root()
    for value in (str(evil), "../" * 12 + str(evil).lstrip("/")):
        assert lab_cli.main(["--project", str(project), "run", "proteins", "-p", "rings_structure", value]) == 2
        err = capsys.readouterr().err
        assert err.startswith("error: parameter rings_structure = ") and "outside the project" in err


# ----------------------------------------------------------------------------- corrupt run folders
CORRUPT = {
    "results-list": ("results.json", "[1, 2]\n", "must hold a flat JSON object of numbers, got a list"),
    "results-huge-int": ("results.json", '{"a": ' + "7" * 5000 + "}\n", "holds a number that cannot be read"),
    "results-deep": ("results.json", "[" * 100_000 + "]" * 100_000, "nested too deeply"),
    "results-dir": ("results.json", None, "is a folder, not a file"),
    "results-string": ("results.json", '{"a": "x"}', "'a' is a str"),
    "results-float-range": ("results.json", '{"a": 1' + "0" * 400 + "}", "beyond the float range"),
    "complete-garbage": ("complete.json", "\x00garbage{", "is not valid JSON"),
    "complete-list": ("complete.json", "[]", "must hold a JSON object, got a list"),
    "complete-seconds": ("complete.json", '{"seconds": "fast", "worker": "w"}', "'seconds' must be a number"),
    "complete-seconds-null": ("complete.json", '{"seconds": null}', "'seconds' must be a number"),
    "complete-worker": ("complete.json", '{"seconds": 1, "worker": [1]}', "'worker' and 'error' must be strings"),
    "complete-dir": ("complete.json", None, "is a folder, not a file"),
    "failed-garbage": ("failed.json", "{", "is not valid JSON"),
}


def _spoil(path, file, text):
    target = path / file
    if file == "failed.json":
        (path / "complete.json").unlink()
    if target.is_dir():
        return
    target.unlink(missing_ok=True)
    if text is None:
        target.mkdir()
    else:
        target.write_text(text)


@pytest.mark.parametrize("case", sorted(CORRUPT))
def test_corrupt_run_folders_are_reported_and_run_again(root, stub, capsys, case):
    """run and sweep name what is wrong with such a run folder (no traceback) and run it again."""
    file, text, message = CORRUPT[case]
    first = runner.run("toy")
    _spoil(first.path, file, text)
    read = runner.read_run("toy", first.params)
    assert read.status == "corrupt" and message in read.error and file in read.error
    assert lab_cli.main(["run", "toy"]) == 0
    captured = capsys.readouterr()
    assert f"corrupt run folder {first.path}: " in captured.err and message in captured.err
    assert "Traceback" not in captured.err and captured.out.startswith("ok: ")
    assert runner.read_run("toy", first.params).status == "ok" and len(stub) == 2  # run again, repaired
    _spoil(first.path, file, text)
    assert lab_cli.main(["sweep", "toy", "-p", "n", "3", "4", "-q"]) == 0
    captured = capsys.readouterr()
    assert f"corrupt run folder {first.path}: " in captured.err and "Traceback" not in captured.err
    assert len(stub) == 4 and runner.read_run("toy", first.params).results["square"] == 9
    _spoil(first.path, file, text)
    assert lab_cli.main(["collect", "toy", "-p", "n", "3", "4"]) == 1  # nothing is run: it says so
    captured = capsys.readouterr()
    assert "1 corrupt" in captured.err and message in captured.err and len(stub) == 4


def test_a_notebook_writing_unusable_results_is_a_failed_run(root, monkeypatch):
    monkeypatch.setattr(runner, "execute", lambda spec, **kw: execute.RunOutput(
        "ok", seconds=1.0, files={"results.json": b"[1]"}))
    result = runner.run("toy")
    assert result.status == "failed" and "the notebook wrote an unusable results.json" in result.error
    assert not (result.path / "complete.json").exists()
    assert runner.read_run("toy", result.params).status == "failed"


# ----------------------------------------------------------------------------- stored results (report)
@pytest.mark.parametrize("case", [c for c in sorted(CORRUPT) if c.startswith("results")])
def test_corrupt_stored_results_are_named_by_load_and_the_report(root, capsys, case):
    """`load` and `report` name a results.json that is a folder, nested 10⁵ deep or holds a 5,000-digit
    integer (no traceback)."""
    _, text, message = CORRUPT[case]
    folder = root / "experiments" / "results" / "toy"
    folder.mkdir(parents=True)
    if text is None:
        (folder / "results.json").mkdir()
    else:
        (folder / "results.json").write_text(text)
    with pytest.raises(ResultsError, match="results.json") as info:
        load("toy")
    assert message in str(info.value) and "restore it" in str(info.value)
    claims = root / "experiments" / "claims"
    claims.mkdir()
    (claims / "toy.toml").write_text('[[claim]]\nid = "toy-square"\nwhere = "Example 1.1"\nthesis = 9\n'
                                     'result = "toy:square"\ncompare = "eq"\nprovenance = "computed"\n')
    for argv in (["report"], ["report", "--json"]):
        assert lab_cli.main(argv) == 2
        err = capsys.readouterr().err
        assert err.startswith("error: ") and str(folder / "results.json") in err and message in err


# ----------------------------------------------------------------------------- a full disk
def _full_disk(monkeypatch):
    real = atomic.staging

    import contextlib

    @contextlib.contextmanager
    def staging(dest):
        with real(dest) as tmp:
            yield tmp
            raise OSError(errno.ENOSPC, "No space left on device", str(tmp / "results.json"))

    monkeypatch.setattr(atomic, "staging", staging)


def test_a_full_disk_says_nothing_was_written_or_marked_complete(root, stub, monkeypatch, capsys):
    """On a full disk run and sweep say that nothing was written or marked complete (no `OSError: [Errno 28]`
    traceback)."""
    kept = runner.run("toy", {"n": 5})
    _full_disk(monkeypatch)
    for argv in (["run", "toy"], ["sweep", "toy", "-p", "n", "5", "6", "-q"]):
        assert lab_cli.main(argv) == 1
        err = capsys.readouterr().err
        assert err.startswith("error: no space left on the device writing ") and "Traceback" not in err
        assert "nothing of this step was written or marked complete" in err
    names = sorted(p.name for p in (root / "runs" / "toy").iterdir())
    assert names == [kept.path.name]  # no half-written run folder, the complete one kept
    assert runner.read_run("toy", kept.params).status == "ok"


def test_other_os_errors_are_not_disguised_as_a_full_disk(root, stub, monkeypatch):
    def boom(*a, **k):
        raise PermissionError(errno.EACCES, "Permission denied")

    monkeypatch.setattr(runner, "write_run", boom)
    with pytest.raises(PermissionError):
        lab_cli.main(["run", "toy"])

