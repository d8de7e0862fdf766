"""The class report's list of students: one row each, sortable by any column without a server.

Each row links the student's feedback page (a relative path, so the results folder can be moved or
zipped), and says the score, the status, the lessons handed in late and what each cost, and the lessons
not handed in or not readable. A small inline script sorts the rows when a column's button is pressed
(and sets ``aria-sort``); without scripts the table stays sorted by student id.

Examples
--------
>>> html = students_table_html(results, {"ana": "feedback/ana.html"})        # doctest: +SKIP
"""

from __future__ import annotations

from urllib.parse import quote

from autograder.grading.results import MISSING, StudentResult
from autograder.lessons.untrusted_text import html_text as escape
from autograder.lessons.untrusted_text import safe_name
from autograder.reports.lateness import late_summary

STYLE = """
table.sortable th button { font: inherit; font-weight: bold; background: none; border: 0; padding: 0;
  cursor: pointer; color: inherit; text-decoration: underline dotted; }
table.sortable th button:focus-visible { outline: 2px solid #0969da; }
"""

SCRIPT = """
document.querySelectorAll("table.sortable").forEach(function (table) {
  var buttons = table.querySelectorAll("thead th button");
  buttons.forEach(function (button, column) {
    button.addEventListener("click", function () {
      var head = button.parentElement, ascending = head.getAttribute("aria-sort") !== "ascending";
      table.querySelectorAll("thead th").forEach(function (th) { th.removeAttribute("aria-sort"); });
      buttons.forEach(function (b) { b.querySelector("span").textContent = ""; });
      head.setAttribute("aria-sort", ascending ? "ascending" : "descending");
      button.querySelector("span").textContent = ascending ? " \\u25B2" : " \\u25BC";
      var numeric = button.dataset.type === "number", body = table.tBodies[0];
      var rows = Array.prototype.slice.call(body.rows);
      rows.sort(function (a, b) {
        var x = a.cells[column].dataset.sort, y = b.cells[column].dataset.sort;
        if (numeric) { x = parseFloat(x); y = parseFloat(y); }
        return (x < y ? -1 : x > y ? 1 : 0) * (ascending ? 1 : -1);
      });
      rows.forEach(function (row) { body.appendChild(row); });
    });
  });
});
"""

COLUMNS = (
    ("student", "text"),
    ("score", "number"),
    ("%", "number"),
    ("status", "text"),
    ("late (penalty)", "text"),
    ("not handed in or unreadable", "text"),
)


def feedback_link(student_id: str) -> str:
    """The feedback page of ``student_id`` relative to the report (``feedback/<safe name>.html``, URL-quoted)."""
    return f"feedback/{quote(safe_name(student_id))}.html"


def _absent(result):
    if result.status == MISSING:
        return "everything"
    return ", ".join(
        lesson.number + ("" if lesson.status == "missing" else " (unreadable)")
        for lesson in result.lessons
        if lesson.status != "graded"
    )


def _cell(text, sort, number=False):
    klass = ' class="num"' if number else ""
    return f'<td{klass} data-sort="{escape(str(sort), 300)}">{text}</td>'


def students_table_html(results: list[StudentResult], linked: frozenset = frozenset()) -> str:
    """The sortable table of students; ``linked``: the ids that have a feedback page to link."""
    heads = "".join(
        f'<th scope="col"><button type="button" data-type="{kind}">{escape(name)}<span '
        'aria-hidden="true"></span></button></th>'
        for name, kind in COLUMNS
    )
    rows = []
    for result in sorted(results, key=lambda r: r.student_id):
        shown = f"<code>{escape(result.student_id, 300)}</code>"
        if result.student_id in linked:
            shown = f'<a href="{escape(feedback_link(result.student_id), 2000)}">{shown}</a>'
        share = 100 * result.score / result.max_score if result.max_score else -1
        score = f"{result.score:g} / {result.max_score:g}" if result.max_score else "—"
        late, absent = late_summary(result), _absent(result)
        status = result.status + (f" — {result.reason}" if result.reason else "")
        rows.append(
            "<tr>"
            + _cell(shown, result.student_id.lower())
            + _cell(score, result.score if result.max_score else -1, number=True)
            + _cell(f"{share:.0f}%" if share >= 0 else "—", share, number=True)
            + _cell(escape(status, 300), result.status)
            + _cell(escape(late) or '<span class="muted">none</span>', late)
            + _cell(escape(absent) or '<span class="muted">none</span>', absent)
            + "</tr>"
        )
    return (
        '<h2 id="students">Students</h2><table class="sortable"><caption class="muted">Sorted by student; '
        "press a column's heading to sort by it (again to reverse). Each name opens the student's feedback "
        f"page.</caption><thead><tr>{heads}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
        f"<script>{SCRIPT}</script>"
    )
