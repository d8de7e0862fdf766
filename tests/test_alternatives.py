"""Correct answers written differently from the reference get full marks, hidden and public.

Each :class:`~autograder.mistakes.Alternative` (another formula, lists instead
of arrays, the other valid branch at a singularity) is put into an otherwise
correct submission; it must earn every hidden point of its lesson and pass
every public check of its exercise.
"""

from collections import Counter

import pytest

from autograder.mistakes import all_alternatives
from public_runner import run_public_checks
from support import build_submission, grade
from support import THIS_COURSE

ALTERNATIVES = all_alternatives()


def _ids(name):
    return f"lesson{THIS_COURSE.catalog.exercise(ALTERNATIVES[name].exercise).lesson}-{name}"


@pytest.mark.parametrize("name", sorted(ALTERNATIVES), ids=_ids)
def test_alternative_gets_full_hidden_marks(name, tmp_path, warm_slot):
    alternative = ALTERNATIVES[name]
    lesson = THIS_COURSE.catalog.exercise(alternative.exercise).lesson
    folder = build_submission(tmp_path / "student", {alternative.exercise: alternative.source}, lessons=(lesson,))
    result = grade(folder, lessons=(lesson,), slot=warm_slot)
    failed = [(c.exercise, c.description, c.reason, c.hint) for e in result.exercises for c in e.checks if not c.passed]
    assert not failed, f"{name} ({alternative.description}) lost points: {failed}"


@pytest.mark.parametrize("name", sorted(ALTERNATIVES), ids=_ids)
def test_alternative_passes_the_public_checks(name):
    alternative = ALTERNATIVES[name]
    passed, printed = run_public_checks(THIS_COURSE, alternative.exercise, alternative.source)
    assert passed, f"{name} ({alternative.description}) fails a public check:\n{printed}"


def test_every_lesson_has_alternatives():
    counts = Counter(THIS_COURSE.catalog.exercise(a.exercise).lesson for a in ALTERNATIVES.values())
    missing = [lesson.number for lesson in THIS_COURSE.catalog.graded_lessons if counts[lesson.number] == 0]
    assert not missing, f"lessons without correct alternatives: {missing}"
