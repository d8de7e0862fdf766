"""What an instructor does between two gradings, driven through the real command on a real class folder.

- Notebooks are found by their content: a renamed notebook (``dan_exp_log_final.ipynb``) is graded,
  a ``-Copy1`` holding the work beats the untouched original, and a notebook that belongs to no
  lesson is named in the feedback and in ``status``.
- ``--student`` re-grades a few students; no command shrinks an existing gradebook.
"""

import csv
import json
import shutil
import subprocess
import sys

import pytest

from autograder.lessons.paths import PROJECT_ROOT
from support import STUB, build_submission
from support import THIS_COURSE

LESSON = THIS_COURSE.catalog.lesson("01")


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "autograder", *args], cwd=PROJECT_ROOT, capture_output=True, text=True, timeout=600
    )


def _grade(submissions, out, *extra):
    run = _run("grade", str(submissions), "--out", str(out), "--no-nbval", "--lessons", LESSON.number, *extra)
    assert run.returncode == 0, run.stdout[-1500:] + run.stderr[-1500:]
    return run.stdout


def _rows(out):
    with open(out / "grades.csv", newline="", encoding="utf-8") as handle:
        return {row["student_id"]: row for row in csv.DictReader(handle)}


@pytest.fixture()
def class_folder(tmp_path):
    root = tmp_path / "class"
    build_submission(root / "ana", lessons=(LESSON.number,))
    build_submission(root / "bo", default=STUB, lessons=(LESSON.number,))
    dan = build_submission(root / "dan", lessons=(LESSON.number,))
    (dan / LESSON.filename).rename(dan / "dan_frames_final-Copy1.ipynb")
    shutil.copy(root / "bo" / LESSON.filename, dan / LESSON.filename)  # the untouched original beside it
    (dan / "scratch notes.ipynb").write_text(
        json.dumps(
            {
                "cells": [{"cell_type": "markdown", "metadata": {}, "source": "ideas"}],
                "metadata": {},
                "nbformat": 4,
                "nbformat_minor": 5,
            }
        ),
        encoding="utf-8",
    )
    return root


def test_notebooks_are_matched_by_content(class_folder, tmp_path):
    out = tmp_path / "out"
    _grade(class_folder, out)
    dan = _rows(out)["dan"]
    assert float(dan["score"]) == LESSON.points and dan["status"] == "graded with problems"
    page = (out / "feedback" / "dan.html").read_text(encoding="utf-8")
    assert "graded dan_frames_final-Copy1.ipynb" in page and "not graded: 01_frames_and_rotations.ipynb" in page
    assert "scratch notes.ipynb was not graded: it holds no exercise of the course" in page
    status = _run("status", "--out", str(out)).stdout
    assert "scratch notes.ipynb was not graded" in status and "graded dan_frames_final-Copy1.ipynb" in status
    assert float(_rows(out)["bo"]["score"]) == 0


def test_regrade_a_few_students_and_never_shrink_the_gradebook(class_folder, tmp_path):
    out = tmp_path / "out"
    _grade(class_folder, out)
    assert sorted(_rows(out)) == ["ana", "bo", "dan"]

    build_submission(class_folder / "bo", lessons=(LESSON.number,))  # bo hands in the work
    stdout = _grade(class_folder, out, "--student", "bo")
    assert "graded 1 student(s), 2 unchanged and reused" in stdout
    rows = _rows(out)
    assert sorted(rows) == ["ana", "bo", "dan"] and float(rows["bo"]["score"]) == LESSON.points

    alone = tmp_path / "only-ana"
    shutil.copytree(class_folder / "ana", alone / "ana")
    stdout = _grade(alone, out)
    assert "2 graded earlier and not under" in stdout and "kept as they were: bo, dan" in stdout
    assert sorted(_rows(out)) == ["ana", "bo", "dan"]
    status = _run("status", "--out", str(out)).stdout
    assert all(f"\n{student} " in status for student in ("ana", "bo", "dan")), status

    before = (out / "grades.csv").read_bytes()
    unknown = _run(
        "grade", str(class_folder), "--out", str(out), "--no-nbval", "--lessons", LESSON.number, "--student", "nobody"
    )
    assert unknown.returncode == 2 and "no submission folder" in unknown.stderr and "nobody" in unknown.stderr
    assert (out / "grades.csv").read_bytes() == before


