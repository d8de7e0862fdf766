"""Print what each typical mistake of a lesson is told: hidden points, failed checks with hints, public ✗ lines.

An authoring aid for ``autograder/mistakes/lessonNN.py``: run it, read what each
mistake gets, and declare the hint that names the real mistake (``hint=`` a
substring of the hidden feedback, ``public_hint=`` of the check cell's output).

Usage, from the project root::

    .venv/bin/python tests/mistake_report.py 03            # every mistake of lesson 03
    .venv/bin/python tests/mistake_report.py 03 log_naive  # mistakes whose name contains "log_naive"
"""

import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
for entry in (ROOT, ROOT / "tests", ROOT / "solutions"):
    sys.path.insert(0, str(entry))

from autograder.mistakes import all_mistakes  # noqa: E402
from public_runner import run_public_checks  # noqa: E402
from support import THIS_COURSE, build_submission, grade, points_by_exercise  # noqa: E402


def report(lesson, name_part=""):
    catalog = THIS_COURSE.catalog
    for name, mistake in sorted(all_mistakes().items()):
        if catalog.exercise(mistake.exercise).lesson != lesson or name_part not in name:
            continue
        print(f"=== {name} ({mistake.exercise}, {mistake.kind}): {mistake.description}")
        print(f"    declared: hint={mistake.hint!r} public_hint={mistake.public_hint!r}")
        with tempfile.TemporaryDirectory() as scratch:
            folder = build_submission(Path(scratch) / "s", {mistake.exercise: mistake.source}, lessons=(lesson,))
            result = grade(folder, lessons=(lesson,))
        earned, available = points_by_exercise(result)[mistake.exercise]
        print(f"    hidden: {earned:g}/{available:g}")
        for exercise in result.exercises:
            for check in exercise.checks:
                if exercise.name == mistake.exercise and not check.passed:
                    print(
                        f"      ✗ {check.description} (weight {check.weight:g}): {check.reason}\n        hint: {check.hint}"
                    )
        if mistake.kind == "mistake":
            passed, printed = run_public_checks(THIS_COURSE, mistake.exercise, mistake.source)
            print(f"    public: {'all pass' if passed else 'fails'}")
            for line in printed.splitlines():
                if "✗" in line or "hint" in line:
                    print(f"      {line.strip()}")


if __name__ == "__main__":
    report(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else "")
