"""Where the project's parts live, relative to the ``autograder`` package."""

from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent  # autograder/
PROJECT_ROOT = PACKAGE.parent
SOLUTIONS = PROJECT_ROOT / "solutions"
COURSE = PROJECT_ROOT / "course"
HIDDEN_SUITE = PACKAGE / "hidden"
SUPPORT_PACKAGE = "coursekit"
