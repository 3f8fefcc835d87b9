"""Finding the project from any folder: --project, THESIS_LAB_PROJECT, upward search, the
package's own location; atomic writes and folder swaps; the one Markdown table writer."""

from __future__ import annotations

import os

import pytest
from lab_helpers import make_project

from thesis_lib.lab import atomic, paths
from thesis_lib.lab.paths import ProjectError, project_root
from thesis_lib.lab.tables import markdown_table


@pytest.fixture
def clean_env(monkeypatch):
    monkeypatch.delenv("THESIS_LAB_PROJECT", raising=False)
    return monkeypatch


def test_environment_names_the_project(clean_env, tmp_path):
    clean_env.setenv("THESIS_LAB_PROJECT", str(tmp_path))
    assert project_root() == tmp_path.resolve()
    (tmp_path / "file").write_text("x")
    clean_env.setenv("THESIS_LAB_PROJECT", str(tmp_path / "file"))
    with pytest.raises(ProjectError, match="is a file, not a project folder"):
        project_root()


def test_the_project_is_found_upward_from_the_current_folder(clean_env, tmp_path):
    project = make_project(tmp_path / "copy")  # no git, no install: just the folder
    deep = project / "experiments" / "results" / "toy"
    deep.mkdir(parents=True)
    clean_env.chdir(deep)
    assert project_root() == project.resolve()


def test_outside_any_project_the_installed_one_is_used_or_a_clear_error(clean_env, tmp_path, monkeypatch):
    clean_env.chdir(tmp_path)
    installed = paths.Path(paths.__file__).resolve().parents[2]
    assert project_root() == installed  # an editable install inside a checkout
    monkeypatch.setattr(paths, "is_project", lambda folder: False)
    with pytest.raises(ProjectError, match="pass --project DIR, or set THESIS_LAB_PROJECT=DIR"):
        project_root()


def test_atomic_write_leaves_the_old_file_when_interrupted(tmp_path):
    target = tmp_path / "results.json"
    atomic.write_text(target, "old")
    with pytest.raises(KeyboardInterrupt):
        with atomic.replacing(target) as tmp:
            tmp.write_text("half")
            raise KeyboardInterrupt
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["results.json"]


def test_staging_swaps_a_folder_in_one_step_or_not_at_all(tmp_path):
    dest = tmp_path / "results" / "toy"
    with atomic.staging(dest) as tmp:
        (tmp / "a.txt").write_text("1")
    assert (dest / "a.txt").read_text() == "1"
    with pytest.raises(RuntimeError):
        with atomic.staging(dest) as tmp:
            (tmp / "b.txt").write_text("2")
            raise RuntimeError("the notebook failed")
    assert [p.name for p in dest.iterdir()] == ["a.txt"] and [p.name for p in dest.parent.iterdir()] == ["toy"]
    with atomic.staging(dest) as tmp:
        (tmp / "c.txt").write_text("3")
    assert [p.name for p in dest.iterdir()] == ["c.txt"]


def test_an_interrupted_two_rename_swap_is_recovered(tmp_path):
    dest = tmp_path / "toy"
    dest.mkdir()
    (dest / "a").write_text("old")
    dead = 2**22 + 7  # no such process
    while True:
        try:
            os.kill(dead, 0)
            dead += 1
        except ProcessLookupError:
            break
    os.rename(dest, tmp_path / f".toy.old-{dead}-abcd")  # the process died between the two renames
    atomic.recover(dest)
    assert (dest / "a").read_text() == "old"
    (tmp_path / f".toy.tmp-{dead}-x").mkdir()
    (tmp_path / f".toy.tmp-{os.getpid()}-y").mkdir()
    assert [p.name for p in atomic.clean_stale(tmp_path)] == [f".toy.tmp-{dead}-x"]
    assert (tmp_path / f".toy.tmp-{os.getpid()}-y").exists()  # a live writer's folder is left alone


def test_one_markdown_table_writer():
    md = markdown_table(["a", "b|c"], [[1.23456789, None], ["x|y", "multi\nline"]], digits=3)
    assert md == "| a | b\\|c |\n|---|---|\n| 1.23 |  |\n| x\\|y | multi line |\n"
    with pytest.raises(ValueError, match="2 cells for 1 columns"):
        markdown_table(["a"], [[1, 2]])
