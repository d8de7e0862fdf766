"""Every command-line mistake of an instructor's first hour gets one clear line and the right exit status.

Each test runs ``python -m autograder`` as a user types it (a subprocess, real files in a temporary folder).
Usage mistakes end before any grading (exit status 2), so these tests cost seconds; the one that needs a
grader at work (Ctrl-C) interrupts it early.
"""

import os
import re
import shutil
import signal
import subprocess
import sys
import time
from datetime import datetime, timezone
from pathlib import Path

import pytest

from autograder.batch.class_run import Outputs, Saved, Stamp, regrade_reason, save_result
from autograder.grading.submissions import submission_hash
from autograder.grading.results import GRADED_WITH_PROBLEMS, StudentResult
from autograder.lessons.paths import COURSE
from autograder.reports.lateness import ConfigError, parse_config, submission_time
from support import THIS_COURSE

LESSONS = [lesson.number for lesson in THIS_COURSE.catalog.graded_lessons]

USAGE = 2


def autograder(*args, cwd, timeout=120):
    """Run ``python -m autograder ARGS`` in ``cwd``; the finished process (text output)."""
    return subprocess.run(
        [sys.executable, "-m", "autograder", *args], cwd=cwd, capture_output=True, text=True, timeout=timeout
    )


def one_error_line(run):
    """The single line a usage mistake prints: no traceback, nothing else on stderr."""
    lines = [line for line in run.stderr.splitlines() if line.strip()]
    assert "Traceback" not in run.stderr, run.stderr
    assert len(lines) == 1, f"expected one line, got:\n{run.stderr}"
    return lines[0]


@pytest.fixture
def classroom(tmp_path):
    """A submissions folder with two students holding lesson 01, and an empty folder."""
    notebook = next(COURSE.glob("01_*.ipynb"))
    for student in ("anna", "ben"):
        (tmp_path / "class" / student).mkdir(parents=True)
        shutil.copy(notebook, tmp_path / "class" / student / notebook.name)
    (tmp_path / "empty").mkdir()
    return tmp_path


@pytest.mark.parametrize(
    "command, lesson",
    [
        (["grade", "class", "--out", "results"], "99"),
        (["canary"], "1a"),
        (["gradescope", "--out", "a.zip"], "00"),
        (["nbgrader-course", "--out", "nb"], "10"),
    ],
)
def test_an_unknown_lesson_names_the_valid_ones(classroom, command, lesson):
    run = autograder(*command, "--lessons", lesson, cwd=classroom)
    assert run.returncode == USAGE, (command, run.stderr)
    line = one_error_line(run)
    assert f"unknown lesson '{lesson}'" in line and "01 02 03" in line and "09" in line, line
    assert not (classroom / "results").exists() and not (classroom / "a.zip").exists()


def test_a_one_digit_lesson_is_read_as_its_two_digit_number(classroom):
    """--lessons 3 means lesson 03, and the run says so (here it then stops: the folder holds no students)."""
    run = autograder("grade", "empty", "--out", "results", "--lessons", "3", cwd=classroom)
    assert run.returncode == USAGE
    assert "--lessons 3 read as 03" in run.stderr
    assert "unknown lesson" not in run.stderr and "no student folders" in run.stderr


@pytest.mark.parametrize("jobs", ["0", "-3"])
def test_jobs_below_one_is_refused(classroom, jobs):
    run = autograder("grade", "class", "--out", "results", f"--jobs={jobs}", cwd=classroom)
    assert run.returncode == USAGE
    line = one_error_line(run)
    assert "--jobs" in line and (f"got {jobs}" in line or repr(jobs) in line), line


def test_no_students_says_what_a_submissions_folder_looks_like(classroom):
    run = autograder("grade", "empty", "--out", "results", cwd=classroom)
    assert run.returncode == USAGE
    line = one_error_line(run)
    assert "no student folders in empty" in line and "one folder per student" in line, line
    assert not (classroom / "results").exists()


def test_one_students_folder_is_recognised(classroom):
    run = autograder("grade", "class/anna", "--out", "results", cwd=classroom)
    assert run.returncode == USAGE
    line = one_error_line(run)
    assert "looks like one student's folder" in line and "one folder per student" in line, line


