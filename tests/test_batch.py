"""Bulk grading: resumable, atomic, escaped, reported, with progress on a terminal."""

import csv
import io
import json
import os
import signal
import subprocess
import sys
import time

import pytest

from autograder.batch.class_run import grade_class, safe_name
from autograder.batch.progress import Progress
from autograder.grading.pipeline import GradingContext, GradingOptions
from autograder.grading.results import CheckResult, ExerciseResult, LessonResult, StudentResult
from autograder.lessons.paths import PROJECT_ROOT
from autograder.reports.class_report import class_report_html
from autograder.reports.gradebook import spreadsheet_safe
from support import STUB, build_submission
from support import THIS_COURSE

FIRST = THIS_COURSE.catalog.graded_lessons[0].number
FAST = GradingOptions(nbval=False, lessons=(FIRST,))


@pytest.fixture(scope="module")
def small_class(tmp_path_factory):
    """Six students of the first lesson: three correct, three untouched."""
    root = tmp_path_factory.mktemp("class")
    for index in range(6):
        default = "reference" if index % 2 == 0 else STUB
        build_submission(root / f"s{index}", default=default, lessons=(FIRST,))
    return root


def _rows(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return {row["student_id"]: row for row in csv.DictReader(handle)}


def test_rerun_skips_unchanged_and_regrades_changed(small_class, tmp_path):
    out = tmp_path / "out"
    first = grade_class(small_class, out, THIS_COURSE, jobs=2, options=FAST)
    assert len(first.graded) == 6 and not first.skipped
    second = grade_class(small_class, out, THIS_COURSE, jobs=2, options=FAST)
    assert len(second.skipped) == 6 and not second.graded
    notebook = next((small_class / "s1").glob("*.ipynb"))
    original = notebook.read_bytes()
    try:
        notebook.write_bytes(original.replace(b'"cells"', b'"cells"', 1) + b"\n")
        third = grade_class(small_class, out, THIS_COURSE, jobs=2, options=FAST)
        assert [row[0] for row in third.graded] == ["s1"] and len(third.skipped) == 5
        forced = grade_class(small_class, out, THIS_COURSE, jobs=2, options=FAST, force=True)
        assert len(forced.graded) == 6
    finally:
        notebook.write_bytes(original)


def test_killed_run_loses_nothing_already_graded(small_class, tmp_path):
    out_full, out_killed = tmp_path / "full", tmp_path / "killed"
    grade_class(small_class, out_full, THIS_COURSE, jobs=2, options=FAST)
    command = [
        sys.executable,
        "-m",
        "autograder",
        "grade",
        str(small_class),
        "--out",
        str(out_killed),
        "--no-nbval",
        "--lessons",
        FIRST,
        "--jobs",
        "1",
    ]
    process = subprocess.Popen(
        command, cwd=PROJECT_ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True
    )
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and len(list((out_killed / "students").glob("*.json"))) < 2:
        time.sleep(0.05)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    saved = sorted((out_killed / "students").glob("*.json"))
    assert 2 <= len(saved) < 6, "the kill came too late to test anything"
    for path in saved:  # every saved result is whole
        json.loads(path.read_text(encoding="utf-8"))
    resumed = grade_class(small_class, out_killed, THIS_COURSE, jobs=2, options=FAST)
    assert len(resumed.skipped) == len(saved) and len(resumed.graded) == 6 - len(saved)

    def strip(rows):
        return {k: {c: v for c, v in r.items() if c != "graded_at"} for k, r in rows.items()}

    assert strip(_rows(out_killed / "grades.csv")) == strip(_rows(out_full / "grades.csv"))


def test_roster_marks_absent_students_missing(small_class, tmp_path):
    summary = grade_class(small_class, tmp_path / "out", THIS_COURSE, jobs=2, options=FAST, roster=("s0", "zoe"))
    status = {r.student_id: r.status for r in summary.results}
    assert status["zoe"] == "missing" and status["s0"] == "graded"


@pytest.mark.parametrize("text", ["=1+1", "+cmd", "-2+3", "@SUM(A1)", "\tx", "\rx"])
def test_formulas_are_escaped(text):
    assert spreadsheet_safe(text) == "'" + text
    assert spreadsheet_safe("ada") == "ada"


def test_unsafe_ids_make_safe_file_names():
    assert safe_name("../etc/passwd") == "..%2Fetc%2Fpasswd"
    assert "/" not in safe_name("a/b") and safe_name("..") != ".."


def _result(student, passed):
    check = CheckResult(
        exercise="rot_z",
        description="quarter turn sends x to y",
        weight=1.0,
        passed=passed,
        reason="" if passed else "got x → -y",
        hint="" if passed else "looks like the transpose",
    )
    exercise = ExerciseResult(name="rot_z", lesson="01", max_points=1.0, points=1.0 if passed else 0.0, checks=[check])
    return StudentResult(
        student_id=student,
        status="graded",
        lessons=[LessonResult(number="01", title="Frames", notebook="01.ipynb", status="graded", exercises=[exercise])],
    )


def test_class_report_contents():
    results = [
        _result("<script>alert(1)</script>", False),
        _result("bo", True),
        _result("cy", False),
        StudentResult(student_id="dee", status="missing", reason="no submission folder"),
    ]
    html = class_report_html(results, THIS_COURSE.catalog)
    assert "rot_z" in html and "33%" in html  # one of three graded students has full marks
    assert "quarter turn sends x to y" in html and "looks like the transpose" in html and "(2)" in html
    assert "data:image/png;base64," in html and "http://" not in html and "https://" not in html
    assert "<script>alert" not in html
    assert "dee" in html and "no submission folder" in html


def test_progress_draws_at_once_and_on_a_terminal_only():
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    terminal, log = Terminal(), io.StringIO()
    for stream in (terminal, log):
        progress = Progress(stream)
        progress.start(4)
        if stream is terminal:
            assert "0/4 students" in terminal.getvalue() and "estimated after the first student" in terminal.getvalue()
        progress.advance()
        progress.advance()
        progress.finish()
    assert "2/4 students" in terminal.getvalue() and "/min" in terminal.getvalue() and "left" in terminal.getvalue()
    assert log.getvalue() == ""


def test_nbgrader_submitted_layout(tmp_path):
    """PATH may be an nbgrader course: submitted/<student>/<assignment>/<notebook>."""
    lesson = THIS_COURSE.catalog.graded_lessons[0]
    for student, default in (("ana", "reference"), ("bo", STUB)):
        folder = tmp_path / "course" / "submitted" / student / f"lesson{lesson.number}"
        build_submission(folder, default=default, lessons=(lesson.number,))
    (tmp_path / "course" / "nbgrader_config.py").write_text("c = get_config()\n", encoding="utf-8")  # its course root
    summary = grade_class(tmp_path / "course", tmp_path / "out", THIS_COURSE, jobs=2, options=FAST)
    scores = {r.student_id: (r.score, r.max_score) for r in summary.results}
    assert scores == {"ana": (lesson.points, lesson.points), "bo": (0.0, lesson.points)}


def test_a_grader_killed_by_student_code_is_reported_and_the_batch_finishes(tmp_path):
    """Without namespaces (forced here), student code may kill the process grading it: the batch goes on."""
    lesson = THIS_COURSE.catalog.lesson("01")
    killer = "import os, signal\nos.kill(os.getppid(), signal.SIGKILL)\n"
    build_submission(
        tmp_path / "class" / "killer", {"rot_z": killer + "def rot_z(a):\n    return None\n"}, lessons=("01",)
    )
    build_submission(tmp_path / "class" / "honest", lessons=("01",))
    env = dict(os.environ, AUTOGRADER_SANDBOX="limits")
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "autograder",
            "grade",
            str(tmp_path / "class"),
            "--out",
            str(tmp_path / "out"),
            "--no-nbval",
            "--lessons",
            "01",
        ],
        cwd=PROJECT_ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr[-2000:]
    assert "RESOURCE LIMITS ONLY" in run.stdout
    rows = _rows(tmp_path / "out" / "grades.csv")
    assert float(rows["honest"]["score"]) == lesson.points
    if rows["killer"]["status"] == "could not grade":  # running as root: the kill reached the grader
        assert "killed by SIGKILL" in rows["killer"]["problems"]
    else:  # an ordinary user: the kill was refused or hit only the sandbox
        assert float(rows["killer"]["score"]) < lesson.points


