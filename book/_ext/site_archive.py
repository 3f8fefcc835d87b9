"""Pack the built site as ``_build/thesis-lab-book.zip`` for hosting anywhere.

The archive holds ``html/`` (every page links relatively, so it works unpacked at any path or from
``file://``). Entries are sorted and dated 1980-01-01, so the same site gives the same archive.
"""

from __future__ import annotations

import os
import zipfile
from pathlib import Path

ARCHIVE = "thesis-lab-book.zip"
_EPOCH = (1980, 1, 1, 0, 0, 0)


def write_archive(html: Path, target: Path) -> Path:
    """Zip the folder ``html`` into ``target`` (atomically: a temporary file, then a rename)."""
    tmp = target.with_name(target.name + ".tmp")
    with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for path in sorted(p for p in html.rglob("*") if p.is_file()):
            info = zipfile.ZipInfo(str(Path(html.name) / path.relative_to(html)), date_time=_EPOCH)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            archive.writestr(info, path.read_bytes())
    os.replace(tmp, target)
    return target


def _build_finished(app, exception) -> None:
    if exception is None and app.builder.format == "html":
        html = Path(app.outdir)
        write_archive(html, html.parent / ARCHIVE)


def setup(app):
    # after the other build-finished handlers (offline_mathjax copies MathJax into the site)
    app.connect("build-finished", _build_finished, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