def test_one_students_nbgrader_folder_is_recognised(classroom):
    """submitted/anna/ with its assignment folders lesson01/, lesson03/: one student, not two."""
    student = classroom / "submitted_anna"
    for assignment in ("lesson01", "lesson03"):
        (student / assignment).mkdir(parents=True)
        shutil.copy(next(COURSE.glob("01_*.ipynb")), student / assignment)
    run = autograder("grade", "submitted_anna", "--out", "results", cwd=classroom)
    assert run.returncode == USAGE
    assert "looks like one student's folder (assignment folders" in one_error_line(run)


@pytest.mark.parametrize(
    "command, roster_text, expected",
    [
        (["grade", "class", "--out", "results"], None, "cannot read the roster roster.csv"),
        (["grade", "class", "--out", "results"], "name,email\nAnna,anna@example.org\n", "no id column"),
        (["status", "--out", "results"], None, "cannot read the roster roster.csv"),
        (["status", "--out", "results"], "name,email\nAnna,anna@example.org\n", "no id column"),
        (["export", "--out", "results", "--to", "canvas"], "name,email\nAnna,anna@example.org\n", "no id column"),
    ],
)
def test_roster_mistakes_in_grade_status_and_export(classroom, command, roster_text, expected):
    if roster_text is not None:
        (classroom / "roster.csv").write_text(roster_text, encoding="utf-8")
    run = autograder(*command, "--roster", "roster.csv", cwd=classroom)
    assert run.returncode == USAGE, (command, run.stdout, run.stderr)
    assert expected in one_error_line(run), (command, run.stderr)


CONFIG_MISTAKES = [
    ("[late_policy]\npenalty_per_days = 0.1\n", "did you mean 'penalty_per_day'?"),
    ("[lessons.3]\ndue = 2026-12-01T23:59:00\n", """unknown lesson '3' under [lessons]; did you mean [lessons."03"]"""),
    ('[lessons."99"]\ndue = 2026-12-01T23:59:00\n', "unknown lesson '99'"),
    ('[lessons."03"]\ndeu = 2026-12-01T23:59:00\n', "did you mean 'due'?"),
    ('timezon = "Europe/Berlin"\n', "did you mean 'timezone'?"),
    ("penalty_per_day = 0.1\n", "belongs in [late_policy]"),
    ("late_policy = 3\n", "late_policy must be a table"),
]


@pytest.mark.parametrize("toml, expected", CONFIG_MISTAKES[:2])
def test_course_config_is_checked_against_its_schema(classroom, toml, expected):
    (classroom / "course.toml").write_text(toml, encoding="utf-8")
    run = autograder("grade", "class", "--out", "results", "--config", "course.toml", cwd=classroom)
    assert run.returncode == USAGE
    line = one_error_line(run)
    assert line.startswith("error: course.toml") and expected in line, line
    assert not (classroom / "results").exists()


@pytest.mark.parametrize("toml, expected", CONFIG_MISTAKES)
def test_every_schema_mistake_names_the_close_key(toml, expected):
    """The same check in this process, for every kind of mistake (the command above shows it reaches the user)."""
    with pytest.raises(ConfigError, match=re.escape(expected)):
        parse_config(toml, "course.toml", LESSONS)
    parse_config(
        'timezone = "Europe/Berlin"\n[late_policy]\npenalty_per_day = 0.1\n'
        '[lessons."03"]\ndue = 2026-12-01T23:59:00\nmax_penalty = 0.5\n',
        "course.toml",
        LESSONS,
    )


