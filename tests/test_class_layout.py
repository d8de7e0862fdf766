"""The class is read one way, from what the instructor controls; the grader's files on the host are private.

- The layout is the one declared (``grade --layout``) or nbgrader's course root's (a regular
  ``nbgrader_config.py`` or ``gradebook.db`` beside ``submitted/``): a student named ``submitted`` (or
  like any other marker) is a student and hides no one.
- Hand-in times: nbgrader's ``timestamp.txt`` only in nbgrader's layout; any time bounded to 1970..2200 or
  refused for that lesson with the reason (the lesson graded, its lateness unknown), never "could not grade".
- One student's grading walks their folder once and reads each notebook once (one frozen ``StudentFolder``).
- Sandbox folders are private to the grader (0700 parents) and the output folder is readable by its owner
  only, unless ``grade --share-output``.
"""

import os
import stat
import subprocess
import sys
from datetime import datetime, timezone
from pathlib import Path

import pytest

from autograder.batch import class_run
from autograder.grading import fingerprint, submissions, transcript_cache
from autograder.grading.pipeline import GradingContext, GradingOptions, grade_student
from autograder.grading.results import GRADED, LessonResult, StudentResult
from autograder.lessons.paths import PROJECT_ROOT
from autograder.reports.lateness import apply_late_policy, parse_config
from autograder.sandbox import cleanup, launcher, warm
from support import THIS_COURSE, build_submission

LESSON = THIS_COURSE.catalog.graded_lessons[0]
FAST = GradingOptions(nbval=False, lessons=(LESSON.number,))
MARKER_NAMES = ["gradebook.db", "nbgrader_config.py", "source", "autograded", "release", "feedback"]


def _mode(path):
    return stat.S_IMODE(os.lstat(path).st_mode)


def _student(folder, *parts):
    """A student folder holding lesson 01's notebook (under ``parts``, e.g. an assignment folder)."""
    return build_submission(Path(folder, *parts), lessons=(LESSON.number,))


# ------------------------------------------------------------------------------ how the class is read
@pytest.mark.parametrize("other", MARKER_NAMES)
def test_students_named_like_nbgraders_files_hide_no_one(tmp_path, other):
    """Students named `submitted` and like nbgrader's other files are students: everyone is found."""
    for name in ("ana", "bo", "submitted", other):
        _student(tmp_path / name)
    _student(tmp_path / "submitted" / "zed")  # a fake nbgrader student inside the student `submitted`
    found = submissions.scan_submissions(tmp_path)
    assert [name for name, _ in found.files] == sorted(["ana", "bo", "submitted", other])
    assert found.layout.kind == submissions.FOLDERS and found.layout.root == tmp_path
    assert "submitted/ is graded as a student" in found.layout.line()


def test_nbgraders_layout_comes_from_its_course_root_or_the_instructor(tmp_path):
    course = tmp_path / "course"
    _student(course / "submitted" / "ana", "lesson01")
    assert submissions.detect_layout(course).kind == submissions.FOLDERS  # no marker: submitted/ is a student
    (course / "nbgrader_config.py").write_text("c = get_config()\n", encoding="utf-8")
    root = submissions.detect_layout(course)
    assert (root.kind, root.root) == (submissions.NBGRADER, course / "submitted")
    assert "nbgrader_config.py beside submitted/" in root.line()
    inside = submissions.detect_layout(course / "submitted")
    assert (inside.kind, inside.root) == (submissions.NBGRADER, course / "submitted")
    assert [name for name, _ in submissions.scan_submissions(course).files] == ["ana"]
    declared = submissions.detect_layout(course, "folders")
    assert (declared.kind, declared.root, declared.why) == ("folders", course, "declared with --layout folders")
    bare = tmp_path / "bare"
    _student(bare / "submitted" / "bo", "lesson01")
    assert submissions.detect_layout(bare, "nbgrader").root == bare / "submitted"
    (course / "nbgrader_config.py").unlink()
    (course / "nbgrader_config.py").mkdir()  # a folder is no marker
    assert submissions.detect_layout(course).kind == submissions.FOLDERS


