"""The class report: what the class struggled with, at a glance.

One self-contained HTML page (plots embedded as PNG) with the score
distribution, the students (sortable, each linked to their feedback page, with
late and missing lessons), and per exercise the share of students who earned
full marks, the mean points, and the most common failed checks with their hints
(untouched stubs and unreadable notebooks are counted apart from real mistakes). Student
ids and messages are HTML-escaped and bounded. Students who could not be graded or
handed in nothing are listed, not averaged in, and so is what the run skipped.
"""

from __future__ import annotations

import base64
import io
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from autograder.grading.results import COULD_NOT_GRADE, MISSING, StudentResult
from autograder.lessons.catalog import Catalog, Exercise
from autograder.lessons.untrusted_text import html_text as escape
from autograder.reports.attention import stage_warnings, worth_a_look
from autograder.reports.class_students import STYLE as TABLE_STYLE
from autograder.reports.class_students import students_table_html
from autograder.reports.copied_times import copied_times_warning
from autograder.reports.lateness import due_dates, late_summary
from autograder.reports.not_written import unwritten_functions
from autograder.sandbox.launcher import LIMITS_ONLY_WARNING

STYLE = """
body { font-family: system-ui, -apple-system, Segoe UI, Roboto, sans-serif; max-width: 70rem;
       margin: 2rem auto; padding: 0 1rem; color: #1d1d1f; line-height: 1.45; }
table { border-collapse: collapse; margin: .8rem 0; width: 100%; }
td, th { padding: .3rem .6rem; text-align: left; vertical-align: top; border-bottom: 1px solid #eee; }
th { border-bottom: 2px solid #ccc; } .num { text-align: right; white-space: nowrap; }
.bar { background: #d0e6ff; height: .8rem; display: inline-block; } .muted { color: #666; }
img { max-width: 100%; } ol { margin: 0; padding-left: 1.2rem; } li { margin: .15rem 0; }
.warning { background: #fff8c5; border-left: 4px solid #d4a72c; padding: .5rem .8rem; }
"""


def _png(fig):
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return base64.b64encode(buffer.getvalue()).decode("ascii")


def score_histogram(percentages: list[float]) -> str:
    """PNG (base64) of the distribution of scores in percent of the maximum."""
    fig, ax = plt.subplots(figsize=(7.5, 3.2))
    ax.hist(percentages, bins=[i * 10 for i in range(11)], color="tab:blue", edgecolor="white")
    ax.set_xlabel("score [% of the maximum]")
    ax.set_ylabel("students")
    ax.set_title("Score distribution")
    ax.set_xlim(0, 100)
    ax.yaxis.get_major_locator().set_params(integer=True)
    return _png(fig)


def pass_rate_chart(names: list[str], shares: list[float]) -> str:
    """PNG (base64) of the share of students with full marks, one bar per exercise."""
    fig, ax = plt.subplots(figsize=(7.5, 0.28 * len(names) + 1.2))
    positions = list(range(len(names)))[::-1]
    colors = ["tab:green" if s >= 0.8 else "tab:orange" if s >= 0.5 else "tab:red" for s in shares]
    ax.barh(positions, [100 * s for s in shares], color=colors)
    ax.set_yticks(positions, names, fontsize=8)
    ax.set_ylim(-0.6, len(names) - 0.4)
    ax.set_xlim(0, 100)
    ax.set_xlabel("students with full marks [%]")
    ax.set_title("Which exercises the class got right")
    ax.grid(axis="x", alpha=0.3)
    return _png(fig)


def exercise_summary(graded: list[StudentResult], catalog: Catalog) -> list[tuple[Exercise, float, float, list, dict]]:
    """Per exercise: (exercise, share with full marks, mean points, [(count, description, hint)],
    {"stub": students who left it unwritten, "no notebook": students whose notebook was absent or unreadable}).

    The failed checks count real attempts only: a stub or an unreadable notebook fails every check for
    one reason, counted once in the last item instead."""
    rows = []
    for exercise in catalog.exercises:
        entries = [
            (e, lesson) for r in graded for lesson in r.lessons for e in lesson.exercises if e.name == exercise.name
        ]
        if not entries:
            continue
        full = sum(1 for e, _ in entries if e.points >= e.max_points) / len(entries)
        mean = sum(e.points for e, _ in entries) / len(entries)
        reasons, apart = Counter(), Counter()
        for entry, lesson in entries:
            if lesson.status != "graded":
                apart["no notebook"] += 1
                continue
            if unwritten_functions(entry):
                apart["stub"] += 1
                continue
            seen = set()
            for check in entry.checks:
                if not check.passed:
                    key = (check.description.split(" [")[0], check.hint or _kind(check.reason))
                    if key not in seen:
                        seen.add(key)
                        reasons[key] += 1
        common = [(count, description, hint) for (description, hint), count in reasons.most_common(3)]
        rows.append((exercise, full, mean, common, apart))
    return rows


