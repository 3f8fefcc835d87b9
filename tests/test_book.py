"""The book builds from its stored notebooks, has its pages, and renders math with no network."""

from __future__ import annotations

import functools
import http.server
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest
import yaml

from thesis_lib.lab.paths import repo_root

BOOK = repo_root() / "book"


def _toc_files(toc: dict) -> list[str]:
    files = [toc["root"]]
    for part in toc.get("parts", []):
        for chapter in part.get("chapters", []):
            files.append(chapter["file"])
            files += [s["file"] for s in chapter.get("sections", [])]
    return files


@pytest.fixture(scope="module")
def built_book(tmp_path_factory) -> Path:
    """Build the book from the stored (executed) notebooks, warnings as errors, into a temp folder."""
    out = tmp_path_factory.mktemp("book")
    config = yaml.safe_load((BOOK / "_config.yml").read_text())
    config["execute"]["execute_notebooks"] = "off"
    config["sphinx"]["local_extensions"] = {"offline_mathjax": str(BOOK / "_ext")}  # paths are relative to the config
    config_file = out / "_config.yml"
    config_file.write_text(yaml.safe_dump(config))
    jb = Path(sys.executable).with_name("jupyter-book")
    proc = subprocess.run(
        [str(jb), "build", str(BOOK), "-W", "-n", "--keep-going", "--config", str(config_file), "--path-output", str(out)],
        capture_output=True,
        text=True,
    )
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    return out / "_build" / "html"


def test_every_toc_page_is_built(built_book):
    toc = yaml.safe_load((BOOK / "_toc.yml").read_text())
    for file in _toc_files(toc):
        page = built_book / (file + ".html")
        assert page.is_file(), f"{file} missing from the built book"


def test_book_has_intro_landmarks_and_report(built_book):
    assert "Why three approaches" in (built_book / "intro.html").read_text()
    assert "covering_radius_maxmin" in (built_book / "experiments" / "two-circles-landmarks.html").read_text()
    report = (built_book / "report.html").read_text()
    assert "Reproduction report" in report and "claims:" in report


def test_mathjax_is_served_from_the_build(built_book):
    html = (built_book / "intro.html").read_text()
    assert "_static/mathjax/tex-chtml.js" in html
    assert "cdn.jsdelivr" not in html and "mathjax@3" not in html
    assert (built_book / "_static" / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").is_dir()


def _serve(root: Path) -> tuple[http.server.ThreadingHTTPServer, int]:
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=str(root))
    handler.log_message = lambda *a, **k: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, server.server_address[1]


def test_math_renders_offline_in_headless_chromium(built_book, tmp_path):
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    assert chromium, "Debian's chromium is needed for this test: `make test` installs it"
    server, port = _serve(built_book)
    try:
        proc = subprocess.run(
            [
                chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                f"--user-data-dir={tmp_path / 'profile'}",
                # no network: every host but the loopback server goes to a dead proxy
                "--proxy-server=127.0.0.1:9",
                "--virtual-time-budget=20000", "--dump-dom", f"http://127.0.0.1:{port}/intro.html",
            ],
            capture_output=True, text=True, timeout=120,
        )
    finally:
        server.shutdown()
    dom = proc.stdout
    assert "Why three approaches" in dom, proc.stderr[-2000:]
    assert dom.count("<mjx-container") >= 2, "MathJax did not typeset the page's math"
    assert 'class="MathJax CtxtMenu_Attached_0"' in dom or "mjx-math" in dom