def test_a_timestamp_in_a_students_own_folder_is_ignored(tmp_path):
    """One folder per student: a timestamp.txt the student wrote beside their notebook dates nothing."""
    folder = _student(tmp_path / "ana", "lesson01")
    notebook = folder / LESSON.filename
    (folder / "timestamp.txt").write_text("2000-01-01 00:00:00 UTC", encoding="utf-8")
    os.utime(notebook, (1_800_000_000, 1_800_000_000))
    collected = datetime.fromtimestamp(1_800_000_000, timezone.utc)
    assert submissions.handed_in_at(notebook, tmp_path / "ana") == collected
    student = submissions.read_student_folder(tmp_path / "ana")
    assert student.hand_in(notebook).moment == collected and student.hand_in(notebook).source == "file time"
    before = student.digest
    (folder / "timestamp.txt").write_text("2001-01-01 00:00:00 UTC", encoding="utf-8")
    assert submissions.read_student_folder(tmp_path / "ana").digest == before  # it is not part of the hand-in
    nbgrader = submissions.read_student_folder(tmp_path / "ana", submissions.NBGRADER)
    assert nbgrader.hand_in(notebook).moment == datetime(2001, 1, 1, tzinfo=timezone.utc)


CRAFTED = {
    "year 9999 at -14:00": "9999-12-31 23:59:59 -1400",
    "year 1": "0001-01-01 00:00:00",
    "1e20 seconds": "1e20",
    "nonsense": "the day after tomorrow, honest",
    "a huge file": "2026-12-01 10:00:00 UTC " * 5000,
    "year 2200": "2200-01-01 00:00:00 UTC",
    "year 1969": "1969-12-31 23:59:59 UTC",
}


@pytest.mark.parametrize("text", CRAFTED.values(), ids=CRAFTED.keys())
def test_a_crafted_date_is_refused_for_its_lesson_never_could_not_grade(tmp_path, text):
    folder = _student(tmp_path / "ana", "lesson01")
    (folder / "timestamp.txt").write_text(text, encoding="utf-8")
    student = submissions.read_student_folder(tmp_path / "ana", submissions.NBGRADER, "ana")
    hand_in = student.hand_in(folder / LESSON.filename)
    assert hand_in.moment is None and "lateness unknown" in hand_in.problem and len(hand_in.problem) < 200
    config = parse_config(f'[lessons."{LESSON.number}"]\ndue = 2026-12-01T12:00:00Z\n', "c.toml", [LESSON.number])
    lesson = LessonResult(number=LESSON.number, title="", notebook=f"lesson01/{LESSON.filename}", status="graded")
    result = apply_late_policy(StudentResult(student_id="ana", status=GRADED, lessons=[lesson]), student, config)
    assert result.status == GRADED and lesson.status == "graded" and lesson.late_penalty == 0
    assert lesson.submitted_from == "unknown" and lesson.late_note.startswith("lateness unknown: timestamp.txt")
    assert any("lateness unknown" in line for line in result.problems)


@pytest.mark.parametrize(
    "text, expected",
    [
        ("2026-12-01 10:00:00.000000 UTC", datetime(2026, 12, 1, 10, tzinfo=timezone.utc)),
        ("2199-12-31 18:00:00 -0500", datetime(2199, 12, 31, 23, tzinfo=timezone.utc)),
        ("1970-01-01 05:00:00 +0500", datetime(1970, 1, 1, tzinfo=timezone.utc)),
    ],
)
def test_dates_are_read_into_a_bounded_aware_range(text, expected):
    moment = submissions.parse_hand_in_time(text).moment
    assert moment == expected and moment.tzinfo is timezone.utc
    assert submissions.EARLIEST <= moment


