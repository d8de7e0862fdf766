"""Lateness an instructor can trust, and feedback and a class report worth forwarding (issue 28, items 3 and 4).

One small class (lessons 01 and 02), graded once by the real command as an instructor types it, with a
course config whose due date has passed and no ``timestamp.txt``: every notebook's time is the moment
this test wrote it, as after a copy. Then ``status``, and one more grading with ``--ignore-mtimes``.
The class is graded with ``--layout nbgrader``: the instructor says that the times nbgrader recorded
(``<student>/<assignment>/timestamp.txt``) are to be read; in the default layout no student's file dates anything.

- ``ana``: every answer right;  ``bo``: the untouched release;  ``cy``: lesson 01 damaged by a text editor;
  ``dan``: one typical mistake;  ``eve``: lesson 01 only, right, with nbgrader's ``timestamp.txt`` two days
  after the due date;  ``zoe``: on the roster, handed in nothing.
"""

import csv
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

from autograder.lessons.paths import PROJECT_ROOT
from support import STUB, build_submission, mistakes
from support import THIS_COURSE

CATALOG = THIS_COURSE.catalog
FIRST, SECOND = CATALOG.lesson("01"), CATALOG.lesson("02")
LESSONS = (FIRST.number, SECOND.number)
MISTAKE = mistakes()["rot_z_transposed"]
CONFIG = f'''timezone = "Europe/Berlin"
[late_policy]
penalty_per_day = 0.1
max_penalty = 0.3
[lessons."{FIRST.number}"]
due = 2026-01-15T23:59:00
[lessons."{SECOND.number}"]
due = 2026-01-20T12:00:00
'''


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "autograder", *args], cwd=PROJECT_ROOT, capture_output=True, text=True, timeout=900
    )


def _rows(out):
    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        return {row["student_id"]: row for row in csv.DictReader(handle)}


