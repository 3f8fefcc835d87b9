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

from thesis_lib.lab.paths import project_root

ROOT = project_root()


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


#: what environment.yml adds for building the compiled core and pip cannot: the C++ compiler, and CMake
#: and Ninja as conda packages (pip users take the system's compiler; scikit-build-core fetches CMake
#: and Ninja from PyPI when the machine has none)
CONDA_BUILD_TOOLS = {"cxx-compiler": "", "cmake": None, "ninja": ""}


def _extra(project: dict, name: str) -> list[str]:
    """The requirements of an extra, with ``thesis-lab[a,b]`` replaced by those of extras a and b."""
    out = []
    for spec in project["optional-dependencies"][name]:
        package, rest = _requirement(spec)
        if package == project["name"]:
            for inner in rest.strip("[]").split(","):
                out += _extra(project, inner)
        else:
            out.append(spec)
    return out


def _environment_packages() -> dict[str, str]:
    env = yaml.safe_load((ROOT / "environment.yml").read_text())
    have: dict[str, str] = {}
    for dep in env["dependencies"]:
        if isinstance(dep, dict):
            have.update(_requirement(s) for s in dep["pip"] if not s.startswith("-e"))
        elif not dep.startswith(("python", "pip")):
            name, floor = _requirement(dep)
            have[name] = floor
    return have


def test_the_extras_expand():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert [_requirement(s)[0] for s in _extra(project, "plot")] == ["matplotlib"]
    book = [_requirement(s)[0] for s in _extra(project, "book")]
    assert {"matplotlib", "pyvista", "pymeshlab", "biotite", "papermill", "jupyter-book"} <= set(book)
    assert project["name"] not in {_requirement(s)[0] for s in _extra(project, "dev")}


def test_environment_yml_has_the_same_packages_and_floors_as_pyproject():
    # conda installs everything: the library, every package of every extra with the floor of
    # pyproject.toml, and the build requirements of the compiled core; nothing else
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    project = pyproject["project"]
    wanted = dict(_requirement(s) for s in project["dependencies"])
    for extra in project["optional-dependencies"]:
        for spec in _extra(project, extra):
            name, floor = _requirement(spec)
            assert wanted.get(name, floor) == floor, f"{name} has two floors in pyproject.toml"
            wanted[name] = floor
    wanted.update(_requirement(s) for s in pyproject["build-system"]["requires"])
    wanted.update({name: floor for name, floor in CONDA_BUILD_TOOLS.items() if floor is not None})
    wanted["cmake"] = pyproject["tool"]["scikit-build"]["cmake"].get("version", "")
    have = _environment_packages()
    assert {name: have.get(name) for name in wanted if have.get(name) != wanted[name]} == {}
    assert sorted(set(have) - set(wanted)) == []
    env = yaml.safe_load((ROOT / "environment.yml").read_text())
    assert [s for dep in env["dependencies"] if isinstance(dep, dict) for s in dep["pip"]][-1] == "-e ."


def test_numba_is_no_dependency():
    # the kernels are compiled C++: numba is neither required nor offered, nor in the conda route
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text())
    project = pyproject["project"]
    specs = project["dependencies"] + pyproject["build-system"]["requires"] + [
        s for extra in project["optional-dependencies"].values() for s in extra]
    names = {_requirement(s)[0] for s in specs} | set(_environment_packages())
    assert "numba" not in names and "llvmlite" not in names
    assert "numpy" in names  # the names were read


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