def test_a_closed_pipe_ends_status_quietly(tmp_path):
    """`status | head -1` on a gradebook longer than a pipe's buffer: no traceback, the exit status of SIGPIPE."""
    outputs = Outputs(tmp_path / "results")
    stamp = Stamp("0" * 16, {})
    for index in range(150):
        result = StudentResult(
            student_id=f"student{index:03}",
            status=GRADED_WITH_PROBLEMS,
            problems=[f"problem {k}: " + "x" * 150 for k in range(3)],
        )
        save_result(outputs, result, stamp, "2026-11-25 06:00:00")
    reader = subprocess.Popen(
        [sys.executable, "-m", "autograder", "status", "--out", str(outputs.root)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    first = reader.stdout.readline()
    reader.stdout.close()  # what `head -1` does after its line
    stderr = reader.stderr.read()
    assert reader.wait(timeout=60) == 141
    assert first.startswith("student") and stderr == "", stderr


def test_ctrl_c_says_what_is_saved_and_how_to_resume(classroom):
    """Ctrl-C reaches the whole foreground process group; the grader ends with one line and status 130."""
    grader = subprocess.Popen(
        [sys.executable, "-m", "autograder", "grade", "class", "--out", "results", "--lessons", "01", "--no-nbval"],
        cwd=classroom,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    started = grader.stdout.readline()  # the sandbox line, then how the class is read and why: the grader is at work
    assert started.startswith("sandbox"), started
    layout = grader.stdout.readline()
    assert layout.startswith("layout: folders"), layout
    time.sleep(1.0)
    os.killpg(grader.pid, signal.SIGINT)
    stdout, stderr = grader.communicate(timeout=60)
    assert grader.returncode == 130, (stdout, stderr)
    assert "Traceback" not in stderr and "KeyboardInterrupt" not in stderr, stderr
    last = [line for line in stderr.splitlines() if line.strip()][-1]
    assert last == (
        f"interrupted: every student graded so far is saved in {Path('results') / 'students'}; run the "
        "same command again to resume (saved students are not graded twice)"
    ), stderr


def _nbgrader_student(root):
    """submitted/ana/lesson01/ with lesson 01's notebook and nbgrader's timestamp, as `nbgrader collect` leaves it."""
    folder = root / "submitted" / "ana"
    (folder / "lesson01").mkdir(parents=True)
    notebook = folder / "lesson01" / next(COURSE.glob("01_*.ipynb")).name
    shutil.copy(next(COURSE.glob("01_*.ipynb")), notebook)
    (folder / "lesson01" / "timestamp.txt").write_text("2026-12-01 10:00:00.000000 UTC", encoding="utf-8")
    os.utime(notebook, (1_900_000_000, 1_900_000_000))  # collected much later than handed in
    return folder, notebook


def test_the_hand_in_time_comes_from_nbgraders_timestamp_only(tmp_path):
    """A timestamp.txt the student wrote (beside a notebook deeper down, or in their own folder) is never read."""
    folder, notebook = _nbgrader_student(tmp_path)
    assert submission_time(notebook, folder, "nbgrader") == datetime(2026, 12, 1, 10, 0, tzinfo=timezone.utc)
    (folder / "timestamp.txt").write_text("2026-11-01 10:00:00 UTC", encoding="utf-8")
    deeper = folder / "lesson01" / "mine"
    deeper.mkdir()
    shutil.copy(notebook, deeper / notebook.name)
    (deeper / "timestamp.txt").write_text("2026-11-01 10:00:00 UTC", encoding="utf-8")
    assert submission_time(deeper / notebook.name, folder, "nbgrader") == datetime(
        2026, 12, 1, 10, 0, tzinfo=timezone.utc
    )
    assert submission_time(notebook, folder, "nbgrader") == datetime(2026, 12, 1, 10, 0, tzinfo=timezone.utc)

    student = tmp_path / "class" / "bo"  # one folder per student (an LMS download): the file's time as collected
    student.mkdir(parents=True)
    shutil.copy(notebook, student / notebook.name)
    (student / "timestamp.txt").write_text("2026-11-01 10:00:00 UTC", encoding="utf-8")
    os.utime(student / notebook.name, (1_800_000_000, 1_800_000_000))
    assert submission_time(student / notebook.name, student) == datetime.fromtimestamp(1_800_000_000, timezone.utc)


def test_a_corrected_hand_in_time_re_grades_the_student(tmp_path):
    """The saved grade depends on when the notebooks were handed in, not on their bytes only."""
    folder, notebook = _nbgrader_student(tmp_path)
    stamp = Stamp("0" * 16, {})
    saved = Saved(
        stamp,
        StudentResult(
            student_id="ana", status=GRADED_WITH_PROBLEMS, submission_hash=submission_hash(folder, "nbgrader")
        ),
    )
    assert regrade_reason(saved, stamp, submission_hash(folder, "nbgrader")) is None
    (folder / "lesson01" / "timestamp.txt").write_text("2026-12-03 10:00:00.000000 UTC", encoding="utf-8")
    assert regrade_reason(saved, stamp, submission_hash(folder, "nbgrader")) == "the submission changed"

    student = tmp_path / "class" / "bo"  # without nbgrader: the file's time
    student.mkdir(parents=True)
    shutil.copy(notebook, student / notebook.name)
    before = submission_hash(student)
    os.utime(student / notebook.name, (1_700_000_000, 1_700_000_000))
    assert submission_hash(student) != before
