"""Grading is unchanged by the student's versions: a notebook last run under the floors grades the same.

A student on Python 3.10 with numpy 1.23 hands in a notebook whose outputs, metadata (kernel, language
version) and widget state come from that setup; the grader, on its own newer lock, must give it the
points it gives the same answers never run. Oracle: grading the same lesson built from the released
notebook with the reference answers (``tests/support.build_submission``), exercise by exercise and
the notebook stage's point.

The floor-run notebooks come from ``tests/student_floor.py``: its output in ``$STUDENT_FLOOR_OUT``
when ``.ci/run`` started it beside the suite (waited for, up to 20 minutes), else a run of its own for
these lessons only (a floor venv install, a couple of minutes with pip's cache).
"""

import json
import os
import shutil
import sys
import time
from pathlib import Path

import pytest

from autograder.lessons.catalog import load_catalog
from support import build_submission, grade, points_by_exercise

sys.path.insert(0, str(Path(__file__).parent))
import student_floor  # noqa: E402

# 03, 05 and 09 ran into Python 3.10's missing co_qualname in their public checks (issue 35).
LESSONS = ("03", "09")
WAIT_SECONDS = 20 * 60


@pytest.fixture(scope="module")
def floor_run(tmp_path_factory):
    """The folder of a finished floor run (``summary.json`` and ``executed/``)."""
    shared = os.environ.get("STUDENT_FLOOR_OUT")
    if shared:
        summary = Path(shared) / "summary.json"
        deadline = time.monotonic() + WAIT_SECONDS
        while not summary.exists() and time.monotonic() < deadline:
            time.sleep(10)
        if summary.exists():
            return Path(shared)
    out = tmp_path_factory.mktemp("floor")
    student_floor.main(["--out", str(out), "--lessons", *LESSONS])
    return out


def test_every_lesson_of_the_floor_run_ran_clean(floor_run):
    summary = json.loads((floor_run / "summary.json").read_text(encoding="utf-8"))
    module = student_floor.student_install()
    assert tuple(int(part) for part in summary["python"].split(".")[:2]) >= module.PYTHON_FLOOR
    assert {name: summary["versions"][name] for name, *_ in module.PACKAGES} == \
        {name: floor for name, floor, *_ in module.PACKAGES}, "the run did not use the floors"
    errors = {name: run["errors"] for name, run in summary["lessons"].items() if run["errors"]}
    assert not errors, errors


@pytest.mark.parametrize("lesson", LESSONS)
def test_a_notebook_last_run_under_the_floors_grades_as_the_same_answers_never_run(lesson, floor_run, tmp_path):
    filename = next(les.filename for les in load_catalog().graded_lessons if les.number == lesson)
    floor_student = tmp_path / "floor"
    floor_student.mkdir()
    shutil.copy(floor_run / "executed" / filename, floor_student / filename)
    never_run = build_submission(tmp_path / "never_run", lessons=(lesson,))
    floor_result = grade(floor_student, lessons=(lesson,), nbval=True)
    reference = grade(never_run, lessons=(lesson,), nbval=True)
    assert points_by_exercise(floor_result) == points_by_exercise(reference)
    assert [les.run.points for les in floor_result.lessons] == [les.run.points for les in reference.lessons]
    assert floor_result.score == reference.score == reference.max_score