def build_class(root):
    """The class of this module's docstring, in ``root``; returns the roster file."""
    build_submission(root / "ana", lessons=LESSONS)
    build_submission(root / "bo", default=STUB, lessons=LESSONS)
    cy = build_submission(root / "cy", lessons=LESSONS)
    damaged = cy / FIRST.filename
    damaged.write_text(damaged.read_text(encoding="utf-8")[:-200], encoding="utf-8")  # cut short: not JSON
    build_submission(root / "dan", {MISTAKE.exercise: MISTAKE.source}, lessons=LESSONS)
    eve = build_submission(root / "eve", lessons=(FIRST.number,))
    assignment = eve / f"lesson{FIRST.number}"  # nbgrader's layout: the time nbgrader recorded sits beside
    assignment.mkdir()  # the assignment's folder, the one trusted place for it
    (eve / FIRST.filename).rename(assignment / FIRST.filename)
    (assignment / "timestamp.txt").write_text("2026-01-17 20:00:00.000000 UTC", encoding="utf-8")
    roster = root.parent / "roster.csv"
    roster.write_text("id\nana\nbo\ncy\ndan\neve\nzoe\n", encoding="utf-8")
    return roster


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """``(out, grade's run, status's run, the class folder, the config file)``: one grading for the module."""
    root = tmp_path_factory.mktemp("forwarded")
    roster = build_class(root / "class")
    config = root / "course.toml"
    config.write_text(CONFIG, encoding="utf-8")
    out = root / "out"
    run = _run(
        "grade",
        str(root / "class"),
        "--out",
        str(out),
        "--lessons",
        *LESSONS,
        "--roster",
        str(roster),
        "--config",
        str(config),
        "--no-nbval",
        "--layout",
        "nbgrader",
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    status = _run("status", "--out", str(out), "--roster", str(roster))
    assert status.returncode == 0, status.stdout[-2000:] + status.stderr[-2000:]
    return out, run.stdout, status.stdout, root, config


def _line(text, student):
    return next(line for line in text.splitlines() if line.startswith(f"{student} "))


def _page(out, name):
    return (out / name).read_text(encoding="utf-8")


def _section(page, lesson):
    """The part of a feedback page about ``lesson``."""
    start = page.index(f'id="lesson-{lesson.number}"')
    end = page.find('id="lesson-', start + 1)
    return page[start : end if end > 0 else len(page)]


class Table(HTMLParser):
    """The class report's students table: rows of (cell text, the cell's link or None)."""

    def __init__(self):
        super().__init__()
        self.inside, self.rows, self.heads, self.link = False, [], [], None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "table" and "sortable" in (attrs.get("class") or ""):
            self.inside = True
        elif self.inside and tag == "th":
            self.heads.append(attrs)
        elif self.inside and tag == "tr":
            self.rows.append([])
        elif self.inside and tag == "td":
            self.rows[-1].append(["", None])
        elif self.inside and tag == "a" and self.rows and self.rows[-1]:
            self.rows[-1][-1][1] = attrs.get("href")

    def handle_endtag(self, tag):
        if tag == "table":
            self.inside = False

    def handle_data(self, data):
        if self.inside and self.rows and self.rows[-1]:
            self.rows[-1][-1][0] += data


def _students(report):
    table = Table()
    table.feed(report)
    rows = [row for row in table.rows if row]
    return {cells[0][0]: cells for cells in rows}, table.heads


def test_copied_file_times_are_a_loud_warning(graded):
    out, stdout, status, _, _ = graded
    for text in (stdout, status):
        warning = next(line for line in text.splitlines() if line.startswith("WARNING: late penalties may be wrong"))
        assert "--ignore-mtimes" in warning and "timestamp.txt" in warning
        assert f"lesson {FIRST.number}: 4 of 4 students' notebooks modified within one minute" in warning
        assert "all 4 after the due date" in warning  # eve's time is nbgrader's, not a file's: not counted
    report = _page(out, "report.html")
    assert "<strong>Warning:</strong> late penalties may be wrong" in report and "--ignore-mtimes" in report


def test_late_students_penalties_and_due_dates_in_the_course_timezone(graded):
    out, stdout, status, _, _ = graded
    for text in (stdout, status):
        assert _line(text, "student").split()[:4] == ["student", "score", "late", "status"]
        assert f"{FIRST.number} −30%, {SECOND.number} −30%" in _line(text, "ana")
        assert f"{FIRST.number} −20%" in _line(text, "eve") and f"{SECOND.number} −" not in _line(text, "eve")
        assert "−" not in _line(text, "zoe")
        assert (
            f"due: lesson {FIRST.number} 2026-01-15 23:59 CET, lesson {SECOND.number} 2026-01-20 12:00 CET; "
            "5 of 6 students lost points for lateness"
        ) in text
    assert float(_rows(out)["eve"]["score"]) == round(FIRST.points * 0.8, 2)
    report = _page(out, "report.html")
    assert f"lesson {FIRST.number} 2026-01-15 23:59 CET" in report and "Late: 5 of 6 students." in report
    late = _page(out, "feedback/eve.html")
    assert "handed in 2026-01-17 21:00 CET, 1 day 21 h after the due date (2026-01-15 23:59 CET)" in late


def test_ignore_mtimes_takes_lateness_from_timestamp_files_only(graded, tmp_path):
    _, _, _, root, config = graded
    copy = tmp_path / "class"
    for student in ("ana", "eve"):
        shutil.copytree(root / "class" / student, copy / student)  # copy2: the file times are kept
    out = tmp_path / "out"
    run = _run(
        "grade",
        str(copy),
        "--out",
        str(out),
        "--lessons",
        *LESSONS,
        "--config",
        str(config),
        "--no-nbval",
        "--ignore-mtimes",
        "--layout",
        "nbgrader",
    )
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    rows = _rows(out)
    assert rows["ana"]["late"] == "" and rows["ana"]["timestamp"] == ""
    assert float(rows["ana"]["score"]) == FIRST.points + SECOND.points
    assert rows["eve"]["late"] == f"{FIRST.number}: −20%"  # nbgrader's timestamp.txt still counts
    assert "WARNING" not in run.stdout and "1 of 2 students lost points for lateness" in run.stdout


def test_feedback_says_an_untouched_exercise_once(graded):
    out = graded[0]
    page = _page(out, "feedback/bo.html")
    exercises = FIRST.exercises + SECOND.exercises
    assert page.count("Not written yet") == len(exercises)
    assert "is not written yet" not in page and "hint:" not in page
    for exercise in exercises:
        assert f"Write <code>{exercise.name}</code>, then run the check cell under it" in page
    mistake = _page(out, "feedback/dan.html")  # a real mistake keeps its checks and hints
    assert "Not written yet" not in mistake and "looks like the transpose" in mistake and "hint:" in mistake


def test_feedback_says_a_damaged_notebook_once(graded):
    out = graded[0]
    damaged = _section(_page(out, "feedback/cy.html"), FIRST)
    assert damaged.count("is not valid JSON") == 1 and "hint:" not in damaged
    assert f"{FIRST.filename}: {FIRST.filename}" not in damaged
    assert f"its {len(FIRST.exercises)} exercises (<code>{FIRST.exercises[0].name}</code>" in damaged
    assert "Hand in a copy that opens in JupyterLab" in damaged
    missing = _section(_page(out, "feedback/eve.html"), SECOND)
    assert f"its {len(SECOND.exercises)} exercises earned no points" in missing


def test_class_report_lists_students_with_links_late_and_missing_lessons(graded):
    out = graded[0]
    students, heads = _students(_page(out, "report.html"))
    assert sorted(students) == ["ana", "bo", "cy", "dan", "eve", "zoe"]
    assert all(head.get("scope") == "col" for head in heads) and len(heads) == 6
    for student in ("ana", "bo", "cy", "dan", "eve"):
        link = students[student][0][1]
        assert link == f"feedback/{student}.html" and (out / link).is_file()
    assert students["zoe"][0][1] is None  # no submission, no page
    most = FIRST.points + SECOND.points
    assert [cell[0] for cell in students["ana"][1:]] == [
        f"{round(0.7 * most, 2):g} / {most:g}",
        "70%",
        "graded",
        f"{FIRST.number} −30%, {SECOND.number} −30%",
        "none",
    ]
    assert students["cy"][5][0] == f"{FIRST.number} (unreadable)"
    assert students["eve"][5][0] == SECOND.number and students["zoe"][5][0] == "everything"


def test_class_report_counts_stubs_apart_from_mistakes(graded):
    report = _page(graded[0], "report.html")
    rows = {}
    section = report[report.index("<h2>Exercises</h2>") :]
    section = section[: section.find("<h2>", 5)] if "<h2>" in section[5:] else section  # later sections: not ours
    for row in section.split("<tr>")[2:]:
        name = row.split("<code>")[1].split("</code>")[0]
        rows[name] = row
    transposed = rows[MISTAKE.exercise]
    assert "looks like the transpose" in transposed and "(1)" in transposed  # dan's mistake, once
    assert "not written yet" not in report  # stubs are no failed checks
    for exercise in FIRST.exercises:
        assert "1 left as the stub, 1 without a readable notebook" in rows[exercise.name]
        if exercise.name != MISTAKE.exercise:
            assert "<ol></ol>" in rows[exercise.name]
    for exercise in SECOND.exercises:  # eve handed no lesson 02 in
        assert "1 left as the stub, 1 without a readable notebook" in rows[exercise.name]


def test_class_report_sorts_by_score_without_a_server(graded, tmp_path):
    chromium = shutil.which("chromium") or "/usr/bin/chromium"
    if not Path(chromium).exists():
        pytest.skip("Chromium is not installed")
    report = _page(graded[0], "report.html")
    press = (
        '<script>var b = document.querySelectorAll("table.sortable th button")[1]; b.click(); b.click();'
        "</script></body>"
    )
    pressed = graded[0] / "report-pressed.html"  # beside the report, as an instructor opens it
    pressed.write_text(report.replace("</body>", press), encoding="utf-8")
    try:
        dom = subprocess.run(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom", pressed.as_uri()],
            capture_output=True,
            text=True,
            timeout=120,
        ).stdout
    finally:
        pressed.unlink()
    students, heads = _students(dom)
    rows = _rows(graded[0])
    by_score = sorted((r for r in rows.values() if r["status"] != "missing"), key=lambda r: -float(r["score"]))
    assert list(students) == [r["student_id"] for r in by_score] + ["zoe"]  # highest first, no submission last
    assert list(students) != sorted(students)
    assert heads[1].get("aria-sort") == "descending"


def test_notebook_run_sentences_are_grammatical():
    """Each outcome of the notebook stage is one correct sentence on the feedback page."""
    from autograder.grading.nbval_stage import not_run_for_lost_points
    from autograder.grading.results import ExerciseResult, LessonResult, NotebookRun, StudentResult
    from autograder.reports.feedback import feedback_html

    def lesson(number, run):
        return LessonResult(
            number=number,
            title="",
            notebook=f"{number}.ipynb",
            status="graded",
            run=run,
            exercises=[ExerciseResult(name=f"f{number}", lesson=number, max_points=1, points=1)],
        )

    runs = {
        "01": NotebookRun("passed", 1, 1),
        "02": NotebookRun("failed", 1, 0, ["cell 4 raised ValueError"]),
        "03": not_run_for_lost_points(1),
    }
    page = feedback_html(StudentResult("ana", "graded", lessons=[lesson(n, r) for n, r in runs.items()]))
    assert (
        "Your answers, placed in the reference notebook, ran top to bottom and reproduced its printed outputs."
    ) in page
    assert "Your answers, placed in the reference notebook, did not run cleanly:" in page
    assert "cell 4 raised ValueError" in page
    assert "Your answers were not run in the reference notebook:" in page
    assert "<li>the point needs every exercise of the lesson to pass its hidden checks</li>" in page
    assert " was not run" not in page and "was run" not in page
