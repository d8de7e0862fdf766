"""The page written when a full page (feedback or class report) could not be made.

It needs nothing but the results' ids, statuses, scores, reasons and problems,
each escaped and bounded, so a result that breaks the full page still leaves
the instructor a page that says who got what and why.

Examples
--------
>>> page = plain_page("Class report", results, "the full report could not be made (ValueError: ...)")  # doctest: +SKIP
"""

from __future__ import annotations

from autograder.grading.results import StudentResult
from autograder.lessons.untrusted_text import html_text

MAX_PROBLEMS = 20  # listed per student


def plain_page(title: str, results: list[StudentResult], why: str) -> str:
    """An HTML page: ``title``, ``why`` the full page is missing, then one entry per result."""
    items = []
    for result in results:
        try:
            score = f"{result.score:g} / {result.max_score:g}"
        except Exception:  # a result too damaged to add up: its status and reason still say enough
            score = "—"
        lines = ([result.reason] if result.reason else []) + list(result.problems)[:MAX_PROBLEMS]
        details = "".join(f"<li>{html_text(line, 2000)}</li>" for line in lines)
        items.append(
            f"<li><code>{html_text(result.student_id, 300)}</code>: {score}, {html_text(result.status)}"
            f"<ul>{details}</ul></li>"
        )
    return (
        f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{html_text(title)}</title></head>'
        f"<body><h1>{html_text(title)}</h1><p>{html_text(why)}</p><ul>{''.join(items)}</ul></body></html>\n"
    )
