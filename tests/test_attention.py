"""The class report's warnings: a stage that failed for most of the class points at the grader."""

from autograder.grading.results import CheckResult, ExerciseResult, LessonResult, NotebookRun, StudentResult
from autograder.reports.attention import stage_warnings, worth_a_look


def _student(student_id, notebook_status, full=True, note=""):
    exercise = ExerciseResult(
        name="rot_z",
        lesson="01",
        max_points=1.0,
        points=1.0 if full else 0.0,
        checks=[CheckResult("rot_z", "a quarter turn", 1.0, full, "" if full else note)],
    )
    lesson = LessonResult(
        number="01",
        title="Frames",
        notebook="01.ipynb",
        status="graded",
        exercises=[exercise],
        run=NotebookRun(status=notebook_status, max_points=1.0),
    )
    return StudentResult(student_id=student_id, status="graded", lessons=[lesson])


def test_a_notebook_stage_that_fails_for_most_of_the_class_is_flagged():
    results = [_student(f"s{i}", "failed") for i in range(3)] + [_student("s3", "passed")]
    (warning,) = stage_warnings(results)
    assert "lesson 01: the notebook stage failed for 3 of 4 students who had full hidden marks" in warning.text


def test_a_class_with_a_few_failures_is_not_flagged():
    results = [_student("a", "failed")] + [_student(f"s{i}", "passed") for i in range(3)]
    results.append(_student("wrong", "failed", full=False, note="looks like the transpose"))
    assert stage_warnings(results) == []


def test_worth_a_look_names_the_kind_and_counts():
    looped = _student("ivy", "passed", full=False, note="rot_z did not return within 5 s (an endless loop?)")
    honest = _student("ada", "passed")
    (concern,) = worth_a_look([looped, honest])
    assert (concern.student_id, concern.kind, concern.count) == ("ivy", "timeout", 1)
