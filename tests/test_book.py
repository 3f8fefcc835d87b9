"""The built book: every page, its tables, figures and math, from a server at a sub-path and from file://.

The book is built once for this module from the stored (executed) notebooks, with the book's own
configuration (warnings are errors), into a temporary folder. The pages are then opened in headless
Chromium with no network: a harness page loads each one in a frame of 1280 × 1000 CSS pixels (a
desktop viewport) and reports what it sees: tables, math, raw LaTeX left in the text, anything wider
than the article's column, the smallest text of each figure at its shown width, console errors.
"""

from __future__ import annotations

import functools
import html
import http.server
import io
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import zipfile
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest
import yaml

from thesis_lib.lab import bench
from thesis_lib.lab.paths import project_root, shared_dir
from thesis_lib.lab.report import report
from thesis_lib.lab.results import DEFAULT_RUN_ENV

ROOT = project_root()
BOOK = ROOT / "book"
ARCHIVE = "thesis-lab-book.zip"


def _toc_files(toc: dict) -> list[str]:
    files = [toc["root"]]
    for part in toc.get("parts", []):
        for chapter in part.get("chapters", []):
            files.append(chapter["file"])
            files += [s["file"] for s in chapter.get("sections", [])]
    return files


PAGES = _toc_files(yaml.safe_load((BOOK / "_toc.yml").read_text()))


def _git_status() -> str:
    return subprocess.run(["git", "status", "--porcelain"], cwd=ROOT, capture_output=True, text=True, check=True).stdout


def build_config(out: Path, **execute) -> Path:
    """The book's _config.yml with paths made absolute (the copy lives in ``out``) and ``execute`` changed."""
    config = yaml.safe_load((BOOK / "_config.yml").read_text())
    config["execute"].update(execute)
    config["sphinx"]["local_extensions"] = {k: str(BOOK / v) for k, v in config["sphinx"]["local_extensions"].items()}
    config["bibtex_bibfiles"] = [str(BOOK / f) for f in config["bibtex_bibfiles"]]
    path = out / "_config.yml"
    path.write_text(yaml.safe_dump(config))
    return path


def jupyter_book(source: Path, config: Path, out: Path, env: dict | None = None) -> subprocess.CompletedProcess:
    jb = Path(sys.executable).with_name("jupyter-book")
    return subprocess.run(
        [str(jb), "build", str(source), "-W", "-n", "--keep-going", "--config", str(config), "--path-output", str(out)],
        capture_output=True, text=True, env=env,
    )


@pytest.fixture(scope="module")
def built_book(tmp_path_factory) -> Path:
    """Build the book from the stored notebooks (no execution), warnings as errors, into a temp folder."""
    out = tmp_path_factory.mktemp("book")
    before = _git_status()
    proc = jupyter_book(BOOK, build_config(out, execute_notebooks="off"), out)
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    assert "WARNING" not in proc.stdout + proc.stderr
    assert _git_status() == before, "building the book changed files of the checkout"
    return out / "_build" / "html"


def test_pages_that_read_stored_files_are_rebuilt_every_time(built_book):
    """The report and the summary read the claims and stored results, which Sphinx does not track."""
    out = built_book.parent.parent
    proc = jupyter_book(BOOK, out / "_config.yml", out)
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    log = re.sub(r"\x1b\[[0-9;]*m", "", proc.stdout)
    reread = set(re.findall(r"reading sources\.\.\. \[\s*\d+%\] (\S+)", log))
    assert reread == {"report", "ch5-summary"}


def test_every_toc_page_is_built(built_book):
    for file in PAGES:
        assert (built_book / (file + ".html")).is_file(), f"{file} missing from the built book"


def test_book_has_intro_landmarks_report_and_references(built_book):
    assert "Why three approaches" in (built_book / "intro.html").read_text()
    assert "covering radius: maxmin" in (built_book / "experiments" / "two-circles-landmarks.html").read_text()
    report_text = re.sub(r"<[^>]+>", "", (built_book / "report.html").read_text())
    assert "Reproduction report" in report_text and f"The registry holds {len(report())} claims" in report_text
    refs = (built_book / "references.html").read_text()
    assert 'role="doc-biblioentry"' in refs and ">ABK98<" in refs


API_ANCHORS = [
    "thesis_lib.homology.filtration.Filtration",
    "thesis_lib.complexes.rips",
    "thesis_lib.homology.homology",
    "thesis_lib.persistence.persistence",
    "thesis_lib.curvature.mean_curvature",
    "thesis_lib.morse.morse_matching",
    "thesis_lib.multiparameter.rank_invariant",
    "thesis_lib.lab.runner.run",
]


