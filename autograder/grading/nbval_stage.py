"""The nbval stage: do the student's functions make the reference notebook run as it did?

For every lesson we take the master from ``solutions/`` (with its recorded
demonstration outputs) and run it with ``pytest --nbval-lax``, one pytest run
per student, in a sandbox of its own. A lesson passes when every cell runs and
every cell tagged ``nbval-check-output`` prints what the reference printed.

**No student code runs in that kernel.** Each answer cell is replaced by one
that binds the exercise's name to a function calling the student's own
sandbox (``sandbox/child/student_client.py``): a fresh sandbox per lesson,
loaded with the student's cells, whose two pipes are handed to the notebook's
sandbox. Values come back as plain data. So the student's code cannot rewrite
a later cell (an IPython input transformer), read the notebook's recorded
outputs or end the kernel: the kernel, nbval and their verdict are ours, and
the student's code only ever sees the calls the notebook makes.

A lesson's "notebook" point is awarded only when nbval passed **and** the
hidden suite gave every exercise of the lesson full marks (:func:`award`): the
grader runs the hidden suite first and gives nbval only the lessons with full
hidden marks; for the others the point is 0 whatever nbval would say, and
their run is ``skipped`` with that reason (:func:`not_run_for_lost_points`).
"""

from __future__ import annotations

import json
import os
import select
import subprocess
import sys
import time
from pathlib import Path

import nbformat

from autograder.grading import notebook_calls
from autograder.grading.options import GradingOptions
from autograder.grading.results import LessonResult, NotebookRun
from autograder.lessons import cells
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import canonical_text, read_master
from autograder.sandbox import cleanup, launcher
from autograder.sandbox.session import LessonProgram, SandboxUnavailable, StudentError, StudentSandbox
from autograder.sandbox.warm import WarmSlot

SANITIZE = """[hex addresses]
regex: 0x[0-9a-fA-F]+
replace: 0xADDRESS

[negative zero]
regex: -0\\.0+\\b
replace: 0.0
"""
SUMMARY_LIMIT = 1 << 20


BIND = "from student_client import student_function\n{name} = student_function({lesson!r}, {name!r})\n"


CHECK_ONLY = ("check(", "from coursekit import ready_to_hand_in")


def _only_runs_public_checks(cell) -> bool:
    """A student-only cell that runs public checks and nothing else (``check("name", name)``, the hand-in cell)."""
    source = cell.source.strip()
    return (
        cell.cell_type == "code"
        and "student-only" in cell.metadata.get("tags", [])
        and source.startswith(CHECK_ONLY)
        and all(
            line.startswith(("check(", "from coursekit import", "ready_to_hand_in(")) or not line.strip()
            for line in source.splitlines()
        )
    )


def merged_notebook(master: nbformat.NotebookNode, lesson: str) -> nbformat.NotebookNode:
    """The master with each answer cell replaced by a binding of its exercise to the student's function, and
    without the cells that only run public checks: nbval runs only for lessons whose hidden checks all passed,
    which grade every public check's claim already (in one batch per test), and no check cell's output is
    compared; run here, each check would cross the sandbox once per call (the contract line alone makes about 30
    calls per exercise), and the hand-in cell runs them all a second time."""
    master.cells = [cell for cell in master.cells if not _only_runs_public_checks(cell)]
    for cell in master.cells:
        if cells.is_answer_cell(cell):
            cell.source = BIND.format(name=cells.grade_id(cell), lesson=lesson)
    return master


def _stage_timeout(count):
    return 60.0 + 45.0 * count


