"""The reference answers earn full marks and the released stubs earn zero, lesson by lesson."""

import pytest

from support import STUB, build_submission, grade
from support import THIS_COURSE

LESSONS = [lesson.number for lesson in THIS_COURSE.catalog.graded_lessons]


@pytest.mark.parametrize("lesson", LESSONS, ids=lambda n: f"lesson{n}")
def test_reference_answers_score_full_marks(lesson, tmp_path):
    result = grade(build_submission(tmp_path / "ref", lessons=(lesson,)), lessons=(lesson,))
    failed = [(c.exercise, c.description, c.reason) for e in result.exercises for c in e.checks if not c.passed]
    assert not failed, failed
    assert result.score == result.max_score > 0
    assert result.status == "graded", result.problems


@pytest.mark.parametrize("lesson", LESSONS, ids=lambda n: f"lesson{n}")
def test_released_stubs_score_zero(lesson, tmp_path):
    result = grade(build_submission(tmp_path / "stub", default=STUB, lessons=(lesson,)), lessons=(lesson,))
    assert result.score == 0, {e.name: e.points for e in result.exercises}
    reasons = {c.reason for e in result.exercises for c in e.checks}
    assert all("not written yet" in r for r in reasons), reasons


def test_every_exercise_has_hidden_checks(tmp_path):
    result = grade(build_submission(tmp_path / "ref"))
    empty = [e.name for e in result.exercises if not e.checks]
    assert not empty, f"exercises without hidden checks: {empty}"


def test_a_failed_prerequisite_is_named(tmp_path):
    """An exercise that calls another, broken exercise of its lesson says so in its notes."""
    broken_rot_z = "def rot_z(a):\n    return 2.0 * np.eye(3)\n"
    uses_rot_z = "def compose(R_ab, R_bc):\n    return np.asarray(R_ab) @ np.asarray(R_bc) @ rot_z(0.1)\n"
    folder = build_submission(tmp_path / "s", {"rot_z": broken_rot_z, "compose": uses_rot_z}, lessons=("01",))
    compose = next(e for e in grade(folder, lessons=("01",)).exercises if e.name == "compose")
    assert compose.points < compose.max_points
    assert any("calls your rot_z" in note for note in compose.notes), compose.notes
