"""The canary grades the reference one fork per lesson (autograder/grading/canary.py): the lessons' results are
joined into one, in lesson order, so a shortfall anywhere still names its lesson and stage."""

from autograder.grading.canary import _joined, shortfalls
from autograder.grading.results import ExerciseResult, LessonResult, StudentResult


def _lesson(number, points, max_points=2.0):
    return LessonResult(
        number=number,
        title="",
        notebook=f"{number}.ipynb",
        status="graded",
        exercises=[ExerciseResult(name=f"e{number}", lesson=number, points=points, max_points=max_points)],
    )


def test_the_lessons_graded_apart_join_in_order_with_their_points():
    joined = _joined(
        [
            StudentResult(student_id="canary", status="graded", lessons=[_lesson("09", 2.0)]),
            StudentResult(student_id="canary", status="graded", lessons=[_lesson("01", 2.0)]),
        ]
    )
    assert [lesson.number for lesson in joined.lessons] == ["01", "09"]
    assert (joined.score, joined.max_score) == (4.0, 4.0)
    assert shortfalls(joined) == []


def test_a_shortfall_in_one_lesson_survives_the_join():
    joined = _joined(
        [
            StudentResult(student_id="canary", status="graded", lessons=[_lesson("01", 2.0)]),
            StudentResult(student_id="canary", status="graded", lessons=[_lesson("04", 1.0)]),
        ]
    )
    assert joined.score == 3.0
    assert len(shortfalls(joined)) == 1 and shortfalls(joined)[0].startswith("lesson 04, hidden suite, e04 (1/2)")


def test_a_reason_given_by_any_fork_is_kept():
    joined = _joined(
        [
            StudentResult(student_id="canary", status="graded", lessons=[_lesson("01", 2.0)]),
            StudentResult(student_id="canary", status="could not grade", reason="the sandbox did not start"),
        ]
    )
    assert joined.status == "could not grade" and joined.reason == "the sandbox did not start"
    assert shortfalls(joined)[0] == "could not grade: the sandbox did not start"