def test_api_reference_documents_the_public_functions(built_book):
    """The API page is generated from the docstrings: each function has its anchor, signature and text."""
    import importlib

    page = (built_book / "api.html").read_text()
    ids = _parse(built_book / "api.html").ids
    for anchor in API_ANCHORS:
        assert anchor in ids, f"{anchor} not documented on the API page"
        module, _, name = anchor.rpartition(".")
        summary = importlib.import_module(module).__dict__[name].__doc__.strip().splitlines()[0]
        shown = html.unescape(re.sub(r"<[^>]+>", "", page[page.index(f'id="{anchor}"'):][:4000]))
        words = re.findall(r"[A-Za-z]{3,}", summary)[:4]
        assert words and all(w in shown for w in words), f"{anchor}: docstring not shown"
    # every public function of the complexes package, and each object once
    documented = re.findall(r'<dt class="sig sig-object py" id="([^"]+)"', page)
    assert len(documented) == len(set(documented))
    complexes = importlib.import_module("thesis_lib.complexes")
    functions = [n for n in complexes.__all__
                 if callable(getattr(complexes, n)) and n not in ("Filtration", "as_complex")]
    assert {f"thesis_lib.complexes.{n}" for n in functions} <= set(documented)


def test_api_docstrings_read_bars_as_norms_outside_literals():
    """|H| in a plain-text docstring is an absolute value, not a reST substitution; literals keep theirs."""
    sys.path.insert(0, str(BOOK / "_ext"))
    try:
        from api_docstrings import escape_bars
    finally:
        sys.path.remove(str(BOOK / "_ext"))
    lines = ["|H| = |u − x|², ``a|b`` and :math:`|x|`", "Example::", "", "    a | b", "after |y|", ">>> 1 | 2"]
    escape_bars(lines)
    assert lines == [r"\|H\| = \|u − x\|², ``a|b`` and :math:`|x|`", "Example::", "", "    a | b", r"after \|y\|",
                     ">>> 1 | 2"]


def test_api_docstrings_set_latex_scripts_as_sub_and_superscripts():
    """k_{p+1} in a plain-text docstring becomes k<sub>p+1</sub> on the API page, not raw LaTeX."""
    sys.path.insert(0, str(BOOK / "_ext"))
    try:
        from api_docstrings import escape_bars
    finally:
        sys.path.remove(str(BOOK / "_ext"))
    lines = ["rank B_p = k_{p+1} in R^{n+1}", "``k_{p}`` and :math:`x_{1}`", "Example::", "", "    x_{1}", ">>> a_{1}"]
    escape_bars(lines)
    assert lines == [r"rank B_p = k\ :sub:`p+1`\  in R\ :sup:`n+1`\ ", "``k_{p}`` and :math:`x_{1}`", "Example::", "",
                     "    x_{1}", ">>> a_{1}"]


def test_citations_link_to_the_references_page(built_book):
    intro = (built_book / "intro.html").read_text()
    assert re.search(r'<a class="reference internal" href="references.html#[^"]+"[^>]*>Bot11</a>', intro)


def _toc_titles(toc: dict) -> dict[str, str]:
    entries = [c for part in toc.get("parts", []) for c in part.get("chapters", [])]
    entries += [s for c in list(entries) for s in c.get("sections", [])]
    return {e["file"]: e["title"] for e in entries if "title" in e}


def _sidebar(built_book: Path) -> list[tuple[str, str]]:
    """(href, title) of every entry of the primary sidebar (on the landing page, where it is whole)."""
    page = html.unescape((built_book / "intro.html").read_text())
    nav = page[page.index('<nav class="bd-links bd-docs-nav"'):]
    nav = nav[:nav.index("</nav>")]
    return [(href, re.sub(r"\s+", " ", re.sub(r"<[^>]+>", "", text)).strip())
            for href, text in re.findall(r'<a class="reference internal" href="([^"#]+)"[^>]*>(.*?)</a>', nav, re.S)]


def _thesis_numbers() -> set[str]:
    """The numbers of the thesis's chapters and sections, read from its text."""
    text = (shared_dir() / "thesis" / "botnan-2011-three-approaches.txt").read_text()
    sections = set(re.findall(r"^ ?(\d+(?:\.\d+)+) [A-Z]", text, re.M))
    return sections | {n.split(".")[0] for n in sections} | set(re.findall(r"CHAPTER (\d+)\. ", text))


def _numbers(title: str) -> list[str]:
    """The thesis numbers a sidebar title claims: '2.1–2.2 Complexes' -> ['2.1', '2.2']."""
    m = re.match(r"(\d+(?:\.\d+)*)(?:–(\d+(?:\.\d+)*))? ", title)
    return [n for n in (m.groups() if m else ()) if n]


