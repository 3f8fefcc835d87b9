"""Cite the thesis's references with the thesis's own labels ([MDSB02], [ABK98], ...).

``book/references.bib`` keys its entries by the labels the thesis prints; this extension registers
a pybtex style (``thesis``) whose label is the entry key, so that ``{cite}`ABK98``` renders as
[ABK98] and links to the entry on the references page. Entries are sorted by author, year, title.
"""

from __future__ import annotations

from pybtex.plugin import register_plugin
from pybtex.style.formatting.unsrt import Style as UnsrtStyle
from pybtex.style.labels import BaseLabelStyle


class KeyLabelStyle(BaseLabelStyle):
    """The label of an entry is its key."""

    def format_labels(self, sorted_entries):
        for entry in sorted_entries:
            yield entry.key


class ThesisStyle(UnsrtStyle):
    """pybtex's ``alpha`` formatting with the thesis's keys as labels."""

    default_sorting_style = "author_year_title"
    default_label_style = "thesis-keys"


def setup(app):
    register_plugin("pybtex.style.labels", "thesis-keys", KeyLabelStyle, force=True)
    register_plugin("pybtex.style.formatting", "thesis", ThesisStyle, force=True)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
