"""Grading is unchanged by the student's versions: a notebook last run under the floors grades the same.

A student on Python 3.10 with numpy 1.23 hands in a notebook whose outputs, metadata (kernel, language
version) and widget state come from that setup; the grader, on its own newer lock, must give it the
points it gives the same answers never run: full marks, exercise by exercise and the notebook stage's
point, as the reference answers get them (``tests/test_sample_class.py``: ada, 176/176). The floor run's
notebooks are the solved masters, so their answers are the reference answers.

The floor-run notebooks come from ``tests/student_floor.py``: its output in ``$STUDENT_FLOOR_OUT``
when ``.ci/run`` started it beside the suite (waited for while it runs, up to 20 minutes), else a run of its own
for these lessons only (a floor venv install, a couple of minutes with pip's cache): a ``$STUDENT_FLOOR_OUT``
that names no live or finished run costs no wait.
"""

import json
import os
import shutil
import sys
import time
from pathlib import Path

import pytest

from support import grade, points_by_exercise

sys.path.insert(0, str(Path(__file__).parent))
import student_floor  # noqa: E402
from support import THIS_COURSE

ROOT = Path(__file__).resolve().parents[1]

# Two of the lessons whose public checks ran into Python 3.10's missing co_qualname (issue 35).
LESSONS = ("03", "05")
WAIT_SECONDS = 20 * 60


@pytest.fixture(scope="module")
def floor_run(tmp_path_factory):
    """The folder of a finished floor run (``summary.json`` and ``executed/``)."""
    shared = os.environ.get("STUDENT_FLOOR_OUT")
    if shared:
        summary = Path(shared) / "summary.json"
        deadline = time.monotonic() + WAIT_SECONDS
        while not summary.exists() and time.monotonic() < deadline and student_floor.running(shared):
            time.sleep(10)
        if summary.exists():
            return Path(shared)
    out = tmp_path_factory.mktemp("floor")
    student_floor.main(["--out", str(out), "--lessons", *LESSONS])
    return out


def test_the_recorded_floor_run_is_of_the_current_masters_and_coursekit():
    """A master's code or coursekit changed without a new record makes every ``.ci/run`` run every lesson at
    the floors beside the suite, CPU time taken from the suite, until someone records again."""
    record = student_floor.read_record(ROOT / "tests" / "student_floor.lock.json")
    assert record is not None and record["ok"], record
    module = student_floor.student_install()
    recorded_python = tuple(int(part) for part in record["python"].split("."))
    assert record["key"] == student_floor.run_key(module, recorded_python), (
        "a master's code, coursekit, a floor or tests/student_floor.py changed since the recorded floor run: run "
        "python3 tests/student_floor.py --out /tmp/floor --record tests/student_floor.lock.json "
        "and commit tests/student_floor.lock.json"
    )
    assert set(record["lessons"]) == {path.name for path in student_floor.masters()}


def test_every_lesson_of_the_floor_run_ran_clean(floor_run):
    summary = json.loads((floor_run / "summary.json").read_text(encoding="utf-8"))
    module = student_floor.student_install()
    assert tuple(int(part) for part in summary["python"].split(".")[:2]) >= module.PYTHON_FLOOR
    assert {name: summary["versions"][name] for name, *_ in module.PACKAGES} == {
        name: floor for name, floor, *_ in module.PACKAGES
    }, "the run did not use the floors"
    errors = {name: run["errors"] for name, run in summary["lessons"].items() if run["errors"]}
    assert not errors, errors
    recorded = summary.get("recorded")
    if recorded:  # .ci/run ran only the lessons graded below: a clean full run of the same content stands for the rest
        assert recorded["key"] == summary["key"] == student_floor.run_key(module, summary["python"].split("."))
        assert recorded["ok"] and not any(recorded["lessons"].values()), recorded["lessons"]
        assert set(recorded["lessons"]) == {path.name for path in student_floor.masters()}


def test_notebooks_last_run_under_the_floors_grade_as_the_reference_answers(floor_run, tmp_path):
    catalog = {lesson.number: lesson for lesson in THIS_COURSE.catalog.graded_lessons}
    student = tmp_path / "floor_student"
    student.mkdir()
    for number in LESSONS:
        shutil.copy(floor_run / "executed" / catalog[number].filename, student / catalog[number].filename)
    result = grade(student, lessons=LESSONS, nbval=True)
    assert [lesson.number for lesson in result.lessons] == list(LESSONS)
    assert points_by_exercise(result) == {
        exercise.name: (exercise.max_points, exercise.max_points) for exercise in result.exercises
    }, "an exercise lost points"
    runs = {lesson.number: (lesson.run.status, lesson.run.points, lesson.run.max_points) for lesson in result.lessons}
    assert all(status == "passed" and points == top for status, points, top in runs.values()), runs
    assert result.score == result.max_score > 0
