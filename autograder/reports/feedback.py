"""One self-contained HTML feedback page per student.

It shows the score per lesson and exercise, every failed check with its
one-line reason and hint, what the student's code printed (truncated), and
the notebook stage. An exercise left as its stub gets one line, not one per
check, and so does a notebook that could not be read
(:mod:`autograder.reports.not_written`). It never shows a hidden test's source: only the
sentence that describes each check. Everything that came from a student
(ids, messages, printed text) is HTML-escaped and bounded
(:func:`~autograder.lessons.untrusted_text.html_text`).
"""

from __future__ import annotations

from autograder.grading.results import StudentResult
from autograder.lessons.untrusted_text import html_text
from autograder.reports.not_written import unwritten_functions
from autograder.sandbox.launcher import LIMITS_ONLY_WARNING

STYLE = """
body { font-family: system-ui, -apple-system, Segoe UI, Roboto, sans-serif; max-width: 60rem;
       margin: 2rem auto; padding: 0 1rem; color: #1d1d1f; line-height: 1.45; }
h1 { font-size: 1.6rem; margin-bottom: .2rem; } h2 { margin-top: 2rem; border-bottom: 1px solid #ddd; }
h3 { margin: 1.2rem 0 .3rem; font-size: 1.05rem; }
.score { font-size: 1.25rem; } .muted { color: #666; } .ok { color: #1a7f37; } .bad { color: #b42318; }
.partial { color: #9a6700; }
table { border-collapse: collapse; margin: .6rem 0; } td, th { padding: .25rem .8rem; text-align: left; }
tr:nth-child(even) { background: #f6f8fa; } th { border-bottom: 2px solid #ddd; }
ul.checks { list-style: none; padding-left: .5rem; } ul.checks li { margin: .35rem 0; }
.hint { display: block; margin-left: 1.4rem; color: #555; }
pre { background: #f6f8fa; padding: .6rem; overflow-x: auto; max-height: 18rem; white-space: pre-wrap; }
details { margin: .3rem 0 .3rem .5rem; } .note { background: #fff8c5; padding: .4rem .6rem; }
"""


def _e(text):
    return html_text(text)


def _points(points, max_points):
    return f"{points:g} / {max_points:g}"


def _css_class(points, max_points):
    if max_points and points >= max_points:
        return "ok"
    return "bad" if points <= 0 else "partial"


def _plural(count, noun):
    return f"{count} {noun}" + ("" if count == 1 else "s")


def _names(names):
    """``rot_x``, ``rot_x and rot_y``, ``rot_x, rot_y and rot_z``, as HTML code."""
    shown = [f"<code>{_e(name)}</code>" for name in names]
    return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " and " + shown[-1]


def _exercise_html(exercise):
    klass = _css_class(exercise.points, exercise.max_points)
    parts = [
        f'<h3 id="{_e(exercise.name)}"><code>{_e(exercise.name)}</code> '
        f'<span class="{klass}">{_points(exercise.points, exercise.max_points)}</span></h3>'
    ]
    for note in exercise.notes:
        parts.append(f'<p class="note">{_e(note)}</p>')
    failed = [c for c in exercise.checks if not c.passed]
    passed = [c for c in exercise.checks if c.passed]
    stubs = unwritten_functions(exercise)
    if stubs:
        needs = (
            ""
            if stubs == [exercise.name]
            else f" (it needs {_names(stubs)}, which {'is' if len(stubs) == 1 else 'are'} not written yet)"
        )
        parts.append(
            f'<p><span class="bad">✗</span> Not written yet{_e(needs)}: '
            f"{_plural(len(failed), 'check')} could not run. Write {_names(stubs)}, "
            "then run the check cell under it in your notebook.</p>"
        )
        failed = []
    if failed:
        items = []
        for check in failed:
            item = f'<li><span class="bad">✗</span> {_e(check.description)}'
            if check.reason:
                item += f": {_e(check.reason)}"
            if check.hint:
                item += f'<span class="hint">hint: {_e(check.hint)}</span>'
            items.append(item + "</li>")
        parts.append('<ul class="checks">' + "".join(items) + "</ul>")
    if passed:
        items = "".join(f'<li><span class="ok">✓</span> {_e(c.description)}</li>' for c in passed)
        label = "1 check passed" if len(passed) == 1 else f"{len(passed)} checks passed"
        parts.append(f'<details><summary>{label}</summary><ul class="checks">{items}</ul></details>')
    if not exercise.checks and not exercise.notes:
        parts.append('<p class="muted">No checks ran for this exercise.</p>')
    printed = "".join(dict.fromkeys(c.printed for c in exercise.checks if c.printed))
    if printed:
        parts.append(
            "<details><summary>what your code printed while being checked</summary>"
            f"<pre>{_e(printed[:4000])}</pre></details>"
        )
    return "\n".join(parts)


