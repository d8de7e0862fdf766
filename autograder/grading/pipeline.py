"""Grade one student: notebooks → answers → sandbox → hidden suite (→ nbval) → result.

nbval runs after the hidden suite, and only on the lessons whose exercises all
got full hidden marks: the notebook point needs them (:func:`nbval_stage.award`),
so for any other lesson nbval could not change the grade; its run is
``skipped``, worth 0, with the reason.

This is GUIDE's "Grading, end to end" for a single student. Each lesson and
each exercise is graded on its own: a notebook that cannot be read costs that
lesson's points (with the reason), a function that crashes or hangs costs
that exercise's points, and everything else is still graded.
"""

from __future__ import annotations

import ast
import time
from pathlib import Path
from typing import Callable

from autograder.grading import extract, submissions
from autograder.grading.budget import cut, cut_list, fit_result
from autograder.grading.context import GradingContext
from autograder.grading.nbval_stage import award, full_hidden_marks, not_run_for_lost_points, run_notebooks
from autograder.grading.options import GradingOptions
from autograder.grading.results import (
    COULD_NOT_GRADE,
    GRADED,
    GRADED_WITH_PROBLEMS,
    MISSING,
    ExerciseResult,
    LessonResult,
    NotebookRun,
    StudentResult,
)
from autograder.grading.suite import StudentProxy, run_hidden_suite
from autograder.lessons import cells
from autograder.lessons.notebook_files import UnreadableNotebook
from autograder.sandbox import launcher
from autograder.sandbox.session import SandboxUnavailable, StudentError, StudentSandbox
from autograder.sandbox.warm import WarmSlot

__all__ = ["GradingContext", "GradingOptions", "grade_student"]  # what a caller needs to grade one student


def _score(max_points, checks):
    total = sum(c.weight for c in checks)
    if not total:
        return 0.0
    passed = sum(c.weight for c in checks if c.passed)
    return round(max_points * passed / total, 2)


def _calls_to_other_exercises(source, names):
    """Exercise names (from ``names``) that a student's answer cell refers to."""
    tree = cells.parse_source(source)
    if tree is None:
        return set()
    return {node.id for node in ast.walk(tree) if isinstance(node, ast.Name) and node.id in names}


def _note_failed_prerequisites(shell, program):
    """Say plainly when an exercise that lost points calls another exercise that lost points."""
    if program is None:
        return
    sources = dict(program.cells)
    lost = {e.name for e in shell.exercises if e.points < e.max_points}
    for exercise in shell.exercises:
        if exercise.name not in lost or exercise.name not in sources:
            continue
        used = _calls_to_other_exercises(sources[exercise.name], lost - {exercise.name})
        for other in sorted(used):
            exercise.notes.append(
                f"your {exercise.name} calls your {other}, which also lost points: "
                f"fix {other} first, its mistake may be the cause here"
            )


def _read_lessons(student, course, only=()):
    """For each graded lesson: (LessonResult shell, notebook path, program or None); notes on the files
    (which of several notebooks was graded, notebooks that belong to no lesson); and one line for each
    thing of the folder that was skipped (hidden, a link, too deep), with why. ``student``: the folder as read
    once (:class:`~autograder.grading.submissions.StudentFolder`; a path is read here, in one walk); nothing
    here reads the disk again."""
    if not isinstance(student, submissions.StudentFolder):
        student = submissions.read_student_folder(student)
    catalog, folder = course.catalog, student.path
    files = submissions.match_lessons(folder, catalog, course.released, student=student)
    notes = [files.notes[number] for number in sorted(files.notes) if not only or number in only]
    notes += [
        f"{path.relative_to(folder)} was not graded: "
        + (files.unreadable.get(path) or "it holds no exercise of the course (no answer cell and no exercise function)")
        for path in files.unmatched
    ]
    found = []
    for lesson in catalog.graded_lessons:
        if only and lesson.number not in only:
            continue
        shell = LessonResult(number=lesson.number, title=lesson.title, notebook=lesson.filename, status="graded")
        path = files.chosen.get(lesson.number)
        if path is None:
            shell.status, shell.reason = "missing", f"no notebook {lesson.filename} in the submission"
            found.append((shell, None, None))
            continue
        shell.notebook = str(path.relative_to(folder))
        try:
            program = extract.lesson_program(student.read(path), lesson)
        except UnreadableNotebook as error:
            shell.status, shell.reason = "unreadable", cut(error)
            program = None
        except Exception as error:  # whatever else this notebook does to the grader costs this notebook only
            shell.status = "unreadable"
            shell.reason = cut(f"the grader could not read this notebook ({type(error).__name__}: {error})")
            program = None
        found.append((shell, path, program))
    return found, cut_list([cut(note) for note in notes]), cut_list([cut(item.line()) for item in files.skipped])