def _student_channels(runnable, options, support, slot):
    """One loaded sandbox per lesson (forked from this grader's warm slot, if any), its pipes handed over.

    Returns ``(sandboxes, {lesson: (request fd, reply fd)}, {lesson: why it could not start})``.
    """
    sandboxes, channels, problems = [], {}, {}
    for shell, program in runnable:
        box = StudentSandbox(
            {shell.number: program}, support, limits=options.limits, slot=slot, resets_slot=False, direct=True
        )
        sandboxes.append(box)
        try:
            channels[shell.number] = box.hand_over()
            for fd in channels[shell.number]:
                # the kernel, another user when the grader is root, reopens them through /proc
                os.fchmod(fd, 0o666)
        except (StudentError, SandboxUnavailable) as error:
            problems[shell.number] = f"the student's code could not be loaded ({error})"
    return sandboxes, channels, problems


def run_notebooks(
    folder: Path,
    lessons: list[tuple[LessonResult, Path, LessonProgram | None]],
    options: GradingOptions,
    course: Course,
    slot: WarmSlot | None = None,
    replay: bool = True,
) -> dict[str, NotebookRun]:
    """Run nbval on every readable lesson notebook of one student, against ``course``'s masters.

    ``slot``: the grader's warm slot, whose zygote forks the lessons' sandboxes; None: cold starts.
    ``replay``: a lesson with a notebook transcript (:mod:`autograder.grading.notebook_calls`, learned by
    :func:`record_notebook_calls`) whose recorded calls all return the reference's values in a fresh sandbox of
    the student's is ``passed`` without a kernel run; False runs every kernel.

    Returns ``{lesson number: NotebookRun}`` with points decided later by
    :func:`award`; here ``points`` is 0 and ``status`` is nbval's verdict.
    """
    runnable = [(shell, program) for shell, _, program in lessons if program is not None]
    runs = {}
    if replay:
        learned = notebook_calls.memo(course)
        to_run = []
        for shell, program in runnable:
            transcript = learned.get(shell.number)
            if transcript is not None and _replays(shell.number, program, transcript, options, course, slot):
                runs[shell.number] = NotebookRun(status="passed", max_points=options.notebook_points, failures=[])
            else:
                to_run.append((shell, program))
        runnable = to_run
    if runnable:
        runs.update(_kernel_runs(runnable, options, course, slot)[0])
    return runs


def _replays(lesson, program, transcript, options, course, slot):
    """Do the lesson's recorded calls return the reference's values in a fresh sandbox of the student's?"""
    try:
        with StudentSandbox(
            {lesson: program}, course.support, limits=options.limits, slot=slot, resets_slot=False
        ) as box:
            return notebook_calls.replays_as_recorded(box, transcript)
    except (StudentError, SandboxUnavailable):
        return False