def _lesson_html(lesson):
    title = f"Lesson {lesson.number}" + (f" — {lesson.title}" if lesson.title else "")
    parts = [
        f'<h2 id="lesson-{_e(lesson.number)}">{_e(title)} '
        f'<span class="{_css_class(lesson.points, lesson.max_points)}">'
        f"{_points(lesson.points, lesson.max_points)}</span></h2>",
        f'<p class="muted">notebook: <code>{_e(lesson.notebook)}</code></p>',
    ]
    if lesson.late_penalty:
        parts.append(
            f'<p class="note">Late: {_e(lesson.late_note)}. Points before the penalty: '
            f"{_points(lesson.raw_points, lesson.max_points)}.</p>"
        )
    if lesson.status == "missing":
        return "\n".join(
            parts[:1]
            + [
                f'<p class="note">{_e(lesson.reason)}: its '
                f"{_plural(len(lesson.exercises), 'exercise')} earned no points.</p>"
            ]
        )
    if lesson.status != "graded":  # one line: each check would only repeat why the notebook could not be read
        names = [e.name for e in lesson.exercises]
        parts.append(
            f'<p class="note"><span class="bad">✗</span> This notebook could not be graded, so its '
            f"{_plural(len(names), 'exercise')} ({_names(names)}) earned no points: {_e(lesson.reason)}. "
            "Hand in a copy that opens in JupyterLab; if yours no longer opens, copy your answers into "
            "a fresh copy of the lesson's notebook.</p>"
        )
        return "\n".join(parts)
    for exercise in lesson.exercises:
        parts.append(_exercise_html(exercise))
    if lesson.run is not None:
        run = lesson.run
        verdict = {
            "passed": "Your answers, placed in the reference notebook, ran top to bottom and reproduced "
            "its printed outputs.",
            "failed": "Your answers, placed in the reference notebook, did not run cleanly:",
            "skipped": "Your answers were not run in the reference notebook:",
        }.get(run.status, run.status)
        parts.append(
            f'<h3>Notebook run <span class="{_css_class(run.points, run.max_points)}">'
            f"{_points(run.points, run.max_points)}</span></h3>"
            f"<p>{_e(verdict)}</p>"
        )
        if run.failures:
            failures = [f.removeprefix("not run: ") for f in run.failures]  # the sentence above says it
            parts.append('<ul class="checks">' + "".join(f"<li>{_e(f)}</li>" for f in failures) + "</ul>")
    return "\n".join(parts)


def feedback_html(result: StudentResult) -> str:
    """The feedback page for one :class:`~autograder.grading.results.StudentResult`."""
    rows = "".join(
        f'<tr><td><a href="#lesson-{_e(lesson.number)}">{_e(lesson.number)}</a></td><td>{_e(lesson.title)}</td>'
        f'<td class="{_css_class(lesson.points, lesson.max_points)}">{_points(lesson.points, lesson.max_points)}</td></tr>'
        for lesson in result.lessons
    )
    problems = ""
    if result.reason or result.problems:
        items = "".join(f"<li>{_e(p)}</li>" for p in ([result.reason] if result.reason else []) + result.problems)
        problems = f"<h2>Worth a look</h2><ul>{items}</ul>"
    lessons = "\n".join(_lesson_html(lesson) for lesson in result.lessons)
    if result.skipped:
        lessons += (
            '\n<h2>Not looked at</h2><p class="muted">What your folder holds that the grader did not '
            "read (hidden, a link, too deep):</p><ul>" + "".join(f"<li>{_e(s)}</li>" for s in result.skipped) + "</ul>"
        )
    isolation = f'<p class="note">{_e(LIMITS_ONLY_WARNING)}</p>' if result.isolation == "limits" else ""
    raw = (
        f' <span class="muted">({_points(result.raw_score, result.max_score)} before late penalties)</span>'
        if result.raw_score != result.score
        else ""
    )
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Feedback — {_e(result.student_id)}</title><style>{STYLE}</style></head>
<body>
<h1>Feedback for {_e(result.student_id)}</h1>
<p class="score">Score: <strong>{_points(result.score, result.max_score)}</strong>{raw}
<span class="muted">— status: {_e(result.status)}</span></p>
{isolation}
<table><tr><th>lesson</th><th>title</th><th>points</th></tr>{rows}</table>
{problems}
{lessons}
<p class="muted">Each check is described by what it tests; the hidden tests themselves are not shown.
Re-run the check cells in your notebook after fixing an exercise.</p>
</body></html>
"""
