"""The reproduction report as the book's report page shows it: MyST badges for the statuses, the thesis
places linked to where the book computes each claim, the counts by chapter as a table and a chart.

:mod:`thesis_lib.lab.report` evaluates the claims and writes plain Markdown; this module writes the
page's MyST (``{bdg-…}`` badges, ``{ref}`` / ``{doc}`` links, ``:::{table}`` directives).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._optional import require
from .report import (
    BADGES,
    COULD_FAIL,
    PROVENANCE_LEGEND,
    PROVENANCES,
    STATUS_LEGEND,
    STATUSES,
    errata_markdown,
    table_cell,
    why,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["STATUS_COLOURS", "badge", "status_legend", "counts_table", "plot_status_counts",
           "place", "claims_table", "errata_table"]

#: the badges' colours in the book's theme, for the bar chart (figure-only a shade darker, to show on
#: white; the outlined badges of the statuses shown apart as paler shades of their colour)
STATUS_COLOURS = {"reproduced": "#00843f", "erratum": "#f66a0a", "differs": "#d72d47", "identity": "#8ccaa3",
                  "consistent": "#93b5f3", "not-comparable": "#6c7380", "figure-only": "#c4c8cf",
                  "not-reproducible": "#29313d", "new": "#0a7d91"}


def badge(status: str) -> str:
    """A status as the page's MyST badge.

    Thesis: none (the report's page).

    Parameters
    ----------
    status : str
        One of ``STATUSES``.

    Returns
    -------
    str
        ``{bdg-<colour>}`<status>```.

    Examples
    --------
    >>> badge("reproduced")
    '{bdg-success}`reproduced`'
    """
    return f"{{bdg-{BADGES[status]}}}`{status}`"


def status_legend() -> str:
    """The legend of the statuses (those that could have failed first) and of the inputs.

    Thesis: none (the report's page).

    Returns
    -------
    str
        MyST lists, one line per status and per provenance.

    Examples
    --------
    >>> status_legend().splitlines()[0]
    'Could have failed:'
    """
    apart = [s for s in STATUSES if s not in COULD_FAIL and s != "new"]
    legend = ["Could have failed:", ""] + [f"* {badge(s)}: {STATUS_LEGEND[s]};" for s in COULD_FAIL]
    legend += ["", "Shown apart, never counted as reproduced:", ""]
    legend += [f"* {badge(s)}: {STATUS_LEGEND[s]};" for s in apart]
    legend += [f"* {badge('new')}: {STATUS_LEGEND['new']}."]
    legend += ["", "The input of each claim (in italics after its status):", ""]
    legend += [f"* `{p}`: {PROVENANCE_LEGEND[p]}{';' if p != PROVENANCES[-1] else '.'}" for p in PROVENANCES]
    return "\n".join(legend)


def counts_table(counts: dict[str, object]) -> str:
    """The thesis's claims by status (rows; those that could have failed first) and chapter (columns).

    Thesis: the checkable statements of each chapter.

    Parameters
    ----------
    counts : dict
        :func:`~thesis_lib.lab.report.summary` of the report.

    Returns
    -------
    str
        A ``:::{table}`` directive named ``tbl-report-counts``; the line "could have failed" after the
        last status that could, and the totals in bold.

    Examples
    --------
    >>> print(counts_table({"by_chapter": {"2": {"reproduced": 2, "identity": 1}}}).splitlines()[-2])
    | **all** | **3** | **3** |
    """
    chapters = list(counts["by_chapter"])
    shown = [s for s in STATUSES if s != "new" and any(s in c for c in counts["by_chapter"].values())]
    lines = ["| status | " + " | ".join(f"ch. {c}" if c.isdigit() else c for c in chapters) + " | all |",
             "|---|" + "---:|" * (len(chapters) + 1)]

    def line(title: str, statuses: list[str] | tuple[str, ...], bold: bool = False) -> str:
        n = [sum(counts["by_chapter"][c].get(s, 0) for s in statuses) for c in chapters]
        cells = [str(k) for k in n] + [str(sum(n))]
        return f"| {title} | " + " | ".join(f"**{k}**" if bold else k for k in cells) + " |"

    for s in shown:
        lines.append(line(badge(s), [s]))
        if s == COULD_FAIL[-1]:
            lines.append(line("*could have failed*", COULD_FAIL, bold=True))
    lines.append(line("**all**", shown, bold=True))
    head = ":::{table} Claims of the thesis by status and chapter\n:name: tbl-report-counts\n"
    return head + "\n".join(lines) + "\n:::\n"


def plot_status_counts(counts: dict[str, object]) -> Figure:
    """The thesis's claims per chapter as stacked horizontal bars, one colour per status.

    Thesis: the checkable statements of each chapter.

    Parameters
    ----------
    counts : dict
        :func:`~thesis_lib.lab.report.summary` of the report.

    Returns
    -------
    matplotlib.figure.Figure
        One bar per chapter (the front matter named so), the legend above.

    Raises
    ------
    ImportError
        If matplotlib is not installed (the ``[plot]`` extra).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig = plot_status_counts({"by_chapter": {"2": {"reproduced": 2}, "front": {"erratum": 1}}})
    >>> [t.get_text() for t in fig.axes[0].get_yticklabels()]
    ['chapter 2', 'front matter']
    >>> plt.close(fig)
    """
    plt = require("matplotlib.pyplot", extra="plot", purpose="drawing the report's counts")
    chapters = list(counts["by_chapter"])
    names = [f"chapter {c}" if c.isdigit() else "front matter" if c == "front" else c for c in chapters]
    fig, ax = plt.subplots(figsize=(7.0, 0.45 * len(chapters) + 1.3))
    left = [0] * len(chapters)
    for s in STATUSES:
        n = [counts["by_chapter"][c].get(s, 0) for c in chapters]
        if any(n):
            ax.barh(names, n, left=left, color=STATUS_COLOURS[s], label=s)
            left = [a + b for a, b in zip(left, n)]
    ax.invert_yaxis()
    ax.set_xlabel("claims")
    ax.legend(ncols=4, frameon=False, loc="lower center", bbox_to_anchor=(0.5, 1.0))
    return fig


def place(row: dict[str, object]) -> str:
    """A claim's thesis place, linked to where the book computes it (its ``link``: ``page#label``).

    Thesis: the place of the statement in the thesis.

    Parameters
    ----------
    row : dict
        A report row.

    Returns
    -------
    str
        A ``{ref}`` link to the label, a ``{doc}`` link to the page, or the place as text.

    Examples
    --------
    >>> place({"where": "Example 2.38", "link": "ch2-persistence#sec-2-38"})
    '{ref}`Example 2.38 <sec-2-38>`'
    """
    link = row.get("link")
    if not link:
        return table_cell(row["where"])
    page, _, label = str(link).partition("#")
    where = table_cell(row["where"])
    return f"{{ref}}`{where} <{label}>`" if label else f"{{doc}}`{where} <{page}>`"


def claims_table(rows: list[dict[str, object]], *, name: str, caption: str) -> str:
    """Report rows as the page's table: place, the thesis's statement and how it is compared, ours,
    the status badge and the input, why.

    Thesis: the checkable statements, each beside our result.

    Parameters
    ----------
    rows : list of dict
        The report rows to show.
    name : str
        The table's label.
    caption : str
        Its caption.

    Returns
    -------
    str
        A ``:::{table}`` directive.

    Examples
    --------
    >>> claims_table([], name="tbl-x", caption="None").splitlines()[:2]
    [':::{table} None', ':name: tbl-x']
    """
    def thesis_cell(row: dict[str, object]) -> str:
        test = row["compared_as"]
        return table_cell(row["thesis"]) + ("" if test == "—" else f" — *compared as* {table_cell(test)}")

    lines = ["| thesis place | thesis — compared as | ours | status, *input* | why |", "|---|---|---|---|---|"]
    lines += [f"| {place(r)} | {thesis_cell(r)} | {table_cell(r['ours'])} "
              f"| {badge(str(r['status']))} *{r.get('provenance') or ''}* | {table_cell(why(r))} |" for r in rows]
    return f":::{{table}} {caption}\n:name: {name}\n" + "\n".join(lines) + "\n:::\n"


def errata_table(rows: list[dict[str, object]]) -> str:
    """The errata as the page's table (places linked), or a sentence saying there is none.

    Thesis: the errata of every chapter, each beside its correction.

    Parameters
    ----------
    rows : list of dict
        The report rows (only the errata are shown).

    Returns
    -------
    str
        A ``:::{table}`` directive named ``tbl-report-errata``, or "No erratum is registered.".

    Examples
    --------
    >>> errata_table([])
    'No erratum is registered.'
    """
    errata = errata_markdown(rows, place=place)
    return f":::{{table}} Errata of the thesis\n:name: tbl-report-errata\n{errata}:::\n" if errata else \
        "No erratum is registered."