def test_due_dates_late_penalties_and_submission_times(tmp_path):
    """nbgrader's timestamp.txt decides when a lesson was handed in; the raw score stays beside the penalised one."""
    submitted = tmp_path / "course" / "submitted"
    for student, stamp in (("early", "2026-11-30 13:00:00.000000 UTC"), ("late", "2026-12-02 13:00:00.000000 UTC")):
        folder = build_submission(submitted / student / f"lesson{LESSON.number}", lessons=(LESSON.number,))
        (folder / "timestamp.txt").write_text(stamp, encoding="utf-8")
    (tmp_path / "course" / "gradebook.db").write_bytes(b"")  # nbgrader's course root: its layout, its timestamps
    config = tmp_path / "course.toml"
    config.write_text(
        f"[late_policy]\npenalty_per_day = 0.1\ngrace_minutes = 30\n"
        f'[lessons."{LESSON.number}"]\ndue = 2026-12-01T12:00:00Z\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    _grade(tmp_path / "course", out, "--config", str(config))
    rows = _rows(out)
    assert float(rows["early"]["score"]) == LESSON.points and rows["early"]["late"] == ""
    assert rows["early"]["timestamp"] == "2026-11-30T13:00:00+00:00"
    penalised = round(LESSON.points * 0.8, 2)  # 1 day 1 h late: 2 started days, 10% each
    assert float(rows["late"]["score"]) == penalised == float(rows["late"][f"lesson_{LESSON.number}"])
    assert float(rows["late"]["raw_score"]) == LESSON.points and rows["late"]["late"] == f"{LESSON.number}: −20%"
    page = (out / "feedback" / "late.html").read_text(encoding="utf-8")
    assert "2 days late, −20%" in page and "before late penalties" in page
    gradescope = json.loads((out / "results" / "late.json").read_text(encoding="utf-8"))
    assert gradescope["score"] == penalised and "2 days late" in gradescope["output"]

    config.write_text(config.read_text(encoding="utf-8").replace("0.1", "0.25"), encoding="utf-8")
    stdout = _grade(tmp_path / "course", out, "--config", str(config))
    assert "re-graded: changed since the last grading: course config" in stdout
    assert float(_rows(out)["late"]["score"]) == round(LESSON.points * 0.5, 2)

    config.write_text("[late_policy]\npenalty_per_day = -1\n", encoding="utf-8")
    bad = _run("grade", str(tmp_path / "course"), "--out", str(out), "--config", str(config))
    assert bad.returncode == 2 and "penalty_per_day must be a number ≥ 0" in bad.stderr


def test_per_lesson_totals_and_canvas_export(class_folder, tmp_path):
    out = tmp_path / "out"
    _grade(class_folder, out)
    header = (out / "grades.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    lessons = [f"lesson_{lesson.number}" for lesson in THIS_COURSE.catalog.graded_lessons]
    assert header[4 : 4 + len(lessons)] == lessons
    assert float(_rows(out)["ana"][f"lesson_{LESSON.number}"]) == LESSON.points

    roster = tmp_path / "roster.csv"
    roster.write_text(
        "ID,Name,Section,SIS User ID\nana,Ana Lima,A,S001\nbo,Bo Chen,B,S002\ncy,Cy Park,B,S003\n", encoding="utf-8"
    )
    run = _run("export", "--out", str(out), "--to", "canvas", "--roster", str(roster))
    assert run.returncode == 0, run.stderr
    with open(out / "canvas.csv", newline="", encoding="utf-8") as handle:
        table = list(csv.reader(handle))
    assert table[0][:5] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
    column = table[0].index(f"Lesson {LESSON.number}: {LESSON.title}")
    assert table[1][0] == "Points Possible" and float(table[1][column]) == LESSON.points
    people = {row[3]: row for row in table[2:]}
    assert people["ana"][:5] == ["Ana Lima", "", "S001", "ana", "A"] and float(people["ana"][column]) == LESSON.points
    assert float(people["bo"][column]) == 0 and people["cy"][column] == "0"  # cy: on the roster, nothing handed in
    assert people["dan"][2] == "dan"  # not on the roster: matched by the grader's id
    others = [i for i, name in enumerate(table[0]) if name.startswith("Lesson ") and i != column]
    assert others and all(people["ana"][i] == "0" for i in others)  # lessons ana did not hand in: 0 by default
    assert "lesson(s) not handed in: exported as 0 (--missing blank leaves them empty)" in run.stdout

    blank = _run(
        "export",
        "--out",
        str(out),
        "--to",
        "canvas",
        "--roster",
        str(roster),
        "--missing",
        "blank",
        "--file",
        str(tmp_path / "blank.csv"),
    )
    assert blank.returncode == 0, blank.stderr
    with open(tmp_path / "blank.csv", newline="", encoding="utf-8") as handle:
        kept = {row[3]: row for row in list(csv.reader(handle))[2:]}
    assert kept["cy"][column] == "" and all(kept["ana"][i] == "" for i in others)
    assert float(kept["ana"][column]) == LESSON.points and float(kept["bo"][column]) == 0
