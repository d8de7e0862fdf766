"""Where this repository's own parts live, relative to the ``autograder`` package: read by the CLI (the default
``--course``) and the tests only; below the CLI a :class:`~autograder.lessons.course.Course` is passed down."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from autograder.lessons.course import Course

PACKAGE = Path(__file__).resolve().parent.parent  # autograder/
PROJECT_ROOT = PACKAGE.parent
SOLUTIONS = PROJECT_ROOT / "solutions"
COURSE = PROJECT_ROOT / "course"
HIDDEN_SUITE = PACKAGE / "hidden"
SUPPORT_PACKAGE = "coursekit"


def this_course() -> Course:
    """This repository's own course, "Rotations, hands on" (the CLI's default ``--course``)."""
    from autograder.lessons.course import Course

    return Course.at(PROJECT_ROOT)