def record_notebook_calls(course: Course, options: GradingOptions, lessons: tuple = (), times: int = 2) -> dict:
    """Learn the notebook transcripts of ``course``'s lessons (all, or ``lessons``): run the masters with the
    reference's functions ``times`` times, noting every call (:mod:`autograder.grading.notebook_calls`).

    The lessons are shared out between as many forks as this process may use CPUs (:func:`_shared_out`), and
    each fork records its lessons ``times`` times in a row, with cold sandboxes (a warm slot serves one process
    only): the CPUs work side by side, and no more lessons' sandboxes are alive at once than
    one recording of every lesson holds. Kept on the reference's memo and on disk; a lesson learned before (here
    or by an earlier run on this machine) is not run again. Speed only: a failure leaves the lesson without a
    transcript (its kernel runs). Returns the memo, ``{lesson: NotebookTranscript or None}``.
    """
    from autograder.grading.suite import reference_programs
    from autograder.sandbox.forking import fork_each

    learned = notebook_calls.memo(course)
    wanted = [lesson.number for lesson in course.catalog.graded_lessons if not lessons or lesson.number in lessons]
    if any(number not in learned for number in wanted):
        saved = notebook_calls.load(course)
        if saved:
            learned.update({number: t for number, t in saved.items() if number not in learned})
    todo = [number for number in wanted if number not in learned]
    if not todo:
        return learned
    programs = reference_programs(course)
    groups = _shared_out(course, todo, max(1, min(len(todo), len(os.sched_getaffinity(0)))))

    def record_group(index, _slot):  # in a fork: {lesson: [the calls noted in each run, or None]} into a file
        shells = [
            (LessonResult(number=number, title="", notebook="", status="graded"), programs[number])
            for number in groups[index]
        ]
        noted = {number: [] for number in groups[index]}
        for _ in range(times):
            runs, records = _kernel_runs(shells, options, course, None, record=True)
            for number in groups[index]:
                ok = runs.get(number) is not None and runs[number].status == "passed" and records is not None
                mine = [r for r in records if isinstance(r, dict) and r.get("lesson") == number] if ok else None
                noted[number].append(mine)
        (Path(base) / f"{index}.json").write_text(json.dumps(noted), encoding="utf-8")

    recorded = {}
    try:
        with cleanup.private_folder_for("recordings") as base:
            fork_each(
                record_group,
                list(range(len(groups))),
                jobs=len(groups),
                on_done=lambda *_: None,
                deadline_seconds=times * _stage_timeout(len(todo)) + 60,
            )
            for index in range(len(groups)):
                try:
                    recorded.update(json.loads((Path(base) / f"{index}.json").read_text(encoding="utf-8")))
                except (OSError, ValueError):
                    pass  # that fork died: its lessons are not replayed
    except Exception:  # speed only: these lessons simply run their kernels
        return learned
    for number in todo:
        learned[number] = notebook_calls.transcript_from(recorded.get(number) or [None])
    notebook_calls.save(course, learned)
    return learned


def _shared_out(course: Course, lessons: list[str], forks: int) -> list[list[str]]:
    """``lessons`` in ``forks`` groups of about equal work, the heaviest first, each to the group with the least
    work so far. A master's work is guessed from the length of its code outside the answer cells, squared: the
    longest masters are also those that run their exercises in loops (on this course, measured one lesson at a
    time, this guess splits 52 s of recording into 25.5 s and 26.7 s).

    >>> _shared_out(course, ["01", "02", "09"], 2)          # doctest: +SKIP
    [['09'], ['01', '02']]
    """

    def work(number):
        master = read_master(course.solutions / course.catalog.lesson(number).filename)
        code = sum(len(c.source) for c in master.cells if c.cell_type == "code" and not cells.is_answer_cell(c))
        return code**2

    groups, loads = [[] for _ in range(forks)], [0] * forks
    for load, number in sorted(((work(n), n) for n in lessons), reverse=True):
        least = loads.index(min(loads))
        groups[least].append(number)
        loads[least] += load
    return [group for group in groups if group]