def grade_student(
    student_id: str,
    folder: Path | submissions.StudentFolder,
    context: GradingContext,
    slot: WarmSlot | None = None,
    answers: Callable[[dict[str, str]], dict] | None = None,
) -> StudentResult:
    """Grade the submission in ``folder`` in ``context`` (the course and the run's options); never raises for
    anything the student did.

    ``folder``: the student's folder as read once (:class:`~autograder.grading.submissions.StudentFolder`),
    whose notebooks, digest and skipped entries are all this uses; a path is read here, in one walk.

    ``slot``: the warm slot (:class:`~autograder.sandbox.warm.WarmSlot`) this grader process was
    given, whose zygote forks the student's sandboxes; None starts each sandbox cold.

    ``answers``: called here, in the student's own grading process, with ``{exercise: answer source}`` as
    extracted for grading; what it returns (bounded: :data:`~autograder.grading.budget.ANSWERS_BYTES`) is kept
    as ``result.answers`` for the similarity stage, which then reads and parses nothing of the student's.
    Every student-controlled text of the result is bounded (:func:`~autograder.grading.budget.fit_result`).

    >>> grade_student("ada", Path("class/ada"), context).status        # doctest: +SKIP
    'graded'
    """
    started = time.monotonic()
    student = folder if isinstance(folder, submissions.StudentFolder) else submissions.read_student_folder(folder)
    folder = student.path
    course, options = context.course, context.options
    catalog, reference = course.catalog, course.reference
    result = StudentResult(
        student_id=student_id,
        status=GRADED,
        submission_hash=student.digest,
        isolation=launcher.isolation()[0],
    )
    lessons, file_notes, result.skipped = _read_lessons(student, course, options.lessons)
    result.problems.extend(file_notes)
    programs = {shell.number: program for shell, _, program in lessons if program is not None}
    unavailable = {
        shell.number: f"{shell.notebook}: {shell.reason}" for shell, _, program in lessons if program is None
    }

    checks, suite_problems = [], []
    with StudentSandbox(programs, course.support, limits=options.limits, slot=slot) as sandbox:
        proxy = StudentProxy(sandbox, catalog, unavailable)
        try:
            checks, suite_problems = run_hidden_suite(
                proxy, reference, course, lessons=[shell.number for shell, _, _ in lessons]
            )
        except StudentError as error:  # e.g. the sandbox crashed too many times
            result.problems.append(cut(f"grading stopped early: {error.message}"))
        except SandboxUnavailable as error:  # nothing of the student's ran: no grade rather than a zero
            result.status = COULD_NOT_GRADE
            result.reason = cut(f"{error}: a problem of this machine or of the grader, not of the submission")
        outcomes = {(o.lesson, o.label): o for o in sandbox.outcomes}
    if answers is not None:
        try:
            result.answers = answers({name: source for p in programs.values() for name, source in p.cells})
        except Exception:  # no grade depends on it: the similarity stage reads this student in a limited fork
            result.answers = None

    for shell, path, program in lessons:
        lesson = catalog.lesson(shell.number)
        if program is not None:
            result.problems.extend(cut(f"{shell.notebook}: {p}") for p in cut_list(program.problems))
        elif shell.status != "graded":
            result.problems.append(cut(f"lesson {shell.number}: {shell.reason}"))
        for exercise in lesson.exercises:
            own = [c for c in checks if c.exercise == exercise.name]
            entry = ExerciseResult(
                name=exercise.name,
                lesson=lesson.number,
                max_points=exercise.points,
                points=_score(exercise.points, own),
                checks=own,
            )
            outcome = outcomes.get((lesson.number, exercise.name))
            if outcome is not None and not outcome.ok:
                entry.notes.append(cut(f"running the answer cell failed: {outcome.message}"))
            setup = outcomes.get((lesson.number, "setup"))
            if setup is not None and not setup.ok:
                entry.notes.append(cut(f"the lesson's setup cell failed: {setup.message}"))
            if program is None:
                entry.notes.append(shell.reason)
            shell.exercises.append(entry)
        _note_failed_prerequisites(shell, program)
        result.lessons.append(shell)

    if options.nbval and result.status != COULD_NOT_GRADE:
        # The notebook point needs full hidden marks on the lesson (nbval_stage.award), so nbval
        # runs only where it can still change the grade; the other lessons say why it did not run.
        worth_running = [
            (shell, path, program)
            for shell, path, program in lessons
            if program is not None and full_hidden_marks(shell)
        ]
        stage_failed = ""
        try:
            runs = run_notebooks(folder, worth_running, options, course, slot=slot) if worth_running else {}
        except Exception as error:  # costs this student's notebook points, with the reason
            runs, stage_failed = {}, cut(f"the notebook stage failed ({type(error).__name__}: {error})")
        for shell, _, program in lessons:
            if program is not None and not full_hidden_marks(shell):
                shell.run = not_run_for_lost_points(options.notebook_points)
            else:
                shell.run = runs.get(shell.number) or NotebookRun(
                    status="failed",
                    max_points=options.notebook_points,
                    failures=[shell.reason or stage_failed or "the notebook stage did not run"],
                )
            award(shell)

    result.problems.extend(cut(problem) for problem in cut_list(suite_problems))
    fit_result(result)  # one budget for all the student's text of this result
    if result.status != COULD_NOT_GRADE:
        if all(shell.status == "missing" for shell, _, _ in lessons):
            result.status, result.reason = MISSING, "the submission holds none of the course's notebooks"
        elif result.problems:
            result.status = GRADED_WITH_PROBLEMS
    result.seconds = round(time.monotonic() - started, 2)
    return result
