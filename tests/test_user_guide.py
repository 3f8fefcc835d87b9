"""The user guide (book/user-guide.ipynb) stays true to the package it describes.

Its install section names every extra of pyproject.toml and no other, with the sizes the README
states; every ``thesis_lib.…`` name its prose mentions exists; its cells call only public names.
nbval (``make test``) re-executes its cells against the stored outputs.
"""

from __future__ import annotations

import importlib
import re
import tomllib

import nbformat
import pytest

from thesis_lib.lab.paths import project_root

ROOT = project_root()
GUIDE = ROOT / "book" / "user-guide.ipynb"


def _markdown() -> str:
    nb = nbformat.read(GUIDE, as_version=4)
    return "\n\n".join(c.source for c in nb.cells if c.cell_type == "markdown")


def _install_section() -> str:
    text = _markdown()
    start = text.index("## Install")
    return text[start:text.index("\n## ", start + 1)]


def _extras() -> set[str]:
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    return set(pyproject["project"]["optional-dependencies"])


def test_the_install_section_names_every_extra_and_no_other():
    named = set(re.findall(r"\[(\w+)\]", _install_section()))
    assert named == _extras(), f"guide: {sorted(named)}, pyproject.toml: {sorted(_extras())}"


def test_the_sizes_are_the_readmes():
    """Each extra's size in the guide's table is the one in the README's install block."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    readme_sizes = dict(re.findall(r'pip install "\.\[(\w+)\]".*?\(about (\d+) MB\)', readme, re.S))
    guide_sizes = dict(re.findall(r"\| `\[(\w+)\]` \|[^\n]*\| about (\d+) MB \|", _install_section()))
    assert guide_sizes and guide_sizes == readme_sizes
    base = re.search(r"pip install \. .*?about (\d+) MB beyond them", readme).group(1)
    assert f"about {base} MB beyond numpy and scipy" in _install_section()


def _mentioned_names() -> list[str]:
    """Every dotted ``thesis_lib.x.y`` in the guide's prose (``thesis_lib.meshes.merge_coincident``)."""
    return sorted(set(re.findall(r"\bthesis_lib(?:\.\w+)+", _markdown())))


def test_the_prose_mentions_some_names():
    # a pattern that silently matched nothing would pass the test below
    assert len(_mentioned_names()) >= 5


@pytest.mark.parametrize("dotted", _mentioned_names())
def test_every_name_the_prose_mentions_exists(dotted):
    parts = dotted.split(".")
    for split in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:split]))
        except ImportError:
            continue
        for attr in parts[split:]:
            assert hasattr(obj, attr), f"{dotted}: {obj.__name__} has no {attr}"
            obj = getattr(obj, attr)
        return
    pytest.fail(f"{dotted}: no such module")


def test_the_guide_is_in_the_sidebar_and_keeps_to_the_notebook_rule():
    from test_notebook_style import NOTEBOOKS, style_violations

    assert "book/user-guide.ipynb" in NOTEBOOKS
    assert style_violations(GUIDE) == []
    assert "file: user-guide" in (ROOT / "book" / "_toc.yml").read_text(encoding="utf-8")
