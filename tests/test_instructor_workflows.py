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

from autograder.catalog import load_catalog
from autograder.paths import PROJECT_ROOT
from support import STUB, build_submission

LESSON = load_catalog().lesson("01")


def _run(*args):
    return subprocess.run([sys.executable, "-m", "autograder", *args], cwd=PROJECT_ROOT, capture_output=True,
                          text=True, timeout=600)


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
    (dan / "scratch notes.ipynb").write_text(json.dumps(
        {"cells": [{"cell_type": "markdown", "metadata": {}, "source": "ideas"}], "metadata": {},
         "nbformat": 4, "nbformat_minor": 5}), encoding="utf-8")
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
    unknown = _run("grade", str(class_folder), "--out", str(out), "--no-nbval", "--lessons", LESSON.number,
                   "--student", "nobody")
    assert unknown.returncode == 2 and "no submission folder" in unknown.stderr and "nobody" in unknown.stderr
    assert (out / "grades.csv").read_bytes() == before
