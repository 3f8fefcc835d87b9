"""README, CI, pyproject and environment.yml stay consistent with each other."""

from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
import yaml

from thesis_lib.lab.paths import repo_root

ROOT = repo_root()


def _readme_commands() -> list[str]:
    text = (ROOT / "README.md").read_text()
    section = text.split("## The two commands", 1)[1].split("\n## ", 1)[0]
    block = re.search(r"```bash\n(.*?)```", section, re.S).group(1)
    return [line.split("#", 1)[0].strip() for line in block.strip().splitlines()]


def test_readme_has_exactly_two_setup_commands():
    assert _readme_commands() == ["make book", "make test"]


def test_ci_runs_exactly_the_readme_test_command():
    lines = [l for l in (ROOT / ".ci" / "run").read_text().splitlines() if l.strip() and not l.startswith("#")]
    assert lines[-1].strip() == _readme_commands()[1]
    assert all(l.startswith(("set ", "cd ")) for l in lines[:-1])


def test_book_workflow_runs_the_readme_book_command_and_publishes_the_site():
    workflow = yaml.safe_load((ROOT / ".github" / "workflows" / "book.yml").read_text())
    steps = [step for job in workflow["jobs"].values() for step in job.get("steps", [])]
    runs = [step["run"].strip() for step in steps if "run" in step]
    assert _readme_commands()[0] in runs
    uploads = [step for step in steps if step.get("uses", "").startswith("actions/upload-pages-artifact@")]
    assert [u["with"]["path"] for u in uploads] == ["book/_build/html"]
    assert any(step.get("uses", "").startswith("actions/deploy-pages@") for step in steps)
    assert workflow["permissions"]["pages"] == "write" and workflow["permissions"]["id-token"] == "write"


def test_licence_is_an_spdx_expression():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert isinstance(project["license"], str) and project["license"] == cff["license"]
    assert all((ROOT / f).is_file() for f in project.get("license-files", []))


def test_makefile_targets_exist():
    text = (ROOT / "Makefile").read_text()
    for target in ["book", "test", "experiments", "sweep", "bench", "clean", "install"]:
        assert re.search(rf"^{target}:", text, re.M), target


def _requirement(spec: str) -> tuple[str, str]:
    m = re.match(r"\s*([A-Za-z0-9_.\-]+)\s*(.*)", spec)
    return m.group(1).lower().replace("_", "-"), m.group(2).replace(" ", "")


def test_environment_yml_has_the_same_packages_and_floors_as_pyproject():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    wanted = dict(_requirement(s) for s in project["dependencies"] + project["optional-dependencies"]["dev"])
    env = yaml.safe_load((ROOT / "environment.yml").read_text())
    have: dict[str, str] = {}
    for dep in env["dependencies"]:
        if isinstance(dep, dict):
            have.update(_requirement(s) for s in dep["pip"] if not s.startswith("-e"))
        elif not dep.startswith(("python", "pip")):
            name, floor = _requirement(dep)
            have[name] = floor
    assert have == wanted


def test_console_script_and_citation():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["scripts"]["thesis-lab"] == "thesis_lib.lab.cli:main"
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["preferred-citation"]["authors"][0]["family-names"] == "Botnan"
    assert cff["preferred-citation"]["year"] == 2011


def test_readme_library_example_runs_and_prints_what_it_says(capsys):
    text = (ROOT / "README.md").read_text()
    code = re.search(r"```python\n(.*?)```", text, re.S).group(1)
    exec(compile(code, "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert "[(1, []), (0, [2]), (0, [])]" in out
    expected = re.search(r"# (\[\(1, \[\]\), \(0, \[2\]\), \(0, \[\]\)\])", code).group(1)
    assert expected in out


def test_ruff_is_clean():
    """The code base is lint-clean under the project's ruff configuration (pyproject.toml, [tool.ruff])."""
    ruff = shutil.which("ruff", path=str(Path(sys.executable).parent))
    if ruff is None and importlib.util.find_spec("ruff") is None:
        pytest.skip("ruff is not installed (pip install -e '.[dev]')")
    cmd = [ruff] if ruff else [sys.executable, "-m", "ruff"]
    proc = subprocess.run([*cmd, "check", "--no-cache", "--output-format", "concise", "."], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
