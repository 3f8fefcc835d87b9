"""The report page's MyST (lab.report_page): badges, the counts table and chart, linked places, the tables."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from thesis_lib.lab import report_page as rp  # noqa: E402
from thesis_lib.lab.report import BADGES, COULD_FAIL, STATUSES, provenance_text  # noqa: E402

COUNTS = {"by_chapter": {"front": {"erratum": 1}, "2": {"reproduced": 4, "identity": 2, "differs": 1},
                         "3": {"reproduced": 1, "new": 3}},
          "by_provenance": {"computed": 5, "typed": 2}}


def test_every_status_has_a_badge_a_colour_and_a_legend_line():
    legend = rp.status_legend()
    for s in STATUSES:
        assert rp.badge(s) == f"{{bdg-{BADGES[s]}}}`{s}`" and s in rp.STATUS_COLOURS
        assert f"* {rp.badge(s)}:" in legend
    first = legend.index("Shown apart")
    assert all(legend.index(rp.badge(s)) < first for s in COULD_FAIL)


def test_the_counts_table_sums_rows_and_columns():
    lines = rp.counts_table(COUNTS).splitlines()
    assert lines[2] == "| status | front | ch. 2 | ch. 3 | all |"
    assert f"| {rp.badge('reproduced')} | 0 | 4 | 1 | 5 |" in lines
    assert "| *could have failed* | **1** | **5** | **1** | **7** |" in lines  # reproduced + erratum + differs
    assert lines[-2] == "| **all** | **1** | **7** | **1** | **9** |"  # 'new' is not a claim of the thesis
    assert not any("new" in line for line in lines)


def test_the_chart_stacks_each_status_in_its_colour():
    fig = rp.plot_status_counts(COUNTS)
    ax = fig.axes[0]
    assert [t.get_text() for t in ax.get_yticklabels()] == ["front matter", "chapter 2", "chapter 3"]
    widths = {c.get_label(): [round(p.get_width()) for p in c] for c in ax.containers}
    assert widths["reproduced"] == [0, 4, 1] and widths["new"] == [0, 0, 3] and "consistent" not in widths
    plt.close(fig)


def test_places_link_to_labels_or_pages_and_tables_carry_their_names():
    assert rp.place({"where": "§2.4", "link": "ch2-persistence"}) == "{doc}`§2.4 <ch2-persistence>`"
    assert rp.place({"where": "§2.4"}) == "§2.4"
    row = {"where": "Ex. 2.38", "link": "p#l", "thesis": 3, "compared_as": "—", "ours": 3, "status": "reproduced",
           "provenance": "computed", "note": ""}
    table = rp.claims_table([row], name="tbl-x", caption="Cap")
    assert table.startswith(":::{table} Cap\n:name: tbl-x\n") and table.endswith("\n:::\n")
    assert "| {ref}`Ex. 2.38 <l>` | 3 | 3 | {bdg-success}`reproduced` *computed* |" in table
    assert rp.errata_table([row]) == "No erratum is registered."
    assert provenance_text(COUNTS) == "5 computed, 2 typed"  # the known ones in their order, any other after
