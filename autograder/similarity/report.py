"""What the similarity stage writes: a "Similar answers" section for the class report and a CSV.

Every student id and every line of code is escaped (code through copydetect's
escaping, ids by :func:`~autograder.lessons.untrusted_text.html_text`); matching
spans are marked with ``<mark>`` (an element screen readers announce, drawn
with an outline too, so colour is never the only cue). The wording is "worth a
look": nothing here says who copied whom, and nothing changes a grade.

Examples
--------
>>> html = similar_answers_html(findings)        # doctest: +SKIP
>>> "Similar answers" in html
True
"""

from __future__ import annotations

import csv
import io

from autograder.lessons.untrusted_text import csv_cell
from autograder.lessons.untrusted_text import html_text as escape
from autograder.similarity.findings import REFERENCE, Findings, Pair
from autograder.similarity.fingerprints import K, highlighted

LOCAL = (
    "Computed on this machine: no answer was sent anywhere. A finding is worth a look, not a verdict: "
    "answers can be alike because students worked together as allowed, followed the same lecture "
    "example or found the same obvious solution. Nothing here changes a grade."
)
STYLE = """
.side { display: grid; grid-template-columns: 1fr 1fr; gap: .6rem; }
.side pre { background: #f6f8fa; padding: .5rem; overflow-x: auto; font-size: .8rem; margin: .2rem 0; }
.side mark { background: #fff1a8; outline: 1px solid #9a7d00; }
"""
SHOWN_CLUSTERS = 50
SHOWN_VIEWS = 3  # side-by-side views per cluster


def _side_by_side(findings, pair):
    first = findings.fingerprint(pair.exercise, pair.first)
    second = findings.fingerprint(pair.exercise, pair.second)
    if first is None or second is None:
        return ""
    left, right = highlighted(first, second)
    return (
        f"<p><code>{escape(pair.exercise)}</code>: <code>{escape(pair.first)}</code> and "
        f"<code>{escape(pair.second)}</code>: {100 * pair.score:.0f}% of the shorter answer is shared "
        f"({pair.shared} runs of {K} characters of code in common, a name counting as one character; "
        f"this exercise's bar in this class: {100 * pair.threshold:.0f}%). "
        "Shared spans are <mark>marked</mark>.</p>"
        f'<div class="side"><div><p class="muted">{escape(pair.first)}</p><pre>{left}</pre></div>'
        f'<div><p class="muted">{escape(pair.second)}</p><pre>{right}</pre></div></div>'
    )


def _cluster_html(findings, number, cluster):
    members = ", ".join(f"<code>{escape(m)}</code>" for m in cluster.members)
    exercises = ", ".join(f"<code>{escape(e)}</code>" for e in cluster.exercises)
    shown, views = set(), []
    for pair in cluster.pairs:  # strongest first, one view per exercise
        if pair.exercise not in shown and len(views) < SHOWN_VIEWS:
            shown.add(pair.exercise)
            views.append(_side_by_side(findings, pair))
    return (
        f"<h3>Finding {number}: {len(cluster.members)} students, {len(cluster.exercises)} "
        f"exercise{'s' if len(cluster.exercises) > 1 else ''}, up to {100 * cluster.score:.0f}% shared</h3>"
        f"<p>Students: {members}. Exercises: {exercises}.</p>" + "".join(views)
    )


def reference_matches_by_student(findings: Findings) -> dict[str, list[Pair]]:
    """``{student: [reference-match Pair, ...]}``, students in order."""
    grouped = {}
    for pair in findings.reference_matches:
        grouped.setdefault(pair.first, []).append(pair)
    return grouped


def similar_answers_html(findings: Findings) -> str:
    """The "Similar answers" section (an HTML fragment with its own small style sheet)."""
    parts = [f"<style>{STYLE}</style><h2>Similar answers</h2><p>{escape(LOCAL)}</p>"]
    compared = sum(findings.compared.values())
    parts.append(
        f"<p class='muted'>{compared} answers compared over {len(findings.compared)} exercises "
        "(answers that are the untouched stub or too short to tell apart are left out).</p>"
    )
    if findings.clusters:
        parts.append(
            f"<p>{len(findings.clusters)} group{'s' if len(findings.clusters) > 1 else ''} of answers "
            "much more alike than this class's answers to the same exercise usually are: worth a look.</p>"
        )
        for number, cluster in enumerate(findings.clusters[:SHOWN_CLUSTERS], 1):
            parts.append(_cluster_html(findings, number, cluster))
        if len(findings.clusters) > SHOWN_CLUSTERS:
            parts.append(f"<p>and {len(findings.clusters) - SHOWN_CLUSTERS} more in similar_answers.csv.</p>")
    else:
        parts.append("<p class='muted'>No pair of students' answers stands out from the rest of the class.</p>")
    if findings.reference_matches:
        rows = "".join(
            f"<tr><td><code>{escape(student)}</code></td><td class='num'>{len(pairs)}</td><td>"
            + ", ".join(f"<code>{escape(p.exercise)}</code> {100 * p.score:.0f}%" for p in pairs)
            + "</td></tr>"
            for student, pairs in reference_matches_by_student(findings).items()
        )
        parts.append(
            "<h3>Answers close to the published reference solution</h3><p>The course's solutions are "
            "public: these answers share most of their fingerprints with the reference answer "
            "(names, comments and layout aside). Worth a look.</p>"
            "<table><tr><th>student</th><th class='num'>answers</th><th>exercises (shared)</th></tr>"
            f"{rows}</table>"
        )
        parts.append(_side_by_side(findings, findings.reference_matches[0]))
    if findings.unread:
        rows = "".join(
            f"<li><code>{escape(a)}</code>: {escape(why)}</li>" for a, why in sorted(findings.unread.items())
        )
        parts.append(f"<p>Folders that could not be read for this comparison:</p><ul>{rows}</ul>")
    return "\n".join(parts)


def similar_answers_csv(findings: Findings) -> str:
    """One row per flagged pair and per reference match: the finding it belongs to, the exercise, both
    authors, the score, the exercise's bar and the k-grams the two share (spreadsheet-safe cells)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["finding", "kind", "exercise", "first", "second", "score", "threshold", "shared_kgrams"])
    for number, cluster in enumerate(findings.clusters, 1):
        for pair in cluster.pairs:
            kind = "past term" if "/" in pair.first + pair.second else "students"
            writer.writerow(
                [
                    number,
                    kind,
                    csv_cell(pair.exercise),
                    csv_cell(pair.first),
                    csv_cell(pair.second),
                    f"{pair.score:.3f}",
                    f"{pair.threshold:.3f}",
                    pair.shared,
                ]
            )
    for pair in findings.reference_matches:
        writer.writerow(
            [
                "",
                "reference",
                csv_cell(pair.exercise),
                csv_cell(pair.first),
                REFERENCE,
                f"{pair.score:.3f}",
                f"{pair.threshold:.3f}",
                pair.shared,
            ]
        )
    return buffer.getvalue()