def test_sidebar_titles_follow_the_thesis(built_book):
    titles = _toc_titles(yaml.safe_load((BOOK / "_toc.yml").read_text()))
    for title in ["2.1–2.2 Complexes and homology", "2.3 Persistent homology", "2.4 Experiments",
                  "3 Discrete differential geometry", "4 Discrete Morse theory", "5 Summary"]:
        assert title in titles.values(), title
    nav = html.unescape((built_book / "intro.html").read_text())
    # Sphinx keeps a page's own heading in the sidebar when the page has more than one top-level (#) heading
    wrong = [f"{file}: {title!r}" for file, title in titles.items() if f'href="{file}.html">{title}</a>' not in nav]
    assert not wrong, "sidebar entries that lost their title (one # heading per page):\n" + "\n".join(wrong)


def test_sidebar_has_one_entry_per_page_and_each_number_once(built_book):
    """Every page once; no two entries with the same title or the same thesis number; each number is
    one the thesis gives a chapter or section."""
    entries = _sidebar(built_book)
    hrefs = Counter(href for href, _ in entries)
    assert {f"{p}.html" for p in PAGES[1:]} <= set(hrefs), "pages missing from the sidebar"
    assert not [h for h, n in hrefs.items() if n > 1], f"pages listed twice: {[h for h, n in hrefs.items() if n > 1]}"
    titles = Counter(title for _, title in entries)
    assert not [t for t, n in titles.items() if n > 1], f"titles used twice: {[t for t, n in titles.items() if n > 1]}"
    numbers = Counter(n for _, title in entries for n in _numbers(title))
    twice = {n: [t for _, t in entries if n in _numbers(t)] for n, k in numbers.items() if k > 1}
    assert not twice, f"numbers used by two entries: {twice}"
    thesis = _thesis_numbers()
    assert not set(numbers) - thesis, f"numbers the thesis does not give a section: {sorted(set(numbers) - thesis)}"


def test_references_are_the_thesis_bibliography_then_further_reading(built_book):
    """The references page lists the works the book cites: first those of the thesis's bibliography
    (under the thesis's labels, each cited by the thesis as [label]), then, under Further reading,
    the others."""
    page = (built_book / "references.html").read_text()
    at = page.index('id="further-reading"')
    def labels(part: str) -> list[str]:
        spans = re.findall(r'role="doc-biblioentry">\s*<span class="label">(.*?)</span>\s*<p>', part, re.S)
        return [re.sub(r"<[^>]+>", "", span).strip("[] \n") for span in spans]

    thesis_part, further = labels(page[:at]), labels(page[at:])
    text = (shared_dir() / "thesis" / "botnan-2011-three-approaches.txt").read_text()
    assert thesis_part and further, (thesis_part, further)
    assert not [k for k in thesis_part if f"[{k}]" not in text and not re.search(rf"[\[,; ]{k}[\],;]", text)], thesis_part
    assert not [k for k in further if f"{k}]" in text or f"[{k}" in text], further
    assert "Bot11" in further and "ABK98" in thesis_part
    cited = set()
    for source in [*BOOK.glob("*.ipynb"), *BOOK.glob("*.md"), *(ROOT / "experiments").glob("*.ipynb")]:
        for keys in re.findall(r"\{cite(?::\w+)?\}`([^`]+)`", source.read_text()):
            cited |= {k.strip() for k in keys.split(",")}
    assert set(thesis_part) | set(further) == cited