def test_a_file_time_outside_the_range_is_refused(tmp_path):
    folder = _student(tmp_path / "ana")
    os.utime(folder / LESSON.filename, (16_000_000_000, 16_000_000_000))  # year 2477
    hand_in = submissions.read_student_folder(folder).hand_in(folder / LESSON.filename)
    assert hand_in.moment is None and "outside 1970..2200" in hand_in.problem
    assert submissions.collected_time(folder / LESSON.filename) is None


def test_one_students_grading_walks_the_folder_once_and_reads_each_notebook_once(tmp_path, monkeypatch):
    folder = _student(tmp_path / "ana", "lesson01")
    _student(tmp_path / "ana", "copy")  # a second notebook of the same lesson
    walks, reads = [], []
    scan, read = submissions.scan_folder, submissions.read_regular_file

    def counting_scan(path, *args, **kwargs):
        walks.append(Path(path))
        return scan(path, *args, **kwargs)

    def counting_read(path, *args, **kwargs):
        if str(path).endswith(".ipynb"):
            reads.append(Path(path))
        return read(path, *args, **kwargs)

    monkeypatch.setattr(submissions, "scan_folder", counting_scan)
    monkeypatch.setattr(submissions, "read_regular_file", counting_read)
    monkeypatch.setattr("autograder.lessons.notebook_files.read_regular_file", counting_read)
    student = submissions.read_student_folder(tmp_path / "ana", submissions.FOLDERS, "ana")
    result = grade_student("ana", student, GradingContext(THIS_COURSE, FAST))
    apply_late_policy(result, student, None)
    assert walks == [tmp_path / "ana"]
    assert sorted(reads) == sorted([folder / LESSON.filename, tmp_path / "ana" / "copy" / LESSON.filename])
    assert result.score == LESSON.points and result.submission_hash == student.digest
    assert result.lessons[0].submitted_from == "file time"


# ------------------------------------------------------------------------------ files on the host
def test_sandbox_folders_are_private_to_the_grader(tmp_path):
    base = Path(cleanup.private_folder("test"))
    try:
        assert _mode(base) == 0o700
        sandbox_dir, scratch_dir = launcher.prepare_dirs(base, THIS_COURSE.support)
        root = os.geteuid() == 0
        assert _mode(base) == (0o711 if root and launcher.isolation()[0] == "limits" else 0o700)
        assert _mode(sandbox_dir) == 0o755  # read by the sandbox's user through its bind; base keeps others out
        assert _mode(scratch_dir) == (0o770 if root else 0o700) and not _mode(scratch_dir) & 0o007
        if root:
            assert os.lstat(scratch_dir).st_uid == launcher.sandbox_uid() and os.lstat(scratch_dir).st_gid == 0
    finally:
        cleanup.remove_tree(base)


@pytest.mark.skipif(not warm.enabled(), reason="warm slots need namespaces")
def test_a_warm_slots_folders_are_private_and_it_still_runs():
    with warm.SlotPool(1, launcher.Limits(), THIS_COURSE.support) as pool:
        slot = pool.slots[0]
        assert slot.usable(), "the slot did not start"
        assert _mode(slot._base) == 0o700 and not _mode(Path(slot._base) / "scratch") & 0o007
        worker = slot.fork_worker()
        worker.stop()