def _kernel_runs(runnable, options, course, slot, record=False):
    """nbval on the lessons of ``runnable`` (``[(LessonResult, LessonProgram)]``) in one runner: returns
    ``({lesson: NotebookRun}, the calls noted when ``record`` (reference code only), else None)``."""
    runs, records = {}, None
    catalog = course.catalog
    sandboxes, channels, problems = _student_channels(runnable, options, course.support, slot)
    try:
        with cleanup.private_folder_for("nbval") as base:
            sandbox_dir, scratch_dir = launcher.prepare_dirs(base, course.support)
            (sandbox_dir / "nbval_sanitize.cfg").write_text(SANITIZE)
            names = []
            for shell, _ in runnable:
                if shell.number not in channels:
                    continue
                lesson = catalog.lesson(shell.number)
                nb = merged_notebook(read_master(course.solutions / lesson.filename), shell.number)
                (scratch_dir / lesson.filename).write_text(canonical_text(nb), encoding="utf-8")
                os.chmod(scratch_dir / lesson.filename, 0o644)
                names.append(lesson.filename)
            limits = launcher.Limits(
                memory_bytes=options.limits.memory_bytes,
                cpu_seconds=int(_stage_timeout(len(names))),
                processes=options.limits.processes,
                file_bytes=options.limits.file_bytes,
                open_files=max(options.limits.open_files, 1024),
                extra_env={
                    "PYTHONPATH": "/sandbox",
                    "JUPYTER_RUNTIME_DIR": "/tmp/.jupyter-runtime",
                    "IPYTHONDIR": "/tmp/.ipython",
                    "JUPYTER_PLATFORM_DIRS": "1",
                    **(notebook_calls.environment_flag() if record else {}),
                },
            )
            summary, error = (
                _run(names, channels, sandbox_dir, scratch_dir, limits, _stage_timeout(len(names)))
                if names
                else ({}, "")
            )
            if record:
                records = notebook_calls.read_records(scratch_dir)
    finally:
        for box in sandboxes:
            box.close()
    for shell, _ in runnable:
        lesson = catalog.lesson(shell.number)
        entry = (summary or {}).get(lesson.filename) if summary else None
        if shell.number in problems or error or not isinstance(entry, dict):
            why = problems.get(shell.number) or error or "the notebook did not run"
            runs[shell.number] = NotebookRun(status="failed", max_points=options.notebook_points, failures=[why])
            continue
        failures = [str(f)[:300] for f in entry.get("failures", [])][:20]
        runs[shell.number] = NotebookRun(
            status="failed" if failures else "passed", max_points=options.notebook_points, failures=failures
        )
    return runs, records


def _run(names, channels, sandbox_dir, scratch_dir, limits, timeout):
    """Start the runner in its sandbox; return (summary dict or None, error line or '')."""
    spec = json.dumps({lesson: list(fds) for lesson, fds in channels.items()})
    program = (
        [sys.executable, "-I", "-B", "/sandbox/nbval_runner.py"]
        + launcher.worker_flags()
        + ["--channels", spec]
        + names
    )
    process = launcher.spawn(
        program,
        sandbox_dir,
        scratch_dir,
        limits,
        stdin=subprocess.DEVNULL,
        pass_fds=[fd for fds in channels.values() for fd in fds],
    )
    deadline = time.monotonic() + timeout
    output = b""
    try:
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                return None, f"the notebooks did not finish within {timeout:g} s"
            ready, _, _ = select.select([process.stdout], [], [], remaining)
            if not ready:
                continue
            chunk = os.read(process.stdout.fileno(), 65536)
            if not chunk:
                break
            output += chunk
            if len(output) > SUMMARY_LIMIT:
                return None, "the notebook stage produced too much output"
    finally:
        launcher.terminate(process)
    lines = output.decode("utf-8", "replace").strip().splitlines()
    try:
        data = json.loads(lines[-1]) if lines else None
        notebooks = data["notebooks"]
        if not isinstance(notebooks, dict):
            raise TypeError
    except (ValueError, KeyError, TypeError, IndexError):
        return None, "the notebook stage ended without a result"
    return notebooks, ""


NEEDS_FULL_MARKS = "the point needs every exercise of the lesson to pass its hidden checks"


def full_hidden_marks(lesson_result: LessonResult) -> bool:
    """Did every exercise of the lesson earn full marks in the hidden suite?"""
    return all(e.points >= e.max_points for e in lesson_result.exercises)


def not_run_for_lost_points(max_points: float) -> NotebookRun:
    """The run of a lesson that lost hidden points: nbval is not started, the point is 0 whatever it says."""
    return NotebookRun(status="skipped", max_points=max_points, failures=[f"not run: {NEEDS_FULL_MARKS}"])


def award(lesson_result: LessonResult) -> None:
    """Give the notebook point only if nbval passed and every exercise earned full marks."""
    run = lesson_result.run
    if run is None:
        return
    full = full_hidden_marks(lesson_result)
    if run.status == "passed" and full:
        run.points = run.max_points
    else:
        run.points = 0.0
        if run.status == "passed" and not full:
            run.failures = [f"the notebook ran, but {NEEDS_FULL_MARKS}"]
