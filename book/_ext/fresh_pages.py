"""Pages that read stored files are re-read and re-executed on every build.

Sphinx re-reads only the sources that changed, and jupyter-cache re-executes only the notebooks
whose code changed; a page such as the reproduction report reads files that neither of them sees
(the claim registry, the stored results), so an incremental build would keep it stale. A notebook
whose metadata asks MyST-NB to execute it every time (``"mystnb": {"execution_mode": "force"}``)
is marked out of date on every build here, so that it is.
"""

from __future__ import annotations

import json
from pathlib import Path


def forced_pages(env) -> list[str]:
    """Documents of ``env`` that are notebooks with MyST-NB execution mode ``force``."""
    pages = []
    for docname in sorted(env.found_docs):
        path = Path(env.doc2path(docname))
        if path.suffix == ".ipynb":
            metadata = json.loads(path.read_text(encoding="utf-8")).get("metadata", {})
            if metadata.get("mystnb", {}).get("execution_mode") == "force":
                pages.append(docname)
    return pages


def _outdated(app, env, added, changed, removed) -> list[str]:
    return [page for page in forced_pages(env) if page not in added and page not in changed]


def setup(app):
    app.connect("env-get-outdated", _outdated)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