def test_the_slot_a_grader_is_handed_reaches_every_sandbox_of_its_student(tmp_path, monkeypatch):
    """grade_task -> grade_student -> the hidden suite's sandbox and each notebook-stage sandbox: the warm
    slot is passed down, not found in a global (a dropped slot would only make grading cold, silently)."""
    from autograder.batch import class_run
    from autograder.grading import nbval_stage, pipeline
    from autograder.sandbox.session import StudentSandbox

    handed = object()
    seen = []

    class Recording(StudentSandbox):
        def __init__(self, *args, slot=None, **kwargs):
            seen.append(slot)
            super().__init__(*args, slot=None, **kwargs)  # graded cold: the stand-in is no slot

    monkeypatch.setattr(pipeline, "StudentSandbox", Recording)
    monkeypatch.setattr(nbval_stage, "StudentSandbox", Recording)
    folder = build_submission(tmp_path / "ada", lessons=(FIRST,))
    result = pipeline.grade_student(
        "ada", folder, GradingContext(THIS_COURSE, GradingOptions(lessons=(FIRST,))), slot=handed
    )
    assert result.score == result.max_score > 0
    assert seen == [handed, handed], seen  # the suite's sandbox, then lesson 01's notebook

    graded = []
    monkeypatch.setattr(class_run, "grade_student", lambda *args, slot=None, **kwargs: graded.append(slot) or result)
    for name in ("become_subreaper", "kill_descendants"):  # not in this test process: it has other children
        monkeypatch.setattr(class_run.process_tree, name, lambda *args, **kwargs: None)
    task = class_run.GradingTask(
        "ada", str(folder), GradingContext(THIS_COURSE, FAST), str(tmp_path / "out"), class_run.Stamp("f", {}), None
    )
    class_run.grade_task(task, handed)
    assert graded == [handed]
