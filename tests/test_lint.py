"""The code reads clean: ``ruff check`` (configured in pyproject.toml) finds nothing in the grader, the
tests, the course's package and the lesson masters (their code cells included), and ``ruff format`` would
change nothing in the grader, its tests and benchmarks (the course's own files are laid out by hand).

Oracle: ruff's exit status and its report. The released ``course/`` is generated from the masters and
is not linted on its own.
"""

import subprocess
import sys

from autograder.lessons.paths import PROJECT_ROOT


def test_ruff_finds_nothing():
    ruff = [sys.executable, "-m", "ruff"]
    run = subprocess.run(
        [*ruff, "check", "--no-cache", "--output-format", "concise", "autograder", "tests", "solutions", "benchmarks"],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout + run.stderr


def test_ruff_format_changes_nothing():
    run = subprocess.run(
        [sys.executable, "-m", "ruff", "format", "--check", "--no-cache", "autograder", "tests", "benchmarks"],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout + run.stderr
