"""Build submissions from answer choices and grade them in-process (for the tests).

Examples
--------
>>> folder = build_submission(tmp_path, {"rot_z": mistakes["rot_z_transposed"].source})  # doctest: +SKIP
>>> result = grade(folder, lessons=("01",))                                             # doctest: +SKIP
"""

import csv
import os
import subprocess
import sys
import zlib
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path

from autograder.grading.pipeline import GradingContext, GradingOptions, grade_student
from autograder.lessons.hand_ins import write_submission
from autograder.lessons.paths import PROJECT_ROOT, this_course
from autograder.lessons.reference import answer_sources
from autograder.mistakes import all_mistakes

STUB = "stub"
THIS_COURSE = this_course()  # the course the tests grade (a second one is built in tests/test_second_course.py)


@lru_cache(maxsize=1)
def references():
    return answer_sources(THIS_COURSE.solutions)


@lru_cache(maxsize=1)
def mistakes():
    return all_mistakes()


def build_submission(folder, overrides=None, default="reference", lessons=None):
    """Write one student's notebooks into ``folder`` from the released course.

    ``overrides`` maps an exercise to an answer-cell source (or ``STUB``);
    other exercises get ``default``: ``"reference"`` or ``STUB``.
    """
    overrides = overrides or {}
    answers = {}
    for name, source in references().items():
        choice = overrides.get(name, default)
        if choice != STUB:
            answers[name] = source if choice == "reference" else choice
    return write_submission(THIS_COURSE, folder, answers, lessons or ())


def benchmark_class(target, count):
    """``count`` students for every lesson: even ones hand in the reference answers, every fourth from
    the second on untouched stubs, the rest a handful of typical mistakes, different for each student.

    The class of ``benchmarks/grading_speed.py`` and of the golden gradebook
    ``tests/golden/benchmark_class_grades.csv``. Returns the student folders, sorted.
    """
    by_exercise = {}
    for mistake in sorted((m for m in all_mistakes().values() if m.kind == "mistake"), key=lambda m: m.name):
        by_exercise.setdefault(mistake.exercise, []).append(mistake)
    target = Path(target)
    target.mkdir(parents=True, exist_ok=True)
    for index in range(count):
        folder = target / f"student{index:03d}"
        if index % 2 == 0:
            build_submission(folder)
        elif index % 4 == 1:
            build_submission(folder, default=STUB)
        else:
            build_submission(folder, _drawn_mistakes(folder.name, by_exercise))
    return sorted(p for p in target.iterdir() if p.is_dir())


def _drawn_mistakes(student, by_exercise, share=3):
    """``{exercise: source}``: a mistake in about one exercise of ``share``, drawn by a hash of the student's and the
    exercise's names, so a mistake added to the corpus moves only its own exercise's draws (and the golden
    gradebook only there)."""
    chosen = {}
    for exercise, mistakes in by_exercise.items():
        draw = zlib.crc32(f"{student}/{exercise}".encode())
        if draw % share == 0:
            chosen[exercise] = mistakes[(draw // share) % len(mistakes)].source
    return chosen


def grade(folder, lessons=(), nbval=False, slot=None):
    """Grade one folder in this process and return its StudentResult.

    ``slot``: a started warm slot (the ``warm_slot`` fixture of ``tests/conftest.py``) whose zygote forks the
    student's sandbox, as a class run does (about 0.2 s a student instead of 0.6 s for a cold sandbox).
    """
    return grade_student(
        Path(folder).name,
        Path(folder),
        GradingContext(THIS_COURSE, GradingOptions(nbval=nbval, lessons=tuple(lessons))),
        slot=slot,
    )


def points_by_exercise(result):
    return {e.name: (e.points, e.max_points) for e in result.exercises}


def grade_sample_class(out, sandbox=None):
    """Run the README's main command (the bundled sample class, nbval included) into ``out``.

    ``sandbox="limits"`` asks for resource limits only (``AUTOGRADER_SANDBOX=limits``).
    Returns ``(out, stdout, {student_id: grades.csv row})``.
    """
    env = {key: value for key, value in os.environ.items() if key != "AUTOGRADER_SANDBOX"}
    if sandbox:
        env["AUTOGRADER_SANDBOX"] = sandbox
    result = subprocess.run(
        [sys.executable, "-m", "autograder", "grade", "--out", str(out)],
        cwd=PROJECT_ROOT,
        capture_output=True,
        text=True,
        timeout=1500,
        env=env,
    )
    assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    with open(Path(out) / "grades.csv", newline="", encoding="utf-8") as handle:
        rows = {row["student_id"]: row for row in csv.DictReader(handle)}
    return out, result.stdout, rows


@contextmanager
def started_warm_slot():
    """A warm slot of this course with the default limits, its zygote started and ready; closed after."""
    from autograder.sandbox import launcher, warm

    slot = warm.WarmSlot(0, launcher.Limits(), THIS_COURSE.support)
    slot.spawn()
    slot.wait_ready()
    assert slot.usable(), "the slot's zygote did not start"
    try:
        yield slot
    finally:
        slot.close()
