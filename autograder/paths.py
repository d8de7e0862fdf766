"""Where the project's parts live, relative to this package."""

from pathlib import Path

PROJECT_ROOT = Path(__file__).resolve().parent.parent
SOLUTIONS = PROJECT_ROOT / "solutions"
COURSE = PROJECT_ROOT / "course"
HIDDEN_SUITE = Path(__file__).resolve().parent / "hidden"
SUPPORT_PACKAGE = "coursekit"
