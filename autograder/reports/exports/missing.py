"""What an export writes for a lesson that was not handed in: ``"zero"`` (0 points, the default) or
``"blank"`` (an empty cell, which learning-management systems leave ungraded).

Examples
--------
>>> MISSING_CHOICES
('zero', 'blank')
"""

from __future__ import annotations

from autograder.grading.results import COULD_NOT_GRADE, StudentResult
from autograder.lessons.catalog import Lesson

MISSING_CHOICES = ("zero", "blank")


def not_handed_in(result: StudentResult, lessons: tuple[Lesson, ...]) -> list[str]:
    """The numbers of ``lessons`` that ``result``'s student did not hand in (every one for a student without a
    submission); none for a student who could not be graded (their grade is unknown, never a 0).

    Examples
    --------
    >>> not_handed_in(result, catalog.graded_lessons)          # doctest: +SKIP
    ['04', '09']
    """
    if result.status == COULD_NOT_GRADE:
        return []
    handed_in = {lesson.number for lesson in result.lessons if lesson.status != "missing"}
    return [lesson.number for lesson in lessons if lesson.number not in handed_in]