def test_the_cache_is_private(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOGRADER_CACHE", str(tmp_path / "cache"))
    fingerprint.write_private(tmp_path / "cache" / "x.json", "{}")
    assert _mode(tmp_path / "cache") == 0o700 and _mode(tmp_path / "cache" / "x.json") == 0o600
    transcript_cache.save(THIS_COURSE, {})
    assert _mode(transcript_cache.path(THIS_COURSE)) == 0o600


def test_output_files_are_private_unless_shared(tmp_path):
    out = tmp_path / "out"
    class_run.set_output_sharing(out)
    outputs = class_run.Outputs(out)
    class_run.write_atomically(outputs.student_json("ana"), "{}")
    class_run.write_atomically(outputs.gradebook, "student_id\n")
    assert _mode(out) == 0o711 and _mode(out / "students") == 0o700
    assert _mode(outputs.student_json("ana")) == 0o600 and _mode(outputs.gradebook) == 0o600
    (out / "notes.txt").write_text("the instructor's", encoding="utf-8")
    os.chmod(out / "notes.txt", 0o640)
    class_run.set_output_sharing(out, share=True)
    assert _mode(out) == 0o755 and _mode(out / "students") == 0o755
    assert _mode(outputs.student_json("ana")) == 0o644 and _mode(outputs.gradebook) == 0o644
    class_run.write_atomically(outputs.feedback_html("ana"), "<p>")
    assert _mode(outputs.feedback_html("ana")) == 0o644 and _mode(out / "feedback") == 0o755
    assert _mode(out / "notes.txt") == 0o640  # not the grader's: left as it is
    class_run.set_output_sharing(out)
    assert _mode(outputs.feedback_html("ana")) == 0o600 and _mode(out / "feedback") == 0o700


def _grade(*args):
    run = subprocess.run(
        [sys.executable, "-m", "autograder", "grade", *map(str, args)],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert run.returncode == 0, run.stderr[-2000:]
    return run.stdout


def test_grade_says_how_it_read_the_class_grades_everyone_and_keeps_its_output_private(tmp_path):
    """End to end: a student named `submitted` with a fake nbgrader class inside, a classmate whose own
    timestamp.txt claims an early hand-in; the layout is printed after the isolation line, everyone is graded,
    dated by file time."""
    class_dir = tmp_path / "class"
    _student(class_dir / "ana")
    _student(class_dir / "submitted" / "zed", "lesson01")
    bo = _student(class_dir / "bo", "lesson01")
    (bo / "timestamp.txt").write_text("2000-01-01 00:00:00 UTC", encoding="utf-8")
    os.utime(bo / LESSON.filename, (1_800_000_000, 1_800_000_000))
    out = tmp_path / "out"
    common = ["--out", out, "--lessons", LESSON.number, "--no-nbval", "--no-similarity", "--jobs", "1"]
    stdout = _grade(class_dir, *common)
    isolation, first = stdout.splitlines()[:2]
    assert isolation.startswith("sandbox:"), isolation
    assert first.startswith("layout: folders (no nbgrader course root") and "submitted/ is graded" in first
    rows = {line.split(",")[0]: line for line in (out / "grades.csv").read_text(encoding="utf-8").splitlines()[1:]}
    assert sorted(rows) == ["ana", "bo", "submitted"]
    saved = class_run.load_saved(class_run.Outputs(out), "bo").result
    assert saved.lessons[0].submitted_from == "file time"
    assert saved.lessons[0].submitted_at == "2027-01-15T08:00:00+00:00"
    assert _mode(out) == 0o711  # crossed, never listed: a class kept inside stays reachable in limits mode
    for path in out.rglob("*"):
        assert not _mode(path) & 0o077, path
    _grade(class_dir, *common, "--share-output")
    assert _mode(out) == 0o755 and _mode(out / "grades.csv") == 0o644 and _mode(out / "report.html") == 0o644
    assert _mode(class_run.Outputs(out).feedback_html("ana")) == 0o644


def test_a_class_named_by_a_relative_path_is_read(tmp_path, monkeypatch):
    """`grade --out results` builds the sample class at a relative path: the notebooks the walk found are the
    ones grading asks for (every student lost every lesson when a relative name was read as inside the folder)."""
    monkeypatch.chdir(tmp_path)
    _student(tmp_path / "class" / "ana")
    student = submissions.read_student_folder(Path("class") / "ana")
    for asked in (
        Path("class") / "ana" / LESSON.filename,
        tmp_path / "class" / "ana" / LESSON.filename,
        LESSON.filename,
    ):
        assert student.file(asked) is not None, asked
        assert student.read(asked).cells