def _kind(reason):
    """A failure reason without its numbers, so similar failures group together."""
    for marker in ("is not written yet", "did not return within", "raised", "returned shape", "returned None"):
        if marker in reason:
            return reason[reason.index(marker) :].split(":")[0].split("(")[0].strip()
    return ""


def _worth_a_look_html(concerns):
    if not concerns:
        return "<h2>Worth a look</h2><p class='muted'>No attempted tampering, timeout or crash in this run.</p>"
    rows = "".join(
        f"<tr><td><code>{escape(c.student_id)}</code></td><td>{escape(c.kind)}</td>"
        f'<td class="num">{c.count}</td><td>{escape(c.example)}</td></tr>'
        for c in concerns
    )
    return (
        "<h2>Worth a look</h2><p>Attempted tampering, timeouts and crashes: each cost only its own "
        "points, but deserves a look at the student's feedback page.</p><table><tr><th>student</th>"
        f'<th>what</th><th class="num">times</th><th>for example</th></tr>{rows}</table>'
    )


def _skipped_html(skipped, results, shown=200):
    """What the run did not grade: entries of the submissions folder (``skipped``: ``Skipped``), and
    per student what the walk of their folder skipped."""
    inside = [(r.student_id, r.skipped) for r in results if r.skipped]
    if not skipped and not inside:
        return ""
    parts = ["<h2>Skipped</h2>"]
    if skipped:
        rows = "".join(f"<li><code>{escape(s.path, 300)}</code>: {escape(s.why)}</li>" for s in skipped[:shown])
        more = f"<li>and {len(skipped) - shown} more</li>" if len(skipped) > shown else ""
        parts.append(f"<p>In the submissions folder, not graded as students:</p><ul>{rows}{more}</ul>")
    if inside:
        rows = "".join(
            f"<li><code>{escape(student, 300)}</code>: "
            + "; ".join(escape(line, 300) for line in lines[:5])
            + (f"; and {len(lines) - 5} more (see the feedback page)" if len(lines) > 5 else "")
            + "</li>"
            for student, lines in inside[:shown]
        )
        parts.append(f"<p>Inside students' folders, not read (hidden, links, too deep):</p><ul>{rows}</ul>")
    return "\n".join(parts)


def _not_attempted(apart):
    parts = ([f"{apart['stub']} left as the stub"] if apart["stub"] else []) + (
        [f"{apart['no notebook']} without a readable notebook"] if apart["no notebook"] else []
    )
    return ", ".join(parts) or '<span class="muted">none</span>'


