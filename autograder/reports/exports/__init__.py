"""Gradebook exports for learning-management systems, one small module each.

An exporter is a function ``write(results, catalog, roster, missing="zero") -> str``
(the file's text) registered in :data:`EXPORTERS`. ``missing`` says what a lesson
that was not handed in becomes: ``"zero"`` (the default: 0 points) or ``"blank"``
(an empty cell, which LMSs leave ungraded); :func:`not_handed_in` names those lessons. To add Moodle or Blackboard,
copy :mod:`autograder.reports.exports.canvas`, change the columns, and register it
here; ``python -m autograder export --to NAME`` then offers it.
"""

from autograder.grading.results import COULD_NOT_GRADE

MISSING_CHOICES = ("zero", "blank")


def not_handed_in(result, lessons):
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


from autograder.reports.exports import canvas  # noqa: E402  (canvas uses not_handed_in)

EXPORTERS = {"canvas": canvas.write}