def test_mathjax_is_served_from_the_build(built_book):
    page = (built_book / "intro.html").read_text()
    assert "_static/mathjax/tex-chtml.js" in page
    assert "cdn.jsdelivr" not in page and "mathjax@3" not in page
    assert (built_book / "_static" / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").is_dir()


def test_site_archive_holds_the_site(built_book):
    with zipfile.ZipFile(built_book.parent / ARCHIVE) as archive:
        names = set(archive.namelist())
    assert {f"html/{p}.html" for p in PAGES} <= names
    assert "html/_static/mathjax/tex-chtml.js" in names
    on_disk = {f"html/{p.relative_to(built_book).as_posix()}" for p in built_book.rglob("*") if p.is_file()}
    assert names == on_disk


class _Links(HTMLParser):
    """Every href/src of a page, and every id it defines."""

    def __init__(self):
        super().__init__()
        self.links: list[str] = []
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        for key in ("href", "src"):
            if attrs.get(key) and not (tag == "link" and attrs.get("rel") in ("preconnect", "dns-prefetch")):
                self.links.append(html.unescape(attrs[key]))


@functools.cache
def _parse(path: Path) -> _Links:
    parser = _Links()
    parser.feed(path.read_text(errors="replace"))
    return parser


def test_every_link_is_relative_and_resolves(built_book):
    """Relative links only, so the site works at any sub-path and from file://; every target exists."""
    bad = []
    pages = [p for p in sorted(built_book.rglob("*.html")) if "_static" not in p.relative_to(built_book).parts]
    for page in pages:  # (_static holds the themes' template macros, not pages)
        for link in _parse(page).links:
            parts = urlsplit(link)
            if parts.scheme in ("http", "https", "mailto", "data", "javascript"):
                continue
            if parts.scheme or link.startswith("/"):
                bad.append(f"{page.name}: absolute link {link}")
                continue
            if not parts.path:
                continue  # a fragment of the page itself (headings' permalinks)
            target = (page.parent / unquote(parts.path)).resolve()
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                bad.append(f"{page.relative_to(built_book)}: {link} does not exist")
            elif parts.fragment and target.suffix == ".html" and parts.fragment not in _parse(target).ids:
                bad.append(f"{page.relative_to(built_book)}: {link} has no anchor #{parts.fragment}")
    assert not bad, "\n".join(bad[:40])


# ---------------------------------------------------------------------------------------------------
# In the browser
#
# Chromium shows each page in a frame of 1280 × 1000 CSS pixels (a desktop viewport: the theme shows
# the primary sidebar, the article column and the page's table of contents side by side).

#: the smallest figure text allowed, in CSS pixels at the width the page shows the image at
MIN_FIGURE_TEXT_PX = 9.0
#: the PNG tEXt chunk that the book's figures carry (thesis_lib.graphics.style.TEXT_PX_KEY)
TEXT_PX_KEY = "thesis-lab:smallest-text-px"
VIEWPORT = (1280, 1000)

HARNESS = r"""<!DOCTYPE html><html><body><pre id="out">running</pre><script>
const PAGES = %(pages)s, PREFIX = %(prefix)s, TEXT_PX_KEY = %(key)s, VIEWPORT = %(viewport)s;
function cssBroken(link) {
  try { return !link.sheet || link.sheet.cssRules.length === 0; } catch (e) { return false; }
}
function visibleText(doc) {
  const body = doc.body.cloneNode(true);
  body.querySelectorAll("pre, code, script, style, .cell_input, .highlight").forEach(e => e.remove());
  return body.textContent;
}
// where an element is: its tag, id or the nearest id, and its classes
function where(el) {
  const near = el.closest("[id]");
  const cls = (el.getAttribute("class") || "").trim().split(/\s+/).filter(Boolean).slice(0, 3).join(".");
  return el.tagName.toLowerCase() + (cls ? "." + cls : "") + (el.id ? "#" + el.id : near ? " in #" + near.id : "");
}
function snippet(text, at, n) {
  return text.slice(Math.max(0, at - n), at + n).replace(/\s+/g, " ").trim();
}
// raw LaTeX in the rendered text: outside MathJax's output, code, scripts and the search dialog
const NOT_PROSE = "pre, code, kbd, samp, script, style, mjx-container, .cell_input, .highlight, dialog, " +
                  "textarea, noscript, .sig";
const RAW_TEX = /_\{|\^\{|\\[A-Za-z]+|\\[{}()\[\]]/g;
function rawLatex(doc) {
  const found = [], walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const parent = node.parentElement;
    if (!parent || parent.closest(NOT_PROSE)) continue;
    const text = node.nodeValue;
    for (const m of text.matchAll(RAW_TEX))
      found.push(JSON.stringify(m[0]) + " in " + where(parent) + ": \u2026" + snippet(text, m.index, 40) + "\u2026");
  }
  for (const m of doc.title.matchAll(RAW_TEX))   // the browser tab's title
    found.push(JSON.stringify(m[0]) + " in the title: " + JSON.stringify(doc.title));
  return found;
}
// anything wider than the article's text column
function column(doc) {
  const article = doc.querySelector("article.bd-article") || doc.querySelector("[role=main]") || doc.body;
  const r = article.getBoundingClientRect(), s = doc.defaultView.getComputedStyle(article);
  return {left: r.left + parseFloat(s.paddingLeft), right: r.right - parseFloat(s.paddingRight), article: article};
}
function tooWide(doc) {
  const col = column(doc), width = col.right - col.left, found = [], flagged = new Set();
  const kinds = [["img", "image"], ["table", "table"], ["pre", "pre"], ['mjx-container[display="true"]', "display formula"],
                 [".cell_output, .output", "output"]];
  for (const [selector, kind] of kinds) {
    for (const el of col.article.querySelectorAll(selector)) {
      if ([...flagged].some(f => el.contains(f))) continue;   // the wide thing inside was named already
      const r = el.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;            // not displayed (a collapsed block)
      const scrolled = el.scrollWidth - el.clientWidth;          // content hidden behind a scroll bar
      const out = Math.max(r.right - col.right, col.left - r.left);
      const source = kind === "pre" && el.closest(".cell_input, div[class*=highlight-]") && !el.closest(".cell_output, .output");
      if (source) continue;                                      // source code scrolls: code, not output
      if (out > 1 || (kind !== "image" && scrolled > 1)) {
        flagged.add(el);
        const shown = Math.round(Math.max(r.width, el.scrollWidth));
        found.push(kind + " " + where(el) + " is " + shown + " px wide, the column " + Math.round(width) + " px: " +
                   JSON.stringify((el.getAttribute("src") || el.textContent || "").replace(/\s+/g, " ").trim().slice(0, 80)));
      }
    }
  }
  return found;
}
// the smallest text of each figure at the width it is shown, from the PNG's tEXt chunk
function latin1(bytes) { return [...bytes].map(b => String.fromCharCode(b)).join(""); }
async function pngText(url) {
  const buf = new Uint8Array(await (await fetch(url)).arrayBuffer()), view = new DataView(buf.buffer);
  if (latin1(buf.slice(1, 4)) !== "PNG") return null;
  const out = {};
  for (let at = 8; at + 8 <= buf.length;) {
    const length = view.getUint32(at), kind = latin1(buf.slice(at + 4, at + 8));
    if (kind === "tEXt") {
      const body = buf.slice(at + 8, at + 8 + length), zero = body.indexOf(0);
      out[latin1(body.slice(0, zero))] = latin1(body.slice(zero + 1));
    }
    if (kind === "IEND") break;
    at += 12 + length;
  }
  return out;
}
async function figureText(doc) {
  const col = column(doc), found = [], sizes = [];
  for (const img of col.article.querySelectorAll("img")) {
    const src = img.getAttribute("src") || "";
    let text;
    try { text = await pngText(img.currentSrc || img.src); } catch (e) { found.push("image " + src + ": not readable (" + e + ")"); continue; }
    if (text === null) { found.push("image " + src + " in " + where(img) + ": not a PNG, so its text size is unknown"); continue; }
    if (!(TEXT_PX_KEY in text)) { found.push("image " + src + " in " + where(img) + ": no " + TEXT_PX_KEY + " chunk (not saved through thesis_lib.graphics.style)"); continue; }
    if (text[TEXT_PX_KEY] === "none") continue;   // a figure without text
    const shown = img.clientWidth || Math.min(img.naturalWidth, col.right - col.left);
    const px = parseFloat(text[TEXT_PX_KEY]) * shown / img.naturalWidth;
    sizes.push(Math.round(px * 100) / 100);
    if (!(px >= %(min_px)s))
      found.push("image " + src + " in " + where(img) + ": smallest text " + px.toFixed(1) + " px at " + shown +
                 " px wide (" + text[TEXT_PX_KEY] + " px at its natural " + img.naturalWidth + " px)");
  }
  return {found: found, sizes: sizes};
}
function searchBoxes(doc) {
  return [...doc.querySelectorAll(".search-button-field, .search-button, form.bd-search, input[type=search]")]
    .filter(e => !e.closest("dialog") && e.getClientRects().length > 0 && e.getBoundingClientRect().width > 0 &&
                 doc.defaultView.getComputedStyle(e).visibility !== "hidden")
    .filter((e, i, all) => !all.some(o => o !== e && o.contains(e)))
    .map(e => where(e));
}
async function check(page) {
  console.log("HARNESS-PAGE " + page);
  const frame = document.createElement("iframe");
  frame.style.width = VIEWPORT[0] + "px"; frame.style.height = VIEWPORT[1] + "px";
  document.body.appendChild(frame);
  await new Promise(resolve => { frame.onload = resolve; frame.src = PREFIX + page + ".html"; });
  const win = frame.contentWindow, doc = frame.contentDocument;
  const errors = [];
  if (!win.__consoleErrors) {   // served without the hook (file://): errors after the load only
    win.addEventListener("error", e => errors.push("uncaught: " + e.message));
    win.addEventListener("unhandledrejection", e => errors.push("unhandled rejection: " + e.reason));
  }
  for (let i = 0; i < 200 && !(win.MathJax && win.MathJax.startup && win.MathJax.startup.promise); i++)
    await new Promise(r => setTimeout(r, 50));
  if (win.MathJax && win.MathJax.startup) await win.MathJax.startup.promise;
  await Promise.all([...doc.images].map(img => img.complete ? null :
    new Promise(r => { img.addEventListener("load", r); img.addEventListener("error", r); })));
  await new Promise(r => setTimeout(r, 200));
  const text = visibleText(doc);
  const tables = [...doc.querySelectorAll("table")].map(t => ({
    id: t.id || (t.closest("[id]") || {}).id || "",
    rows: [...t.tBodies].reduce((n, b) => n + b.rows.length, 0),
    first: [...t.tBodies].flatMap(b => [...b.rows].map(r => r.cells[0].textContent.trim())),
    links: [...t.querySelectorAll("tbody tr td:first-child a")].map(a => a.getAttribute("href")),
  }));
  const figures = await figureText(doc);
  const result = {
    title: doc.title,
    raw_tables: (text.match(/\|\s*:?-{3,}:?\s*\|/g) || []).length,
    images: doc.images.length,
    broken_images: [...doc.images].filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute("src")),
    broken_css: [...doc.querySelectorAll("link[rel=stylesheet]")].filter(cssBroken).map(l => l.getAttribute("href")),
    bad_outputs: [...doc.querySelectorAll(".cell_output, .output")].map(e => e.textContent)
      .filter(t => /Traceback|Warning/.test(t)).map(t => t.slice(0, 300)),
    math: doc.querySelectorAll(".math").length,
    math_unrendered: [...doc.querySelectorAll(".math")].filter(e => !e.querySelector("mjx-container")).length,
    tables: tables,
    raw_latex: rawLatex(doc),
    too_wide: tooWide(doc),
    column_px: Math.round(column(doc).right - column(doc).left),
    figure_text: figures.found,
    figure_text_px: figures.sizes,
    search_boxes: searchBoxes(doc),
    late_errors: (win.__consoleErrors || []).concat(errors),
  };
  frame.remove();
  return result;
}
(async () => {
  const results = {};
  for (const page of PAGES) {
    try { results[page] = await check(page); } catch (e) { results[page] = {error: String(e)}; }
  }
  console.log("HARNESS-PAGE (done)");
  document.getElementById("out").textContent = JSON.stringify(results);
})();
</script></body></html>"""


def harness_page(pages: list[str], prefix: str) -> str:
    """The harness page that opens ``pages`` (paths without ``.html``) under ``prefix`` one by one."""
    return HARNESS % {"pages": json.dumps(pages), "prefix": json.dumps(prefix), "key": json.dumps(TEXT_PX_KEY),
                      "viewport": json.dumps(VIEWPORT), "min_px": MIN_FIGURE_TEXT_PX}


def _chromium() -> str:
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    assert chromium, "Debian's chromium is needed for the browser tests: `make test` installs it"
    return chromium


#: a console message in Chromium's log (--enable-logging=stderr): ``...:INFO:CONSOLE:12] "text", source: url (12)``.
#: Headless Chromium logs every level alike (console.log and console.error both as INFO), so from the
#: log only what reads as an error is taken (uncaught exceptions, resources that failed to load); the
#: pages' console.error calls are recorded by CONSOLE_HOOK in the page itself.
_CONSOLE = re.compile(r':[A-Z]+:CONSOLE(?::\d+|\(\d+\))\] "(.*)", source: (.*?)(?: \(\d+\))?$')
_LOGGED_ERROR = re.compile(r"^Uncaught |Failed to load resource|net::ERR_|^Refused to |Mixed Content")


def console_errors(log: str) -> dict[str, list[str]]:
    """Errors in Chromium's console log, by the page the harness was showing when they came.

    The harness logs ``HARNESS-PAGE <page>`` before it opens each page, so every message after it,
    up to the next one, belongs to that page (they load one at a time).
    """
    errors: dict[str, list[str]] = {}
    page = "(harness)"
    for line in log.splitlines():
        m = _CONSOLE.search(line)
        if not m:
            continue
        text, source = m.groups()
        if text.startswith("HARNESS-PAGE "):
            page = text[len("HARNESS-PAGE "):]
        elif _LOGGED_ERROR.search(text):
            errors.setdefault(page, []).append(f"{text} ({source.rsplit('/', 1)[-1]})")
    return errors


def _run_harness(url: str, profile: Path, extra: list[str] = ()) -> dict:
    proc = subprocess.run(
        [
            _chromium(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            f"--user-data-dir={profile}", f"--window-size={VIEWPORT[0] + 40},{VIEWPORT[1] + 100}",
            "--enable-logging=stderr", "--v=0",
            # no network: every host but the loopback server goes to a dead proxy
            "--proxy-server=127.0.0.1:9", *extra,
            "--virtual-time-budget=600000", "--dump-dom", url,
        ],
        capture_output=True, text=True, timeout=600,
    )
    m = re.search(r'<pre id="out">(.*?)</pre>', proc.stdout, re.S)
    assert m and m.group(1) != "running", "the harness did not finish: " + proc.stdout[-1000:] + proc.stderr[-2000:]
    seen = json.loads(html.unescape(m.group(1)))
    for page, errors in console_errors(proc.stderr).items():
        if page in seen:
            seen[page]["console_errors"] = errors
        else:
            seen.setdefault("(harness)", {}).setdefault("console_errors", []).extend(errors)
    return seen


#: the first script of every page the test server sends (a test instrument, not part of the site):
#: it records console.error calls, uncaught errors (a script's syntax errors included), unhandled
#: rejections and resources that fail to load, from the first moment of the page's load
CONSOLE_HOOK = """<script>(() => {
  const seen = window.__consoleErrors = [];
  const error = console.error.bind(console);
  console.error = (...args) => { seen.push("console.error: " + args.map(String).join(" ")); error(...args); };
  window.addEventListener("error", e => {
    if (e.target && e.target !== window) seen.push("failed to load " + (e.target.src || e.target.href || e.target.tagName));
    else seen.push("uncaught: " + e.message + " (" + String(e.filename).split("/").pop() + ":" + e.lineno + ")");
  }, true);
  window.addEventListener("unhandledrejection", e => seen.push("unhandled rejection: " + e.reason));
})();</script>"""


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


class _HookingHandler(_QuietHandler):
    """Serves the book's pages with CONSOLE_HOOK as the first thing in their <head>."""

    def send_head(self):
        path = Path(self.translate_path(self.path))
        if not (path.suffix == ".html" and SUBPATH in self.path and path.is_file()):
            return super().send_head()
        body = re.sub(r"(<head[^>]*>)", lambda m: m.group(1) + CONSOLE_HOOK, path.read_text(), count=1).encode()
        self.send_response(200)
        self.send_header("Content-Type", "text/html; charset=utf-8")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        return io.BytesIO(body)


def _serve(root: Path, handler_class: type = _QuietHandler) -> http.server.ThreadingHTTPServer:
    handler = functools.partial(handler_class, directory=str(root))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


SUBPATH = "pages/thesis-lab/"


@pytest.fixture(scope="module")
def seen_at_subpath(built_book, tmp_path_factory) -> dict:
    """Every page as Chromium shows it, served by `python -m http.server` under a sub-path."""
    root = tmp_path_factory.mktemp("site")
    (root / SUBPATH).parent.mkdir(parents=True)
    (root / SUBPATH).symlink_to(built_book, target_is_directory=True)
    (root / "harness.html").write_text(harness_page(PAGES, SUBPATH))
    server = _serve(root, _HookingHandler)
    try:
        return _run_harness(f"http://127.0.0.1:{server.server_address[1]}/harness.html", root / "profile")
    finally:
        server.shutdown()


@pytest.mark.parametrize("page", PAGES)
def test_page_in_the_browser(seen_at_subpath, page):
    seen = seen_at_subpath[page]
    assert "error" not in seen, seen
    assert seen["raw_tables"] == 0, "Markdown table text shown as text (a table that did not render)"
    assert not seen["broken_images"], f"images that do not load: {seen['broken_images']}"
    assert not seen["broken_css"], f"style sheets that do not load: {seen['broken_css']}"
    assert not seen["bad_outputs"], f"outputs with a traceback or warning: {seen['bad_outputs']}"
    assert seen["math_unrendered"] == 0, f"{seen['math_unrendered']} of {seen['math']} formulas not typeset"


def _fail_with(page: str, what: str, found: list[str]) -> None:
    assert not found, f"{page}: {what}:\n  " + "\n  ".join(found)


@pytest.mark.parametrize("page", PAGES)
def test_no_raw_latex_in_the_text(seen_at_subpath, page):
    """No `_{`, `^{` or backslash command in the rendered text outside MathJax's output and code."""
    _fail_with(page, "raw LaTeX in the text", seen_at_subpath[page]["raw_latex"])


@pytest.mark.parametrize("page", PAGES)
def test_nothing_is_wider_than_the_text_column(seen_at_subpath, page):
    """No output, table, printed text, image or display formula sticks out of the article's column or
    hides part of itself behind a scroll bar (at the 1280 px viewport); source code may scroll."""
    _fail_with(page, f"wider than the text column ({seen_at_subpath[page]['column_px']} px)",
               seen_at_subpath[page]["too_wide"])


@pytest.mark.parametrize("page", PAGES)
def test_figure_text_is_legible(seen_at_subpath, page):
    """Every figure's smallest text, read from its PNG and scaled to the width the page shows it at,
    is at least 9 px; a figure that does not say its text size fails."""
    _fail_with(page, f"figure text under {MIN_FIGURE_TEXT_PX:g} px or unknown", seen_at_subpath[page]["figure_text"])


@pytest.mark.parametrize("page", PAGES)
def test_no_console_errors(seen_at_subpath, page):
    """Nothing on the page logs an error to the console, during its load or after."""
    seen = seen_at_subpath[page]
    _fail_with(page, "console errors", seen.get("console_errors", []) + seen["late_errors"])


def test_the_harness_itself_logged_no_errors(seen_at_subpath):
    _fail_with("harness", "console errors outside any page", seen_at_subpath.get("(harness)", {}).get("console_errors", []))


@pytest.mark.parametrize("page", PAGES)
def test_one_search_box_and_a_proper_title(seen_at_subpath, page):
    seen = seen_at_subpath[page]
    assert len(seen["search_boxes"]) == 1, f"{page}: {len(seen['search_boxes'])} search controls: {seen['search_boxes']}"
    head, _, site = seen["title"].rpartition(" — ")
    assert head and site and head.strip() != site.strip(), f"{page}: title {seen['title']!r}"


def test_console_errors_are_read_from_the_log():
    log = "\n".join([
        '[1:1:1201/234510.36:INFO:CONSOLE:3] "HARNESS-PAGE intro", source: http://h/harness.html (3)',
        '[1:1:1201/234510.60:INFO:CONSOLE:59] "Uncaught SyntaxError: Identifier \'X\' has already been declared", '
        'source: http://h/intro.html (59)',
        '[1:1:1201/234510.61:INFO:CONSOLE:7] "[PST]: Changed to auto mode", source: http://h/_static/x.js (7)',
        '[1:1:1201/234510.62:INFO:CONSOLE:3] "HARNESS-PAGE report", source: http://h/harness.html (3)',
        '[1:1:1201/234510.63:ERROR:CONSOLE(0)] "Failed to load resource: net::ERR_FAILED", source: http://h/a.png (0)',
        '[1:1:1201/234510.63:INFO:other.cc(3)] not a console line',
    ])
    assert console_errors(log) == {
        "intro": ["Uncaught SyntaxError: Identifier 'X' has already been declared (intro.html)"],
        "report": ["Failed to load resource: net::ERR_FAILED (a.png)"]}


def test_math_is_typeset(seen_at_subpath):
    assert seen_at_subpath["intro"]["math"] >= 2
    assert sum(p["math"] for p in seen_at_subpath.values()) > 50


def test_report_tables_have_a_row_per_claim(seen_at_subpath):
    rows = report()
    tables = {t["id"]: t for t in seen_at_subpath["report"]["tables"]}
    beyond = [r for r in rows if r.get("section") == "beyond" or r["status"] == "new"]
    thesis = [r for r in rows if r not in beyond]
    assert tables["tbl-report-thesis"]["rows"] == len(thesis)
    assert tables["tbl-report-thesis"]["first"] == [r["where"] for r in thesis]
    assert tables.get("tbl-report-beyond", {"rows": 0})["rows"] == len(beyond)
    assert tables["tbl-report-counts"]["first"][-1] == "all"
    linked = [r for r in thesis if r.get("link")]
    assert len(tables["tbl-report-thesis"]["links"]) == len(linked)
    for href, r in zip(tables["tbl-report-thesis"]["links"], linked):
        page, _, label = r["link"].partition("#")
        assert href.split("#")[0] == page + ".html", (r["id"], href)
        assert href.endswith(f"#{label}" if label else ".html"), (r["id"], href)


def test_performance_tables_have_a_row_per_benchmark_case(seen_at_subpath):
    tables = seen_at_subpath["performance"]["tables"]
    for topic in bench.topics():
        cases = [str(r.get("case")) for r in bench.load(topic)]
        # one table per benchmark, or several that split its rows (e.g. by kind of case)
        parts = [t["first"] for t in tables if t["first"] and not Counter(t["first"]) - Counter(cases)]
        shown = Counter(case for part in parts for case in part)
        assert not Counter(cases) - shown, f"no tables of benchmark {topic!r} with the rows of cases {cases}"


def test_pages_work_from_file_urls(built_book, tmp_path):
    """Opened from disk (file://), the pages find their style sheets, images, scripts and math."""
    pages = ["intro", "report", "experiments/two-circles-landmarks"]
    harness = tmp_path / "harness.html"
    harness.write_text(harness_page(pages, built_book.as_uri() + "/"))
    seen = _run_harness(harness.as_uri(), tmp_path / "profile", ["--allow-file-access-from-files"])
    for page in pages:
        assert "error" not in seen[page], seen[page]
        assert not seen[page]["broken_css"] and not seen[page]["broken_images"], seen[page]
        assert seen[page]["math_unrendered"] == 0
    assert seen["experiments/two-circles-landmarks"]["images"] >= 1
    assert seen["intro"]["math"] >= 2


# ---------------------------------------------------------------------------------------------------
# Executing a page through the book's configuration


def test_executing_an_experiment_page_writes_nothing_into_the_checkout(tmp_path):
    """The build executes experiments with their default run redirected into _build/.../default-runs."""
    before = _git_status()
    env = {k: v for k, v in os.environ.items() if k != DEFAULT_RUN_ENV}
    name = "rp2-morse"
    proc = jupyter_book(BOOK / "experiments" / f"{name}.ipynb", build_config(tmp_path, execute_notebooks="force"),
                        tmp_path, env=env)
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    assert "running over TCP without encryption" not in proc.stdout + proc.stderr
    assert _git_status() == before, "executing a page changed files of the checkout"
    (written,) = (tmp_path / "_build").rglob(f"default-runs/{name}/results.json")
    assert written.read_bytes() == (ROOT / "experiments" / "results" / name / "results.json").read_bytes()