def class_report_html(
    results: list[StudentResult],
    catalog: Catalog,
    title: str = "Class report",
    skipped: tuple = (),
    linked: frozenset = frozenset(),
    extra_sections: tuple = (),
) -> str:
    """The report page for a list of StudentResult; ``skipped``: entries of the submissions folder that
    are not students (:class:`~autograder.grading.submissions.Skipped`); ``linked``: the students whose
    feedback page exists (``feedback/<id>.html`` beside the report), linked from the students' table;
    ``extra_sections``: HTML fragments made by other stages (the similarity stage's), placed after the
    exercises, already escaped."""
    graded = [r for r in results if r.status not in (MISSING, COULD_NOT_GRADE)]
    missing = [r for r in results if r.status == MISSING]
    failed = [r for r in results if r.status == COULD_NOT_GRADE]
    parts = [
        f"<h1>{escape(title)}</h1>",
        f"<p>{len(results)} student{'' if len(results) == 1 else 's'}: {len(graded)} graded, "
        f"{len(failed)} could not be graded, {len(missing)} missing.</p>",
    ]
    limited = [r for r in results if r.isolation == "limits"]
    if limited:
        parts.append(
            f'<p class="warning"><strong>{len(limited)} of {len(results)} students were graded with '
            f"resource limits only.</strong> {escape(LIMITS_ONLY_WARNING)}</p>"
        )
    parts += [
        f'<p class="warning"><strong>Check the grader:</strong> {escape(w.text)}</p>' for w in stage_warnings(results)
    ]
    copied = copied_times_warning(results)
    if copied:
        parts.append(f'<p class="warning"><strong>Warning:</strong> {escape(copied)}</p>')
    due = due_dates(results)
    if due:
        parts.append(
            f"<p>Due: {escape(due)}. Late: {sum(1 for r in results if late_summary(r))} of {len(results)} students.</p>"
        )
    parts.append(_worth_a_look_html(worth_a_look(results)))
    parts.append(students_table_html(results, linked))
    if graded:
        percentages = [100 * r.score / r.max_score if r.max_score else 0.0 for r in graded]
        mean = sum(percentages) / len(percentages)
        ordered = sorted(percentages)
        median = (
            ordered[len(ordered) // 2]
            if len(ordered) % 2
            else (ordered[len(ordered) // 2 - 1] + ordered[len(ordered) // 2]) / 2
        )
        parts.append(f"<p>Mean score {mean:.0f}%, median {median:.0f}%.</p>")
        parts.append(f'<img alt="score distribution" src="data:image/png;base64,{score_histogram(percentages)}">')
        summary = exercise_summary(graded, catalog)
        if summary:
            parts.append(
                f'<img alt="pass rate per exercise" src="data:image/png;base64,'
                f'{pass_rate_chart([e.name for e, *_ in summary], [s for _, s, *_ in summary])}">'
            )
            parts.append(
                "<h2>Exercises</h2><table><tr><th>lesson</th><th>exercise</th>"
                '<th class="num">full marks</th><th class="num">mean</th>'
                "<th>most common failed checks (students)</th><th>not attempted (students)</th></tr>"
            )
            for exercise, share, mean_points, common, apart in summary:
                reasons = "".join(
                    f"<li>{escape(description)} <span class='muted'>({count})"
                    + (f" — {escape(hint)}" if hint else "")
                    + "</span></li>"
                    for count, description, hint in common
                )
                parts.append(
                    f"<tr><td>{escape(exercise.lesson)}</td><td><code>{escape(exercise.name)}</code></td>"
                    f'<td class="num"><span class="bar" style="width:{40 * share:.0f}px"></span> '
                    f"{100 * share:.0f}%</td>"
                    f'<td class="num">{mean_points:.2f} / {exercise.points:g}</td>'
                    f"<td><ol>{reasons}</ol></td><td>{_not_attempted(apart)}</td></tr>"
                )
            parts.append("</table>")
        runs = {}  # lesson -> statuses of its notebook runs ("passed", "failed", "skipped")
        for r in graded:
            for lesson in r.lessons:
                if lesson.run is not None:
                    runs.setdefault(lesson.number, []).append(lesson.run.status)
        if runs:
            parts.append(
                "<h2>Notebook stage (nbval)</h2>"
                '<p class="muted">nbval runs only the notebooks whose lesson has full marks on the '
                "hidden checks: the point needs them, so the others are not run.</p>"
                '<table><tr><th>lesson</th><th class="num">ran and reproduced the reference</th>'
                '<th class="num">ran</th><th class="num">not run (hidden points lost)</th></tr>'
            )
            for number, statuses in sorted(runs.items()):
                ran = [s for s in statuses if s != "skipped"]
                parts.append(
                    f'<tr><td>{escape(number)}</td><td class="num">'
                    f'{ran.count("passed")} / {len(ran)}</td><td class="num">{len(ran)}</td>'
                    f'<td class="num">{len(statuses) - len(ran)}</td></tr>'
                )
            parts.append("</table>")
    if failed or missing:
        parts.append("<h2>Not graded</h2><ul>")
        for r in failed + missing:
            parts.append(
                f"<li><code>{escape(r.student_id)}</code>: {escape(r.status)}"
                + (f" — {escape(r.reason)}" if r.reason else "")
                + "</li>"
            )
        parts.append("</ul>")
    parts += [section for section in extra_sections if section]
    parts.append(_skipped_html(list(skipped), results))
    body = "\n".join(parts)
    return (
        f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>{escape(title)}</title>'
        f"<style>{STYLE}{TABLE_STYLE}</style></head><body>{body}</body></html>\n"
    )
