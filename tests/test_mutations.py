"""The hidden suite can fail: each typical mistake loses points on its exercise, and only there.

Every :class:`~autograder.mistakes.Mistake` is put into an otherwise correct
submission of its lesson; the test requires that the mistaken exercise scores
below its maximum and that every other exercise of the lesson keeps full
marks (so one mistake, crash or hang never costs points elsewhere).
"""

import pytest

from autograder.catalog import load_catalog
from autograder.mistakes import all_mistakes
from support import build_submission, grade, points_by_exercise

MISTAKES = all_mistakes()


def _lesson(mistake):
    try:
        return load_catalog().exercise(mistake.exercise).lesson
    except KeyError:  # a lesson's mistakes written before its master: reported by the test below
        return "??"


@pytest.mark.parametrize("name", sorted(MISTAKES), ids=lambda n: f"lesson{_lesson(MISTAKES[n])}-{n}")
def test_mistake_costs_points_on_its_exercise_only(name, tmp_path):
    mistake = MISTAKES[name]
    lesson = _lesson(mistake)
    assert lesson != "??", f"{name}: no master defines {mistake.exercise}"
    folder = build_submission(tmp_path / "student", {mistake.exercise: mistake.source}, lessons=(lesson,))
    points = points_by_exercise(grade(folder, lessons=(lesson,)))
    earned, available = points[mistake.exercise]
    assert earned < available, f"{name} ({mistake.description}) kept full marks on {mistake.exercise}"
    elsewhere = {ex: p for ex, p in points.items() if ex != mistake.exercise and p[0] < p[1]}
    assert not elsewhere, f"{name} also cost points on {elsewhere}"


def test_every_lesson_has_mistakes():
    """Each graded lesson has at least five typical mistakes to prove its suite can fail."""
    orphans = [name for name, mistake in MISTAKES.items() if _lesson(mistake) == "??"]
    assert not orphans, f"mistakes for exercises that no master defines: {orphans}"
    counts = {lesson.number: 0 for lesson in load_catalog().graded_lessons}
    for mistake in MISTAKES.values():
        if mistake.kind == "mistake":
            counts[_lesson(mistake)] += 1
    assert all(n >= 5 for n in counts.values()), counts
